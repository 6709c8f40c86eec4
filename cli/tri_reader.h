// The .tri screen-space triangle list (docs/formats.md): reader and writer.
// One triangle a line: x0 y0 z0 x1 y1 z1 x2 y2 z2 (pixels, y down; depth in [0, 1]), optionally
// followed by r g b (flat, integers 0..255) or r0 g0 b0 r1 g1 b1 r2 g2 b2 (per vertex). No colour:
// white. Then optionally (version 2) `uvw u0 v0 w0 u1 v1 w1 u2 v2 w2`: the vertices' texture
// coordinates and clip-space w. '#' starts a comment, blank lines are ignored.
#pragma once

#include <istream>
#include <ostream>
#include <string>
#include <vector>

#include "model/profile.h"
#include "model/triangle.h"

namespace rastersim {

// The most triangles a .tri file may hold: a scene's limit (frontend::kMaxSceneTriangles), about
// 1.2 GB as ScreenTriangles.
constexpr size_t kMaxTriTriangles = 4'000'000;

// Reads every triangle of `in` in line order, each one checked against the profile's guard band
// (check_screen_triangle). `file_name` only names the source in errors. Throws InputError
// "file:line: problem" at the first bad line, and at the line of triangle max_triangles + 1.
std::vector<ScreenTriangle> read_tri(std::istream& in, const std::string& file_name, const Profile& profile,
                                     size_t max_triangles = kMaxTriTriangles);

// Opens and reads a .tri file; a missing or unreadable file is an InputError naming it.
std::vector<ScreenTriangle> read_tri_file(const std::string& path, const Profile& profile);

// Writes triangles so that read_tri gives back bit-identical doubles (%.17g) and colours: no colour
// when all vertices are white, r g b when they share one colour, nine values otherwise; the uvw
// section for a textured triangle.
// Each line of `comment` (may be empty) is written first as a '#' comment.
void write_tri(std::ostream& out, const std::vector<ScreenTriangle>& triangles, const std::string& comment = "");

}  // namespace rastersim
