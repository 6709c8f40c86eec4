#include "tri_reader.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "model/input_error.h"
#include "model/text_file.h"

namespace rastersim {
namespace {

const char* const kCoordinateNames[9] = {"x0", "y0", "z0", "x1", "y1", "z1", "x2", "y2", "z2"};
const char* const kFlatColorNames[3] = {"r", "g", "b"};
const char* const kVertexColorNames[9] = {"r0", "g0", "b0", "r1", "g1", "b1", "r2", "g2", "b2"};
const char* const kTextureNames[9] = {"u0", "v0", "w0", "u1", "v1", "w1", "u2", "v2", "w2"};
// Starts a line's texture section (format version 2): nine numbers u v w per vertex.
const char* const kTextureKeyword = "uvw";

// Lines of `in` without their ends: a line ends at "\n", "\r\n" or a lone "\r" (old Mac files:
// their second line was read as the colours of the first). A physical line longer than
// kMaxTriLineBytes is not read further (a .tri line is under a kilobyte; /dev/zero is one endless
// line): next() reports it as TooLong.
constexpr size_t kMaxTriLineBytes = size_t(1) << 20;

class LineReader {
 public:
  enum Result { Line, End, TooLong };
  explicit LineReader(std::istream& in) : in_(in) {}
  Result next(std::string& line) {
    if (at_ == std::string::npos) {
      const Result read = read_physical_line();
      if (read != Line) return read;
      at_ = 0;
    }
    const size_t cr = text_.find('\r', at_);
    if (cr == std::string::npos) {
      line.assign(text_, at_, std::string::npos);
      at_ = std::string::npos;
    } else {
      line.assign(text_, at_, cr - at_);
      at_ = cr + 1 == text_.size() ? std::string::npos : cr + 1;  // "\r\n" ends one line
    }
    return Line;
  }

 private:
  // Up to "\n" (dropped), at most kMaxTriLineBytes bytes.
  Result read_physical_line() {
    text_.clear();
    std::streambuf* buffer = in_.rdbuf();
    for (bool any = false;;) {
      const int c = buffer->sbumpc();
      if (c == std::char_traits<char>::eof()) {
        in_.setstate(std::ios::eofbit);
        return any ? Line : End;
      }
      any = true;
      if (c == '\n') return Line;
      if (text_.size() == kMaxTriLineBytes) return TooLong;
      text_.push_back(char(c));
    }
  }

  std::istream& in_;
  std::string text_;
  size_t at_ = std::string::npos;  // where the next line starts in text_; npos: read another
};

std::vector<std::string> split_tokens(const std::string& text) {
  std::vector<std::string> tokens;
  size_t i = 0;
  auto is_space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; };
  while (i < text.size()) {
    while (i < text.size() && is_space(text[i])) ++i;
    const size_t start = i;
    while (i < text.size() && !is_space(text[i])) ++i;
    if (i > start) tokens.push_back(text.substr(start, i - start));
  }
  return tokens;
}

// Strict: the whole token must be a decimal (or hexadecimal) floating-point literal with a finite
// value. strtod accepts "nan" and "inf", which are reported as not finite, not as numbers read.
std::string parse_real(const std::string& token, const char* field, double& out) {
  const char* begin = token.c_str();
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(begin, &end);
  if (end == begin || end != begin + token.size())
    return std::string(field) + " '" + token + "' is not a number";
  if (!std::isfinite(value)) return std::string(field) + " '" + token + "' is not a finite number";
  out = value;
  return "";
}

std::string parse_channel(const std::string& token, const char* field, uint8_t& out) {
  double value = 0;
  std::string error = parse_real(token, field, value);
  if (!error.empty()) return error;
  if (value != std::floor(value)) return std::string(field) + " '" + token + "' is not an integer colour value";
  if (value < 0 || value > 255) return std::string(field) + " " + token + " is outside the colour range 0..255";
  out = uint8_t(value);
  return "";
}

// Parses a line's texture section, the tokens [first, last) after "uvw".
std::string parse_texture(std::vector<std::string>::const_iterator first, std::vector<std::string>::const_iterator last,
                          ScreenTriangle& tri) {
  if (last - first != 9)
    return std::string("expected 9 numbers 'u0 v0 w0 u1 v1 w1 u2 v2 w2' after '") + kTextureKeyword +
           "', but there are " + std::to_string(last - first);
  for (int i = 0; i < 9; ++i) {
    ScreenVertex& v = tri.v[i / 3];
    std::string error = parse_real(first[i], kTextureNames[i], i % 3 == 0 ? v.u : i % 3 == 1 ? v.v : v.w);
    if (!error.empty()) return error;
  }
  tri.textured = true;
  return "";
}

// Parses one triangle line; returns an error sentence or an empty string.
std::string parse_triangle(const std::vector<std::string>& tokens, ScreenTriangle& tri) {
  const auto keyword = std::find(tokens.begin(), tokens.end(), kTextureKeyword);
  if (keyword != tokens.end()) {
    std::string error = parse_texture(keyword + 1, tokens.end(), tri);
    if (!error.empty()) return error;
  }
  const size_t n = size_t(keyword - tokens.begin());  // the values before any texture section
  if (n != 9 && n != 12 && n != 18)
    return "expected 9 numbers 'x0 y0 z0 x1 y1 z1 x2 y2 z2', optionally followed by 3 colour values "
           "'r g b' or 9 'r0 g0 b0 r1 g1 b1 r2 g2 b2', but the line has " +
           std::to_string(n) + " value" + (n == 1 ? "" : "s");
  for (int i = 0; i < 9; ++i) {
    ScreenVertex& v = tri.v[i / 3];
    double& field = i % 3 == 0 ? v.x : i % 3 == 1 ? v.y : v.z;
    std::string error = parse_real(tokens[size_t(i)], kCoordinateNames[i], field);
    if (!error.empty()) return error;
    if (i % 3 == 2 && (field < 0.0 || field > 1.0))
      return std::string(kCoordinateNames[i]) + " " + tokens[size_t(i)] + " is outside the depth range [0, 1]";
  }
  if (n == 12) {
    Rgb flat;
    uint8_t* channels[3] = {&flat.r, &flat.g, &flat.b};
    for (int c = 0; c < 3; ++c) {
      std::string error = parse_channel(tokens[size_t(9 + c)], kFlatColorNames[c], *channels[c]);
      if (!error.empty()) return error;
    }
    for (ScreenVertex& v : tri.v) v.color = flat;
  } else if (n == 18) {
    for (int i = 0; i < 9; ++i) {
      Rgb& color = tri.v[i / 3].color;
      uint8_t& channel = i % 3 == 0 ? color.r : i % 3 == 1 ? color.g : color.b;
      std::string error = parse_channel(tokens[size_t(9 + i)], kVertexColorNames[i], channel);
      if (!error.empty()) return error;
    }
  }
  return "";
}

}  // namespace

std::vector<ScreenTriangle> read_tri(std::istream& in, const std::string& file_name, const Profile& profile,
                                     size_t max_triangles) {
  std::vector<ScreenTriangle> triangles;
  std::string line;
  int line_number = 0;
  LineReader lines(in);
  for (LineReader::Result read; (read = lines.next(line)) != LineReader::End;) {
    ++line_number;
    if (read == LineReader::TooLong)
      throw InputError(file_name, line_number, "the line is longer than " + std::to_string(kMaxTriLineBytes >> 20) +
                                                   " MiB, far more than a triangle (is this a .tri file?)");
    // A UTF-8 byte-order mark before the first line is not part of it (it made x0 not a number).
    if (line_number == 1 && line.compare(0, 3, "\xEF\xBB\xBF") == 0) line.erase(0, 3);
    const size_t comment = line.find('#');
    if (comment != std::string::npos) line.resize(comment);
    const std::vector<std::string> tokens = split_tokens(line);
    if (tokens.empty()) continue;
    ScreenTriangle tri;
    std::string error = parse_triangle(tokens, tri);
    if (error.empty()) error = check_screen_triangle(tri, profile);
    if (!error.empty()) throw InputError(file_name, line_number, error);
    if (triangles.size() == max_triangles)
      throw InputError(file_name, line_number, "more than " + std::to_string(max_triangles) +
                                                   " triangles, the limit of a .tri file");
    triangles.push_back(tri);
  }
  if (in.bad()) throw InputError(file_name, line_number + 1, "read error");
  return triangles;
}

std::vector<ScreenTriangle> read_tri_file(const std::string& path, const Profile& profile) {
  refuse_special_file(path, "a .tri file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, std::string("cannot open: ") + std::strerror(errno));
  return read_tri(in, path, profile);
}

void write_tri(std::ostream& out, const std::vector<ScreenTriangle>& triangles, const std::string& comment) {
  if (!comment.empty()) {
    std::istringstream lines(comment);
    std::string line;
    while (std::getline(lines, line)) out << "# " << line << '\n';
  }
  char buffer[64];
  for (const ScreenTriangle& tri : triangles) {
    std::string text;
    for (int k = 0; k < 3; ++k) {
      for (double value : {tri.v[k].x, tri.v[k].y, tri.v[k].z}) {
        std::snprintf(buffer, sizeof buffer, "%.17g", value);
        if (!text.empty()) text += ' ';
        text += buffer;
      }
    }
    const Rgb& c0 = tri.v[0].color;
    const bool flat = c0 == tri.v[1].color && c0 == tri.v[2].color;
    if (!(flat && c0 == Rgb{})) {
      for (int k = 0; k < (flat ? 1 : 3); ++k) {
        const Rgb& c = tri.v[k].color;
        std::snprintf(buffer, sizeof buffer, " %d %d %d", c.r, c.g, c.b);
        text += buffer;
      }
    }
    if (tri.textured) {
      text += std::string(" ") + kTextureKeyword;
      for (const ScreenVertex& v : tri.v)
        for (double value : {v.u, v.v, v.w}) {
          std::snprintf(buffer, sizeof buffer, " %.17g", value);
          text += buffer;
        }
    }
    out << text << '\n';
  }
}

}  // namespace rastersim
