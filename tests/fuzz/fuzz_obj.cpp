// Fuzz target: the OBJ loader (frontend/obj_loader.cpp parse_obj_mesh, with tinyobjloader behind
// its own line checks) as `rastersim render FILE.obj` uses it, then the front end and setup on the
// mesh it returns.
#include <cstdint>
#include <string>

#include "frontend/obj_loader.h"
#include "model/input_error.h"
#include "tests/fuzz/fuzz_frontend.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace rastersim;
  const std::string text(reinterpret_cast<const char*>(data), size);
  frontend::Mesh mesh;
  try {
    mesh = frontend::parse_obj_mesh(text, "fuzz.obj");
  } catch (const InputError& e) {
    fuzz::require_located_message(e.what(), "fuzz.obj", false);
    return 0;
  }
  FUZZ_REQUIRE(!mesh.triangles.empty(), "an accepted OBJ file has no triangles");
  for (const auto& triangle : mesh.triangles)
    for (uint32_t corner : triangle) FUZZ_REQUIRE(corner < mesh.positions.size(), "a triangle corner is out of range");
  try {
    fuzz::render_and_set_up(frontend::obj_scene(std::move(mesh)));
  } catch (const InputError&) {
    // A degenerate automatic camera (for example every vertex at one point) is reported, not drawn.
  }
  return 0;
}
