// `rastersim cosim`: directed and constrained-random frames through the model and the RTL in
// lockstep; the first divergence is reported with a replay command. Frames split deterministically
// into shards (--shard K/N) and the results go to JUnit XML (--junit), so a batch system can farm a
// long regression out and merge it. A functional coverage table says which corners the frames
// reached (--coverage writes it as JSON).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "outputs.h"
#include "profile_options.h"

namespace rastersim {

struct CosimOptions {
  int64_t count = 100;        // random frames (after the directed ones)
  uint64_t seed = 1;          // frame k uses seed + k for its triangles, settings and power-on state
  int triangles = 16;         // triangles per random frame
  bool directed = true;
  bool fixed_settings = false;  // random frames keep the profile's runtime settings
  bool keep_going = false;      // run every frame even after a divergence
  std::string shard = "1/1";    // K/N: this run takes frames k with k mod N = K - 1
  std::string junit_out;        // JUnit XML of the frames run, when not empty
  std::string replay_dir = ".";
  WaveOptions wave;             // the RTL waveform of the last frame run
  int64_t frame = -1;           // run only this frame (>= 0)
  int jobs = 1;                 // frames run in parallel
  int threads = 1;              // 2: each frame's model run on its own thread beside the RTL's (or design's)
  std::string export_dir;       // write the frames as replay files instead of running them
  std::string coverage_out;     // the functional coverage as JSON, when not empty
  bool coverage_gate = true;    // a whole run exits 1 when a reachable coverage bin stays at zero
  std::string compare;            // cycle, stream, triangle or frame; empty: cycle, stream with --dut
  std::string dut;                // a user's design behind the verification interface: file list or folder
  std::string top;                // its top module
  std::vector<std::string> generics;  // -G NAME=value for it
  std::string unit;               // setup, walker or zbuffer: --dut is that unit alone (its unit-level interface)
  std::string tolerance;          // depth=N,color=M in LSBs of the model's words (functional modes)
  ProfileOptions profile;
};

CLI::App* add_cosim_command(CLI::App& app, CosimOptions& options);

// `rastersim junit-merge -o OUT IN...`: the JUnit files of a sharded cosim run as one (every
// shard's testsuite, the totals summed); a frame in two inputs is an error.
struct JunitMergeOptions {
  std::string out;
  std::vector<std::string> inputs;
};
CLI::App* add_junit_merge_command(CLI::App& app, JunitMergeOptions& options);
// 0 when no merged frame failed, 1 otherwise; throws InputError for a file that is not a cosim JUnit file.
int run_junit_merge(const JunitMergeOptions& options);
// 0 when every frame agrees (and, for a whole run, every reachable coverage bin is hit), 1 when one
// diverged or a reachable bin stayed at zero; throws InputError for bad usage.
int run_cosim(const CosimOptions& options);

}  // namespace rastersim
