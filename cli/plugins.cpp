#include "plugins.h"

#include <dlfcn.h>

#include <filesystem>
#include <map>
#include <mutex>
#include <sstream>
#include <stdexcept>

#include "image_plugin.h"
#include "outputs.h"
#include "png_writer.h"

namespace rastersim {
namespace {

// Where a module can be: beside the program and in ../LIBDIR (installed), in the build folders this
// binary was built from, then wherever dlopen looks by itself. The paths are explicit because a
// sanitizer's dlopen interceptor makes dlopen search its run path instead of the program's.
std::vector<std::string> candidates(const char* file) {
  std::vector<std::string> paths;
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    paths.push_back((exe.parent_path() / file).string());
    paths.push_back((exe.parent_path() / ".." / RASTERSIM_INSTALL_LIBDIR / file).string());
  }
  std::istringstream build_dirs(RASTERSIM_PLUGIN_BUILD_DIRS);
  for (std::string dir; std::getline(build_dirs, dir, ':');)
    if (!dir.empty()) paths.push_back((std::filesystem::path(dir) / file).string());
  paths.push_back(file);
  return paths;
}

void* load(const char* file, const char* what) {
  std::string error;
  for (const std::string& path : candidates(file)) {
    if (path != file && !std::filesystem::exists(path)) continue;
    if (void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL)) return handle;
    error = dlerror();
  }
  throw std::runtime_error(std::string("cannot load ") + what + " (" + file + "): " + error);
}

template <class F>
F symbol(void* handle, const char* name, const char* file) {
  void* s = dlsym(handle, name);
  if (!s) throw std::runtime_error(std::string(file) + " has no " + name + ": a library of another version?");
  return reinterpret_cast<F>(s);
}

struct Images {
  decltype(&rastersim_image_writable) writable;
  decltype(&rastersim_image_encode) encode;
  decltype(&rastersim_image_free) free;
  decltype(&rastersim_image_decode_rgb8) decode_rgb8;
};

const Images& images() {
  static std::once_flag once;
  static Images table;
  std::call_once(once, [] {
    const char* file = "librastersim_images.so";
    void* h = load(file, "the image module (OpenImageIO)");
    table = {symbol<decltype(table.writable)>(h, "rastersim_image_writable", file),
             symbol<decltype(table.encode)>(h, "rastersim_image_encode", file),
             symbol<decltype(table.free)>(h, "rastersim_image_free", file),
             symbol<decltype(table.decode_rgb8)>(h, "rastersim_image_decode_rgb8", file)};
  });
  return table;
}

}  // namespace

bool image_format_writable(const std::string& path) { return lower_extension(path) == ".png" || images().writable(path.c_str()) != 0; }

std::vector<unsigned char> encode_image(const std::string& path, int width, int height, int channels, PixelType type,
                                        const void* pixels) {
  // PNG without OpenImageIO (its samples are integers of 8 or 16 bits).
  if (lower_extension(path) == ".png" && type != PixelType::Float)
    return encode_png(width, height, channels, type == PixelType::UInt8 ? 8 : 16, pixels);
  unsigned char* data = nullptr;
  size_t size = 0;
  char error[512];
  if (images().encode(path.c_str(), width, height, channels, int(type), pixels, &data, &size, error, sizeof error) != 0)
    throw std::runtime_error(error);
  std::vector<unsigned char> bytes(data, data + size);
  images().free(data);
  return bytes;
}

DecodedImage decode_image_rgb8(const std::string& path, int max_size) {
  DecodedImage image;
  unsigned char* pixels = nullptr;
  char error[512];
  if (images().decode_rgb8(path.c_str(), max_size, &image.width, &image.height, &pixels, error, sizeof error) != 0)
    throw std::runtime_error(error);
  if (pixels) {
    image.rgb.assign(pixels, pixels + 3 * size_t(image.width) * size_t(image.height));
    images().free(pixels);
  }
  return image;
}

const void* systemc_api(const std::string& library_path, const std::string& abi) {
  static std::mutex mutex;
  static std::map<std::string, const void*> loaded;  // by path; each library is opened once
  const std::lock_guard<std::mutex> lock(mutex);
  const void*& api = loaded[library_path];
  if (!api) {
    const std::string file = library_path.empty() ? "librastersim_systemc.so" : library_path;
    void* h = load(file.c_str(), "the SystemC backend");
    const char* stamp = symbol<const char* (*)()>(h, "rastersim_module_abi", file.c_str())();
    if (abi != stamp)
      throw std::runtime_error(file + " was built against other records (" + stamp + ") than this program (" + abi +
                               ")");
    api = symbol<const void* (*)()>(h, "rastersim_systemc_api", file.c_str())();
  }
  return api;
}

}  // namespace rastersim
