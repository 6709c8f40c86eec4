// The one place where `--backend` is dispatched. This binary runs the C++ model; the RTL
// (Verilator) and co-simulation backends are wired here when they are built.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "model/pipeline.h"

namespace rastersim {

enum class Backend { Model };

// Every name --backend accepts (known backends, built or not).
const std::vector<std::string>& backend_names();

// Throws InputError "backend X is not built in this binary" for a known backend this binary lacks.
Backend select_backend(const std::string& name);

struct RenderResult {
  FrameStats stats;
  ZBuffer buffers;  // final depth and colour
};

// Called with the number of triangles submitted so far.
using ProgressCallback = std::function<void(size_t done)>;

// Renders the triangles in order (triangle index = position) through the backend. `sink` (may be
// null) receives every fragment in emission order.
RenderResult render_triangles(Backend backend, const Profile& profile, const std::vector<SnappedTriangle>& triangles,
                              FragmentSink* sink, const ProgressCallback& progress);

}  // namespace rastersim
