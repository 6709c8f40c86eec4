// `rastersim sweep`: one scene rendered at every combination of the values given for some profile
// keys (and camera keys near, far, fov), into a CSV of cycle and precision figures per point, the
// hardware cost of each point's profile (--hw-cost, hw_cost.h) and gnuplot PNG plots
// (docs/studies.md).
#pragma once

#include <cstdint>
#include <exception>
#include <string>
#include <thread>
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
  int threads = 1;                 // threads of each point's depth-error meter
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
//
// With threads > 1 the calling thread (the render's) only keeps the fragments, per band of
// kMeterBandRows rows, and hands every `chunk` of them to threads - 1 meter threads (thread k
// takes the bands b with b % (threads - 1) == k), which meter them while the render goes on. A
// pixel's fragments keep their order within its band, and the figures (a maximum and a count) do
// not depend on the order between pixels, so they are the same at any thread count.
class DepthErrorMeter : public FragmentSink {
 public:
  static constexpr int kMeterBandRows = 8;
  DepthErrorMeter(const std::vector<ScreenTriangle>& screen, const std::vector<SnappedTriangle>& snapped,
                  const Profile& profile, int threads = 1, size_t chunk = size_t(1) << 18);
  ~DepthErrorMeter() override;
  DepthErrorMeter(const DepthErrorMeter&) = delete;
  DepthErrorMeter& operator=(const DepthErrorMeter&) = delete;
  void on_fragment(const Fragment& f) override;
  // Meters the fragments still kept and waits for the meter threads; the figures below are the
  // frame's after it.
  void finish();
  double max_depth_error() const;
  int64_t wrong_depth_tests() const;

 private:
  struct Kept {  // what the figures need of a fragment
    int64_t tri;
    int x, y;
    uint32_t z;
    bool pass;
  };
  struct alignas(64) Figures {  // one cache line per thread
    double max = 0;
    int64_t wrong = 0;
  };
  void meter(const Kept& f, Figures& figures);
  void hand_over();  // the kept chunk to the meter threads, once they are done with the last one
  void join();       // waits for the meter threads; rethrows what one of them threw
  void check_finished() const;
  const std::vector<ScreenTriangle>& screen_;
  const std::vector<SnappedTriangle>& snapped_;
  Profile profile_;
  std::vector<long double> ideal_depth_;  // each pixel read and written by its band's thread only
  DepthWord word_;
  size_t meter_threads_;                  // 0: metered at once on the calling thread
  size_t chunk_;
  std::vector<std::vector<Kept>> filling_, metering_;  // per meter thread
  size_t kept_count_ = 0;
  std::vector<Figures> figures_;  // per meter thread (one without them)
  std::vector<std::thread> running_;
  std::vector<std::exception_ptr> failures_;
};

// |z - exact depth of the plane of t at the centre of pixel (x, y)| in LSBs (t not degenerate).
double depth_error_lsb(const SnappedTriangle& t, int subpixel_bits, int x, int y, uint32_t z);

// The barycentric weights of the centre of pixel (x, y) in the snapped triangle (exact up to the
// final division), summing to 1.
void pixel_weights(const SnappedTriangle& t, int subpixel_bits, int x, int y, long double weight[3]);

}  // namespace rastersim
