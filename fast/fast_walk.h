// The untraced walk's fast path: without a fragment sink the pipeline takes whole runs of fragments
// at once once no hazard can stall them (fast/zbuffer_runs.h), through the run kernels
// (fast/run_kernels.h), and with the AVX-512 kernel the whole walk is compiled for AVX-512 with the
// kernel inlined. A WalkRunner (model/pipeline.h) beside the model: the same fragments, buffers,
// counters and cycles as the specification's walk, which tests/test_fast_path.cpp checks.
// A program selects it for every Pipeline it makes with use_fast_walk() (rastersim's main does).
#pragma once

#include <memory>

// Relative, as in model/: installed, these headers are reached as <rastersim/fast/...>.
#include "../model/pipeline.h"

namespace rastersim {

// The fast walk for `p` with the run kernel selected now (selected_run_kernel_version), or nullptr
// where it does not apply: with a texture unit, a floating-point depth word or a depth bias.
std::shared_ptr<const WalkRunner> fast_walk_runner(const Pipeline& p);

// Every Pipeline constructed from now on takes fast_walk_runner's walk where it applies. Call it
// once, before pipelines are made (the choice is a process-wide setting, not synchronized).
void use_fast_walk();

}  // namespace rastersim
