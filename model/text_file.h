// Reading an input file whole, bounded: a device such as /dev/zero or a file far larger than any
// input of its kind ends with an error naming the file, not with gigabytes read (docs/robustness.md).
#pragma once

#include <cstddef>
#include <string>

namespace rastersim {

constexpr size_t kMiB = size_t(1) << 20;

// Throws InputError unless `path` is a regular file or does not exist (opening it then says so): a
// folder, or a device, FIFO or socket, which would block the open or never end. `what` names the
// kind of file ("a profile file").
void refuse_special_file(const std::string& path, const std::string& what);

// The bytes of `path`, at most `max_bytes` of them. `what` names the kind of file in errors ("a
// profile file"). Throws InputError: a folder, a file that cannot be opened or read, or one longer
// than max_bytes.
std::string read_text_file(const std::string& path, const std::string& what, size_t max_bytes);

}  // namespace rastersim
