// Built-in screen-space test scenes, generated for the profile's width and height (always inside
// the guard band, so every profile that validates can render them).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "model/profile.h"
#include "model/triangle.h"

namespace rastersim {

struct BuiltinScene {
  std::string name;
  std::string description;  // one line, for `rastersim scenes`
  std::function<std::vector<ScreenTriangle>(const Profile&)> generate;
};

// Every screen-space scene, in listing order (the 3D scenes, "default" among them, are the front end's).
const std::vector<BuiltinScene>& builtin_scenes();
// nullptr when no scene has that name.
const BuiltinScene* find_builtin_scene(const std::string& name);

// `count` random Gouraud triangles with random depths, their vertices within `size` x `size`
// pixels of a centre on the screen, the size drawn from [min_size, max_size]; clamped into the
// guard band [-W, 2W) x [-H, 2H). Deterministic for a seed on every platform (mt19937_64 words, no std distributions).
std::vector<ScreenTriangle> random_triangles(int64_t count, double min_size, double max_size, uint64_t seed,
                                             const Profile& profile);

}  // namespace rastersim
