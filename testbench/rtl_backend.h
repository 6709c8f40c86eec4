// The RTL backend: the synthesizable pipeline (rtl/) verilated at build time for a few profiles
// (and, through load_module, for any other profile on demand: modules.h), driven cycle by cycle, with its transactions observed at the unit boundaries and turned into the
// same records the model produces (model/pipeline.h), so that the two compare field by field.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "model/pipeline.h"
#include "model/profile.h"
#include "model/texture_unit.h"
#include "model/triangle.h"

namespace rastersim::rtl {

struct RtlOptions {
  uint64_t seed = 1;       // random power-on state (registers and memories), printed on failure
  // A waveform of the frame when not empty: FST, or VCD when wave_vcd. With wave_from / wave_to
  // >= 0 only the frame cycles in [wave_from, wave_to] are dumped (otherwise from the start of
  // reset, memory clear included, to the end). One time unit per half clock from the start of
  // reset; the debug monitor's frame_cycle signal gives the frame cycle (docs/debugging.md).
  std::string wave_path;
  bool wave_vcd = false;
  std::string wave_fst_scratch;  // with wave_vcd: the FST written first (default wave_path + ".fst-part")
  int64_t wave_from = -1, wave_to = -1;
  // A GTKWave save file for the waveform when not empty, naming wave_name as the file to open; it
  // opens on the window (markers window_start and window_end) and, with wave_marker >= 0, puts the
  // primary marker and a marker "mismatch" on that frame cycle's rising edge.
  std::string gtkwave_save_path, wave_name;
  int64_t wave_marker = -1;
  int64_t max_cycles = 0;  // 0: a generous bound from the triangles' bounding boxes
  // Read the final memories through the RTL's synchronous read-back port (W H cycles) instead of
  // directly from the verilated memory arrays; both give the same words (tests/rtl checks it).
  bool readback_through_port = false;
  // What the texture unit samples (profiles with texture_unit): loaded into the texture memory
  // before the frame.
  TextureBinding texture;
  // cosim: the model's run of the frame on a thread of its own, beside the RTL's (the same report).
  bool model_beside = false;
};

// Everything a backend produces for one frame. Fragment.pass and TriangleRecord fields as in the
// model; depth / color are the final memories, row-major, color 0x00RRGGBB.
struct RtlResult {
  std::vector<Fragment> fragments;
  std::vector<TriangleRecord> triangles;
  std::vector<uint32_t> depth, color;
  FrameStats stats;
  // Per triangle, the setup unit's output record as the walker took it (drawn triangles only;
  // front_facing, area2 and the owns_samples flags are not part of the record and stay default).
  std::vector<SetupResult> setups;
  bool finished = true;  // false: the RTL did not finish within max_cycles
  std::string note;      // why it did not finish
  int64_t assertion_cycle = -1;  // the cycle an assertion of the RTL failed in (it stopped there)
  // Only what the verification interface carries (a design behind cosim --dut): each triangle's
  // index, status and setup_decided, each fragment's fields and `tested` (its retirement), the final
  // buffers and stats.cycles (frame_done); cycles count from the first command handshake.
  bool interface_only = false;
  // Of such a design: the harness cycle of the first handshake (cycles after reset). A waveform's time
  // of cycle c (from the first handshake) is 2 (first_handshake + c) + 8 at its clock's low half and
  // one more at its rising edge (4 reset cycles come first, two time steps a cycle).
  int64_t first_handshake = 0;
};

// The profiles verilated into this build and loaded from modules, as "name: WxH subpixel_bits .."
// lines.
std::vector<std::string> built_configurations();
// True when a built or loaded configuration runs the profile's geometry, setup_interval and
// memory_latency (configuration_error() may still refuse it for other reasons).
bool has_configuration(const Profile& profile);
// Adds the configuration of a module built on demand (modules.h, module_library) to those
// run_rtl chooses from. Throws std::runtime_error when the library is not a module of this program.
void load_module(const std::string& library_path);
// The largest memory_latency the RTL built for `profile`'s geometry takes; 0 when none is built.
int built_max_memory_latency(const Profile& profile);
// Empty when the RTL can run `profile`; otherwise a sentence saying why and how to build it.
std::string configuration_error(const Profile& profile);

// Runs the triangles through the RTL. Throws std::invalid_argument with configuration_error()
// when the profile is not built. The triangles must be checked (check_screen_triangle) and snapped.
RtlResult run_rtl(const Profile& profile, const std::vector<SnappedTriangle>& triangles,
                  const RtlOptions& options = {});

// The same through the model (the specification), sampling `texture` with the profile's texture unit.
RtlResult run_model(const Profile& profile, const std::vector<SnappedTriangle>& triangles,
                    const TextureBinding& texture = {});

// The first divergence between the model (expected) and the RTL (actual), earliest triangle first.
struct Divergence {
  bool found = false;
  int64_t triangle = -1;  // -1: a frame-level field (memories, stats)
  std::string unit;       // triangle_setup, scanline_walker, z_adder, texture_unit, zbuffer, pipeline
  std::string field;
  std::string expected, actual;
  int64_t cycle = -1;     // the cycle of the event in the model's timeline, -1 when not an event
  std::string sentence;   // all of the above as one sentence
};
Divergence compare(const RtlResult& model, const RtlResult& rtl);

// Writes a replay of the case: <prefix>.tri (%.17g coordinates that snap back to exactly these
// vertices, nine colour values) and <prefix>.json (the profile). Returns the replay command, which
// carries the power-on seed.
std::string write_replay(const std::string& prefix, const Profile& profile,
                         const std::vector<SnappedTriangle>& triangles, uint64_t seed);

// The frame cycles a divergence's waveform window covers: 32 cycles either side of its cycle (of
// the frame's last cycle for a frame-level field), clipped to the frame.
std::pair<int64_t, int64_t> divergence_window(const Divergence& divergence, const RtlResult& model);

// Model and RTL on one frame, compared. On a divergence, when replay_prefix is not empty, writes
// the replay files there and puts the replay command in the report.
struct CosimReport {
  bool passed = true;
  Divergence divergence;
  std::string replay_command;
  // On a divergence with a replay prefix: <prefix>.fst and <prefix>.gtkw, the frame cycles
  // [wave_from, wave_to] around the divergence (docs/debugging.md).
  std::string waveform, gtkwave_save;
  int64_t wave_from = -1, wave_to = -1;
  RtlResult model, rtl;
  std::string message() const;  // one paragraph: the sentence, the seed hint and the replay command
};
CosimReport cosim(const Profile& profile, const std::vector<SnappedTriangle>& triangles,
                  const RtlOptions& options = {}, const std::string& replay_prefix = "");

}  // namespace rastersim::rtl
