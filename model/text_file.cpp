#include "text_file.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "input_error.h"

namespace rastersim {

void refuse_special_file(const std::string& path, const std::string& what) {
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  if (std::filesystem::is_directory(status)) throw InputError(path, 0, "is a directory, not " + what);
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
    throw InputError(path, 0, "is not a regular file (a device, FIFO or socket), so it cannot be " + what);
}

std::string read_text_file(const std::string& path, const std::string& what, size_t max_bytes) {
  refuse_special_file(path, what);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "cannot open " + what + ": " + std::strerror(errno));
  std::string text;
  char chunk[1 << 16];
  while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
    if (text.size() + size_t(in.gcount()) > max_bytes)
      throw InputError(path, 0, "is longer than " + std::to_string(max_bytes / kMiB) + " MiB, more than " + what +
                                    " can be (is it the right file?)");
    text.append(chunk, size_t(in.gcount()));
  }
  if (in.bad()) throw InputError(path, 0, "cannot read " + what);
  return text;
}

}  // namespace rastersim
