// The one place where `--backend` is dispatched: the C++ model, the verilated RTL, or both in
// lockstep (cosim), when the RTL library is built in (RASTERSIM_HAVE_RTL), and the SystemC system
// model (RASTERSIM_HAVE_SYSTEMC: the verilated core, command FIFO and z-buffer memory model).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "model/pipeline.h"
#include "outputs.h"
#ifdef RASTERSIM_HAVE_RTL
#include "testbench/modules.h"
#endif

namespace rastersim {

enum class Backend { Model, Rtl, Cosim, Systemc };

// Every name --backend accepts (known backends, built or not).
const std::vector<std::string>& backend_names();

// Throws InputError "backend X is not built in this binary" for a known backend this binary lacks.
Backend select_backend(const std::string& name);

// Throws InputError (exit 2) when the backend cannot run this profile. A valid profile that no
// verilated configuration of the build runs is verilated on demand first (testbench/modules.h),
// with progress on stderr.
void check_backend_profile(Backend backend, const Profile& profile);

#ifdef RASTERSIM_HAVE_RTL
// The RTL backend's part of check_backend_profile: loads (building it first when the cache lacks
// it) a module for a valid profile no built configuration runs.
void ensure_rtl_configuration(const Profile& profile);
// The library of a user's design behind the verification interface, verilated on demand with
// progress on stderr (testbench/dut_backend.h).
std::string design_library(const modules::DutDesign& design);
#endif

struct BackendOptions {
  uint64_t seed = 1;         // RTL random power-on state (rtl, cosim; systemc: the process's first frame)
  // RTL waveform (rtl, cosim), when wave_files.wave_temp is not empty.
  WaveFiles wave_files;
  WaveOptions wave;
  std::string replay_prefix; // cosim: where a divergence's replay files go
  TextureBinding texture;    // model: what the texture unit samples
  int threads = 1;           // model without a fragment sink: threads of the render (fast/threaded_render.h);
                             // cosim: 2 or more runs the model beside the RTL
};

struct RenderResult {
  FrameStats stats;
  FrameBuffers buffers;  // final depth and colour
  bool check_failed = false;  // cosim: model and RTL diverged (exit 1)
  std::string report;         // cosim: the first divergence and its replay command
};

// Called with the number of triangles submitted so far.
using ProgressCallback = std::function<void(size_t done)>;

// Renders the triangles in order (triangle index = position) through the backend. `sink` (may be
// null) receives every fragment in emission order.
RenderResult render_triangles(Backend backend, const Profile& profile, const std::vector<SnappedTriangle>& triangles,
                              FragmentSink* sink, const ProgressCallback& progress, const BackendOptions& options = {});

}  // namespace rastersim
