// Fuzz target: the JSON scene parser (frontend/scene.cpp parse_scene) as `rastersim render
// FILE.json` uses it, then the front end and setup on the scene it returns. Mesh files are looked
// up in a folder that does not exist, so the target reads no files.
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "model/input_error.h"
#include "tests/fuzz/fuzz_frontend.h"

namespace {

// Scenes that are valid but merely big (up to 1024 x 1024 divisions per surface) would make single
// inputs take seconds: the fuzzer skips scenes with more than 8 objects or a count parameter above
// 64. Bounds are the parser's to check (and the unit tests do); this keeps the search fast.
bool small_enough(const std::string& text) {
  const nlohmann::json doc = nlohmann::json::parse(text, nullptr, false);
  if (doc.is_discarded() || !doc.is_object() || !doc.contains("objects")) return true;
  const nlohmann::json& objects = doc["objects"];
  if (!objects.is_array()) return true;
  if (objects.size() > 8) return false;
  for (const nlohmann::json& object : objects) {
    if (!object.is_object() || !object.contains("params") || !object["params"].is_object()) continue;
    for (const auto& [key, value] : object["params"].items())
      if (value.is_number() && key != "radius" && key != "major_radius" && key != "minor_radius" && key != "height" &&
          key != "width" && key != "depth" && !(value.get<double>() <= 64))
        return false;
  }
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace rastersim;
  const std::string text(reinterpret_cast<const char*>(data), size);
  if (!small_enough(text)) return 0;
  frontend::Scene scene;
  try {
    scene = frontend::parse_scene(text, "fuzz.json", "/nonexistent-rastersim-fuzz");
  } catch (const InputError& e) {
    fuzz::require_located_message(e.what(), "fuzz.json", false);
    return 0;
  }
  FUZZ_REQUIRE(!scene.objects.empty(), "an accepted scene has no objects");
  try {
    fuzz::render_and_set_up(scene);
  } catch (const InputError&) {
    // A degenerate camera from the file names the file and line of its key; an automatic one
    // (for example a scene of one point) names no file.
  }
  return 0;
}
