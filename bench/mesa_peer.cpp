// Mesa as a speed and coverage peer of the model (docs/performance.md). Renders the same snapped
// triangles as `rastersim bench` (same options) through OSMesa (llvmpipe or softpipe) with the depth
// test on (GL_LESS, depth writes, Gouraud colour), and the model untraced in the same process, the
// repetitions of the two interleaved so that a shared machine's load falls on both alike. Reports:
//  - fragments: covered pixels that entered the depth test; Mesa's counted by an occlusion query in
//    an untimed pass with the depth test off (every covered pixel then passes);
//  - time: Mesa's glDrawArrays + glFinish over the whole list (vertices already in a buffer object,
//    buffers cleared before the clock starts); the model's render of the list; best of --repeat;
//  - coverage against the model: the pixels whose count of covering triangles differs (stencil
//    GL_INCR_WRAP in Mesa, modulo 256 on both sides);
//  - that the model's timed (untraced) render equals a traced one in every counter and buffer word.
// Vertices go to Mesa exactly as snapped: X / 2^S pixels, y down fed unflipped (Mesa keeps left
// edges and, in its y-up window space, edges with the triangle above them: the top-left rule of
// y-down screens). Mesa snaps to 8 subpixel bits, so S <= 8 reaches it unchanged.
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>

#include <chrono>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "bench_command.h"
#include "builtin_scenes.h"
#include "inputs.h"
#include "model/input_error.h"
#include "model/pipeline.h"
#include "profile_options.h"
#include "fast/fast_walk.h"

namespace rastersim {
namespace {

struct PeerOptions {
  BenchInput what;
  std::string driver = "llvmpipe";
  int repeat = 3;
  int show_differences = 0;  // print the first this many differing pixels
  int threads = 1;           // the model's render threads, and llvmpipe's (LP_NUM_THREADS) unless set
  ProfileOptions profile;
};

// Counts, per pixel, the triangles covering it (modulo 256, as Mesa's 8-bit stencil wraps).
struct CoverageCounter : FragmentSink {
  std::vector<uint8_t> count;
  int width = 0;
  void on_fragment(const Fragment& f) override { ++count[size_t(f.y) * size_t(width) + size_t(f.x)]; }
};

struct Vertex {
  float x, y, z;
  uint8_t r, g, b, a;
};

std::vector<Vertex> gl_vertices(const std::vector<SnappedTriangle>& tris, const Profile& p) {
  const float scale = 1.0f / float(1 << p.subpixel_bits);  // exact: S <= 8
  const double z_max = double((uint64_t(1) << p.z_bits) - 1);
  std::vector<Vertex> out;
  out.reserve(tris.size() * 3);
  for (const SnappedTriangle& t : tris)
    for (const SnappedVertex& v : t.v)
      out.push_back({float(v.x) * scale, float(v.y) * scale, float(double(v.z) / z_max), v.color.r, v.color.g,
                     v.color.b, 255});
  return out;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

int run(const PeerOptions& o) {
  const Profile profile = resolve_profile(o.profile);
  if (profile.subpixel_bits > 8) throw InputError("Mesa snaps to 8 subpixel bits: --subpixel-bits must be at most 8");
  std::string source;
  const std::vector<SnappedTriangle> snapped = load_bench_triangles(o.what, profile, source);

  // The model's per-pixel coverage (an untimed traced render).
  CoverageCounter model_coverage;
  model_coverage.width = profile.width;
  model_coverage.count.assign(size_t(profile.width) * size_t(profile.height), 0);
  Pipeline pipeline(profile);
  pipeline.set_fragment_sink(&model_coverage);
  for (const SnappedTriangle& t : snapped) pipeline.submit(t);

  // The driver is chosen when the first context is made.
  setenv("GALLIUM_DRIVER", o.driver.c_str(), 1);
  // One thread: llvmpipe rasterizes in the calling thread (0); N: N rasterizer threads.
  if (!std::getenv("LP_NUM_THREADS")) setenv("LP_NUM_THREADS", std::to_string(o.threads > 1 ? o.threads : 0).c_str(), 1);
  OSMesaContext context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
  if (!context) throw std::runtime_error("OSMesaCreateContextExt failed");
  // The framebuffer spans the whole guard band, [-W, 2W) x [-H, 2H), so that Mesa never clips a
  // triangle (clipping would move its edges by a rounding error); the scissor keeps the screen.
  const int W = profile.width, H = profile.height;
  std::vector<uint8_t> image(size_t(3 * W) * size_t(3 * H) * 4);
  if (!OSMesaMakeCurrent(context, image.data(), GL_UNSIGNED_BYTE, 3 * W, 3 * H))
    throw std::runtime_error("OSMesaMakeCurrent failed");
  const std::string renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  if (renderer.find(o.driver) == std::string::npos)
    throw std::runtime_error("asked for " + o.driver + " but Mesa runs " + renderer);

  glViewport(0, 0, 3 * W, 3 * H);
  glEnable(GL_SCISSOR_TEST);
  glScissor(W, H, W, H);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-W, 2 * W, -H, 2 * H, 0, -1);  // window x, y = pixels + (W, H); window z = z
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glShadeModel(GL_SMOOTH);
  glDisable(GL_DITHER);
  if (profile.cull != CullMode::None) {
    glEnable(GL_CULL_FACE);
    // The same numbers in y-up window space: the screen's counter-clockwise is GL's clockwise.
    glFrontFace(profile.front_face == FrontFace::CCW ? GL_CW : GL_CCW);
    glCullFace(profile.cull == CullMode::Back ? GL_BACK : GL_FRONT);
  }

  const std::vector<Vertex> vertices = gl_vertices(snapped, profile);
  GLuint buffer = 0;
  glGenBuffers(1, &buffer);
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(Vertex)), vertices.data(), GL_STATIC_DRAW);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(3, GL_FLOAT, sizeof(Vertex), reinterpret_cast<const void*>(offsetof(Vertex, x)));
  glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(Vertex), reinterpret_cast<const void*>(offsetof(Vertex, r)));
  const GLsizei vertex_count = GLsizei(vertices.size());

  // Untimed pass: fragments (occlusion query, depth test off) and per-pixel coverage (stencil).
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 0, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_INCR_WRAP);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  GLuint query = 0;
  glGenQueries(1, &query);
  glBeginQuery(GL_SAMPLES_PASSED, query);
  glDrawArrays(GL_TRIANGLES, 0, vertex_count);
  glEndQuery(GL_SAMPLES_PASSED);
  GLuint mesa_fragments = 0;
  glGetQueryObjectuiv(query, GL_QUERY_RESULT, &mesa_fragments);
  std::vector<uint8_t> stencil(size_t(profile.width) * size_t(profile.height));
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(W, H, W, H, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, stencil.data());
  int64_t differing_pixels = 0;
  for (size_t i = 0; i < stencil.size(); ++i) {
    if (stencil[i] == model_coverage.count[i]) continue;
    if (differing_pixels++ < o.show_differences)
      std::fprintf(stderr, "mesa_peer: pixel (%zu, %zu): Mesa %d, model %d covering triangles\n", i % size_t(profile.width),
                   i / size_t(profile.width), stencil[i], model_coverage.count[i]);
  }
  glDisable(GL_STENCIL_TEST);

  // Timed passes: depth test GL_LESS with writes, as the model's default profile.
  if (profile.depth_func != DepthFunc::Less || !profile.depth_write)
    std::fprintf(stderr, "mesa_peer: note: Mesa runs GL_LESS with depth writes whatever the profile says\n");
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glClearDepth(1.0);
  double best = 0, best_cpu = 0;
  ModelRun model_best;
  for (int r = 0; r < o.repeat; ++r) {
    const ModelRun model = time_model(snapped, profile, o.threads);
    if (r == 0 || model.seconds < model_best.seconds) model_best.seconds = model.seconds;
    if (r == 0 || model.cpu_seconds < model_best.cpu_seconds) model_best.cpu_seconds = model.cpu_seconds;
    model_best.stats = model.stats;
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glFinish();
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = process_cpu_seconds();
    glDrawArrays(GL_TRIANGLES, 0, vertex_count);
    glFinish();
    const double cpu_seconds = process_cpu_seconds() - cpu_start;
    const double seconds = seconds_since(start);
    if (r == 0 || seconds < best) best = seconds;
    if (r == 0 || cpu_seconds < best_cpu) best_cpu = cpu_seconds;
  }
  if (glGetError() != GL_NO_ERROR) throw std::runtime_error("OpenGL reported an error");
  glDeleteQueries(1, &query);
  glDeleteBuffers(1, &buffer);
  OSMesaDestroyContext(context);

  const std::string difference = untraced_differs_from_traced(snapped, profile, o.threads);
  const double model_fragments = double(model_best.stats.fragments), triangles = double(snapped.size());
  std::printf("mesa_peer: %s, %zu triangles, %dx%d, subpixel_bits %d, best of %d\n", source.c_str(), snapped.size(),
              profile.width, profile.height, profile.subpixel_bits, o.repeat);
  std::printf("peer              %s, LP_NUM_THREADS=%s\n", renderer.c_str(), std::getenv("LP_NUM_THREADS"));
  std::printf("peer time         %.6f s wall, %.6f s cpu (glDrawArrays + glFinish)\n", best, best_cpu);
  std::printf("peer fragments    %lld, %.4g per second, %.4g per cpu second\n", (long long)mesa_fragments,
              double(mesa_fragments) / best, double(mesa_fragments) / best_cpu);
  std::printf("peer triangles    %.4g per cpu second\n", triangles / best_cpu);
  std::printf("model time        %.6f s wall, %.6f s cpu (untraced render, %s traversal, %d thread%s)\n",
              model_best.seconds, model_best.cpu_seconds, to_string(profile.traversal), o.threads,
              o.threads == 1 ? "" : "s");
  std::printf("model fragments   %lld, %.4g per second, %.4g per cpu second\n", (long long)model_best.stats.fragments,
              model_fragments / model_best.seconds, model_fragments / model_best.cpu_seconds);
  std::printf("model triangles   %.4g per cpu second\n", triangles / model_best.cpu_seconds);
  std::printf("model / peer      %.2f (fragments per cpu second)\n",
              (model_fragments / model_best.cpu_seconds) / (double(mesa_fragments) / best_cpu));
  std::printf("model / peer wall %.2f (fragments per second)\n",
              (model_fragments / model_best.seconds) / (double(mesa_fragments) / best));
  std::printf("differing pixels  %lld (count of covering triangles, modulo 256)\n", (long long)differing_pixels);
  std::printf("model verified    %s\n", difference.empty() ? "untraced render equals a traced one (counters, records, buffers)"
                                                           : ("NO: " + difference).c_str());
  if (!difference.empty()) return 1;
  return 0;
}

}  // namespace
}  // namespace rastersim

int main(int argc, char** argv) {
  using namespace rastersim;
  use_fast_walk();  // the model as rastersim render and bench run it
  CLI::App app{"Mesa (OSMesa) peer: the same triangles as rastersim bench/render through llvmpipe or softpipe, "
               "depth test on; fragments per second and coverage against the model",
               "rastersim_mesa_peer"};
  PeerOptions o;
  add_bench_input_options(app, o.what);
  app.add_option("--driver", o.driver, "Gallium driver")->check(CLI::IsMember({"llvmpipe", "softpipe"}))
      ->capture_default_str();
  app.add_option("--repeat", o.repeat, "timed repetitions; the best is reported")->check(CLI::Range(1, 100))
      ->capture_default_str();
  app.add_option("--show-differences", o.show_differences, "print the first N pixels whose coverage differs")
      ->capture_default_str();
  app.add_option("--threads", o.threads,
                 "the model's render threads, and llvmpipe's rasterizer threads (LP_NUM_THREADS, 0 for one) "
                 "unless LP_NUM_THREADS is set")
      ->check(CLI::Range(1, 256))
      ->capture_default_str();
  add_profile_options(app, o.profile);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  try {
    return run(o);
  } catch (const InputError& e) {
    std::fprintf(stderr, "mesa_peer: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "mesa_peer: error: %s\n", e.what());
    return 1;
  }
}
