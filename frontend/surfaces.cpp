#include "frontend/surfaces.h"

#include <cmath>

namespace rastersim::frontend {
namespace {

constexpr double kPi = 3.14159265358979323846;

// (1 - t) a + t b: exactly a at t = 0 and exactly b at t = 1, so a row shared by two pieces of a
// profile gets bit-identical coordinates from both.
double lerp(double a, double b, double t) { return (1.0 - t) * a + t * b; }

// A point of a profile curve in the (rho, y) half plane (rho = distance from the y axis) and its
// derivative along v. rho == 0 marks a row on the axis (pole, apex, cap centre).
struct ProfileSample {
  double rho, y;
  double drho, dy;
};

// Surfaces of revolution about the y axis: p(u, v) = (rho(v) cos 2pi u, y(v), rho(v) sin 2pi u).
// dp/du x dp/dv = 2 pi rho (-y' cos, rho', -y' sin); the normal drops the factor 2 pi rho >= 0 so it
// stays defined on the axis. It points outwards when the profile runs with the solid on its right in
// the (rho, y) plane (downwards along the outside).
class Lathe {
 public:
  Lathe(Mesh& mesh, int segments) : mesh_(mesh), segments_(segments) {
    for (int i = 0; i < segments; ++i) {
      const double theta = 2.0 * kPi * i / segments;
      const double mid = 2.0 * kPi * (i + 0.5) / segments;
      cos_.push_back(std::cos(theta));
      sin_.push_back(std::sin(theta));
      mid_cos_.push_back(std::cos(mid));
      mid_sin_.push_back(std::sin(mid));
    }
  }

  // One piece of the profile on rows j = 0..rows; with wrap_v the row `rows` is row 0 again.
  template <typename Sample>
  void add_piece(int rows, bool wrap_v, Sample sample) {
    std::vector<std::vector<uint32_t>> row_vertices;
    std::vector<bool> on_axis;
    const int stored_rows = wrap_v ? rows : rows + 1;
    for (int j = 0; j < stored_rows; ++j) {
      const ProfileSample s = sample(j);
      std::vector<uint32_t> ids;
      on_axis.push_back(s.rho == 0.0);
      for (int i = 0; i < segments_; ++i) {
        // On the axis every column is the same point: one position, and per segment the normal of
        // the segment's middle (the apex of a cone keeps its slant).
        const double c = s.rho == 0.0 ? mid_cos_[i] : cos_[i];
        const double sn = s.rho == 0.0 ? mid_sin_[i] : sin_[i];
        const Vec3 position = s.rho == 0.0 ? Vec3{0.0, s.y, 0.0} : Vec3{s.rho * cos_[i], s.y, s.rho * sin_[i]};
        const Vec3 normal = normalize(Vec3{-s.dy * c, s.drho, -s.dy * sn});
        const uint32_t id = uint32_t(mesh_.positions.size());
        ids.push_back(mesh_.add_vertex(position, normal, id));
      }
      row_vertices.push_back(ids);
    }
    for (int j = 0; j < rows; ++j) {
      const int j1 = (j + 1) % stored_rows;
      const auto& r0 = row_vertices[j];
      const auto& r1 = row_vertices[j1];
      for (int i = 0; i < segments_; ++i) {
        const int i1 = (i + 1) % segments_;
        // Quad p00 = (i, j), p10 = (i+1, j), p11 = (i+1, j+1), p01 = (i, j+1): the triangles
        // (p00, p10, p11) and (p00, p11, p01) turn counter-clockwise about du x dv.
        if (on_axis[j] && on_axis[j1]) continue;
        if (!on_axis[j]) mesh_.triangles.push_back({r0[i], r0[i1], on_axis[j1] ? r1[i] : r1[i1]});
        if (!on_axis[j1]) mesh_.triangles.push_back({r0[i], r1[i1], r1[i]});
      }
    }
  }

  // A straight profile piece from a to b (rho, y), `rows` rows.
  void add_segment(double rho_a, double y_a, double rho_b, double y_b, int rows) {
    add_piece(rows, false, [&](int j) {
      const double t = double(j) / rows;
      return ProfileSample{lerp(rho_a, rho_b, t), lerp(y_a, y_b, t), rho_b - rho_a, y_b - y_a};
    });
  }

 private:
  Mesh& mesh_;
  int segments_;
  std::vector<double> cos_, sin_, mid_cos_, mid_sin_;
};

}  // namespace

Mesh make_sphere(double radius, int segments, int rings) {
  Mesh mesh;
  Lathe lathe(mesh, segments);
  // phi = pi v from the north pole: rho = r sin phi, y = r cos phi; the poles are on the axis.
  lathe.add_piece(rings, false, [&](int j) {
    const double phi = kPi * j / rings;
    const bool pole = j == 0 || j == rings;
    return ProfileSample{pole ? 0.0 : radius * std::sin(phi), j == 0 ? radius : j == rings ? -radius : radius * std::cos(phi),
                         kPi * radius * std::cos(phi), -kPi * radius * std::sin(phi)};
  });
  return mesh;
}

Mesh make_torus(double major_radius, double minor_radius, int segments, int sides) {
  Mesh mesh;
  Lathe lathe(mesh, segments);
  // The tube circle clockwise in (rho, y): phi = -2 pi v, rho = R + r cos phi, y = r sin phi.
  lathe.add_piece(sides, true, [&](int j) {
    const double phi = -2.0 * kPi * j / sides;
    return ProfileSample{major_radius + minor_radius * std::cos(phi), minor_radius * std::sin(phi),
                         2.0 * kPi * minor_radius * std::sin(phi), -2.0 * kPi * minor_radius * std::cos(phi)};
  });
  return mesh;
}

Mesh make_cylinder(double radius, double height, int segments, int stacks) {
  Mesh mesh;
  Lathe lathe(mesh, segments);
  const double top = 0.5 * height, bottom = -0.5 * height;
  lathe.add_segment(0.0, top, radius, top, 1);           // top cap, outwards
  lathe.add_segment(radius, top, radius, bottom, stacks);  // side, downwards
  lathe.add_segment(radius, bottom, 0.0, bottom, 1);     // bottom cap, inwards
  return mesh;
}

Mesh make_cone(double radius, double height, int segments, int stacks) {
  Mesh mesh;
  Lathe lathe(mesh, segments);
  const double top = 0.5 * height, bottom = -0.5 * height;
  lathe.add_segment(0.0, top, radius, bottom, stacks);  // slant side from the apex
  lathe.add_segment(radius, bottom, 0.0, bottom, 1);    // base, inwards
  return mesh;
}

Mesh make_plane(double width, double depth, int divisions_x, int divisions_z) {
  Mesh mesh;
  // u along +x, v along -z: dp/du x dp/dv = (w, 0, 0) x (0, 0, -d) = (0, w d, 0), facing +y.
  for (int j = 0; j <= divisions_z; ++j)
    for (int i = 0; i <= divisions_x; ++i) {
      const Vec3 p{lerp(-0.5 * width, 0.5 * width, double(i) / divisions_x), 0.0,
                   lerp(0.5 * depth, -0.5 * depth, double(j) / divisions_z)};
      mesh.add_vertex(p, {0.0, 1.0, 0.0}, uint32_t(mesh.positions.size()));
    }
  const auto at = [&](int i, int j) { return uint32_t(j * (divisions_x + 1) + i); };
  for (int j = 0; j < divisions_z; ++j)
    for (int i = 0; i < divisions_x; ++i) {
      mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return mesh;
}

const std::vector<SurfaceKind>& surface_kinds() {
  const double kLengthMin = 1e-6, kLengthMax = 1e6;
  auto length = [&](const char* name, double value, const char* meaning) {
    return SurfaceParameter{name, value, kLengthMin, kLengthMax, false, meaning};
  };
  auto count = [](const char* name, double value, double min, const char* meaning) {
    return SurfaceParameter{name, value, min, 1024, true, meaning};
  };
  auto no_check = [](const std::vector<double>&) { return std::string(); };
  static const std::vector<SurfaceKind> kinds = {
      {"sphere", "sphere about the origin",
       {length("radius", 1.0, "radius"), count("segments", 32, 3, "divisions around the y axis"),
        count("rings", 16, 2, "divisions from pole to pole")},
       no_check,
       [](const std::vector<double>& p) { return make_sphere(p[0], int(p[1]), int(p[2])); }},
      {"torus", "torus about the y axis in the xz plane",
       {length("major_radius", 1.0, "radius of the tube's centre circle"),
        length("minor_radius", 0.3, "radius of the tube"), count("segments", 48, 3, "divisions around the y axis"),
        count("sides", 24, 3, "divisions around the tube")},
       [](const std::vector<double>& p) {
         return p[1] < p[0] ? std::string() : std::string("minor_radius must be smaller than major_radius");
       },
       [](const std::vector<double>& p) { return make_torus(p[0], p[1], int(p[2]), int(p[3])); }},
      {"cylinder", "closed cylinder along y, centred on the origin",
       {length("radius", 0.5, "radius"), length("height", 1.0, "height along y"),
        count("segments", 32, 3, "divisions around the y axis"), count("stacks", 1, 1, "divisions along y")},
       no_check,
       [](const std::vector<double>& p) { return make_cylinder(p[0], p[1], int(p[2]), int(p[3])); }},
      {"cone", "closed cone along y, apex up, centred on the origin",
       {length("radius", 0.5, "base radius"), length("height", 1.0, "height along y"),
        count("segments", 32, 3, "divisions around the y axis"), count("stacks", 1, 1, "divisions from apex to base")},
       no_check,
       [](const std::vector<double>& p) { return make_cone(p[0], p[1], int(p[2]), int(p[3])); }},
      {"plane", "rectangle in the xz plane facing +y",
       {length("width", 2.0, "extent along x"), length("depth", 2.0, "extent along z"),
        count("divisions_x", 1, 1, "divisions along x"), count("divisions_z", 1, 1, "divisions along z")},
       no_check,
       [](const std::vector<double>& p) { return make_plane(p[0], p[1], int(p[2]), int(p[3])); }},
  };
  return kinds;
}

const SurfaceKind* find_surface_kind(const std::string& name) {
  for (const SurfaceKind& k : surface_kinds())
    if (k.name == name) return &k;
  return nullptr;
}

}  // namespace rastersim::frontend
