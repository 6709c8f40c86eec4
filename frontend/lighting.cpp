#include "frontend/lighting.h"

#include <algorithm>
#include <cmath>

namespace rastersim::frontend {

Vec3 shade(const Material& m, const Lighting& lighting, const Vec3& normal, const Vec3& to_eye) {
  if (m.shading == SurfaceShading::Unlit) return 255.0 * m.color;
  Vec3 diffuse = lighting.ambient;
  Vec3 specular{};
  for (const DirectionalLight& light : lighting.lights) {
    const Vec3 l = -normalize(light.direction);
    const double n_dot_l = dot(normal, l);
    if (n_dot_l <= 0) continue;
    diffuse = diffuse + n_dot_l * light.color;
    if (m.specular.x > 0 || m.specular.y > 0 || m.specular.z > 0) {
      const double n_dot_h = std::max(0.0, dot(normal, normalize(l + to_eye)));
      specular = specular + std::pow(n_dot_h, m.shininess) * hadamard(m.specular, light.color);
    }
  }
  const Vec3 c = hadamard(m.color, diffuse) + specular;
  return {255.0 * std::min(c.x, 1.0), 255.0 * std::min(c.y, 1.0), 255.0 * std::min(c.z, 1.0)};
}

Lighting default_lighting() {
  Lighting l;
  l.ambient = {0.2, 0.2, 0.2};
  l.lights.push_back({{1.0, -1.5, -1.0}, {0.85, 0.85, 0.85}});
  return l;
}

}  // namespace rastersim::frontend
