// librastersim_images.so: the image writers and the texture reader of OpenImageIO behind a C
// interface (image_plugin.h), so that rastersim loads OpenImageIO only when a command writes or
// reads an image.
#include "image_plugin.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <sys/mman.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#define RASTERSIM_IMAGES_API __attribute__((visibility("default")))

namespace {

// One line: OpenImageIO's messages can hold several, each a further detail of the first.
void set_error(char* error, size_t error_size, std::string message) {
  while (!message.empty() && message.back() == '\n') message.pop_back();
  for (size_t at; (at = message.find('\n')) != std::string::npos;) message.replace(at, 1, "; ");
  if (error_size == 0) return;
  std::strncpy(error, message.c_str(), error_size - 1);
  error[error_size - 1] = '\0';
}

// OpenImageIO's PNG reader leaves libpng's default error handler in place, which prints
// "libpng error: ..." on stderr before OpenImageIO reports the same error to us. While a file is
// read, stderr goes to an anonymous in-memory file; what was printed there is then passed on to
// stderr without libpng's lines.
class LibpngLinesDropped {
 public:
  LibpngLinesDropped() {
    std::fflush(stderr);
    const int memory = memfd_create("rastersim-image-stderr", MFD_CLOEXEC);
    if (memory < 0) return;
    saved_ = dup(2);
    if (saved_ < 0 || dup2(memory, 2) < 0) {
      if (saved_ >= 0) close(saved_);
      saved_ = -1;
      close(memory);
      return;
    }
    capture_ = fdopen(memory, "r");
  }
  ~LibpngLinesDropped() {
    if (saved_ < 0) return;
    std::fflush(stderr);
    dup2(saved_, 2);
    close(saved_);
    if (!capture_) return;
    std::rewind(capture_);
    char line[1024];
    while (std::fgets(line, sizeof line, capture_))
      if (std::strncmp(line, "libpng ", 7) != 0) std::fputs(line, stderr);
    std::fclose(capture_);
  }
  LibpngLinesDropped(const LibpngLinesDropped&) = delete;
  LibpngLinesDropped& operator=(const LibpngLinesDropped&) = delete;

 private:
  int saved_ = -1;
  FILE* capture_ = nullptr;
};

}  // namespace

extern "C" RASTERSIM_IMAGES_API int rastersim_image_writable(const char* path) {
  auto out = OIIO::ImageOutput::create(path);
  if (!out) OIIO::geterror();  // clear OpenImageIO's pending error
  return out ? 1 : 0;
}

extern "C" RASTERSIM_IMAGES_API int rastersim_image_encode(const char* path, int width, int height, int channels,
                                                           int type, const void* pixels, unsigned char** data,
                                                           size_t* size, char* error, size_t error_size) {
  const OIIO::TypeDesc types[] = {OIIO::TypeDesc::UINT8, OIIO::TypeDesc::UINT16, OIIO::TypeDesc::FLOAT};
  if (type < 0 || type > 2) return set_error(error, error_size, "unknown pixel type"), 1;
  // Encoded in memory: OpenImageIO 2.4's PNG and TIFF writers report success on a file cut short
  // by a full disk, so the caller writes the bytes with checked writes.
  std::vector<unsigned char> encoded;
  OIIO::Filesystem::IOVecOutput memory(encoded);
  auto out = OIIO::ImageOutput::create(path, &memory);
  const std::string shown(path);
  if (!out) return set_error(error, error_size, shown + ": no image writer for this extension: " + OIIO::geterror()), 1;
  if (!out->supports("ioproxy"))
    return set_error(error, error_size, shown + ": the " + out->format_name() + " writer cannot encode to memory"), 1;
  OIIO::ImageSpec spec(width, height, channels, types[type]);
  if (!out->open(path, spec) || !out->write_image(types[type], pixels) || !out->close())
    return set_error(error, error_size, shown + ": " + out->geterror()), 1;
  *size = encoded.size();
  *data = static_cast<unsigned char*>(std::malloc(encoded.size() ? encoded.size() : 1));
  if (!*data) return set_error(error, error_size, shown + ": out of memory"), 1;
  if (!encoded.empty()) std::memcpy(*data, encoded.data(), encoded.size());
  return 0;
}

extern "C" RASTERSIM_IMAGES_API void rastersim_image_free(unsigned char* data) { std::free(data); }

extern "C" RASTERSIM_IMAGES_API int rastersim_image_decode_rgb8(const char* path, int max_size, int* width,
                                                                int* height, unsigned char** pixels, char* error,
                                                                size_t error_size) {
  *pixels = nullptr;
  const std::string shown(path);
  const LibpngLinesDropped quiet;
  // The colour as stored: a PNG's colour is not multiplied by its alpha on the way in.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(path, &config);
  if (!in) {
    std::string message = OIIO::geterror();
    if (message.empty()) message = "not an image OpenImageIO can read";
    return set_error(error, error_size, shown + ": " + message), 1;
  }
  const OIIO::ImageSpec spec = in->spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 || spec.depth != 1)
    return set_error(error, error_size, shown + ": not a two-dimensional image"), 1;
  *width = spec.width;
  *height = spec.height;
  if (spec.width > max_size || spec.height > max_size) return 0;  // not read; the caller names the limit
  const size_t count = size_t(spec.width) * size_t(spec.height);
  std::vector<unsigned char> read(count * size_t(spec.nchannels));
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, read.data()))
    return set_error(error, error_size, shown + ": " + in->geterror()), 1;
  *pixels = static_cast<unsigned char*>(std::malloc(3 * count));
  if (!*pixels) return set_error(error, error_size, shown + ": out of memory"), 1;
  for (size_t i = 0; i < count; ++i)
    for (int c = 0; c < 3; ++c)
      (*pixels)[3 * i + size_t(c)] = read[i * size_t(spec.nchannels) + size_t(spec.nchannels >= 3 ? c : 0)];
  return 0;
}
