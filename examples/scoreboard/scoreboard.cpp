// The golden model as a scoreboard, from C++ with the model's own headers (docs/library.md): the
// same as scoreboard.c, through rastersim::Pipeline instead of the C API.
// Usage: scoreboard_cpp PROFILE.json TRIANGLES.tri FRAGMENTS.csv BUFFERS.txt
#include <cstdio>
#include <exception>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "model/pipeline.h"
#include "model/profile.h"
#include "model/triangle.h"

namespace {

// Collects every fragment the z-buffer accepts, in order.
struct Collect : rastersim::FragmentSink {
  std::vector<rastersim::Fragment> fragments;
  void on_fragment(const rastersim::Fragment& f) override { fragments.push_back(f); }
};

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: scoreboard_cpp PROFILE.json TRIANGLES.tri FRAGMENTS.csv BUFFERS.txt\n");
    return 2;
  }
  try {
    rastersim::Profile profile;
    rastersim::load_profile_file(profile, argv[1]);
    rastersim::Pipeline pipeline(profile);
    Collect collect;
    std::vector<rastersim::TriangleRecord> records;
    pipeline.set_fragment_sink(&collect);
    pipeline.set_triangle_log(&records);

    std::ifstream tri(argv[2]);
    std::string line;
    for (int number = 1; std::getline(tri, line); ++number) {
      std::istringstream in(line.substr(0, line.find('#')));
      std::vector<double> v;
      for (double value; in >> value;) v.push_back(value);
      if (v.empty()) continue;
      if (v.size() != 9 && v.size() != 12 && v.size() != 18) {
        std::fprintf(stderr, "scoreboard_cpp: %s:%d: %zu values, expected 9, 12 or 18\n", argv[2], number, v.size());
        return 2;
      }
      rastersim::ScreenTriangle t;
      for (int k = 0; k < 3; ++k) {
        const size_t c = v.size() == 9 ? 0 : v.size() == 12 ? 9 : size_t(9 + 3 * k);
        t.v[k].x = v[size_t(3 * k)], t.v[k].y = v[size_t(3 * k + 1)], t.v[k].z = v[size_t(3 * k + 2)];
        if (c) t.v[k].color = {uint8_t(v[c]), uint8_t(v[c + 1]), uint8_t(v[c + 2])};
      }
      const std::string problem = rastersim::check_screen_triangle(t, profile);
      if (!problem.empty()) {
        std::fprintf(stderr, "scoreboard_cpp: %s:%d: %s\n", argv[2], number, problem.c_str());
        return 2;
      }
      pipeline.submit(rastersim::snap(t, profile));
      const rastersim::TriangleRecord& r = records.back();
      std::printf("triangle %lld: %s, setup %lld..%lld, walker %lld..%lld, %lld fragments\n", (long long)r.index,
                  rastersim::to_string(r.status), (long long)r.setup_accept, (long long)r.setup_done,
                  (long long)r.walker_load, (long long)r.walker_end, (long long)r.fragments);
    }
    std::ofstream fragments(argv[3]);
    fragments << "tri,x,y,z,pass,r,g,b,cycle\n";
    for (const rastersim::Fragment& f : collect.fragments)
      fragments << f.tri << ',' << f.x << ',' << f.y << ',' << f.z << ',' << int(f.pass) << ',' << int(f.color.r)
                << ',' << int(f.color.g) << ',' << int(f.color.b) << ',' << f.cycle << '\n';
    std::printf("cycles %lld\n", (long long)pipeline.stats().cycles);
    std::FILE* buffers = std::fopen(argv[4], "w");
    if (!buffers) return 2;
    const std::vector<uint32_t>& depth = pipeline.zbuffer().depth();
    const std::vector<uint32_t>& colour = pipeline.zbuffer().color();
    for (size_t i = 0; i < depth.size(); ++i) std::fprintf(buffers, "%u %06x\n", depth[i], colour[i]);
    std::fclose(buffers);
  } catch (const std::exception& e) {  // the model reports bad input by exceptions
    std::fprintf(stderr, "scoreboard_cpp: %s\n", e.what());
    return 2;
  }
  return 0;
}
