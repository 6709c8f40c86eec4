#include "backend.h"

#include <stdexcept>

#include "fast/threaded_render.h"
#include "model/input_error.h"
#ifdef RASTERSIM_HAVE_RTL
#include <iostream>

#include "testbench/modules.h"
#include "testbench/rtl_backend.h"
#endif
#ifdef RASTERSIM_HAVE_SYSTEMC
#include "plugins.h"
#include "testbench/systemc/systemc_backend.h"
#endif

namespace rastersim {

namespace {

#ifdef RASTERSIM_HAVE_RTL
// Progress of a module build, on stderr (stdout may carry a command's output).
void print_progress(const std::string& line) { std::cerr << "rastersim: " << line << std::endl; }

// The library of a module built on demand for the profile (modules.h); a failed build is an error
// of the tools, not of the input.
std::string module_for(modules::Kind kind, const Profile& profile) {
  return modules::module_library(kind, profile, print_progress);
}
#endif

#ifdef RASTERSIM_HAVE_SYSTEMC
// The SystemC library the backend runs: librastersim_systemc.so, loaded the first time the
// backend is used, or a module built for the profile (check_backend_profile).
std::string systemc_library;
const systemc::Api& systemc_backend() {
  return *static_cast<const systemc::Api*>(systemc_api(systemc_library, modules::abi_stamp()));
}
#endif

}  // namespace

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

#ifdef RASTERSIM_HAVE_RTL
std::string design_library(const modules::DutDesign& design) {
  return modules::dut_library(design, print_progress);
}

void ensure_rtl_configuration(const Profile& profile) {
  // No build runs a z-buffer memory stall pattern (rastersim_top's memory has none): configuration_error
  // says so without a module being built first.
  if (validate(profile).empty() && profile.memory_stall_percent == 0 &&
      !rtl::has_configuration(profile))
    rtl::load_module(module_for(modules::Kind::Rtl, profile));
}
#endif

void check_backend_profile(Backend backend, const Profile& profile) {
  if (backend == Backend::Model) return;
#ifdef RASTERSIM_HAVE_SYSTEMC
  if (backend == Backend::Systemc) {
    if (validate(profile).empty() && !systemc_backend().geometry_error(profile).empty())
      systemc_library = module_for(modules::Kind::Systemc, profile);
    const std::string problem = systemc_backend().configuration_error(profile);
    if (!problem.empty()) throw InputError(problem);
    return;
  }
#endif
#ifdef RASTERSIM_HAVE_RTL
  ensure_rtl_configuration(profile);
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
      pipeline.set_texture(options.texture);
      if (!sink && options.threads > 1) {  // the same frame (tests/test_threads.cpp)
        render_threaded(pipeline, triangles, options.threads);
        if (progress) progress(triangles.size());
      } else {
        for (size_t i = 0; i < triangles.size(); ++i) {
          pipeline.submit(triangles[i]);
          if (progress) progress(i + 1);
        }
      }
      const ZBuffer& z = pipeline.zbuffer();
      return RenderResult{pipeline.stats(), FrameBuffers{z.width(), z.height(), z.depth(), z.color()}, false, ""};
    }
#ifdef RASTERSIM_HAVE_RTL
    case Backend::Rtl: {
      rtl::RtlOptions rtl_options;
      rtl_options.seed = options.seed;
      rtl_options.texture = options.texture;
      set_wave_fields(rtl_options, options.wave_files, options.wave);
      const rtl::RtlResult r = rtl::run_rtl(profile, triangles, rtl_options);
      if (!r.finished) throw std::runtime_error("the RTL did not finish: " + r.note);
      if (progress) progress(triangles.size());
      return from_rtl(profile, r, sink);
    }
    case Backend::Cosim: {
      rtl::RtlOptions rtl_options;
      rtl_options.seed = options.seed;
      rtl_options.texture = options.texture;
      set_wave_fields(rtl_options, options.wave_files, options.wave);
      rtl_options.model_beside = options.threads > 1;
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
      systemc_options.texture = options.texture;
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
