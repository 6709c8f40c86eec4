// Helpers of the front-end tests: temporary files, per-pixel coverage through the model pipeline,
// and a projection written independently of frontend/transform.cpp (camera basis and similar
// triangles instead of matrices).
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "frontend/vecmath.h"
#include "model/pipeline.h"

namespace rastersim::frontend::test_util {

inline std::filesystem::path scratch_folder() {
  return std::filesystem::temp_directory_path() / ("rastersim_frontend_tests_" + std::to_string(::getpid()));
}

// Removes this process's scratch folder when the test program ends.
struct ScratchCleanup {
  ~ScratchCleanup() {
    std::error_code ignored;
    std::filesystem::remove_all(scratch_folder(), ignored);
  }
};
inline ScratchCleanup scratch_cleanup;

// A file in this process's scratch folder.
inline std::string scratch_path(const std::string& name) {
  std::filesystem::create_directories(scratch_folder());
  return (scratch_folder() / name).string();
}

inline std::string write_file(const std::string& name, const std::string& text) {
  const std::string path = scratch_path(name);
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

struct CountFragments : FragmentSink {
  std::vector<int> count;
  int width;
  CountFragments(int w, int h) : count(size_t(w) * h, 0), width(w) {}
  void on_fragment(const Fragment& f) override { ++count[size_t(f.y) * width + f.x]; }
};

// How many fragments each pixel receives when the triangles go through the pipeline with the
// profile's culling and depth_func always (every covered pixel counts, whatever the order).
inline std::vector<int> coverage(const std::vector<ScreenTriangle>& triangles, Profile p) {
  p.depth_func = DepthFunc::Always;
  Pipeline pipe(p);
  CountFragments sink(p.width, p.height);
  pipe.set_fragment_sink(&sink);
  for (const ScreenTriangle& t : triangles) {
    const std::string problem = check_screen_triangle(t, p);
    EXPECT_EQ(problem, "");
    if (problem.empty()) pipe.submit(snap(t, p));
  }
  return sink.count;
}

// A camera as the documentation describes it, evaluated without matrices.
struct IndependentCamera {
  Vec3 eye, target, up;
  double fov = 45, near = 0.1, far = 100;
  bool ortho = false;
  int width = 640, height = 480;

  Vec3 forward() const { return normalize(target - eye); }
  Vec3 right() const { return normalize(cross(forward(), up)); }
  Vec3 true_up() const { return cross(right(), forward()); }
  double aspect() const { return double(width) / height; }
  double tan_half() const { return std::tan(fov * M_PI / 360.0); }
  double ortho_half_height() const { return tan_half() * length(target - eye); }

  // Depth along the view axis (eye-space -z).
  double view_depth(const Vec3& p) const { return dot(p - eye, forward()); }

  // Screen x, y (pixels, y down) and depth in [0, 1] of a world point in front of the eye.
  Vec3 project(const Vec3& p) const {
    const Vec3 rel = p - eye;
    const double xe = dot(rel, right()), ye = dot(rel, true_up()), d = dot(rel, forward());
    double x_ndc, y_ndc, depth;
    if (ortho) {
      x_ndc = xe / (ortho_half_height() * aspect());
      y_ndc = ye / ortho_half_height();
      depth = (d - near) / (far - near);
    } else {
      // Similar triangles: the image plane at distance 1 spans tan(fov/2) * aspect half-width.
      x_ndc = xe / (d * tan_half() * aspect());
      y_ndc = ye / (d * tan_half());
      depth = far * (d - near) / (d * (far - near));
    }
    return {width * (0.5 + 0.5 * x_ndc), height * (0.5 - 0.5 * y_ndc), depth};
  }

  // The world-space ray (origin, direction with unit view depth) through a screen point.
  void ray(double sx, double sy, Vec3& origin, Vec3& direction) const {
    const double x_ndc = 2.0 * sx / width - 1.0, y_ndc = 1.0 - 2.0 * sy / height;
    if (ortho) {
      origin = eye + (x_ndc * ortho_half_height() * aspect()) * right() + (y_ndc * ortho_half_height()) * true_up();
      direction = forward();
    } else {
      origin = eye;
      direction = forward() + (x_ndc * tan_half() * aspect()) * right() + (y_ndc * tan_half()) * true_up();
    }
  }
};

}  // namespace rastersim::frontend::test_util
