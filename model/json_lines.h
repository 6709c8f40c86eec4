// Line numbers for the values of a JSON text, by JSON pointer ("/objects/0/color"), so that errors
// found after parsing (nlohmann::json keeps no positions) can name the line of the offending key.
#pragma once

#include <map>
#include <string>
#include <utility>

#include <nlohmann/json.hpp>

namespace rastersim {

// Parses a JSON document. Any error, a syntax error, a number outside the range of a double or an
// object naming a key twice (at any level, however the key is spelled), throws
// InputError(file_name, line, ...) with the line where parsing stopped or of the second key.
nlohmann::json parse_json_document(const std::string& text, const std::string& file_name);

class JsonLines {
 public:
  // `text` must be valid JSON (parse it with nlohmann::json first).
  explicit JsonLines(const std::string& text);
  // The 1-based line where the member's key (or the array element) starts; for a pointer that is
  // not there (or nested more than 64 containers deep), the line of its closest recorded ancestor;
  // 1 for the root.
  int line(const std::string& pointer) const;

  // The member named twice that comes first in the text and the line of its second occurrence;
  // {"", 0} when no object names a key twice.
  std::pair<std::string, int> first_repeated() const;

  // "/a/b" + "c" with the JSON pointer escapes (~0, ~1).
  static std::string child(const std::string& pointer, const std::string& key);
  static std::string child(const std::string& pointer, size_t index) { return pointer + "/" + std::to_string(index); }

 private:
  std::map<std::string, int> lines_;
  std::map<std::string, int> repeated_;
};

}  // namespace rastersim
