// The pipeline: setup -> walker (+ Z adder) -> z-buffer, with valid/ready coupling, as the RTL top
// connects them. Computes the fragments, the final buffers and the exact cycle of every event
// (docs/cycle-model.md). One Pipeline renders one frame; reset() starts another.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "profile.h"
#include "scanline_walker.h"
#include "texture_unit.h"
#include "triangle.h"
#include "triangle_setup.h"
#include "widths.h"
#include "z_adder.h"
#include "zbuffer.h"

namespace rastersim {

struct Fragment {
  int64_t tri;     // triangle index in submission order
  int x, y;        // pixel
  uint32_t z;      // depth entering the test, uN
  Rgb color;
  bool pass;       // depth test result
  int64_t cycle;   // cycle the z-buffer took it from the walker (or the texture unit; docs/cycle-model.md)
  bool textured = false;  // its triangle is textured: uv holds the divided texture coordinate
  TextureCoordinate uv;   // s8.20 each (docs/arithmetic.md section 5)
  int64_t tested = -1;    // cycle of its depth test and conditional write: its memory read + L
};

class FragmentSink {
 public:
  virtual ~FragmentSink() = default;
  virtual void on_fragment(const Fragment& fragment) = 0;
};

// The transaction record of one triangle: what the setup unit decided and when each unit handled it.
struct TriangleRecord {
  int64_t index = 0;
  SetupStatus status = SetupStatus::Degenerate;
  int64_t setup_accept = 0;    // cycle the setup unit accepted the triangle
  int64_t setup_decided = 0;   // cycle its status is decided (every triangle, drawn or not)
  int64_t setup_done = 0;      // drawn: the cycle its record is in the output register; rejected: its decision cycle
  int64_t walker_load = -1;    // cycle the walker took the record (handshake), -1 if not drawn
  int64_t walker_end = -1;     // walker's last cycle on this triangle
  int64_t fragments = 0;
  int64_t depth_pass = 0;
  int64_t last_write = -1;     // cycle of the last z-buffer write of its fragments
};

struct UnitCounters {
  int64_t busy = 0;
  int64_t stall = 0;
};

struct FrameStats {
  int64_t triangles = 0;
  int64_t triangles_culled = 0;
  int64_t triangles_degenerate = 0;
  int64_t triangles_offscreen = 0;  // the box's pixel-centre columns or rows all beyond the screen
  int64_t triangles_no_centre = 0;  // on the screen, no pixel centre in the box
  int64_t triangles_drawn = 0;
  int64_t candidates = 0;
  int64_t fragments = 0;
  int64_t depth_pass = 0;
  int64_t depth_fail = 0;
  int64_t cycles = 0;          // first cycle after the last unit's last busy cycle
  UnitCounters setup, walker, z_adder, zbuffer;
  UnitCounters texture;        // the texture unit's (profile texture_unit; zero without it)
};

class Pipeline;

// A walk of a drawn triangle without a fragment sink, faster than the specification's one fragment
// at a time, with the same results (tests/test_fast_path.cpp); fast/fast_walk.h has one. It walks
// through Pipeline::walk_offering_runs and returns the walker's last cycle.
class WalkRunner {
 public:
  virtual ~WalkRunner() = default;
  virtual int64_t walk(Pipeline& p, const SetupResult& s, int64_t load_cycle, TriangleRecord& record) const = 0;
  // Called with each triangle before its setup, which takes long enough for the memory to bring in
  // the words of the triangle's first rows if asked for them here (no effect on any result).
  virtual void prefetch(Pipeline&, const SnappedTriangle&) const {}
  // The triangle's setup into `r`, for this walk: the specification's whole setup by default. A walk
  // that enters rows without the planes along the left edges (ZAdder::enter_row_at) may leave
  // r.left as it was; every other field must be the specification's.
  virtual void set_up(const TriangleSetup& setup, const SnappedTriangle& tri, SetupResult& r) const { setup.run(tri, r); }
};
// Picks a new pipeline's walk runner (nullptr: the specification's walk).
using WalkRunnerChoice = std::shared_ptr<const WalkRunner> (*)(const Pipeline& p);

class Pipeline {
 public:
  // Takes the walk runner the process's choice picks, if one is set (set_walk_runner_choice).
  explicit Pipeline(const Profile& profile);

  void reset();
  // Optional observers; pass nullptr to detach. Tracing costs nothing when detached.
  void set_fragment_sink(FragmentSink* sink) { sink_ = sink; }
  void set_triangle_log(std::vector<TriangleRecord>* log) { log_ = log; }
  // What the texture unit samples (with the profile's texture_unit): kept until replaced.
  void set_texture(TextureBinding binding) { texture_ = std::move(binding); }
  // The walk without a fragment sink: the specification's (nullptr) or a runner's. The choice set
  // when a pipeline is constructed picks its runner (fast/fast_walk.h use_fast_walk sets one).
  void set_walk_runner(std::shared_ptr<const WalkRunner> runner) { walk_runner_ = std::move(runner); }
  const WalkRunner* walk_runner() const { return walk_runner_.get(); }
  static void set_walk_runner_choice(WalkRunnerChoice choice);
  static WalkRunnerChoice walk_runner_choice();

  // Runs one triangle through every unit. The triangle must have been checked (check_screen_triangle).
  void submit(const SnappedTriangle& tri);
  const FrameStats& stats();

  const Profile& profile() const { return profile_; }
  const Widths& widths() const { return setup_.widths(); }
  const SetupTiming& setup_timing() const { return timing_; }
  const ZBuffer& zbuffer() const { return zbuffer_; }
  const ZAdder& z_adder() const { return adders_; }
  const SetupResult& last_setup() const { return last_setup_; }
  std::vector<TriangleRecord>* triangle_log() const { return log_; }
  const TextureBinding& texture() const { return texture_; }

  // Timing only (no fragment sink): every fragment is taken with all its cycles and timing
  // counters, but not coloured, tested or written; a caller that tests the same fragments in
  // submission order (fast/threaded_render.h) gives the results back with add_depth_results().
  // No cycle depends on a depth test's result or a buffer word, so the timing is the frame's.
  void set_timing_only(bool on) { timing_only_ = on; }
  void add_depth_results(int64_t passes, int64_t fails) { external_pass_ += passes, external_fail_ += fails; }
  // The buffers, for such a caller's depth tests.
  ZBuffer& zbuffer_words() { return zbuffer_; }

  // For a walk runner: the walk of a drawn triangle loaded in `load_cycle`, without a fragment sink,
  // in which each run of n covered candidates of a row is first offered to
  // runs.run(zbuffer, address, n, adders, cycle, record); it takes them at once, in cycles `cycle`
  // on (true; the adders need not step past them, see kEntersRowsAtOffset in scanline_walker.h), or
  // leaves them to be taken one at a time (false). The fragments go from the walker to the z-buffer
  // (no texture unit); the span walk enters each row with ZAdder::enter_row_at (the same outputs).
  template <class Runs>
  int64_t walk_offering_runs(const SetupResult& s, int64_t load_cycle, TriangleRecord& record, Runs& runs) {
    RunSink<Runs> sink{*this, record, runs};
    return walker_.walk(s, adders_, load_cycle, walker_idle_load_, sink, walker_counters_);
  }
  // The same for a timing-only pipeline: no plane register is stepped, and a run is offered as
  // runs.run(zbuffer, address, n, cycle, record), which takes its cycles alone.
  template <class Runs>
  int64_t walk_timing_offering_runs(const SetupResult& s, int64_t load_cycle, TriangleRecord& record, Runs& runs) {
    NoPlanes planes;
    TimingRunSink<Runs> sink{*this, record, runs};
    return walker_.walk(s, planes, load_cycle, walker_idle_load_, sink, walker_counters_);
  }

 private:
  template <bool Trace>
  struct StepSink;
  // One fragment at a time: the specification's walk, with Trace each reported to the sink.
  template <bool Trace>
  int64_t walk_stepwise(const SetupResult& s, int64_t load_cycle, TriangleRecord& record);
  template <class Runs>
  struct RunSink {
    // Rows entered with ZAdder::enter_row_at: the same outputs, fewer register updates per row.
    static constexpr bool kEntersRowsAtOffset = true;
    Pipeline& p;
    TriangleRecord& record;
    Runs& runs;
    int64_t fragment(int x, int y, const ZAdder& adders, int64_t cycle) {
      return p.take_fragment<false>(x, y, adders, cycle, record);
    }
    bool run(int x, int y, int64_t n, ZAdder& adders, int64_t cycle) {
      return runs.run(p.zbuffer_, p.address(x, y), n, adders, cycle, record);
    }
  };

  // The Z adder's stepping interface without registers, for the timing-only walk: it reads only
  // whether the triangle is textured.
  struct NoPlanes {
    bool textured_ = false;
    void load(const SetupResult& s) { textured_ = s.textured; }
    void step_x() {}
    void next_row() {}
    void enter_row_at(int64_t) {}
    bool textured() const { return textured_; }
  };
  template <class Runs>
  struct TimingRunSink {
    static constexpr bool kEntersRowsAtOffset = true;
    Pipeline& p;
    TriangleRecord& record;
    Runs& runs;
    int64_t fragment(int x, int y, const NoPlanes& planes, int64_t cycle) {
      ++record.fragments;
      return p.take(p.address(x, y), planes.textured(), cycle).walker;
    }
    bool run(int x, int y, int64_t n, NoPlanes&, int64_t cycle) {
      return runs.run(p.zbuffer_, p.address(x, y), n, cycle, record);
    }
  };

  // A pixel's word address in the buffers.
  uint32_t address(int x, int y) const { return uint32_t(y) * uint32_t(profile_.width) + uint32_t(x); }

  // The walker's fragment output, wired to the z-buffer's input (through the texture unit when there
  // is one): the cycles in which the walker's candidate and the z-buffer's input take it.
  struct Taken {
    int64_t walker, zbuffer;
  };
  Taken take(uint32_t address, bool textured, int64_t cycle) {
    int64_t walker_taken = cycle, offered = cycle;
    if (profile_.texture_unit) {
      const TextureUnit::Passage passage = texture_unit_.pass(cycle, textured);
      walker_taken = passage.taken, offered = passage.offered;
    }
    const int64_t taken = zbuffer_.take(address, offered);
    if (profile_.texture_unit) texture_unit_.left(taken);
    else walker_taken = taken;
    return {walker_taken, taken};
  }

  // A fragment taken (take()), its depth test and write; with Trace, reported to the sink. Returns
  // the cycle the walker's candidate is taken.
  template <bool Trace>
  int64_t take_fragment(int x, int y, const ZAdder& adders, int64_t cycle, TriangleRecord& record) {
    const uint32_t address = this->address(x, y);
    const bool textured = adders.textured();
    const Taken cycles = take(address, textured, cycle);
    const int64_t taken = cycles.zbuffer;
    if (!Trace && timing_only_) {
      ++record.fragments;
      return cycles.walker;
    }
    const uint32_t z = adders.depth();
    Rgb color = adders.color();
    TextureCoordinate uv;
    if (textured) {
      uv = adders.texture_coordinate();
      const Texture* texture = texture_.texture.get();
      color = modulate(texture ? texture->sample(uv.u, uv.v, texture_.filter, texture_.wrap) : Rgb{}, color);
    }
    const bool pass = zbuffer_.test_and_write(address, z, color);
    ++record.fragments;
    record.depth_pass += pass;
    if (Trace)
      sink_->on_fragment(
          Fragment{record.index, x, y, z, color, pass, taken, textured, uv, zbuffer_.last_read() + profile_.memory_latency});
    return cycles.walker;
  }

  Profile profile_;
  TriangleSetup setup_;
  SetupTiming timing_;
  ScanlineWalker walker_;
  ZAdder adders_;
  ZBuffer zbuffer_;
  TextureUnit texture_unit_;  // used with the profile's texture_unit
  TextureBinding texture_;
  FragmentSink* sink_ = nullptr;
  std::shared_ptr<const WalkRunner> walk_runner_;
  std::vector<TriangleRecord>* log_ = nullptr;
  SetupResult last_setup_;
  WalkerCounters walker_counters_;
  FrameStats stats_;
  int64_t next_index_ = 0;
  int64_t setup_free_ = 0;       // first cycle the setup unit can accept
  int64_t setup_busy_until_ = -1;  // last cycle the setup unit holds a triangle so far
  // Walker load cycles of the last setup_fifo_depth drawn triangles (a ring): a drawn triangle holds
  // a record credit from its accept to its load, and the setup unit accepts only with a free credit.
  std::vector<int64_t> credit_release_;
  size_t credit_slot_ = 0;       // the ring's entry of the next drawn triangle (drawn so far, modulo its size)
  // setup_done to the cycle a record is ready for the walker: 1 (the FIFO's head), or the bias
  // unit's stages with a depth bias (docs/cycle-model.md, "Depth bias").
  int64_t record_ready_after_ = 1;
  int64_t walker_free_ = -1;     // first cycle the walker can load: the last drawn triangle's walker_end
  bool walker_idle_load_ = true;  // the walker loads the current record in a cycle of its own
  int64_t last_busy_ = -1;       // last cycle any unit was busy
  bool timing_only_ = false;
  int64_t external_pass_ = 0, external_fail_ = 0;  // add_depth_results()
};

}  // namespace rastersim
