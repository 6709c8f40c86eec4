// Fuzz target: the .tri reader (cli/tri_reader.cpp) as `rastersim render FILE.tri` uses it, on a
// 64 x 48 profile (a small guard band, so that accepted triangles are common). An accepted file must
// snap and set up without a width overflow, and write_tri must give it back bit for bit.
#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>

#include "cli/tri_reader.h"
#include "model/input_error.h"
#include "model/triangle_setup.h"
#include "tests/fuzz/fuzz_support.h"

namespace {

using namespace rastersim;

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool same_triangle(const ScreenTriangle& a, const ScreenTriangle& b) {
  for (int k = 0; k < 3; ++k) {
    const ScreenVertex &u = a.v[k], &v = b.v[k];
    if (!same_bits(u.x, v.x) || !same_bits(u.y, v.y) || !same_bits(u.z, v.z) || !(u.color == v.color)) return false;
    if (a.textured && (!same_bits(u.u, v.u) || !same_bits(u.v, v.v) || !same_bits(u.w, v.w))) return false;
  }
  return a.textured == b.textured;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  Profile profile;
  profile.width = 64, profile.height = 48;
  std::vector<ScreenTriangle> triangles;
  try {
    std::istringstream in(text);
    triangles = read_tri(in, "fuzz.tri", profile);
  } catch (const InputError& e) {
    fuzz::require_located_message(e.what(), "fuzz.tri", true);
    return 0;
  }
  const TriangleSetup setup(profile);
  for (const ScreenTriangle& t : triangles) {
    FUZZ_REQUIRE(check_screen_triangle(t, profile).empty(), "read_tri accepted a triangle the setup check refuses");
    setup.run(snap(t, profile));  // a WidthOverflow escapes: a finding
  }
  std::ostringstream out;
  write_tri(out, triangles, "written back\nby fuzz_tri");
  std::istringstream again(out.str());
  const std::vector<ScreenTriangle> reread = read_tri(again, "rewritten.tri", profile);
  FUZZ_REQUIRE(reread.size() == triangles.size(), "write_tri then read_tri changed the triangle count");
  for (size_t i = 0; i < reread.size(); ++i)
    FUZZ_REQUIRE(same_triangle(reread[i], triangles[i]), "write_tri then read_tri changed triangle " + std::to_string(i));
  return 0;
}
