#include "fixed.h"

#include <algorithm>

namespace rastersim {

std::string to_string_i128(i128 v) {
  if (v == 0) return "0";
  const bool negative = v < 0;
  unsigned __int128 mag = negative ? (unsigned __int128)(-(v + 1)) + 1 : (unsigned __int128)v;
  std::string digits;
  while (mag != 0) {
    digits.push_back(char('0' + int(mag % 10)));
    mag /= 10;
  }
  if (negative) digits.push_back('-');
  std::reverse(digits.begin(), digits.end());
  return digits;
}

void throw_register_overflow(int64_t value, int bits, bool is_signed) {
  throw WidthOverflow("value " + std::to_string(value) + " does not fit the register's " + (is_signed ? "s" : "u") +
                      std::to_string(bits));
}

void throw_width_overflow(i128 v, int bits, const char* what) {
  throw WidthOverflow(std::string("value ") + to_string_i128(v) + " of " + what + " does not fit s" +
                      std::to_string(bits));
}

}  // namespace rastersim
