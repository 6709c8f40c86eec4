// Comparing a design whose micro-architecture is not rastersim's against the model
// (docs/verification.md "Compare modes"): the same frame's decisions, fragments and final buffers,
// compared as strictly as the design's conventions allow.
//   cycle     every event at the model's cycle: rastersim's own micro-architecture (rtl::compare of
//             every record), or through the verification interface each decision, retirement and
//             the frame's end at the model's cycle and the stream exactly
//   stream    the same decisions and fragments in the same order, any timing
//   triangle  triangles in order, each triangle's fragments as a set (any order within it)
//   frame     the final colour and depth buffers only
// Coverage is exact in every mode. A tolerance lets a fragment's depth and colour (and the final
// buffer words) differ from the model's by up to N LSBs of the model's words; the report gives the
// distribution of the differences.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "testbench/rtl_backend.h"

namespace rastersim::verify {

enum class CompareMode { Cycle, Stream, Triangle, Frame };
const char* to_string(CompareMode mode);
std::optional<CompareMode> parse_compare_mode(const std::string& text);

// In LSBs of the model's words: depth in depth-word LSBs, colour per 8-bit channel.
struct Tolerance {
  int64_t depth = 0;
  int64_t color = 0;
};
// "depth=N,color=M" (either alone; "colour" also). Returns an error sentence, or "" on success.
std::string parse_tolerance(const std::string& text, Tolerance& out);

// Design minus model, counted by value.
struct ErrorDistribution {
  std::map<int64_t, int64_t> counts;
  void add(int64_t error) { ++counts[error]; }
  int64_t samples() const;
  int64_t max_abs() const;
  // "n samples, error lo..hi: 0 xa, -1 xb" (the range, then the 5 most common values and their counts).
  std::string summary() const;
};

struct Mismatch {
  int64_t triangle = -1;  // -1: a frame-level field (the final buffers)
  int x = -1, y = -1;     // the pixel, -1 when the field is not a pixel's
  std::string field;      // status, fragment, z, color, pass, cycle, order, missing fragment, ...
  std::string expected, actual;
  std::string sentence() const;
};

struct FunctionalReport {
  CompareMode mode = CompareMode::Stream;
  std::vector<Mismatch> mismatches;  // the earliest first, at most the limit given to compare
  int64_t mismatch_count = 0;
  int64_t fragments_compared = 0;
  int64_t words_compared = 0;
  ErrorDistribution depth_error, color_error;  // per fragment in stream and triangle modes, per word in frame mode
  bool passed() const { return mismatch_count == 0; }
  // One line: "stream: 1234 fragments and 3072 buffer words agree" or the first mismatch and the count.
  std::string summary() const;
};

// The design's cycle (from the first handshake) nearest a mismatch, for a waveform window: the
// retirement of the design's fragment at its pixel, else its decision of the triangle, else the
// design's last cycle.
int64_t design_cycle(const Mismatch& mismatch, const rtl::RtlResult& design);

// `model` is run_model's result for the frame, `design` what the design reported for it (its
// fragments in retire order with their triangle index, its decisions as triangle records with the
// index and status, its final buffers when read back: empty vectors are not compared). In cycle mode
// the frame is compared by rtl::compare, every field and cycle.
FunctionalReport compare(const Profile& profile, const rtl::RtlResult& model, const rtl::RtlResult& design,
                         CompareMode mode, const Tolerance& tolerance = {}, size_t max_mismatches = 10);

}  // namespace rastersim::verify
