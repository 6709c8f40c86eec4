// Triangle suites for the co-simulation: directed cases (ties, huge, off-screen, degenerate, depth
// functions, hazards, long rows) and constrained-random frames. Every triangle is valid input:
// snapped, inside the guard band, depths in [0, 2^N - 1].
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "model/profile.h"
#include "model/triangle.h"

namespace rastersim::rtl {

struct CosimCase {
  std::string name;                        // e.g. "random 17" or "directed hazards"
  std::vector<SnappedTriangle> triangles;  // one frame
};

// A constrained-random frame of `count` triangles drawn from every category, reproducible from seed.
CosimCase random_case(const Profile& profile, uint64_t seed, int count);

// The directed frames, each a few dozen triangles at most.
std::vector<CosimCase> directed_cases(const Profile& profile);

}  // namespace rastersim::rtl
