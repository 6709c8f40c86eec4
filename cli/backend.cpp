#include "backend.h"

#include "model/input_error.h"

namespace rastersim {

const std::vector<std::string>& backend_names() {
  static const std::vector<std::string> names = {"model", "rtl", "cosim", "systemc"};
  return names;
}

Backend select_backend(const std::string& name) {
  if (name == "model") return Backend::Model;
  // BACKEND DISPATCH: rtl, cosim and systemc are added here when their libraries are linked in.
  for (const std::string& known : backend_names())
    if (name == known) throw InputError("backend " + name + " is not built in this binary");
  throw InputError("unknown backend '" + name + "'");
}

RenderResult render_triangles(Backend backend, const Profile& profile, const std::vector<SnappedTriangle>& triangles,
                              FragmentSink* sink, const ProgressCallback& progress) {
  switch (backend) {
    case Backend::Model: {
      Pipeline pipeline(profile);
      pipeline.set_fragment_sink(sink);
      for (size_t i = 0; i < triangles.size(); ++i) {
        pipeline.submit(triangles[i]);
        if (progress) progress(i + 1);
      }
      return RenderResult{pipeline.stats(), pipeline.zbuffer()};
    }
  }
  throw std::logic_error("unhandled backend");
}

}  // namespace rastersim
