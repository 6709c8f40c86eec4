// Bad input: the message names the file, the line and the problem. The CLI maps it to exit code 2.
#pragma once

#include <stdexcept>
#include <string>

namespace rastersim {

class InputError : public std::runtime_error {
 public:
  InputError(const std::string& file, int line, const std::string& problem)
      : std::runtime_error(format(file, line, problem)) {}
  explicit InputError(const std::string& message) : std::runtime_error(message) {}

 private:
  static std::string format(const std::string& file, int line, const std::string& problem) {
    return line > 0 ? file + ":" + std::to_string(line) + ": " + problem : file + ": " + problem;
  }
};

}  // namespace rastersim
