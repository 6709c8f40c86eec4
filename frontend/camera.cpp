#include "frontend/camera.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "frontend/transform.h"
#include "model/input_error.h"

namespace rastersim::frontend {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Direction from the target to an automatic eye: right, above and in front (+z).
const Vec3 kAutoViewFrom{0.6, 0.5, 1.0};
// sin of the smallest angle accepted between up and the view direction.
constexpr double kMinUpSine = 1e-6;

std::string number(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", v);
  return buffer;
}

std::string vector_text(const Vec3& v) { return "(" + number(v.x) + ", " + number(v.y) + ", " + number(v.z) + ")"; }

template <typename T>
struct Setting {
  std::optional<T> value;
  Origin origin;
  const char* key;

  // "--near" on the command line, "camera near" in a file.
  std::string name() const { return origin.file.empty() ? std::string("--") + key : std::string("camera ") + key; }
  [[noreturn]] void fail(const std::string& problem) const {
    throw InputError(origin.file.empty() ? "command line" : origin.file, origin.line, name() + " " + problem);
  }
};

template <typename T>
Setting<T> pick(const std::optional<T>& from_file, const Origin& file_origin, const std::optional<T>& from_flags,
                const char* key) {
  if (from_flags) return {from_flags, Origin{}, key};
  return {from_file, file_origin, key};
}

void require_finite(const Setting<Vec3>& s) {
  if (s.value && !is_finite(*s.value)) s.fail("has a coordinate that is not a finite number");
  // The camera's arithmetic takes lengths: a vector whose length overflows cannot be placed.
  if (s.value && !std::isfinite(length(*s.value)))
    s.fail(vector_text(*s.value) + " is too large: its length overflows double precision");
}
void require_finite(const Setting<double>& s) {
  if (s.value && !std::isfinite(*s.value)) s.fail("is not a finite number");
}

}  // namespace

Mat4 Camera::view() const { return look_at(eye, target, up); }

double Camera::ortho_half_height() const { return std::tan(fov * (kPi / 360.0)) * length(target - eye); }

Mat4 Camera::projection() const {
  if (!ortho) return perspective(fov, aspect, near, far);
  const double half_height = ortho_half_height();
  return orthographic(half_height * aspect, half_height, near, far);
}

Camera resolve_camera(const CameraSettings& file, const CameraOptions& flags, const Sphere& bounds, int width,
                      int height, const std::string& scene_source) {
  const Setting<Vec3> eye = pick(file.values.eye, file.eye, flags.eye, "eye");
  const Setting<Vec3> target = pick(file.values.target, file.target, flags.target, "target");
  const Setting<Vec3> up = pick(file.values.up, file.up, flags.up, "up");
  const Setting<double> fov = pick(file.values.fov, file.fov, flags.fov, "fov");
  const Setting<double> near = pick(file.values.near, file.near, flags.near, "near");
  const Setting<double> far = pick(file.values.far, file.far, flags.far, "far");
  require_finite(eye), require_finite(target), require_finite(up);
  require_finite(fov), require_finite(near), require_finite(far);

  Camera c;
  c.ortho = flags.ortho || file.values.ortho;
  c.aspect = double(width) / double(height);
  c.fov = fov.value.value_or(kDefaultFov);
  if (!(c.fov > 0 && c.fov < 180)) fov.fail(number(c.fov) + " is outside (0, 180) degrees");

  const double radius = bounds.radius > 0 ? bounds.radius : 1.0;
  c.target = target.value.value_or(bounds.centre);
  if (eye.value) {
    c.eye = *eye.value;
  } else {
    // Far enough that the bounding sphere, seen from anywhere around the target, fits the smaller
    // of the two fields of view (5% margin).
    const double half_y = c.fov * (kPi / 360.0);
    const double half_x = std::atan(c.aspect * std::tan(half_y));
    const double reach = radius + length(bounds.centre - c.target);
    c.eye = c.target + (1.05 * reach / std::sin(std::min(half_x, half_y))) * normalize(kAutoViewFrom);
    // A placement no user asked for must not be blamed on --eye: say what cannot be framed.
    if (!is_finite(c.eye) || !(length(c.target - c.eye) > 1e-12 * std::max(1.0, length(c.eye))))
      throw InputError(scene_source, 0,
                       "the scene's bounding sphere (centre " + vector_text(bounds.centre) + ", radius " +
                           number(bounds.radius) + ") is too large or too far out to place a camera automatically; "
                           "give --eye (and --target)");
  }
  const Vec3 view = c.target - c.eye;
  if (!std::isfinite(length(view)))
    (eye.value ? eye : target).fail(vector_text(c.eye) + " and target " + vector_text(c.target) +
                                    " are too far apart: their distance overflows double precision");
  if (!(length(view) > 1e-12 * std::max(1.0, length(c.eye)))) {
    (target.value ? target : eye).fail(vector_text(c.target) + ": eye and target are the same point, so there is no view direction");
  }
  const Vec3 forward = normalize(view);
  if (up.value) {
    if (!(length(*up.value) > 0)) up.fail("is the zero vector");
    if (length(cross(forward, normalize(*up.value))) < kMinUpSine)
      up.fail(vector_text(*up.value) + " is parallel to the view direction " + vector_text(forward) +
              " from eye to target");
    c.up = *up.value;
  } else {
    c.up = {0, 1, 0};
    // Looking straight down (or up), the far (or near) side of the scene is up on the screen.
    if (length(cross(forward, c.up)) < kMinUpSine) c.up = forward.y < 0 ? Vec3{0, 0, -1} : Vec3{0, 0, 1};
  }

  // Automatic depth range: the bounding sphere's extent along the view axis, widened by 1%, then
  // adapted to an explicit near or far so that the pair stays valid.
  const double centre_depth = dot(bounds.centre - c.eye, forward);
  const double deepest = centre_depth + radius, shallowest = centre_depth - radius;
  if (near.value && !(*near.value > 0)) near.fail(number(*near.value) + " must be greater than 0");
  if (far.value && !(*far.value > 0)) far.fail(number(*far.value) + " must be greater than 0");
  if (near.value && far.value) {
    c.near = *near.value;
    c.far = *far.value;
    if (!(c.near < c.far)) far.fail(number(c.far) + " must be greater than near " + number(c.near));
  } else if (near.value) {
    c.near = *near.value;
    c.far = std::max(deepest * 1.01, 2.0 * c.near);
  } else {
    c.far = far.value ? *far.value : deepest > 0 ? deepest * 1.01 : 1.0;
    c.near = std::min(std::max(shallowest * 0.99, c.far * 1e-4), c.far * 0.5);
  }
  return c;
}

}  // namespace rastersim::frontend
