// Bad input: the message names the file, the line and the problem. The CLI maps it to exit code 2.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace rastersim {

// `text` as a message shows it: a byte that would not print (a control character, which a NUL
// among would cut the message at; a byte outside a valid UTF-8 sequence) as \xNN; line ends and
// tabs, and valid UTF-8 (a file name in any language), as they are.
inline std::string printable(const std::string& text) {
  static const char hex[] = "0123456789abcdef";
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size();) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    // The length of a valid UTF-8 sequence starting here (0: not one).
    size_t n = 0;
    if (c >= 0x20 && c < 0x7f) n = 1;
    else if (c == '\n' || c == '\t') n = 1;
    else if (c >= 0xc2 && c <= 0xf4) {
      n = c < 0xe0 ? 2 : c < 0xf0 ? 3 : 4;
      if (i + n > text.size()) n = 0;
      for (size_t k = 1; k < n; ++k)
        if ((static_cast<unsigned char>(text[i + k]) & 0xc0) != 0x80) n = 0;
      // Overlong three- and four-byte forms, surrogates and code points above U+10FFFF.
      if (n >= 3) {
        const unsigned char d = static_cast<unsigned char>(text[i + 1]);
        if ((c == 0xe0 && d < 0xa0) || (c == 0xed && d >= 0xa0) || (c == 0xf0 && d < 0x90) || (c == 0xf4 && d >= 0x90))
          n = 0;
      }
    }
    if (n > 0) {
      out.append(text, i, n);
      i += n;
    } else {
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
      ++i;
    }
  }
  return out;
}

class InputError : public std::runtime_error {
 public:
  InputError(const std::string& file, int line, const std::string& problem)
      : std::runtime_error(printable(format(file, line, problem))) {}
  explicit InputError(const std::string& message) : std::runtime_error(printable(message)) {}

 private:
  static std::string format(const std::string& file, int line, const std::string& problem) {
    return line > 0 ? file + ":" + std::to_string(line) + ": " + problem : file + ": " + problem;
  }
};

}  // namespace rastersim
