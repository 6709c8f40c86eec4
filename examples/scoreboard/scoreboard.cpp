// The golden model as a scoreboard, from C++ (docs/library.md): the same as scoreboard.c, through
// rastersim::Scoreboard (rastersim/rastersim.hpp), the C API's C++ face: every call a Status.
// Usage: scoreboard_cpp PROFILE.json TRIANGLES.tri FRAGMENTS.csv BUFFERS.txt
#include <rastersim/rastersim.hpp>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

int fail(const rastersim::Status& s, const std::string& where) {
  std::fprintf(stderr, "scoreboard_cpp: %s: %s\n", where.c_str(), s.message.c_str());
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: scoreboard_cpp PROFILE.json TRIANGLES.tri FRAGMENTS.csv BUFFERS.txt\n");
    return 2;
  }
  std::ifstream profile_file(argv[1]);
  std::stringstream profile;
  profile << profile_file.rdbuf();
  rastersim::Scoreboard model;
  if (rastersim::Status s = model.create(profile.str()); !s) return fail(s, argv[1]);

  std::ifstream tri(argv[2]);
  std::ofstream fragments(argv[3]);
  fragments << "tri,x,y,z,pass,r,g,b,cycle\n";
  std::string line;
  for (int number = 1; std::getline(tri, line); ++number) {
    // Up to a comment or a texture section ("uvw" and nine numbers, format version 2; not used here).
    std::istringstream in(line.substr(0, std::min(line.find('#'), line.find("uvw"))));
    std::vector<double> v;
    for (double value; in >> value;) v.push_back(value);
    if (v.empty()) continue;
    if (v.size() != 9 && v.size() != 12 && v.size() != 18) {
      std::fprintf(stderr, "scoreboard_cpp: %s:%d: %zu values, expected 9, 12 or 18\n", argv[2], number, v.size());
      return 2;
    }
    rastersim::Scoreboard::ScreenTriangle t;
    for (size_t k = 0; k < 3; ++k) {
      const size_t c = v.size() == 9 ? 0 : v.size() == 12 ? 9 : 9 + 3 * k;
      t[k] = {v[3 * k], v[3 * k + 1], v[3 * k + 2], uint8_t(c ? v[c] : 255), uint8_t(c ? v[c + 1] : 255),
              uint8_t(c ? v[c + 2] : 255)};
    }
    int64_t index = 0;
    if (rastersim::Status s = model.submit(t, &index); !s) return fail(s, std::string(argv[2]) + ":" + std::to_string(number));
    rastersim_triangle_record r;
    std::vector<rastersim_fragment> expected;
    model.triangle(index, r);
    model.fragments(index, expected);
    std::printf("triangle %lld: status %d, setup %lld..%lld, walker %lld..%lld, %zu fragments\n", (long long)index,
                r.status, (long long)r.setup_accept, (long long)r.setup_done, (long long)r.walker_load,
                (long long)r.walker_end, expected.size());
    for (const rastersim_fragment& f : expected)
      fragments << f.triangle << ',' << f.x << ',' << f.y << ',' << f.z << ',' << int(f.pass) << ',' << int(f.r)
                << ',' << int(f.g) << ',' << int(f.b) << ',' << f.cycle << '\n';
  }
  int64_t cycles = 0;
  model.frame_cycles(cycles);
  std::printf("cycles %lld\n", (long long)cycles);
  int32_t width = 0, height = 0;
  model.size(width, height);
  std::FILE* buffers = std::fopen(argv[4], "w");
  if (!buffers) return 2;
  for (int32_t y = 0; y < height; ++y)
    for (int32_t x = 0; x < width; ++x) {
      uint32_t depth = 0, rgb = 0;
      model.depth(x, y, depth);
      model.color(x, y, rgb);
      std::fprintf(buffers, "%u %06x\n", depth, rgb);
    }
  std::fclose(buffers);
  return 0;
}
