#include "model/json_lines.h"

#include <cctype>

namespace rastersim {
namespace {

// A recursive walk over valid JSON that records where each value starts.
class Walker {
 public:
  Walker(const std::string& text, std::map<std::string, int>& lines) : s_(text), lines_(lines) {}
  void run() {
    skip_space();
    value("");
  }

 private:
  void skip_space() {
    while (at_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[at_]))) {
      if (s_[at_] == '\n') ++line_;
      ++at_;
    }
  }

  // A string token; returns its text with the simple escapes decoded (\uXXXX kept as written).
  std::string string_token() {
    std::string out;
    ++at_;  // opening quote
    while (at_ < s_.size() && s_[at_] != '"') {
      if (s_[at_] == '\\' && at_ + 1 < s_.size()) {
        const char e = s_[++at_];
        switch (e) {
          case 'n': out += '\n'; break;
          case 't': out += '\t'; break;
          case 'r': out += '\r'; break;
          case 'b': out += '\b'; break;
          case 'f': out += '\f'; break;
          case 'u': out += "\\u"; break;
          default: out += e; break;
        }
      } else {
        out += s_[at_];
      }
      ++at_;
    }
    ++at_;  // closing quote
    return out;
  }

  void value(const std::string& pointer) {
    if (at_ >= s_.size()) return;
    const char c = s_[at_];
    if (c == '{') {
      ++at_;
      skip_space();
      while (at_ < s_.size() && s_[at_] != '}') {
        const int key_line = line_;
        const std::string key = string_token();
        const std::string member = JsonLines::child(pointer, key);
        lines_.emplace(member, key_line);
        skip_space();
        ++at_;  // ':'
        skip_space();
        value(member);
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
        value(element);
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
  size_t at_ = 0;
  int line_ = 1;
};

}  // namespace

JsonLines::JsonLines(const std::string& text) { Walker(text, lines_).run(); }

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
