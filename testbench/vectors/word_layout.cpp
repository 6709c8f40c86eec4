#include "testbench/vectors/word_layout.h"

#include <stdexcept>

namespace rastersim::vectors {

void WordLayout::add(const std::string& name, int bits, bool is_signed, const std::string& meaning) {
  if (bits < 1 || bits > 64) throw std::logic_error("vector field " + name + ": width " + std::to_string(bits));
  Field f;
  f.name = name;
  f.bits = bits;
  f.is_signed = is_signed;
  f.slot_bits = (bits + 3) / 4 * 4;
  f.meaning = meaning;
  // Appending at the least significant end moves every earlier slot up.
  for (Field& earlier : fields_) earlier.lsb += f.slot_bits;
  f.lsb = 0;
  fields_.push_back(f);
  word_bits_ += f.slot_bits;
}

const Field& WordLayout::field(const std::string& name) const {
  for (const Field& f : fields_)
    if (f.name == name) return f;
  throw std::out_of_range("no vector field " + name);
}

std::string WordLayout::word(const std::vector<int64_t>& values) const {
  if (values.size() != fields_.size()) throw std::logic_error("vector word: wrong number of fields");
  static const char kDigits[] = "0123456789abcdef";
  std::string text;
  text.reserve(size_t(digits()));
  for (size_t i = 0; i < fields_.size(); ++i) {
    const Field& f = fields_[i];
    const int64_t v = values[i];
    const bool fits = f.is_signed ? (f.bits == 64 || (v >= -(int64_t(1) << (f.bits - 1)) && v < (int64_t(1) << (f.bits - 1))))
                                  : (v >= 0 && (f.bits >= 63 || v < (int64_t(1) << f.bits)));
    if (!fits)
      throw std::logic_error("vector field " + f.name + ": " + std::to_string(v) + " does not fit " +
                             std::to_string(f.bits) + (f.is_signed ? " signed" : " unsigned") + " bits");
    // Two's complement of v in slot_bits: sign extension for signed fields, zero for the others
    // (an unsigned value that fits is non-negative, so both are the low bits of v).
    const uint64_t bits = uint64_t(v);
    for (int d = f.slot_bits / 4 - 1; d >= 0; --d) text += kDigits[(bits >> (4 * d)) & 15];
  }
  return text;
}

std::vector<int64_t> WordLayout::parse(const std::string& word) const {
  if (int(word.size()) != digits()) throw std::invalid_argument("vector word of " + std::to_string(word.size()) +
                                                                " digits, expected " + std::to_string(digits()));
  std::vector<int64_t> values;
  size_t at = 0;
  for (const Field& f : fields_) {
    uint64_t bits = 0;
    for (int d = 0; d < f.slot_bits / 4; ++d, ++at) {
      const char c = word[at];
      const int digit = c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
      if (digit < 0) throw std::invalid_argument(std::string("not a hex digit: ") + c);
      bits = (bits << 4) | uint64_t(digit);
    }
    if (f.bits < 64) {
      bits &= (uint64_t(1) << f.bits) - 1;
      if (f.is_signed && (bits >> (f.bits - 1)) & 1) bits |= ~uint64_t(0) << f.bits;
    }
    values.push_back(int64_t(bits));
  }
  return values;
}

}  // namespace rastersim::vectors
