// `rastersim sweep`: one scene rendered at every combination of the values given for some profile
// keys (and camera keys near, far, fov), into a CSV of cycle and precision figures per point, the
// hardware cost of each point's profile (--hw-cost, hw_cost.h) and gnuplot PNG plots
// (docs/studies.md).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "model/pipeline.h"
#include "render_command.h"

namespace rastersim {

// The most points (renders) one sweep runs: the product of the --vary value counts.
constexpr size_t kMaxSweepPoints = 10000;

struct SweepOptions {
  RenderOptions scene;             // input or --scene, camera flags, the base profile
  std::vector<std::string> vary;   // "KEY=V1,V2,..." in the order given
  std::string backend = "model";
  std::string out_dir;             // sweep.csv, sweep.gp, one PNG per figure
  bool hw_cost = false;
  std::string hw_cost_cache;       // empty: $XDG_CACHE_HOME or ~/.cache, then rastersim/hw-cost
  std::string rtl_dir;             // empty: the rtl/ of the source tree this binary was built from
  bool plots = true;
  int jobs = 1;                    // points rendered in parallel
};

CLI::App* add_sweep_command(CLI::App& app, SweepOptions& options);
// Returns the exit code; throws InputError (bad input or usage) and std::exception.
int run_sweep(const SweepOptions& options);

// One swept key and its values, from "KEY=V1,V2,...". Throws InputError for an unknown key, an
// empty list or a repeated value.
struct SweepAxis {
  std::string key;
  std::vector<std::string> values;
};
SweepAxis parse_sweep_axis(const std::string& text);

// Precision figures of a frame from its fragments (in emission order):
//  - max_depth_error(): the largest |z - exact| in depth plane LSBs, exact being the plane through
//    the snapped triangle's three vertex depths at the pixel centre (the rounding of the Z adders;
//    with a floating-point depth word z is the word's value, so its truncation counts too, and a
//    depth bias counts in full);
//  - wrong_depth_tests(): fragments whose depth-test result differs from an ideal z-buffer's, one
//    that holds the unquantized depth (the screen triangle's z in [0, 1] interpolated in long
//    double at the same pixel centre) and applies the same depth function and write rule: the
//    z-fighting of the profile's depth precision (z_bits, vertex quantization, Z adder rounding).
class DepthErrorMeter : public FragmentSink {
 public:
  DepthErrorMeter(const std::vector<ScreenTriangle>& screen, const std::vector<SnappedTriangle>& snapped,
                  const Profile& profile);
  void on_fragment(const Fragment& f) override;
  double max_depth_error() const { return max_; }
  int64_t wrong_depth_tests() const { return wrong_; }

 private:
  const std::vector<ScreenTriangle>& screen_;
  const std::vector<SnappedTriangle>& snapped_;
  Profile profile_;
  std::vector<long double> ideal_depth_;
  DepthWord word_;
  double max_ = 0;
  int64_t wrong_ = 0;
};

// |z - exact depth of the plane of t at the centre of pixel (x, y)| in LSBs (t not degenerate).
double depth_error_lsb(const SnappedTriangle& t, int subpixel_bits, int x, int y, uint32_t z);

// The barycentric weights of the centre of pixel (x, y) in the snapped triangle (exact up to the
// final division), summing to 1.
void pixel_weights(const SnappedTriangle& t, int subpixel_bits, int x, int y, long double weight[3]);

}  // namespace rastersim
