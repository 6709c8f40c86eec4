#include "backend.h"

#include <stdexcept>

#include "model/input_error.h"
#ifdef RASTERSIM_HAVE_RTL
#include "testbench/rtl_backend.h"
#endif
#ifdef RASTERSIM_HAVE_SYSTEMC
#include "plugins.h"
#include "testbench/systemc/systemc_backend.h"
#endif

namespace rastersim {

#ifdef RASTERSIM_HAVE_SYSTEMC
namespace {
// librastersim_systemc.so, loaded the first time the SystemC backend is used.
const systemc::Api& systemc_backend() { return *static_cast<const systemc::Api*>(systemc_api()); }
}  // namespace
#endif

const std::vector<std::string>& backend_names() {
  static const std::vector<std::string> names = {"model", "rtl", "cosim", "systemc"};
  return names;
}

Backend select_backend(const std::string& name) {
  if (name == "model") return Backend::Model;
#ifdef RASTERSIM_HAVE_RTL
  if (name == "rtl") return Backend::Rtl;
  if (name == "cosim") return Backend::Cosim;
#endif
#ifdef RASTERSIM_HAVE_SYSTEMC
  if (name == "systemc") return Backend::Systemc;
#endif
  for (const std::string& known : backend_names())
    if (name == known) throw InputError("backend " + name + " is not built in this binary");
  throw InputError("unknown backend '" + name + "'");
}

void check_backend_profile(Backend backend, const Profile& profile) {
  if (backend == Backend::Model) return;
#ifdef RASTERSIM_HAVE_SYSTEMC
  if (backend == Backend::Systemc) {
    const std::string problem = systemc_backend().configuration_error(profile);
    if (!problem.empty()) throw InputError(problem);
    return;
  }
#endif
#ifdef RASTERSIM_HAVE_RTL
  const std::string problem = rtl::configuration_error(profile);
  if (!problem.empty()) throw InputError(problem);
#else
  (void)profile;
#endif
}

namespace {

#ifdef RASTERSIM_HAVE_RTL
RenderResult from_rtl(const Profile& profile, const rtl::RtlResult& r, FragmentSink* sink) {
  if (sink)
    for (const Fragment& f : r.fragments) sink->on_fragment(f);
  return RenderResult{r.stats, FrameBuffers{profile.width, profile.height, r.depth, r.color}, false, ""};
}
#endif


}  // namespace

RenderResult render_triangles(Backend backend, const Profile& profile, const std::vector<SnappedTriangle>& triangles,
                              FragmentSink* sink, const ProgressCallback& progress, const BackendOptions& options) {
  switch (backend) {
    case Backend::Model: {
      Pipeline pipeline(profile);
      pipeline.set_fragment_sink(sink);
      for (size_t i = 0; i < triangles.size(); ++i) {
        pipeline.submit(triangles[i]);
        if (progress) progress(i + 1);
      }
      const ZBuffer& z = pipeline.zbuffer();
      return RenderResult{pipeline.stats(), FrameBuffers{z.width(), z.height(), z.depth(), z.color()}, false, ""};
    }
#ifdef RASTERSIM_HAVE_RTL
    case Backend::Rtl: {
      rtl::RtlOptions rtl_options;
      rtl_options.seed = options.seed;
      set_wave_fields(rtl_options, options.wave_files, options.wave);
      const rtl::RtlResult r = rtl::run_rtl(profile, triangles, rtl_options);
      if (!r.finished) throw std::runtime_error("the RTL did not finish: " + r.note);
      if (progress) progress(triangles.size());
      return from_rtl(profile, r, sink);
    }
    case Backend::Cosim: {
      rtl::RtlOptions rtl_options;
      rtl_options.seed = options.seed;
      set_wave_fields(rtl_options, options.wave_files, options.wave);
      const rtl::CosimReport report = rtl::cosim(profile, triangles, rtl_options, options.replay_prefix);
      if (progress) progress(triangles.size());
      RenderResult result = from_rtl(profile, report.model, sink);
      result.check_failed = !report.passed;
      result.report = report.passed ? "" : report.message();
      return result;
    }
#ifdef RASTERSIM_HAVE_SYSTEMC
    case Backend::Systemc: {
      systemc::SystemcOptions systemc_options;
      systemc_options.seed = options.seed;
      const rtl::RtlResult r = systemc_backend().run_systemc(profile, triangles, systemc_options);
      if (!r.finished) throw std::runtime_error("the SystemC system did not finish: " + r.note);
      if (progress) progress(triangles.size());
      return from_rtl(profile, r, sink);
    }
#endif
#endif
    default:  // a backend this binary lacks: select_backend() never returns it
      break;
  }
  (void)options;
  throw std::logic_error("unhandled backend");
}

}  // namespace rastersim
