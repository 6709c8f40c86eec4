#include <algorithm>
#include <cctype>
#include "frontend/obj_loader.h"

#include <tiny_obj_loader.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "frontend/scene.h"
#include "model/input_error.h"
#include "model/triangle.h"
#include "model/text_file.h"

namespace rastersim::frontend {
namespace {

static_assert(sizeof(tinyobj::real_t) == sizeof(double), "link tinyobjloader_double (TINYOBJLOADER_USE_DOUBLE)");

// OBJ statements that carry nothing the front end draws; accepted and ignored.
const std::set<std::string> kIgnoredStatements = {
    "vt", "vp", "l", "p", "o", "g", "s", "mg", "usemtl", "mtllib", "cstype", "deg", "bmat", "step", "curv",
    "curv2", "surf", "parm", "trim", "hole", "scrv", "sp", "end", "con", "bevel", "c_interp", "d_interp",
    "lod", "shadow_obj", "trace_obj", "ctech", "stech", "maplib", "usemap"};

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// The decimal numbers tinyobjloader reads (no hex, no inf/nan, no trailing text):
// [+-] (digits [. digits] | . digits) [(e|E) [+-] digits].
bool is_decimal(const std::string& s) {
  size_t i = 0;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  size_t digits = 0;
  while (i < s.size() && is_digit(s[i])) ++i, ++digits;
  if (i < s.size() && s[i] == '.') {
    ++i;
    while (i < s.size() && is_digit(s[i])) ++i, ++digits;
  }
  if (digits == 0) return false;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    size_t exponent_digits = 0;
    while (i < s.size() && is_digit(s[i])) ++i, ++exponent_digits;
    if (exponent_digits == 0) return false;
  }
  return i == s.size();
}

bool is_integer(const std::string& s) {
  size_t i = (!s.empty() && (s[0] == '+' || s[0] == '-')) ? 1 : 0;
  if (i == s.size()) return false;
  for (; i < s.size(); ++i)
    if (!is_digit(s[i])) return false;
  return true;
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> tokens;
  std::istringstream in(line);
  for (std::string t; in >> t;) tokens.push_back(t);
  return tokens;
}

struct Counts {
  long v = 0, vt = 0, vn = 0;
};

// A face corner reference after syntax checks: the three indices as written (0 = absent).
struct Reference {
  long v = 0, vt = 0, vn = 0;
};

// A positive index can only be checked against the totals at the end of the file.
struct PendingCheck {
  int line;
  long max_v, max_vt, max_vn;
};

class PreScan {
 public:
  PreScan(const std::string& file) : file_(file) {}

  // Checks one line; returns it without its comment, as tinyobjloader is to read it (it takes a
  // '#' after a face's corners for a corner).
  std::string statement(const std::string& raw, int line) {
    std::string text = raw;
    if (!text.empty() && text.back() == '\r') text.pop_back();
    const size_t hash = text.find('#');
    if (hash != std::string::npos) text.erase(hash);
    // tinyobjloader separates values by spaces and tabs only and ends a line at CR or NUL, where
    // the split below sees white space: a line with such a character would be read differently.
    for (const char c : text)
      if ((static_cast<unsigned char>(c) < 0x20 && c != '\t') || c == 0x7f) {
        char code[8];
        std::snprintf(code, sizeof code, "0x%02X", static_cast<unsigned char>(c));
        fail(line, std::string("control character ") + code +
                       " (values are separated by spaces or tabs; lines end with LF or CR LF)");
      }
    const std::vector<std::string> tokens = split(text);
    if (tokens.empty()) return std::string();
    if (!text.empty() && text.find_last_not_of(" \t") != std::string::npos &&
        text[text.find_last_not_of(" \t")] == '\\')
      fail(line, "line continuation ('\\' at the end of a line) is not supported");
    const std::string& keyword = tokens[0];
    const size_t values = tokens.size() - 1;
    if (keyword == "v") {
      if (values != 3 && values != 4 && values != 6)
        fail(line, "a vertex 'v' takes 3 coordinates (optionally w, or r g b), found " + std::to_string(values) +
                       " values");
      Vec3 p;
      p.x = number(tokens[1], line);
      p.y = number(tokens[2], line);
      p.z = number(tokens[3], line);
      for (size_t k = 4; k < tokens.size(); ++k) number(tokens[k], line);
      positions_.push_back(p);
      position_lines_.push_back(line);
      ++counts_.v;
    } else if (keyword == "vn") {
      if (values != 3) fail(line, "a normal 'vn' takes 3 values, found " + std::to_string(values));
      for (size_t k = 1; k < tokens.size(); ++k) number(tokens[k], line);
      ++counts_.vn;
    } else if (keyword == "vt") {
      if (values < 1 || values > 3) fail(line, "a texture coordinate 'vt' takes 1 to 3 values, found " + std::to_string(values));
      for (size_t k = 1; k < tokens.size(); ++k) number(tokens[k], line);
      texcoords_.push_back({number(tokens[1], line), values >= 2 ? number(tokens[2], line) : 0.0});
      ++counts_.vt;
    } else if (keyword == "f" || keyword == "l" || keyword == "p") {
      const size_t minimum = keyword == "f" ? 3 : keyword == "l" ? 2 : 1;
      if (values < minimum)
        fail(line, "'" + keyword + "' needs at least " + std::to_string(minimum) + " vertices, found " +
                       std::to_string(values));
      if (keyword == "f" && values > 255) fail(line, "a face has more than 255 vertices (the OBJ reader's limit)");
      PendingCheck pending{line, 0, 0, 0};
      for (size_t k = 1; k < tokens.size(); ++k) {
        const Reference r = reference(tokens[k], line);
        pending.max_v = std::max(pending.max_v, r.v);
        pending.max_vt = std::max(pending.max_vt, r.vt);
        pending.max_vn = std::max(pending.max_vn, r.vn);
      }
      pending_.push_back(pending);
      if (keyword == "f") {
        ++faces_;
        // Counted before tinyobjloader fans the faces: 24-corner faces under the size cap made more
        // than the scene's triangle limit and ended in bad_alloc.
        triangles_ += long(values) - 2;
        if (triangles_ > long(kMaxSceneTriangles))
          fail(line, "the faces make more than " + std::to_string(kMaxSceneTriangles) +
                         " triangles (a polygon of n corners makes n - 2), the limit of a scene");
      }
    } else if (!kIgnoredStatements.count(keyword)) {
      // Quoted only when it looks like a statement keyword: a file that is not OBJ at all (a scene's
      // mesh path may name any file) must not have its content echoed into a message.
      const bool keyword_like = keyword.size() <= 16 && std::all_of(keyword.begin(), keyword.end(), [](char ch) {
        return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_';
      });
      fail(line, keyword_like ? "unknown statement '" + keyword + "'"
                              : std::string("not an OBJ statement (the file does not look like a Wavefront OBJ)"));
    }
    return text;
  }

  void finish() {
    for (const PendingCheck& p : pending_) {
      if (p.max_v > counts_.v)
        fail(p.line, "vertex index " + std::to_string(p.max_v) + " is out of range: the file has " +
                         std::to_string(counts_.v) + " vertices");
      if (p.max_vt > counts_.vt)
        fail(p.line, "texture coordinate index " + std::to_string(p.max_vt) + " is out of range: the file has " +
                         std::to_string(counts_.vt));
      if (p.max_vn > counts_.vn)
        fail(p.line, "normal index " + std::to_string(p.max_vn) + " is out of range: the file has " +
                         std::to_string(counts_.vn) + " normals");
    }
    if (faces_ == 0) fail(0, "the file has no faces");
  }

  const std::vector<Vec3>& positions() const { return positions_; }
  const std::vector<int>& position_lines() const { return position_lines_; }
  // (u, v) of every vt line in order, read with the correctly rounded parser; v = 0 when absent.
  const std::vector<std::array<double, 2>>& texcoords() const { return texcoords_; }
  [[noreturn]] void fail(int line, const std::string& problem) const { throw InputError(file_, line, problem); }

 private:
  double number(const std::string& token, int line) const {
    if (!is_decimal(token)) fail(line, "'" + token + "' is not a decimal number");
    const double v = std::strtod(token.c_str(), nullptr);
    if (!std::isfinite(v)) fail(line, "'" + token + "' is not a finite number");
    return v;
  }

  // One index of a corner: 0 when `allow_empty` and the text is empty; a negative index counts
  // back from the last element defined so far.
  long index(const std::string& text, long defined, const char* what, int line, bool allow_empty) const {
    if (text.empty() && allow_empty) return 0;
    if (!is_integer(text)) fail(line, std::string("'") + text + "' is not a valid " + what + " index");
    errno = 0;
    const long i = std::strtol(text.c_str(), nullptr, 10);
    if (errno == ERANGE || i == 0 || i < -defined)
      fail(line, std::string(what) + " index " + text + " is out of range: " + std::to_string(defined) +
                     " defined before this line" + (i == 0 ? " (indices start at 1)" : ""));
    return i < 0 ? defined + i + 1 : i;
  }

  Reference reference(const std::string& token, int line) const {
    // v, v/vt, v//vn or v/vt/vn
    std::vector<std::string> parts;
    size_t start = 0;
    for (size_t slash; (slash = token.find('/', start)) != std::string::npos; start = slash + 1)
      parts.push_back(token.substr(start, slash - start));
    parts.push_back(token.substr(start));
    if (parts.size() > 3 || (parts.size() == 2 && parts[1].empty()))
      fail(line, "'" + token + "' is not a face vertex (v, v/vt, v//vn or v/vt/vn)");
    Reference r;
    r.v = index(parts[0], counts_.v, "vertex", line, false);
    if (parts.size() >= 2) r.vt = index(parts[1], counts_.vt, "texture coordinate", line, parts.size() == 3);
    if (parts.size() == 3) r.vn = index(parts[2], counts_.vn, "normal", line, false);
    return r;
  }

  std::string file_;
  Counts counts_;
  long faces_ = 0, triangles_ = 0;
  std::vector<Vec3> positions_;
  std::vector<int> position_lines_;
  std::vector<std::array<double, 2>> texcoords_;
  std::vector<PendingCheck> pending_;
};

// The line number in a tinyobjloader message ("... line 12 ..."), or 0.
int line_in_message(const std::string& message) {
  std::smatch m;
  if (std::regex_search(message, m, std::regex(R"(line (\d+))"))) return std::atoi(m[1].str().c_str());
  return 0;
}

}  // namespace

Mesh parse_obj_mesh(const std::string& text, const std::string& file_name) {
  PreScan scan(file_name);
  std::string clean;  // the same lines without comments
  {
    std::istringstream lines(text);
    int line = 0;
    for (std::string s; std::getline(lines, s);) clean += scan.statement(s, ++line) + "\n";
    scan.finish();
  }

  tinyobj::ObjReaderConfig config;
  config.triangulate = false;  // fanned here, so that the winding and the split are ours
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  // Materials are not used: an empty material text keeps tinyobjloader away from .mtl files.
  if (!reader.ParseFromString(clean, "", config)) {
    const std::string error = reader.Error();
    scan.fail(line_in_message(error), "tinyobjloader: " + error.substr(0, error.find_last_not_of("\n") + 1));
  }
  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  const std::vector<Vec3>& expected = scan.positions();
  if (attrib.vertices.size() != 3 * expected.size())
    scan.fail(0, "tinyobjloader read " + std::to_string(attrib.vertices.size() / 3) + " vertices, the file has " +
                     std::to_string(expected.size()));
  std::vector<Vec3> positions(expected.size());
  for (size_t i = 0; i < expected.size(); ++i) {
    positions[i] = {attrib.vertices[3 * i], attrib.vertices[3 * i + 1], attrib.vertices[3 * i + 2]};
    // tinyobjloader's own number parser is not correctly rounded; refuse a number it reads wrongly.
    const double got[3] = {positions[i].x, positions[i].y, positions[i].z};
    const double want[3] = {expected[i].x, expected[i].y, expected[i].z};
    for (int k = 0; k < 3; ++k)
      if (!(std::fabs(got[k] - want[k]) <= 1e-12 * std::fabs(want[k]) + 1e-300))
        scan.fail(scan.position_lines()[i], "tinyobjloader reads coordinate " + std::to_string(want[k]) + " as " +
                                                std::to_string(got[k]));
  }

  // Fan every face; remember the corners' normal and texture coordinate indices.
  struct Corner {
    int v, vn, vt;
  };
  std::vector<std::array<Corner, 3>> corners;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    size_t offset = 0;
    for (unsigned char count : shape.mesh.num_face_vertices) {
      const auto at = [&](size_t k) {
        const tinyobj::index_t& i = shape.mesh.indices[offset + k];
        return Corner{i.vertex_index, i.normal_index, i.texcoord_index};
      };
      for (size_t k = 1; k + 1 < count; ++k) corners.push_back({at(0), at(k), at(k + 1)});
      offset += count;
    }
  }
  std::vector<std::array<uint32_t, 3>> by_position;
  for (const auto& c : corners) by_position.push_back({uint32_t(c[0].v), uint32_t(c[1].v), uint32_t(c[2].v)});
  const std::vector<Vec3> computed = area_weighted_normals(positions, by_position);

  // Texture coordinates are kept when every face corner has one and each lies inside the texture
  // sampler's range; otherwise the mesh has none (as an OBJ without vt).
  const std::vector<std::array<double, 2>>& texcoords = scan.texcoords();
  const bool textured = std::all_of(corners.begin(), corners.end(), [&](const auto& c) {
    return std::all_of(c.begin(), c.end(), [&](const Corner& k) {
      return k.vt >= 0 && std::fabs(texcoords[size_t(k.vt)][0]) < kMaxTextureCoordinate &&
             std::fabs(texcoords[size_t(k.vt)][1]) < kMaxTextureCoordinate;
    });
  });
  Mesh mesh;
  std::map<std::array<int, 3>, uint32_t> vertex_of;  // (v, vn or -1, vt or -1) -> mesh vertex
  for (const auto& c : corners) {
    std::array<uint32_t, 3> t{};
    for (int k = 0; k < 3; ++k) {
      const std::array<int, 3> key = {c[k].v, c[k].vn, textured ? c[k].vt : -1};
      auto it = vertex_of.find(key);
      if (it == vertex_of.end()) {
        const Vec3 normal = c[k].vn >= 0 ? normalize(Vec3{attrib.normals[3 * c[k].vn], attrib.normals[3 * c[k].vn + 1],
                                                          attrib.normals[3 * c[k].vn + 2]})
                                         : computed[c[k].v];
        it = vertex_of.emplace(key, mesh.add_vertex(positions[c[k].v], normal, uint32_t(c[k].v))).first;
        if (textured) mesh.texcoords.push_back(texcoords[size_t(c[k].vt)]);
      }
      t[k] = it->second;
    }
    mesh.triangles.push_back(t);
  }
  return mesh;
}

Mesh load_obj_mesh(const std::string& path) {
  return parse_obj_mesh(read_text_file(path, "an OBJ file", kMaxObjBytes), path);
}

}  // namespace rastersim::frontend
