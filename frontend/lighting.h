// Per-vertex lighting on the host: ambient + Lambert diffuse + optional Blinn-Phong specular from
// directional lights, giving the Gouraud colours the pipeline interpolates. docs/frontend.md.
#pragma once

#include <vector>

#include "frontend/vecmath.h"

namespace rastersim::frontend {

// Colours and intensities are linear, 1.0 = full (scene files give them as 0..255).
struct DirectionalLight {
  Vec3 direction{0, -1, 0};  // the direction the light travels, world space (need not be unit)
  Vec3 color{1, 1, 1};
};

struct Lighting {
  Vec3 ambient{0.2, 0.2, 0.2};
  std::vector<DirectionalLight> lights;
};

// smooth: per-vertex normals (Gouraud); faceted: each triangle lit once with its face normal at its
// centroid (one colour per triangle); unlit: the material colour itself.
enum class SurfaceShading { Smooth, Faceted, Unlit };

struct Material {
  Vec3 color{0.8, 0.8, 0.8};  // diffuse albedo
  Vec3 specular{0, 0, 0};     // specular colour; zero turns specular off
  double shininess = 32;      // Blinn-Phong exponent
  SurfaceShading shading = SurfaceShading::Smooth;
};

// The colour (0..255 per channel, clamped, not rounded) of a surface point with unit normal `normal`
// (zero: ambient only) and unit vector `to_eye` from the point towards the viewer:
//   c = color * (ambient + sum_lights max(0, N.L) light)
//     + sum_lights [N.L > 0] specular * light * max(0, N.H)^shininess,  L = -normalize(direction),
//   H = normalize(L + to_eye); then 255 * min(c, 1).
Vec3 shade(const Material& material, const Lighting& lighting, const Vec3& normal, const Vec3& to_eye);

// The lighting of the load_obj and built-in scenes: one white key light from the upper left front
// travelling (1, -1.5, -1) and ambient 0.2.
Lighting default_lighting();

}  // namespace rastersim::frontend
