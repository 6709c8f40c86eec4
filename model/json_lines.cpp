#include "model/json_lines.h"

#include <algorithm>
#include <cctype>

#include "model/input_error.h"

namespace rastersim {
namespace {

// A SAX consumer that builds nothing and keeps where the parser gave up: nlohmann's
// out_of_range errors (number overflow) carry no position, the parser's own report does.
struct ErrorLocator : nlohmann::json_sax<nlohmann::json> {
  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(number_integer_t) override { return true; }
  bool number_unsigned(number_unsigned_t) override { return true; }
  bool number_float(number_float_t, const string_t&) override { return true; }
  bool string(string_t&) override { return true; }
  bool binary(binary_t&) override { return true; }
  bool start_object(std::size_t) override { return true; }
  bool key(string_t&) override { return true; }
  bool end_object() override { return true; }
  bool start_array(std::size_t) override { return true; }
  bool end_array() override { return true; }
  bool parse_error(std::size_t byte, const std::string&, const nlohmann::detail::exception&) override {
    located_byte = byte;
    return false;
  }
  std::size_t located_byte = 0;
};

// A line ends at "\n", "\r\n" or a lone "\r" (old Mac files): true at the byte that ends one.
bool ends_line(const std::string& text, std::size_t at) {
  return text[at] == '\n' || (text[at] == '\r' && (at + 1 >= text.size() || text[at + 1] != '\n'));
}

// The 1-based line of the character before byte `byte` (nlohmann counts the failing character).
int line_before_byte(const std::string& text, std::size_t byte) {
  const std::size_t end = std::min(byte, text.size());
  int line = 1;
  for (std::size_t at = 0; at + 1 < end; ++at) line += ends_line(text, at);
  return line;
}

// A recursive walk over valid JSON that records where each value starts.
class Walker {
 public:
  Walker(const std::string& text, std::map<std::string, int>& lines, std::map<std::string, int>& repeated)
      : s_(text), lines_(lines), repeated_(repeated) {}
  void run() {
    skip_space();
    value("", 0);
  }

 private:
  void skip_space() {
    while (at_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[at_]))) {
      if (ends_line(s_, at_)) ++line_;
      ++at_;
    }
  }

  // A string token, decoded as the parser decodes it: a key spelled with escapes ("w\u0069dth") is
  // the same key as the plain one.
  std::string string_token() {
    const size_t start = at_;
    bool escaped = false;
    ++at_;  // opening quote
    while (at_ < s_.size() && s_[at_] != '"') {
      if (s_[at_] == '\\') {
        escaped = true;
        ++at_;
      }
      ++at_;
    }
    ++at_;  // closing quote
    if (!escaped) return s_.substr(start + 1, at_ - start - 2);
    try {
      return nlohmann::json::parse(s_.substr(start, at_ - start)).get<std::string>();
    } catch (const nlohmann::json::exception&) {
      return s_.substr(start + 1, at_ - start - 2);  // unreachable for text the parser accepted
    }
  }

  // Containers nested deeper than this are stepped over without recording their members: the
  // recursion (and the pointers, which grow with the depth) stay bounded for any input.
  static constexpr int kMaxRecordedDepth = 64;

  // Steps over one object or array, whatever its depth, counting lines.
  void skip_container() {
    int depth = 0;
    do {
      const char c = s_[at_];
      if (c == '"') {
        string_token();
        continue;
      }
      if (ends_line(s_, at_)) ++line_;
      if (c == '{' || c == '[') ++depth;
      else if (c == '}' || c == ']') --depth;
      ++at_;
    } while (at_ < s_.size() && depth > 0);
  }

  void value(const std::string& pointer, int depth) {
    if (at_ >= s_.size()) return;
    const char c = s_[at_];
    if ((c == '{' || c == '[') && depth >= kMaxRecordedDepth) {
      skip_container();
    } else if (c == '{') {
      ++at_;
      skip_space();
      while (at_ < s_.size() && s_[at_] != '}') {
        const int key_line = line_;
        const std::string key = string_token();
        const std::string member = JsonLines::child(pointer, key);
        if (!lines_.emplace(member, key_line).second) repeated_.emplace(member, key_line);
        skip_space();
        ++at_;  // ':'
        skip_space();
        value(member, depth + 1);
        skip_space();
        if (at_ < s_.size() && s_[at_] == ',') ++at_;
        skip_space();
      }
      ++at_;
    } else if (c == '[') {
      ++at_;
      skip_space();
      size_t index = 0;
      while (at_ < s_.size() && s_[at_] != ']') {
        const std::string element = JsonLines::child(pointer, index++);
        lines_.emplace(element, line_);
        value(element, depth + 1);
        skip_space();
        if (at_ < s_.size() && s_[at_] == ',') ++at_;
        skip_space();
      }
      ++at_;
    } else if (c == '"') {
      string_token();
    } else {
      while (at_ < s_.size() && !std::isspace(static_cast<unsigned char>(s_[at_])) && s_[at_] != ',' &&
             s_[at_] != ']' && s_[at_] != '}')
        ++at_;
    }
  }

  const std::string& s_;
  std::map<std::string, int>& lines_;
  std::map<std::string, int>& repeated_;
  size_t at_ = 0;
  int line_ = 1;
};

}  // namespace

nlohmann::json parse_json_document(const std::string& text, const std::string& file_name) {
  try {
    nlohmann::json doc = nlohmann::json::parse(text);
    // The parser keeps the last of two equal keys; a file that names one twice is refused at any level.
    const JsonLines lines(text);
    if (const auto twice = lines.first_repeated(); !twice.first.empty()) {
      const std::string& pointer = twice.first;
      std::string key = pointer.substr(pointer.rfind('/') + 1);
      for (size_t at; (at = key.find("~1")) != std::string::npos;) key.replace(at, 2, "/");
      for (size_t at; (at = key.find("~0")) != std::string::npos;) key.replace(at, 2, "~");
      throw InputError(file_name, twice.second,
                       "key '" + key + "' is given twice (first on line " + std::to_string(lines.line(pointer)) + ")");
    }
    return doc;
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(file_name, line_before_byte(text, e.byte), std::string("malformed JSON: ") + e.what());
  } catch (const nlohmann::json::exception& e) {
    ErrorLocator locator;
    nlohmann::json::sax_parse(text, &locator);
    throw InputError(file_name, line_before_byte(text, locator.located_byte), std::string("malformed JSON: ") + e.what());
  }
}

JsonLines::JsonLines(const std::string& text) { Walker(text, lines_, repeated_).run(); }

std::pair<std::string, int> JsonLines::first_repeated() const {
  std::pair<std::string, int> first{"", 0};
  for (const auto& [pointer, line] : repeated_)
    if (first.first.empty() || line < first.second) first = {pointer, line};
  return first;
}

int JsonLines::line(const std::string& pointer) const {
  std::string p = pointer;
  while (!p.empty()) {
    const auto it = lines_.find(p);
    if (it != lines_.end()) return it->second;
    p.erase(p.rfind('/'));
  }
  return 1;
}

std::string JsonLines::child(const std::string& pointer, const std::string& key) {
  std::string escaped;
  for (char c : key) {
    if (c == '~') escaped += "~0";
    else if (c == '/') escaped += "~1";
    else escaped += c;
  }
  return pointer + "/" + escaped;
}

}  // namespace rastersim
