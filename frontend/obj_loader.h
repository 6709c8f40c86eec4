// Wavefront OBJ input through Debian's tinyobjloader (double precision build). tinyobjloader is
// lenient (bad numbers read as 0, bad faces dropped with a warning), so the text is first checked
// line by line here; any problem throws InputError(file, line, problem).
#pragma once

#include <string>

#include "frontend/mesh.h"

namespace rastersim::frontend {

// The mesh of every face in the file: polygons fanned from their first corner (winding kept),
// a corner's normal from its `vn` (normalized) or, when it has none, the area-weighted normal of its
// position. Statements other than v, vn, vt, f are checked to be known OBJ statements and ignored
// (materials too). A file without faces is an error.
// The largest OBJ file read (a mesh of about five million triangles); more is refused, not read.
constexpr size_t kMaxObjBytes = size_t(256) << 20;
Mesh load_obj_mesh(const std::string& path);

// The same for OBJ text; `file_name` names it in errors.
Mesh parse_obj_mesh(const std::string& text, const std::string& file_name);

}  // namespace rastersim::frontend
