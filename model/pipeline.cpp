#include "pipeline.h"

#include <algorithm>

namespace rastersim {
namespace {

WalkRunnerChoice registered_walk_runner_choice = nullptr;

}  // namespace

void Pipeline::set_walk_runner_choice(WalkRunnerChoice choice) { registered_walk_runner_choice = choice; }
WalkRunnerChoice Pipeline::walk_runner_choice() { return registered_walk_runner_choice; }

Pipeline::Pipeline(const Profile& profile)
    : profile_(profile),
      setup_(profile),
      timing_(rastersim::setup_timing(profile)),
      walker_(profile, setup_.widths()),
      adders_(setup_.widths(), profile),
      zbuffer_(profile),
      texture_unit_(profile),
      credit_release_(size_t(profile.setup_fifo_depth), -1),
      record_ready_after_(profile.depth_biased() ? DepthOutput::kBiasStages : 1) {
  if (registered_walk_runner_choice) walk_runner_ = registered_walk_runner_choice(*this);
}

void Pipeline::reset() {
  zbuffer_.clear();
  texture_unit_.reset();
  walker_counters_ = {};
  stats_ = {};
  next_index_ = 0;
  setup_free_ = 0;
  walker_free_ = -1;
  std::fill(credit_release_.begin(), credit_release_.end(), -1);
  credit_slot_ = 0;
  setup_busy_until_ = -1;
  last_busy_ = -1;
  external_pass_ = external_fail_ = 0;
}

// One fragment at a time, with Trace each reported to the sink: the specification's walk, which the
// co-simulation compares with the RTL.
template <bool Trace>
struct Pipeline::StepSink {
  Pipeline& p;
  TriangleRecord& record;
  int64_t fragment(int x, int y, const ZAdder& adders, int64_t cycle) {
    return p.take_fragment<Trace>(x, y, adders, cycle, record);
  }
};

template <bool Trace>
int64_t Pipeline::walk_stepwise(const SetupResult& s, int64_t load_cycle, TriangleRecord& record) {
  StepSink<Trace> sink{*this, record};
  return walker_.walk(s, adders_, load_cycle, walker_idle_load_, sink, walker_counters_);
}

void Pipeline::submit(const SnappedTriangle& tri) {
  TriangleRecord record;
  record.index = next_index_++;
  if (walk_runner_ && !sink_) {
    walk_runner_->prefetch(*this, tri);
    walk_runner_->set_up(setup_, tri, last_setup_);
  } else {
    setup_.run(tri, last_setup_);
  }
  const SetupResult& s = last_setup_;
  record.status = s.status;
  // The unit accepts when it is free and one of the setup_fifo_depth record credits is: the credit
  // of the drawn triangle setup_fifo_depth drawn triangles back returns the cycle after its load.
  // The pipelined unit accepts only in the first cycle of a slot (frame cycles kI).
  const int64_t credit_free = credit_release_[credit_slot_] + 1;
  int64_t accept = std::max(setup_free_, credit_free);
  const int64_t interval = timing_.interval;
  // (setup_free_ is then a slot's first cycle: only a later credit needs rounding up.)
  if (interval > 0 && accept != setup_free_) accept = (accept + interval - 1) / interval * interval;
  record.setup_accept = accept;
  stats_.setup.stall += accept - setup_free_;  // a triangle waits, the FIFO is full
  ++stats_.triangles;
  const int drawn_latency = s.textured ? timing_.textured_drawn_latency : timing_.drawn_latency;
  record.setup_decided = accept + timing_.rejected_latency;
  record.setup_done = accept + (s.status == SetupStatus::Drawn ? drawn_latency : timing_.rejected_latency);
  setup_free_ = interval > 0 ? accept + interval : record.setup_done + 1;
  // Busy: cycles in which the unit holds a triangle, [accept, setup_done] of each, counted once.
  stats_.setup.busy += std::max<int64_t>(0, record.setup_done - std::max(accept - 1, setup_busy_until_));
  setup_busy_until_ = std::max(setup_busy_until_, record.setup_done);
  if (s.status != SetupStatus::Drawn) {
    switch (s.status) {
      case SetupStatus::Degenerate: ++stats_.triangles_degenerate; break;
      case SetupStatus::Culled: ++stats_.triangles_culled; break;
      case SetupStatus::Offscreen: ++stats_.triangles_offscreen; break;
      default: ++stats_.triangles_no_centre; break;
    }
    last_busy_ = std::max(last_busy_, record.setup_done);
  } else {
    ++stats_.triangles_drawn;
    // The record goes into the record FIFO (as the walker's entry) and is at its head in the next
    // cycle, or with a depth bias ready once the bias unit's last stage has its bias; the walker
    // takes it once the records before it are taken, as early as in the cycle of the previous
    // triangle's last candidate.
    record.walker_load = std::max(record.setup_done + record_ready_after_, walker_free_);
    walker_idle_load_ = record.walker_load > walker_free_;
    credit_release_[credit_slot_] = record.walker_load;
    credit_slot_ = credit_slot_ + 1 == credit_release_.size() ? 0 : credit_slot_ + 1;
    zbuffer_.begin_triangle(record.walker_load);  // the walker presents fragments after loading
    record.walker_end = sink_          ? walk_stepwise<true>(s, record.walker_load, record)
                        : walk_runner_ ? walk_runner_->walk(*this, s, record.walker_load, record)
                                       : walk_stepwise<false>(s, record.walker_load, record);
    walker_free_ = record.walker_end;
    if (record.fragments > 0) record.last_write = zbuffer_.last_busy_cycle();
    last_busy_ = std::max({last_busy_, record.setup_done, record.walker_end, zbuffer_.last_busy_cycle(),
                           texture_unit_.last_busy_cycle()});
  }
  if (log_) log_->push_back(record);
}

const FrameStats& Pipeline::stats() {
  const ZBufferCounters& z = zbuffer_.counters();
  stats_.candidates = walker_counters_.candidates;
  stats_.depth_pass = z.depth_pass + external_pass_;
  stats_.depth_fail = z.depth_fail + external_fail_;
  stats_.fragments = stats_.depth_pass + stats_.depth_fail;
  stats_.cycles = last_busy_ + 1;
  stats_.walker = {walker_counters_.busy, walker_counters_.stall};
  stats_.z_adder = stats_.walker;  // the adders step in lockstep with the walker
  stats_.zbuffer = {z.busy, z.stall};
  stats_.texture = {texture_unit_.counters().busy, texture_unit_.counters().stall};
  return stats_;
}

}  // namespace rastersim
