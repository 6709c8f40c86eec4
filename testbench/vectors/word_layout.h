// The bit layout of one $readmemh word of a test-vector package (docs/vectors.md): named fields,
// first field at the most significant end, each in a slot of whole hex digits so that every field
// starts on a digit boundary of the line. A signed field is sign-extended to its slot, an unsigned
// one zero-extended; the testbench compares whole slots, so every digit of a word is checked.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace rastersim::vectors {

struct Field {
  std::string name;
  int bits = 0;          // the field's own width (the RTL signal's width)
  bool is_signed = false;
  int slot_bits = 0;     // bits rounded up to whole hex digits, at most 64
  int lsb = 0;           // the slot's lowest bit in the word
  std::string meaning;   // one line for the README and the manifest
};

class WordLayout {
 public:
  // Fields are appended from the most significant end towards bit 0.
  void add(const std::string& name, int bits, bool is_signed, const std::string& meaning);

  const std::vector<Field>& fields() const { return fields_; }
  const Field& field(const std::string& name) const;  // throws std::out_of_range
  int word_bits() const { return word_bits_; }
  int digits() const { return word_bits_ / 4; }

  // One line of the file, without the newline: the values in field order, each checked to fit its
  // field (std::logic_error otherwise: the model produced a value its register cannot hold).
  std::string word(const std::vector<int64_t>& values) const;
  // The value of each field of a word written by word(); sign-extended for signed fields.
  std::vector<int64_t> parse(const std::string& word) const;

 private:
  std::vector<Field> fields_;
  int word_bits_ = 0;
};

}  // namespace rastersim::vectors
