#include "testbench/cosim_coverage.h"

#include <algorithm>

#include "model/triangle_setup.h"
#include "model/z_adder.h"

namespace rastersim::rtl {
namespace {

constexpr DepthFunc kDepthFuncs[] = {DepthFunc::Never,   DepthFunc::Less,     DepthFunc::Equal,  DepthFunc::LEqual,
                                     DepthFunc::Greater, DepthFunc::NotEqual, DepthFunc::GEqual, DepthFunc::Always};

// The bins in their fixed order; frame_coverage() fills them in the same order.
enum Fixed : size_t {
  kTieTop, kTieLeft, kTieBottom, kTieRight, kTieVertex,
  kDegenerate, kOffscreen, kNoCentre, kCulled, kDrawnNoFragment, kGuardBandDrawn, kGuardBandLimit,
  kHazardBBox, kHazardSpan, kMemoryBackPressure, kFifoFullDepth1, kFifoFullDeep, kFifoEmpty,
  kLatencyMin, kLatencyMax,
  kDepthFirst  // then per depth function: write on, write off, pass, fail
};
constexpr size_t kPerFunc = 4;
size_t depth_bin(DepthFunc f, size_t which) { return kDepthFirst + size_t(f) * kPerFunc + which; }
// After the depth functions: the depth bias's and the texture unit's inputs, then one hazard bin
// per memory latency 1 .. max_latency.
enum Inputs : size_t {
  kBiasConstantNegative = kDepthFirst + 8 * kPerFunc, kBiasConstantPositive, kBiasSlopeNegative, kBiasSlopePositive,
  kTextureNearest, kTextureBilinear, kTextureRepeat, kTextureClamp, kTextureWRatioLimit, kTextureStall,
  kTextureLatency1, kTextureLatencyMax,
  kHazardLatencyFirst
};
size_t hazard_latency_bin(int latency) { return kHazardLatencyFirst + size_t(latency) - 1; }
size_t bin_count(int max_latency) { return kHazardLatencyFirst + size_t(std::max(1, max_latency)); }

}  // namespace

std::vector<CoverageBin> coverage_bins(const Profile& p, const std::set<std::string>& pinned, int max_latency) {
  auto free = [&](const char* key) { return pinned.count(key) == 0; };
  // Hazard bins per latency up to the built maximum, or with the latency pinned up to it (the same
  // list whatever maximum a design behind the interface is given).
  const int listed_latencies = free("memory_latency") ? max_latency : std::clamp(p.memory_latency, 1, max_latency);
  std::vector<CoverageBin> bins(bin_count(listed_latencies));
  auto set = [&](size_t k, const char* name, const char* description) {
    bins[k].name = name;
    bins[k].description = description;
  };
  auto unreachable = [&](size_t k, const std::string& why) {
    bins[k].reachable = false;
    bins[k].unreachable = why;
  };
  set(kTieTop, "tie_top_edge", "candidate centre exactly on a top edge, inside the others (drawn: top-left rule)");
  set(kTieLeft, "tie_left_edge", "candidate centre exactly on a left edge, inside the others (drawn)");
  set(kTieBottom, "tie_bottom_edge", "candidate centre exactly on a bottom edge, inside the others (not drawn)");
  set(kTieRight, "tie_right_edge", "candidate centre exactly on a right edge, inside the others (not drawn)");
  set(kTieVertex, "tie_vertex", "candidate centre exactly on two edges at once (a vertex)");
  set(kDegenerate, "degenerate", "zero-area triangle");
  set(kOffscreen, "offscreen", "triangle whose box's pixel-centre columns or rows all lie beyond the screen");
  set(kNoCentre, "no_centre", "triangle on the screen whose box holds no pixel centre");
  set(kCulled, "culled", "triangle removed by the cull mode");
  set(kDrawnNoFragment, "drawn_without_fragment", "drawn triangle that covers no pixel centre");
  set(kGuardBandDrawn, "guard_band_drawn", "drawn triangle with a vertex outside the screen");
  set(kGuardBandLimit, "guard_band_limit", "drawn triangle with a vertex on the guard band's limit (-W, 2W, -H or 2H)");
  set(kHazardBBox, "zbuffer_hazard_stall_bbox", "cycle the z-buffer's oldest held fragment waited on a read-after-write hazard (bbox)");
  set(kHazardSpan, "zbuffer_hazard_stall_span", "cycle the z-buffer's oldest held fragment waited on a read-after-write hazard (span)");
  set(kMemoryBackPressure, "memory_back_pressure", "cycle the z-buffer waited on a memory that refused a read");
  set(kFifoFullDepth1, "fifo_full_depth_1", "cycle the setup unit waited for a record credit, setup_fifo_depth 1");
  set(kFifoFullDeep, "fifo_full_depth_2_up", "cycle the setup unit waited for a record credit, setup_fifo_depth >= 2");
  set(kFifoEmpty, "fifo_empty", "drawn triangle (not a frame's first) the idle walker waited for");
  set(kLatencyMin, "memory_latency_1", "fragment at memory_latency 1");
  set(kLatencyMax, "memory_latency_max", "fragment at the largest memory_latency the RTL is built for");
  for (const DepthFunc f : kDepthFuncs) {
    const std::string n = std::string("depth_") + to_string(f);
    bins[depth_bin(f, 0)] = {n + "_write_on", "fragment tested with depth_write true", true, ""};
    bins[depth_bin(f, 1)] = {n + "_write_off", "fragment tested with depth_write false", true, ""};
    bins[depth_bin(f, 2)] = {n + "_pass", "fragment that passed", true, ""};
    bins[depth_bin(f, 3)] = {n + "_fail", "fragment that failed", true, ""};
  }
  set(kBiasConstantNegative, "depth_bias_constant_negative", "fragment of a frame with a negative depth_bias_constant");
  set(kBiasConstantPositive, "depth_bias_constant_positive", "fragment of a frame with a positive depth_bias_constant");
  set(kBiasSlopeNegative, "depth_bias_slope_negative",
      "fragment of a triangle with a depth step, in a frame with a negative depth_bias_slope");
  set(kBiasSlopePositive, "depth_bias_slope_positive",
      "fragment of a triangle with a depth step, in a frame with a positive depth_bias_slope");
  set(kTextureNearest, "texture_nearest", "textured fragment sampled from a texture with the nearest filter");
  set(kTextureBilinear, "texture_bilinear", "textured fragment sampled from a texture with the bilinear filter");
  set(kTextureRepeat, "texture_repeat_outside", "textured fragment with u or v outside [0, 1), wrap repeat");
  set(kTextureClamp, "texture_clamp_outside", "textured fragment with u or v outside [0, 1), wrap clamp");
  set(kTextureWRatioLimit, "texture_w_ratio_limit", "drawn textured triangle whose w ratio is the divide's limit 2^14");
  set(kTextureStall, "texture_memory_stall", "cycle a texture read waited for the texture memory");
  set(kTextureLatency1, "texture_latency_1", "textured fragment at texture_latency 1");
  set(kTextureLatencyMax, "texture_latency_max", "textured fragment at the largest texture_latency (64)");
  for (int latency = 1; latency <= listed_latencies; ++latency) {
    const std::string n = "zbuffer_hazard_stall_latency_" + std::to_string(latency);
    bins[hazard_latency_bin(latency)] = {n, "cycle the z-buffer's oldest held fragment waited on a read-after-write "
                                            "hazard at memory_latency " + std::to_string(latency), true, ""};
  }

  if (!free("cull") && p.cull == CullMode::None) unreachable(kCulled, "cull is pinned to none");
  if (p.subpixel_bits == 1)
    unreachable(kNoCentre, "with one subpixel bit a box between two centres has one coordinate: zero area");
  const bool can_bbox = free("traversal") || p.traversal == Traversal::BBox;
  const bool can_span = free("traversal") || p.traversal == Traversal::Span;
  // A hazard needs the next triangle's first fragment on the last one's pixel within the latency;
  // with the load in the last candidate's cycle they can be in consecutive cycles (latency 1).
  if (!can_bbox) unreachable(kHazardBBox, "traversal is pinned to span");
  if (!can_span) unreachable(kHazardSpan, "traversal is pinned to bbox");
  // With one record at a time the serial unit starts the next triangle only once the walker took
  // the last record, and finishes it long after a small triangle's walk.
  if (p.setup_interval == 0 && !free("setup_fifo_depth") && p.setup_fifo_depth == 1)
    for (const size_t k : {kHazardBBox, kHazardSpan})
      if (bins[k].reachable) unreachable(k, "the serial setup with setup_fifo_depth pinned to 1 leaves a gap");
  unreachable(kMemoryBackPressure,
              "rastersim_top's on-chip memory never refuses a read (the SystemC system's memory does)");
  if (!free("setup_fifo_depth") && p.setup_fifo_depth != 1) unreachable(kFifoFullDepth1, "setup_fifo_depth is pinned");
  if (!free("setup_fifo_depth") && p.setup_fifo_depth == 1) unreachable(kFifoFullDeep, "setup_fifo_depth is pinned to 1");
  if (!free("memory_latency") && p.memory_latency != 1) unreachable(kLatencyMin, "memory_latency is pinned");
  if (!free("memory_latency") && p.memory_latency != max_latency) unreachable(kLatencyMax, "memory_latency is pinned");
  for (int latency = 1; latency <= listed_latencies; ++latency) {
    const size_t k = hazard_latency_bin(latency);
    if (!free("memory_latency") && p.memory_latency != latency) unreachable(k, "memory_latency is pinned");
    else if (!bins[kHazardBBox].reachable && !bins[kHazardSpan].reachable) unreachable(k, bins[kHazardSpan].unreachable);
  }

  // The depth bias's runtime registers exist in a build with it (a biased profile); a pinned value
  // has one sign.
  const std::pair<size_t, size_t> bias_bins[] = {{kBiasConstantNegative, kBiasConstantPositive},
                                                 {kBiasSlopeNegative, kBiasSlopePositive}};
  const char* bias_keys[] = {"depth_bias_constant", "depth_bias_slope"};
  const int64_t bias_values[] = {p.depth_bias_constant, p.depth_bias_slope};
  for (int k = 0; k < 2; ++k) {
    for (const size_t b : {bias_bins[k].first, bias_bins[k].second}) {
      const bool negative = b == bias_bins[k].first;
      if (!p.depth_biased()) unreachable(b, "the build has no depth bias (the profile is unbiased)");
      else if (!free(bias_keys[k]) && (negative ? bias_values[k] >= 0 : bias_values[k] <= 0))
        unreachable(b, std::string(bias_keys[k]) + " is pinned");
    }
  }
  for (size_t k = kTextureNearest; k <= kTextureLatencyMax; ++k)
    if (!p.texture_unit) unreachable(k, "the build has no texture unit");
  if (p.texture_unit && !free("texture_stall_percent") && p.texture_stall_percent == 0)
    unreachable(kTextureStall, "texture_stall_percent is pinned to 0");
  if (p.texture_unit && !free("texture_latency") && p.texture_latency != 1)
    unreachable(kTextureLatency1, "texture_latency is pinned");
  if (p.texture_unit && !free("texture_latency") && p.texture_latency != kMaxTextureLatency)
    unreachable(kTextureLatencyMax, "texture_latency is pinned");

  const bool clear_pinned = !free("depth_clear");
  const uint32_t clear = p.depth_clear_value();
  const bool writes_off_only = !free("depth_write") && !p.depth_write;
  for (const DepthFunc f : kDepthFuncs) {
    if (!free("depth_func") && p.depth_func != f) {
      for (size_t k = 0; k < kPerFunc; ++k) unreachable(depth_bin(f, k), "depth_func is pinned");
      continue;
    }
    if (!free("depth_write")) unreachable(depth_bin(f, p.depth_write ? 1 : 0), "depth_write is pinned");
    // Depths are in [0, 2^N - 1]; a buffer changes only by writes of passing fragments.
    const bool never_pass = f == DepthFunc::Never || (f == DepthFunc::Less && clear_pinned && clear == 0) ||
                            (f == DepthFunc::Greater && clear_pinned && clear == p.depth_max());
    const bool never_fail = f == DepthFunc::Always ||
                            (f == DepthFunc::LEqual && clear_pinned && clear == p.depth_max() && writes_off_only) ||
                            (f == DepthFunc::GEqual && clear_pinned && clear == 0 && writes_off_only);
    if (never_pass) unreachable(depth_bin(f, 2), "no depth passes this function on this buffer");
    if (never_fail) unreachable(depth_bin(f, 3), "no depth fails this function on this buffer");
  }
  return bins;
}

CoverageCounts frame_coverage(const Profile& p, const std::vector<SnappedTriangle>& triangles, const RtlResult& model,
                              int max_latency, const TextureBinding& texture) {
  CoverageCounts hits(bin_count(max_latency), 0);
  const TriangleSetup setup(p);
  const int64_t one = int64_t(1) << p.subpixel_bits;
  const int64_t x_lo = -p.width * one, x_hi = 2 * p.width * one, y_lo = -p.height * one, y_hi = 2 * p.height * one;
  int64_t previous_walker_end = -1;
  bool seen_drawn = false;
  for (size_t t = 0; t < triangles.size(); ++t) {
    const TriangleRecord& record = model.triangles[t];
    switch (record.status) {
      case SetupStatus::Degenerate: ++hits[kDegenerate]; continue;
      case SetupStatus::Offscreen: ++hits[kOffscreen]; continue;
      case SetupStatus::NoCentre: ++hits[kNoCentre]; continue;
      case SetupStatus::Culled: ++hits[kCulled]; continue;
      case SetupStatus::Drawn: break;
    }
    hits[kDrawnNoFragment] += record.fragments == 0;
    bool outside = false, at_limit = false;
    for (const SnappedVertex& v : triangles[t].v) {
      outside |= v.x < 0 || v.y < 0 || v.x >= p.width * one || v.y >= p.height * one;
      at_limit |= v.x == x_lo || v.x == x_hi || v.y == y_lo || v.y == y_hi;
    }
    hits[kGuardBandDrawn] += outside;
    hits[kGuardBandLimit] += at_limit;
    if (p.texture_unit && triangles[t].textured) {
      // q is 2^P / w scaled by the smallest w: the largest q over the smallest is the w ratio.
      int64_t q_min = triangles[t].v[0].q, q_max = q_min;
      for (const SnappedVertex& v : triangles[t].v) q_min = std::min(q_min, v.q), q_max = std::max(q_max, v.q);
      hits[kTextureWRatioLimit] += q_min > 0 && q_min <= (q_max >> 14);
    }
    // Loaded in the cycle its record is ready (docs/cycle-model.md, "Depth bias"), the walker idle.
    const int64_t ready = record.setup_done + (p.depth_biased() ? DepthOutput::kBiasStages : 1);
    if (seen_drawn && record.walker_load == ready && record.walker_load > previous_walker_end)
      ++hits[kFifoEmpty];
    seen_drawn = true;
    previous_walker_end = record.walker_end;

    // Ties: every candidate of the box, each edge's unbiased value E + bias exactly zero.
    const SetupResult s = setup.run(triangles[t]);
    if (s.depth.step_x != 0 || s.depth.step_y != 0) {
      hits[kBiasSlopeNegative] += p.depth_bias_slope < 0 ? record.fragments : 0;
      hits[kBiasSlopePositive] += p.depth_bias_slope > 0 ? record.fragments : 0;
    }
    for (int y = s.y0; y <= s.y1; ++y) {
      for (int x = s.x0; x <= s.x1; ++x) {
        int64_t biased[3];
        int zeros = 0, inside = 0;
        for (int k = 0; k < 3; ++k) {
          const EdgeSetup& e = s.edge[k];
          biased[k] = int64_t(e.start) + int64_t(x - s.x0) * int64_t(e.step_x) + int64_t(y - s.y0) * int64_t(e.step_y);
          const int64_t unbiased = biased[k] + (e.owns_samples ? 0 : 1);
          zeros += unbiased == 0;
          inside += unbiased >= 0;
        }
        if (zeros == 0 || inside < 3) continue;
        if (zeros >= 2) {
          ++hits[kTieVertex];
          continue;
        }
        for (int k = 0; k < 3; ++k) {
          const EdgeSetup& e = s.edge[k];
          if (biased[k] + (e.owns_samples ? 0 : 1) != 0) continue;
          // Where the interior lies (y down): below a horizontal edge with dx > 0 (a top edge), right
          // of an edge with dy < 0 (a left edge); step_x = -dy 2^S, step_y = dx 2^S.
          const bool horizontal = int64_t(e.step_x) == 0;
          ++hits[horizontal ? (int64_t(e.step_y) > 0 ? kTieTop : kTieBottom) : (int64_t(e.step_x) > 0 ? kTieLeft : kTieRight)];
        }
      }
    }
  }
  // In rastersim_top the z-buffer waits only on hazards (its memory never refuses a read).
  hits[p.traversal == Traversal::BBox ? kHazardBBox : kHazardSpan] += model.stats.zbuffer.stall;
  hits[p.setup_fifo_depth == 1 ? kFifoFullDepth1 : kFifoFullDeep] += model.stats.setup.stall;
  if (p.memory_latency >= 1 && p.memory_latency <= max_latency)
    hits[hazard_latency_bin(p.memory_latency)] += model.stats.zbuffer.stall;
  const int64_t fragments = int64_t(model.fragments.size());
  if (p.depth_bias_constant < 0) hits[kBiasConstantNegative] += fragments;
  if (p.depth_bias_constant > 0) hits[kBiasConstantPositive] += fragments;
  if (p.texture_unit) {
    hits[kTextureStall] += model.stats.texture.stall;
    constexpr int32_t kOne = int32_t(1) << 20;  // u, v are s8.20
    for (const Fragment& f : model.fragments) {
      if (!f.textured) continue;
      hits[kTextureLatency1] += p.texture_latency == 1;
      hits[kTextureLatencyMax] += p.texture_latency == kMaxTextureLatency;
      if (!texture.texture) continue;  // no texture: white texels, the filter and wrap unused
      hits[texture.filter == TextureFilter::Nearest ? kTextureNearest : kTextureBilinear] += 1;
      const bool outside = f.uv.u < 0 || f.uv.u >= kOne || f.uv.v < 0 || f.uv.v >= kOne;
      if (outside) ++hits[texture.wrap == TextureWrap::Repeat ? kTextureRepeat : kTextureClamp];
    }
  }
  if (p.memory_latency == 1) hits[kLatencyMin] += fragments;
  if (p.memory_latency == max_latency) hits[kLatencyMax] += fragments;
  hits[depth_bin(p.depth_func, p.depth_write ? 0 : 1)] += fragments;
  for (const Fragment& f : model.fragments) ++hits[depth_bin(p.depth_func, f.pass ? 2 : 3)];
  return hits;
}

std::vector<std::string> coverage_holes(const std::vector<CoverageBin>& bins, const CoverageCounts& hits) {
  std::vector<std::string> holes;
  for (size_t k = 0; k < bins.size(); ++k)
    if (bins[k].reachable && hits[k] == 0) holes.push_back(bins[k].name);
  return holes;
}

}  // namespace rastersim::rtl
