// A harness's view of the ports of rastersim_core (and of rastersim_top, which has the same
// command and trace ports): the words it drives on the command port, and the trace ports sampled
// once per cycle before the rising edge, turned into the model's records (fragments, triangle
// records, frame counters). Shared by the plain verilated harness (rtl_harness.h) and the SystemC
// system (testbench/systemc/), so both drive and observe the RTL the same way. Header-only; the
// port accessors take a verilated C++ model (plain members) or a SystemC module (sc_in / sc_out).
#pragma once

#include <algorithm>
#include <cstdint>
#include <deque>
#include <functional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "testbench/rtl_backend.h"
#include "testbench/setup_record.h"

namespace rastersim::rtl {

inline uint32_t mask_bits(int64_t value, int bits) {
  return uint32_t(uint64_t(value) & ((uint64_t(1) << bits) - 1));
}

// Drives one triangle on the command port: coordinates in two's complement of COORD_BITS.
template <class Ports>
void drive_command(Ports& top, const SnappedTriangle& t, int coord_bits) {
  top.cmd_x0 = mask_bits(t.v[0].x, coord_bits), top.cmd_y0 = mask_bits(t.v[0].y, coord_bits);
  top.cmd_x1 = mask_bits(t.v[1].x, coord_bits), top.cmd_y1 = mask_bits(t.v[1].y, coord_bits);
  top.cmd_x2 = mask_bits(t.v[2].x, coord_bits), top.cmd_y2 = mask_bits(t.v[2].y, coord_bits);
  top.cmd_z0 = t.v[0].z, top.cmd_z1 = t.v[1].z, top.cmd_z2 = t.v[2].z;
  top.cmd_rgb0 = rgb_word(t.v[0].color), top.cmd_rgb1 = rgb_word(t.v[1].color), top.cmd_rgb2 = rgb_word(t.v[2].color);
}

// Drives a triangle's texture coordinates (cmd_textured, cmd_texture0..2: S, T, Q at bits 0, 50,
// 100 of each vertex's word, two's complement of rastersim_pkg::TEXTURE_VERTEX_BITS) on a verilated top's
// wide ports (VlWide words of 32 bits).
template <class Ports>
void drive_texture_command(Ports& top, const SnappedTriangle& t) {
  top.cmd_textured = t.textured;
  auto put = [](auto& word, const SnappedVertex& v) {
    for (int i = 0; i < 5; ++i) word[i] = 0;
    const int64_t values[3] = {v.s, v.t, v.q};
    for (int c = 0; c < 3; ++c)
      for (int bit = 0; bit < kTextureVertexBits; ++bit)
        if ((uint64_t(values[c]) >> bit) & 1) word[(c * kTextureVertexBits + bit) / 32] |= 1u << ((c * kTextureVertexBits + bit) % 32);
  };
  put(top.cmd_texture0, t.v[0]);
  put(top.cmd_texture1, t.v[1]);
  put(top.cmd_texture2, t.v[2]);
}

// A bound on the cycles a correct RTL can take: per triangle the setup, plus every candidate of
// its screen-clipped bounding box and its rows, each possibly stalled by the memory latency, and
// by the memory's back-pressure (at most 90 % of the cycles, so ten times as long, twice over).
inline int64_t default_cycle_bound(const Profile& p, const std::vector<SnappedTriangle>& tris, int setup_cycles) {
  int64_t bound = 16;
  for (const SnappedTriangle& t : tris) {
    int64_t x_lo = t.v[0].x, x_hi = x_lo, y_lo = t.v[0].y, y_hi = y_lo;
    for (const SnappedVertex& v : t.v) {
      x_lo = std::min<int64_t>(x_lo, v.x), x_hi = std::max<int64_t>(x_hi, v.x);
      y_lo = std::min<int64_t>(y_lo, v.y), y_hi = std::max<int64_t>(y_hi, v.y);
    }
    const int64_t columns = std::min<int64_t>(p.width, ((x_hi - x_lo) >> p.subpixel_bits) + 2);
    const int64_t rows = std::min<int64_t>(p.height, ((y_hi - y_lo) >> p.subpixel_bits) + 2);
    bound += setup_cycles + 4 + (columns + 1) * rows * (p.memory_latency + 2);
  }
  if (p.texture_unit) bound += 2 * (p.texture_latency + 40);
  return p.memory_stall_percent > 0 ? 20 * bound : bound;
}

// One cycle of trace ports (names as in rtl/rastersim_core.sv without the trace_ prefix).
struct TraceSample {
  bool cmd_valid = false, cmd_ready = false;
  bool setup_decided = false;
  int setup_status = 0;
  bool setup_busy = false, setup_stall = false, setup_done = false;
  bool walker_load = false, walker_busy = false, walker_candidate = false, walker_last = false;
  bool walker_frag_valid = false, walker_frag_ready = false;  // the walker's fragment handshake
  bool texture_busy = false, texture_stall = false;
  bool frag_valid = false, frag_ready = false;  // the z-buffer's
  int frag_x = 0, frag_y = 0;
  uint32_t frag_z = 0, frag_rgb = 0;
  bool result_valid = false, result_pass = false, zbuffer_busy = false, zbuffer_stall = false;

  bool busy() const { return setup_busy || walker_busy || texture_busy || zbuffer_busy; }
};

// Reads the ports of a verilated top: a C++ model (plain members) or a SystemC module (sc_in /
// sc_out, read through their conversion to the value type).
template <class Ports>
TraceSample sample_trace(const Ports& top) {
  auto bit = [](const auto& port) { return bool(port); };
  auto word = [](const auto& port) { return uint32_t(port); };
  TraceSample s;
  s.cmd_valid = bit(top.cmd_valid);
  s.cmd_ready = bit(top.cmd_ready);
  s.setup_decided = bit(top.trace_setup_decided);
  s.setup_status = int(word(top.trace_setup_status));
  s.setup_busy = bit(top.trace_setup_busy);
  s.setup_stall = bit(top.trace_setup_stall);
  s.setup_done = bit(top.trace_setup_done);
  s.walker_load = bit(top.trace_walker_load);
  s.walker_busy = bit(top.trace_walker_busy);
  s.walker_candidate = bit(top.trace_walker_candidate);
  s.walker_last = bit(top.trace_walker_last);
  s.walker_frag_valid = bit(top.trace_walker_frag_valid);
  s.walker_frag_ready = bit(top.trace_walker_frag_ready);
  s.texture_busy = bit(top.trace_texture_busy);
  s.texture_stall = bit(top.trace_texture_stall);
  s.frag_valid = bit(top.trace_frag_valid);
  s.frag_ready = bit(top.trace_frag_ready);
  s.frag_x = int(word(top.trace_frag_x));
  s.frag_y = int(word(top.trace_frag_y));
  s.frag_z = word(top.trace_frag_z);
  s.frag_rgb = word(top.trace_frag_rgb);
  s.result_valid = bit(top.trace_result_valid);
  s.result_pass = bit(top.trace_result_pass);
  s.zbuffer_busy = bit(top.trace_zbuffer_busy);
  s.zbuffer_stall = bit(top.trace_zbuffer_stall);
  return s;
}

// Bits [lo, lo + width) of a verilated signal, sign-extended when `is_signed`.
inline int64_t field_bits(uint64_t value, int lo, int width, bool is_signed) {
  uint64_t v = (value >> lo) & (width >= 64 ? ~uint64_t(0) : (uint64_t(1) << width) - 1);
  if (is_signed && width < 64 && (v >> (width - 1)) & 1) v |= ~uint64_t(0) << width;
  return int64_t(v);
}
template <class Wide, class = decltype(std::declval<const Wide&>()[0])>
int64_t field_bits(const Wide& value, int lo, int width, bool is_signed) {
  uint64_t v = 0;
  for (int i = 0; i < width; ++i) {
    const int bit = lo + i;
    v |= uint64_t((value[bit / 32] >> (bit % 32)) & 1u) << i;
  }
  return field_bits(v, 0, width, is_signed);
}

// Reads field `f` of the setup record from its rec_* wire of rastersim_core: bound to the wire's
// member once, so that a record is read without looking its wires up by name.
template <class Core>
std::function<int64_t(const Core&)> record_field_reader(const SetupRecordField& f) {
  auto bound = [&f](auto member) -> std::function<int64_t(const Core&)> {
    return [member, lo = f.wire_lo < 0 ? 0 : f.wire_lo, bits = f.bits, is_signed = f.is_signed](const Core& t) {
      const auto& value = t.*member;
      if constexpr (std::is_integral_v<std::decay_t<decltype(value)>>) return field_bits(uint64_t(value), lo, bits, is_signed);
      else return field_bits(value, lo, bits, is_signed);
    };
  };
  const std::string& name = f.wire;
  if (name == "rec_x0") return bound(&Core::rec_x0);
  if (name == "rec_x1") return bound(&Core::rec_x1);
  if (name == "rec_y0") return bound(&Core::rec_y0);
  if (name == "rec_y1") return bound(&Core::rec_y1);
  if (name == "rec_edge_start") return bound(&Core::rec_edge_start);
  if (name == "rec_edge_step_x") return bound(&Core::rec_edge_step_x);
  if (name == "rec_edge_step_y") return bound(&Core::rec_edge_step_y);
  if (name == "rec_span_quot") return bound(&Core::rec_span_quot);
  if (name == "rec_span_rem") return bound(&Core::rec_span_rem);
  if (name == "rec_span_step_quot") return bound(&Core::rec_span_step_quot);
  if (name == "rec_span_step_rem") return bound(&Core::rec_span_step_rem);
  if (name == "rec_depth_start") return bound(&Core::rec_depth_start);
  if (name == "rec_depth_step_x") return bound(&Core::rec_depth_step_x);
  if (name == "rec_depth_step_y") return bound(&Core::rec_depth_step_y);
  if (name == "rec_color_start") return bound(&Core::rec_color_start);
  if (name == "rec_color_step_x") return bound(&Core::rec_color_step_x);
  if (name == "rec_color_step_y") return bound(&Core::rec_color_step_y);
  if (name == "rec_flat_rgb") return bound(&Core::rec_flat_rgb);
  if (name == "rec_left_start") return bound(&Core::rec_left_start);
  if (name == "rec_left_step") return bound(&Core::rec_left_step);
  throw std::logic_error("rastersim_core has no record wire " + name);
}

// The setup record on the record wires of rastersim_core (rec_*, public_flat_rd), field by field
// as setup_record.h lists them; Core is the verilated class of rastersim_core, which publishes
// the profile it was built for.
template <class Core>
SetupResult read_setup_record(const Core& t, bool gouraud) {
  using Reader = std::pair<const SetupRecordField*, std::function<int64_t(const Core&)>>;
  static const Widths widths =
      derive_widths(int(Core::P_WIDTH), int(Core::P_HEIGHT), int(Core::P_SUBPIXEL_BITS),
                    depth_plane_bits(int(Core::P_Z_BITS), int(Core::P_DEPTH_EXPONENT_BITS)), int(Core::P_Z_GUARD_BITS));
  static const std::vector<SetupRecordField> all = setup_record_fields(widths, true);
  static const std::vector<SetupRecordField> flat = setup_record_fields(widths, false);
  auto readers = [](const std::vector<SetupRecordField>& fields) {
    std::vector<Reader> r;
    for (const SetupRecordField& f : fields) r.emplace_back(&f, record_field_reader<Core>(f));
    return r;
  };
  static const std::vector<Reader> all_readers = readers(all), flat_readers = readers(flat);
  SetupResult r;
  r.status = SetupStatus::Drawn;
  for (const auto& [field, read] : gouraud ? all_readers : flat_readers) field->set(r, read(t));
  // The texture record (setup_record.h) in a build with the texture unit.
  if constexpr (int(Core::P_TEXTURE) != 0) unpack_texture_record(t.rec_texture.data(), widths, r);
  return r;
}

// Builds an RtlResult from the samples of one frame, cycle 0 being the first cycle with
// frame_ready high.
class TraceObserver {
 public:
  TraceObserver(RtlResult& out, size_t triangles) : out_(out), total_(triangles) {
    out_.triangles.reserve(triangles);
    out_.setups.resize(triangles);
  }

  // The triangle the command port must present next (== triangles when all were taken).
  size_t next_triangle() const { return next_; }

  // Observes cycle `cycle`. `read_record()` returns the setup record on the rec_* wires (called in
  // the cycle the record is in the setup unit's output register, setup_done). Returns false when the RTL broke the protocol (out.note says how).
  template <class ReadRecord>
  bool observe(int64_t cycle, const TraceSample& s, ReadRecord&& read_record) {
    FrameStats& stats = out_.stats;
    const bool submitting = next_ < total_;
    // Triangles pass each stage in order: accept, decision, record in the output register (drawn
    // ones), walker load.
    if (s.cmd_valid && s.cmd_ready) {
      TriangleRecord r;
      r.index = int64_t(next_);
      r.setup_accept = cycle;
      out_.triangles.push_back(r);
      undecided_.push_back(int64_t(next_));
      ++next_;
      ++stats.triangles;
    }
    if (s.setup_decided && !undecided_.empty()) {
      TriangleRecord& r = out_.triangles[size_t(undecided_.front())];
      r.status = SetupStatus(s.setup_status);
      r.setup_decided = cycle;
      switch (r.status) {
        case SetupStatus::Drawn: ++stats.triangles_drawn, in_setup_.push_back(r.index); break;
        case SetupStatus::Degenerate: ++stats.triangles_degenerate, r.setup_done = cycle; break;
        case SetupStatus::Culled: ++stats.triangles_culled, r.setup_done = cycle; break;
        case SetupStatus::Offscreen: ++stats.triangles_offscreen, r.setup_done = cycle; break;
        case SetupStatus::NoCentre: ++stats.triangles_no_centre, r.setup_done = cycle; break;
      }
      undecided_.pop_front();
    }
    if (s.setup_done && !in_setup_.empty()) {
      out_.triangles[size_t(in_setup_.front())].setup_done = cycle;
      out_.setups[size_t(in_setup_.front())] = read_record();
      waiting_.push_back(in_setup_.front());
      in_setup_.pop_front();
    }
    // A fragment belongs to the triangle in the walker when the walker hands it on; the texture unit
    // (when there is one) keeps the fragments in order.
    if (s.walker_frag_valid && s.walker_frag_ready) {
      passing_.push_back(in_walker_);
      if (in_walker_ >= 0) ++out_.triangles[size_t(in_walker_)].fragments;
    }
    if (s.frag_valid && s.frag_ready) {
      Fragment f;
      f.tri = passing_.empty() ? -1 : passing_.front();
      if (!passing_.empty()) passing_.pop_front();
      f.x = s.frag_x;
      f.y = s.frag_y;
      f.z = s.frag_z;
      f.color = Rgb{uint8_t(s.frag_rgb >> 16), uint8_t(s.frag_rgb >> 8), uint8_t(s.frag_rgb)};
      f.pass = false;
      f.cycle = cycle;
      in_flight_.push_back(out_.fragments.size());
      out_.fragments.push_back(f);
    }
    if (s.result_valid) {
      if (in_flight_.empty()) {
        out_.finished = false;
        out_.note = "the z-buffer produced a depth-test result in cycle " + std::to_string(cycle) +
                    " with no fragment in flight";
        return false;
      }
      Fragment& f = out_.fragments[in_flight_.front()];
      in_flight_.pop_front();
      f.pass = s.result_pass;
      f.tested = cycle;
      if (f.tri >= 0) {
        TriangleRecord& r = out_.triangles[size_t(f.tri)];
        r.depth_pass += f.pass;
        r.last_write = cycle;
      }
      ++(f.pass ? stats.depth_pass : stats.depth_fail);
    }
    if (s.walker_last && in_walker_ >= 0) out_.triangles[size_t(in_walker_)].walker_end = cycle;
    // After the fragment and walker_end: a load can be in the cycle of the previous triangle's last
    // candidate.
    if (s.walker_load && !waiting_.empty()) {
      in_walker_ = waiting_.front();
      waiting_.pop_front();
      out_.triangles[size_t(in_walker_)].walker_load = cycle;
    }
    if (s.walker_candidate) ++stats.candidates;
    stats.setup.busy += s.setup_busy;
    stats.setup.stall += s.setup_stall;
    stats.walker.busy += s.walker_busy;
    stats.walker.stall += s.walker_frag_valid && !s.walker_frag_ready;
    stats.texture.busy += s.texture_busy;
    stats.texture.stall += s.texture_stall;
    stats.zbuffer.busy += s.zbuffer_busy;
    stats.zbuffer.stall += s.zbuffer_stall;
    if (s.busy()) last_busy_ = cycle;
    // A fragment can wait on the memory's back-pressure longer than L cycles with no unit busy, and a
    // record on its depth bias (docs/cycle-model.md, "Depth bias") with none busy either.
    done_ = !submitting && !s.busy() && !s.frag_valid && !s.walker_frag_valid && in_flight_.empty() &&
            waiting_.empty();
    return true;
  }

  // Every triangle taken, the pipeline idle, no record or fragment waiting and none in flight after
  // the last observed cycle.
  bool done() const { return done_; }

  // The frame counters that follow from the observed ones.
  void finish() {
    FrameStats& stats = out_.stats;
    stats.fragments = stats.depth_pass + stats.depth_fail;
    stats.cycles = last_busy_ + 1;
    stats.z_adder = stats.walker;
  }

 private:
  RtlResult& out_;
  size_t total_;
  size_t next_ = 0;            // next triangle to submit
  std::deque<int64_t> undecided_;  // accepted, not yet decided
  std::deque<int64_t> in_setup_;   // drawn, record not yet in the output register
  std::deque<int64_t> waiting_;    // record made, not yet loaded by the walker
  int64_t in_walker_ = -1;     // triangle the walker walks
  std::deque<int64_t> passing_;   // per fragment the walker handed on and the z-buffer did not take: its triangle
  std::deque<size_t> in_flight_;  // fragments taken by the z-buffer, awaiting their result
  int64_t last_busy_ = -1;
  bool done_ = false;
};

}  // namespace rastersim::rtl
