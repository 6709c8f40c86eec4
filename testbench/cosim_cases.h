// Triangle suites for the co-simulation: directed cases (ties, huge, off-screen, degenerate, depth
// functions, hazards, long rows) and constrained-random frames. Every triangle is valid input:
// snapped, inside the guard band, depths in [0, 2^N - 1].
#pragma once

#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "model/profile.h"
#include "model/texture_unit.h"
#include "model/triangle.h"

namespace rastersim::rtl {

struct CosimCase {
  std::string name;                        // e.g. "random 17" or "directed hazards"
  std::vector<SnappedTriangle> triangles;  // one frame
  Profile profile;                         // the frame's profile (its runtime settings may differ)
  TextureBinding texture;                  // what the texture unit samples (profiles with texture_unit)
};

// A constrained-random frame of `count` triangles drawn from every category, reproducible from seed.
// With the profile's texture unit most triangles are textured (random u, v and a w spread up to
// the divide's limit, check_texture_w_ratio) and the frame draws a random texture (1 to 256 texels
// a side, sometimes none), filter and wrap mode.
CosimCase random_case(const Profile& profile, uint64_t seed, int count);

// The profile keys the RTL samples at reset rather than being built for (depth_func, depth_write,
// depth_clear, cull, front_face, traversal, shading, memory_latency).
const std::vector<std::string>& runtime_setting_keys();

// The settings a `cosim` run's random frames keep: with `fixed_settings` every runtime setting (the
// texture unit's and the depth bias's too), else the keys a flag or the profile file gave, less the
// depth bias's (a non-zero bias value selects the build with the bias; its values stay drawn).
std::set<std::string> pinned_settings(const std::set<std::string>& given, bool fixed_settings);

// `profile` with every runtime setting that is not in `pinned` drawn from `seed`: memory latency in
// 1..min(8, max_memory_latency), the depth clear mostly 2^N - 1, the rest uniformly; with the texture
// unit its latency (1..8, now and then 64) and its memory's stall pattern (a third of the frames,
// 1..60 %) too.
Profile random_settings(const Profile& profile, uint64_t seed, const std::set<std::string>& pinned,
                        int max_memory_latency);

// The directed frames of the texture unit (profiles with texture_unit): each filter with each wrap
// mode on u, v in [-3, 3], triangles at the w ratio limit 2^14, and texture memory stalls at
// texture_latency 1 and 64. Settings in `pinned` stay the profile's.
std::vector<CosimCase> texture_cases(const Profile& profile, const std::set<std::string>& pinned);

// The directed frames, each a few dozen triangles at most, on `profile`. Unless depth_func is in
// `pinned`, they end with one frame per depth function (equal depths, the clear value, overlaps).
std::vector<CosimCase> directed_cases(const Profile& profile, const std::set<std::string>& pinned = {"depth_func"});

// Directed frames for the corners of the functional coverage (testbench/cosim_coverage.h) that the
// frames above and the default count of random frames could miss: vertices on the guard band's
// limits, a record FIFO filled behind a whole-screen triangle, hazards at every memory latency
// 1..max_memory_latency, every depth function with depth_write flipped and, with the depth bias,
// each sign of its constant and slope factor. Settings in `pinned` stay the profile's.
std::vector<CosimCase> coverage_cases(const Profile& profile, const std::set<std::string>& pinned,
                                      int max_memory_latency);

// The frames of a `cosim` run in order: the directed frames, with the texture unit texture_cases,
// and the coverage frames (unless `directed` is false), then random ones; frame k's random triangles, settings and power-on state
// come from seed + k. The command line and the bug-injection check run the same frames.
class CosimPlan {
 public:
  CosimPlan(const Profile& profile, const std::set<std::string>& pinned, int max_memory_latency, uint64_t seed,
            int triangles, bool directed);
  int64_t directed_count() const { return int64_t(directed_.size()); }
  CosimCase frame(int64_t k) const;
  // The runtime settings random frames draw (those not pinned).
  const std::vector<std::string>& varied() const { return varied_; }

 private:
  Profile profile_;
  std::set<std::string> pinned_;
  int max_memory_latency_;
  uint64_t seed_;
  int triangles_;
  std::vector<CosimCase> directed_;
  std::vector<std::string> varied_;
};

}  // namespace rastersim::rtl
