// Functional coverage of the co-simulation: the corner cases a frame's stimulus reached, counted
// from the model's run of it (the model and the RTL agree on every event of a passing frame), and
// which corners a run can reach at all given its profile and the settings it pins
// (docs/verification.md, "Functional coverage").
#pragma once

#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "model/profile.h"
#include "model/triangle.h"
#include "testbench/rtl_backend.h"

namespace rastersim::rtl {

struct CoverageBin {
  std::string name;         // e.g. "tie_top_edge"
  std::string description;  // what one hit is
  bool reachable = true;    // false: no frame of this run can hit it
  std::string unreachable;  // why, when not reachable
};

// Hits per bin, in the order of coverage_bins().
using CoverageCounts = std::vector<int64_t>;

// The bins of a run on `profile` whose random frames keep the settings in `pinned`; the RTL is
// built for memory latencies up to `max_memory_latency`.
std::vector<CoverageBin> coverage_bins(const Profile& profile, const std::set<std::string>& pinned,
                                       int max_memory_latency);

// The hits of one frame, in the order of coverage_bins() (at least as many: the hazard bins of
// every latency up to `max_memory_latency`): `frame_profile` is the frame's own profile (its runtime settings drawn or
// directed), `model` the model's run of `triangles` (run_model) with the frame's `texture`.
CoverageCounts frame_coverage(const Profile& frame_profile, const std::vector<SnappedTriangle>& triangles,
                              const RtlResult& model, int max_memory_latency, const TextureBinding& texture = {});

// The reachable bins that no frame hit, by name.
std::vector<std::string> coverage_holes(const std::vector<CoverageBin>& bins, const CoverageCounts& hits);

}  // namespace rastersim::rtl
