// The profile (docs/formats.md "Profile") and the host-side snapping:
// - validate() rejects each key just outside its range, naming the key, and accepts its limits;
// - set_profile_key() parses every key and rejects bad text with a sentence naming the key;
// - load_profile_file() reports malformed JSON, unknown keys and bad values as file:line: problem;
// - snap_coordinate() and quantize_depth() equal floor(v 2^S + 1/2) and floor(z (2^N - 1) + 1/2),
//   checked with exact integer arithmetic, including exact ties and values whose double product
//   would round across an integer;
// - check_screen_triangle() enforces the guard band [-W, 2W) x [-H, 2H), finite values, z in [0, 1].
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <random>

#include <unistd.h>

#include "model/input_error.h"
#include "model/profile.h"
#include "model/triangle.h"

namespace rastersim {
namespace {

using i128 = __int128;

bool mentions(const std::string& text, const std::string& what) { return text.find(what) != std::string::npos; }

struct RangeKey {
  const char* key;
  std::function<void(Profile&, int64_t)> set;
  int64_t lo, hi;
};

TEST(ProfileValidate, EachKeyJustOutsideItsRangeIsRejectedByName) {
  EXPECT_TRUE(validate(Profile{}).empty()) << "the default profile is valid";
  const RangeKey keys[] = {
      {"width", [](Profile& p, int64_t v) { p.width = int(v); }, 1, 4096},
      {"height", [](Profile& p, int64_t v) { p.height = int(v); }, 1, 4096},
      {"subpixel_bits", [](Profile& p, int64_t v) { p.subpixel_bits = int(v); }, 1, 8},
      {"z_bits", [](Profile& p, int64_t v) { p.z_bits = int(v); }, 16, 32},
      {"z_guard_bits", [](Profile& p, int64_t v) { p.z_guard_bits = int(v); }, 0, 24},
      {"memory_latency", [](Profile& p, int64_t v) { p.memory_latency = int(v); }, 1, 64},
      {"memory_stall_percent", [](Profile& p, int64_t v) { p.memory_stall_percent = int(v); }, 0, 90},
      {"setup_fifo_depth", [](Profile& p, int64_t v) { p.setup_fifo_depth = int(v); }, 1, 16},
      {"setup_interval", [](Profile& p, int64_t v) { p.setup_interval = int(v); }, 2, 64},
  };
  for (const RangeKey& k : keys) {
    for (int64_t ok : {k.lo, k.hi}) {
      Profile p;
      k.set(p, ok);
      EXPECT_TRUE(validate(p).empty()) << k.key << " = " << ok;
    }
    for (int64_t bad : {k.lo - 1, k.hi + 1, int64_t(-1000)}) {
      Profile p;
      k.set(p, bad);
      const std::vector<std::string> errors = validate(p);
      ASSERT_EQ(errors.size(), 1u) << k.key << " = " << bad;
      EXPECT_TRUE(mentions(errors[0], k.key)) << errors[0];
      EXPECT_TRUE(mentions(errors[0], std::to_string(bad))) << errors[0];
    }
  }
  // setup_interval 0: the serial unit, below the pipelined unit's range.
  Profile serial;
  serial.setup_interval = 0;
  EXPECT_TRUE(validate(serial).empty());
  // memory_stall_seed: any non-negative int.
  Profile seeded;
  seeded.memory_stall_seed = INT32_MAX;
  EXPECT_TRUE(validate(seeded).empty());
  seeded.memory_stall_seed = -1;
  ASSERT_EQ(validate(seeded).size(), 1u);
  EXPECT_TRUE(mentions(validate(seeded)[0], "memory_stall_seed")) << validate(seeded)[0];
  // depth_clear: -1 means 2^N - 1; otherwise 0..2^N - 1 for the profile's z_bits.
  for (int z_bits : {16, 24, 32}) {
    Profile p;
    p.z_bits = z_bits;
    const int64_t max = (int64_t(1) << z_bits) - 1;
    for (int64_t ok : {int64_t(-1), int64_t(0), max}) {
      p.depth_clear = ok;
      EXPECT_TRUE(validate(p).empty()) << "depth_clear " << ok;
      EXPECT_EQ(p.depth_clear_value(), uint32_t(ok < 0 ? max : ok));
    }
    for (int64_t bad : {int64_t(-2), max + 1}) {
      p.depth_clear = bad;
      const std::vector<std::string> errors = validate(p);
      ASSERT_EQ(errors.size(), 1u) << "depth_clear " << bad;
      EXPECT_TRUE(mentions(errors[0], "depth_clear")) << errors[0];
    }
  }
  // Several bad keys at once: one sentence each.
  Profile p;
  p.width = 0, p.z_bits = 40, p.memory_latency = 0;
  EXPECT_EQ(validate(p).size(), 3u);
}

TEST(ProfileSetKey, EveryKeyParsesAndBadTextIsNamed) {
  Profile p;
  const std::pair<const char*, const char*> good[] = {
      {"width", "1920"},        {"height", "1080"},     {"subpixel_bits", "8"}, {"z_bits", "32"},
      {"z_guard_bits", "20"},   {"depth_func", "gequal"}, {"depth_write", "false"}, {"depth_clear", "12345"},
      {"cull", "front"},        {"front_face", "cw"},   {"traversal", "bbox"},  {"shading", "flat"},
      {"memory_latency", "17"}};
  for (const auto& [key, value] : good) EXPECT_EQ(set_profile_key(p, key, value), "") << key << " = " << value;
  EXPECT_EQ(p.width, 1920);
  EXPECT_EQ(p.height, 1080);
  EXPECT_EQ(p.subpixel_bits, 8);
  EXPECT_EQ(p.z_bits, 32);
  EXPECT_EQ(p.z_guard_bits, 20);
  EXPECT_EQ(p.depth_func, DepthFunc::GEqual);
  EXPECT_FALSE(p.depth_write);
  EXPECT_EQ(p.depth_clear, 12345);
  EXPECT_EQ(p.cull, CullMode::Front);
  EXPECT_EQ(p.front_face, FrontFace::CW);
  EXPECT_EQ(p.traversal, Traversal::BBox);
  EXPECT_EQ(p.shading, Shading::Flat);
  EXPECT_EQ(p.memory_latency, 17);
  EXPECT_EQ(set_profile_key(p, "z_guard_bits", "auto"), "");
  EXPECT_EQ(p.z_guard_bits, 0);
  EXPECT_EQ(set_profile_key(p, "depth_clear", "max"), "");
  EXPECT_EQ(p.depth_clear, -1);
  // Every key of profile_keys() is settable (with some valid text) and every name round-trips.
  for (const std::string& key : profile_keys()) EXPECT_FALSE(mentions(set_profile_key(p, key, "?"), "unknown")) << key;
  for (DepthFunc f : {DepthFunc::Never, DepthFunc::Less, DepthFunc::Equal, DepthFunc::LEqual, DepthFunc::Greater,
                      DepthFunc::NotEqual, DepthFunc::GEqual, DepthFunc::Always})
    EXPECT_EQ(parse_depth_func(to_string(f)), f);

  const std::pair<const char*, const char*> bad[] = {
      {"width", "abc"},        {"width", "12x"},          {"width", ""},        {"width", "99999999999"},
      {"width", "6.5"},        {"subpixel_bits", "4 bits"}, {"depth_func", "lesser"}, {"depth_func", "LESS"},
      {"depth_write", "maybe"}, {"depth_clear", "-5"},    {"depth_clear", "half"}, {"cull", "both"},
      {"front_face", "left"},  {"traversal", "zigzag"},   {"shading", "phong"}, {"memory_latency", "1e3"},
      {"z_guard_bits", "automatic"}};
  for (const auto& [key, value] : bad) {
    Profile q;
    const std::string error = set_profile_key(q, key, value);
    EXPECT_TRUE(mentions(error, key)) << key << " = '" << value << "' gave '" << error << "'";
    EXPECT_TRUE(mentions(error, std::string("'") + value + "'")) << error;
  }
  const std::string unknown = set_profile_key(p, "colour_bits", "8");
  EXPECT_TRUE(mentions(unknown, "unknown") && mentions(unknown, "colour_bits")) << unknown;
  EXPECT_TRUE(mentions(set_profile_key(p, "depth_func", "lesser"), "lequal")) << "the error lists the choices";
}

// Writes `text` to a fresh file in the test's temporary folder and returns its path.
std::string write_file(const std::string& name, const std::string& text) {
  const std::string path =
      (std::filesystem::temp_directory_path() / "rastersim_profile_").string() + std::to_string(getpid()) + "_" + name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

// The InputError message of loading `text`, or "" when it loads.
std::string load_error(const std::string& name, const std::string& text, Profile* out = nullptr) {
  const std::string path = write_file(name, text);
  Profile p;
  try {
    load_profile_file(p, path);
  } catch (const InputError& e) {
    std::remove(path.c_str());
    return e.what();
  }
  std::remove(path.c_str());
  if (out) *out = p;
  return "";
}

TEST(ProfileFile, LoadsEveryKey) {
  Profile p;
  ASSERT_EQ(load_error("good.json",
                       "{\n  \"width\": 320,\n  \"height\": 200,\n  \"subpixel_bits\": 6,\n  \"z_bits\": 20,\n"
                       "  \"z_guard_bits\": \"auto\",\n  \"depth_func\": \"lequal\",\n  \"depth_write\": false,\n"
                       "  \"depth_clear\": 7,\n  \"cull\": \"back\",\n  \"front_face\": \"cw\",\n"
                       "  \"traversal\": \"bbox\",\n  \"shading\": \"flat\",\n  \"memory_latency\": 9,\n"
                       "  \"memory_stall_percent\": 25,\n  \"memory_stall_seed\": 77\n}\n",
                       &p),
            "");
  EXPECT_EQ(p.width, 320);
  EXPECT_EQ(p.height, 200);
  EXPECT_EQ(p.subpixel_bits, 6);
  EXPECT_EQ(p.z_bits, 20);
  EXPECT_EQ(p.z_guard_bits, 0);
  EXPECT_EQ(p.depth_func, DepthFunc::LEqual);
  EXPECT_FALSE(p.depth_write);
  EXPECT_EQ(p.depth_clear, 7);
  EXPECT_EQ(p.cull, CullMode::Back);
  EXPECT_EQ(p.front_face, FrontFace::CW);
  EXPECT_EQ(p.traversal, Traversal::BBox);
  EXPECT_EQ(p.shading, Shading::Flat);
  EXPECT_EQ(p.memory_latency, 9);
  EXPECT_EQ(p.memory_stall_percent, 25);
  EXPECT_EQ(p.memory_stall_seed, 77);
  // The JSON a profile writes loads back to the same profile.
  Profile back;
  ASSERT_EQ(load_error("roundtrip.json", profile_to_json(p), &back), "");
  EXPECT_EQ(profile_to_json(back), profile_to_json(p));
}

TEST(ProfileFile, ErrorsNameFileLineAndProblem) {
  const std::string dir = (std::filesystem::temp_directory_path() / "rastersim_profile_").string() + std::to_string(getpid()) + "_";
  const std::string deep_json =
      "{\n  \"width\": 64,\n  \"deep\": " + std::string(100000, '[') + std::string(100000, ']') + "\n}\n";
  struct Bad {
    const char* name;
    const char* text;
    int line;
    const char* problem;
  };
  const Bad cases[] = {
      // A missing comma: the parser stops at the next key, on line 4.
      {"comma.json", "{\n  \"width\": 64,\n  \"height\": 48\n  \"z_bits\": 16\n}\n", 4, "malformed JSON"},
      {"brace.json", "{\n  \"width\": 64,\n  \"height\": 48,", 3, "malformed JSON"},
      {"garbage.json", "{\n  \"width\": 64,\n  \"height\": 4 8\n}\n", 3, "malformed JSON"},
      {"unknown.json", "{\n  \"width\": 64,\n  \"colour\": 3\n}\n", 3, "unknown profile key 'colour'"},
      {"enum.json", "{\n  \"width\": 64,\n\n  \"depth_func\": \"lesser\"\n}\n", 4, "depth_func"},
      {"type.json", "{\n  \"width\": 64.5\n}\n", 2, "width"},
      {"integer.json", "{\n  \"height\": \"tall\"\n}\n", 2, "height"},
      {"array.json", "[1, 2]\n", 1, "JSON object"},
      // A key whose name appears earlier as a value: the line is the key's, not the value's.
      {"value_named_like_key.json", "{\n  \"traversal\": \"span\",\n  \"span\": 5\n}\n", 3, "unknown profile key 'span'"},
      // Found by fuzz_profile. A number beyond a double's range is a JSON error with a line (it
      // escaped as an uncaught exception).
      {"overflow.json", "{\n  \"width\": 64,\n  \"height\": 1e999\n}\n", 3, "malformed JSON"},
      // An integer above INT64_MAX is refused as written (it wrapped to -1, which is 'max').
      {"unsigned.json", "{\n  \"depth_clear\": 18446744073709551615\n}\n", 2, "depth_clear is '18446744073709551615'; it must be"},
      // Nesting deeper than any stack: the line finder steps over it (it recursed once per level).
      {"deep.json", deep_json.c_str(), 3, "profile key 'deep' must be a string, integer or boolean"},
      // Ranges at the key's line (they were reported without file and line).
      {"range.json", "{\n  \"width\": 64,\n  \"subpixel_bits\": 9\n}\n", 3, "subpixel_bits is 9"},
      {"clear.json", "{\n  \"z_bits\": 16,\n  \"depth_clear\": 70000\n}\n", 3, "depth_clear is 70000"},
      // JSON types as documented (a quoted number and a number for a boolean were taken).
      {"quoted.json", "{\n  \"width\": \"64\"\n}\n", 2, "width must be a JSON integer"},
      {"bool.json", "{\n  \"height\": 48,\n  \"depth_write\": 1\n}\n", 3, "depth_write must be true or false"},
      {"enum_number.json", "{\n  \"cull\": 1\n}\n", 2, "cull"},
      // 0 is not in 1..24 (it was taken as auto).
      {"guard.json", "{\n  \"z_guard_bits\": 0\n}\n", 2, "z_guard_bits is '0'"},
      // A key given twice (the last one silently won).
      {"twice.json", "{\n  \"width\": 64,\n  \"height\": 48,\n  \"width\": 32\n}\n", 4,
       "'width' is given twice (first on line 2)"},
      // The same key spelled with a JSON escape is the same key (it passed the check).
      {"escaped_twice.json", "{\n  \"width\": 64,\n  \"w\\u0069dth\": 32\n}\n", 3,
       "'width' is given twice (first on line 2)"},
  };
  for (const Bad& c : cases) {
    const std::string error = load_error(c.name, c.text);
    const std::string where = dir + c.name + ":" + std::to_string(c.line) + ": ";
    EXPECT_EQ(error.rfind(where, 0), 0u) << c.name << ": '" << error << "' does not start with '" << where << "'";
    EXPECT_TRUE(mentions(error, c.problem)) << c.name << ": '" << error << "'";
  }
  Profile p;
  try {
    load_profile_file(p, dir + "does_not_exist.json");
    ADD_FAILURE() << "no InputError for a missing file";
  } catch (const InputError& e) {
    EXPECT_TRUE(mentions(e.what(), "does_not_exist.json")) << e.what();
  }
}

// Exact check of Z = floor(a + 1/2) for a = v 2^S (exact in double): Z - 1/2 <= a < Z + 1/2.
void expect_snapped(double v, int S) {
  const int64_t z = snap_coordinate(v, S, VertexSnap::Nearest);
  const double a = std::ldexp(v, S);
  EXPECT_TRUE(double(z) - 0.5 <= a && a < double(z) + 0.5) << "v " << v << " S " << S << " gave " << z;
}

TEST(Snapping, CoordinatesRoundHalfUpExactly) {
  std::mt19937_64 rng(2024);
  for (int S = 1; S <= 8; ++S) {
    const double unit = std::ldexp(1.0, -S);
    for (int64_t n = -40; n <= 40; ++n) {
      const double tie = (double(n) + 0.5) * unit;  // exactly halfway between two subpixels
      EXPECT_EQ(snap_coordinate(tie, S, VertexSnap::Nearest), n + 1) << "tie " << tie << " S " << S;
      EXPECT_EQ(snap_coordinate(std::nextafter(tie, -1e9), S, VertexSnap::Nearest), n) << "just below the tie " << tie;
      EXPECT_EQ(snap_coordinate(std::nextafter(tie, 1e9), S, VertexSnap::Nearest), n + 1) << "just above the tie " << tie;
      EXPECT_EQ(snap_coordinate(double(n) * unit, S, VertexSnap::Nearest), n);
    }
    std::uniform_real_distribution<double> anywhere(-4096.0, 8192.0);
    for (int k = 0; k < 2000; ++k) expect_snapped(anywhere(rng), S);
    // Ties at the ends of the guard band's coordinate range.
    for (int64_t n : {-(int64_t(4096) << S), (int64_t(8192) << S) - 1, int64_t(1234567) % (int64_t(8192) << S)}) {
      const double tie = (double(n) + 0.5) * unit;
      EXPECT_EQ(snap_coordinate(tie, S, VertexSnap::Nearest), n + 1) << tie;
      expect_snapped(std::nextafter(tie, 0.0), S);
    }
  }
  EXPECT_EQ(snap_coordinate(-0.0, 4, VertexSnap::Nearest), 0);
}

// Exact check of Z = floor(z (2^N - 1) + 1/2) with z = m 2^-k: (2Z - 1) 2^k <= 2 m (2^N - 1) < (2Z + 1) 2^k.
bool depth_is_exact(double z, int N, uint32_t got) {
  const i128 scale = (i128(1) << N) - 1;
  if (z == 0.0) return got == 0;
  int e = 0;
  const double f = std::frexp(z, &e);
  if (e < -39) return got == 0 && z * double(scale) < 0.25;  // z (2^N - 1) < 1/2 by a wide margin
  const i128 m = i128(std::ldexp(f, 53));
  const int k = 53 - e;
  const i128 lhs = 2 * m * scale, Z = got;
  return (2 * Z - 1) * (i128(1) << k) <= lhs && lhs < (2 * Z + 1) * (i128(1) << k);
}

TEST(Snapping, DepthQuantizationIsExact) {
  std::mt19937_64 rng(77);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int N : {16, 17, 24, 31, 32}) {
    const double scale = std::ldexp(1.0, N) - 1;
    EXPECT_EQ(quantize_depth(0.0, N), 0u);
    EXPECT_EQ(quantize_depth(1.0, N), uint32_t(scale));
    // The one exact tie: 1/2 (2^N - 1) = 2^(N-1) - 1/2 rounds up.
    EXPECT_EQ(quantize_depth(0.5, N), uint32_t(1) << (N - 1));
    EXPECT_EQ(quantize_depth(std::nextafter(0.5, 0.0), N), (uint32_t(1) << (N - 1)) - 1);
    for (double z : {std::nextafter(1.0, 0.0), 0x1p-40, 0x1p-41, 1e-300, 4.9e-324, 0x1p-33, 0x1p-32, 0x1p-31})
      EXPECT_TRUE(depth_is_exact(z, N, quantize_depth(z, N))) << "z " << z << " N " << N;
    for (int k = 0; k < 20000; ++k) {
      const double z = unit(rng);
      ASSERT_TRUE(depth_is_exact(z, N, quantize_depth(z, N))) << "z " << z << " N " << N;
    }
    // Near-ties: z = (n + 1/2) / (2^N - 1) rounded to double, and its neighbours. For many of them
    // the double product z (2^N - 1) rounds to exactly n + 1/2, so a floating-point quantizer errs.
    int double_rounding_traps = 0;
    std::uniform_int_distribution<int64_t> level(0, int64_t(scale) - 1);
    for (int k = 0; k < 20000; ++k) {
      const double centre = (double(level(rng)) + 0.5) / scale;
      for (double z : {std::nextafter(centre, 0.0), centre, std::nextafter(centre, 1.0)}) {
        const uint32_t got = quantize_depth(z, N);
        ASSERT_TRUE(depth_is_exact(z, N, got)) << "z " << z << " N " << N << " gave " << got;
        double_rounding_traps += uint32_t(std::floor(z * scale + 0.5)) != got;
      }
    }
    EXPECT_GT(double_rounding_traps, 0) << "N " << N << ": the near-ties must include values a double product gets wrong";
  }
}

TEST(ScreenTriangle, GuardBandAndValuesAreChecked) {
  Profile p;
  p.width = 100, p.height = 50, p.subpixel_bits = 4;
  auto with_first = [](double x, double y, double z) {
    ScreenTriangle t;
    t.v[0] = {x, y, z, {}};
    t.v[1] = {10, 10, 0.5, {}};
    t.v[2] = {20, 30, 0.5, {}};
    return t;
  };
  EXPECT_EQ(check_screen_triangle(with_first(-100, -50, 0), p), "");
  EXPECT_EQ(check_screen_triangle(with_first(std::nextafter(200.0, 0.0), std::nextafter(100.0, 0.0), 1), p), "");
  for (const auto& [x, y] : {std::pair{200.0, 0.0}, std::pair{0.0, 100.0}, std::pair{-100.001, 0.0},
                             std::pair{0.0, -50.001}, std::pair{1e300, 0.0}, std::pair{0.0, -1e300}}) {
    const std::string error = check_screen_triangle(with_first(x, y, 0.5), p);
    EXPECT_TRUE(mentions(error, "first vertex") && mentions(error, "guard band")) << x << ", " << y << ": " << error;
  }
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (const ScreenTriangle& t : {with_first(nan, 0, 0), with_first(0, inf, 0), with_first(0, 0, nan), with_first(0, 0, -inf)})
    EXPECT_TRUE(mentions(check_screen_triangle(t, p), "first vertex")) << check_screen_triangle(t, p);
  for (double z : {-0.001, 1.000001})
    EXPECT_TRUE(mentions(check_screen_triangle(with_first(0, 0, z), p), "depth")) << z;
  ScreenTriangle third = with_first(0, 0, 0);
  third.v[2].y = 100;
  EXPECT_TRUE(mentions(check_screen_triangle(third, p), "third vertex"));
  // A vertex just inside the guard band snaps to its closed end, 2W * 2^S, which the widths hold.
  const SnappedTriangle s = snap(with_first(std::nextafter(200.0, 0.0), 0, 0), p);
  EXPECT_EQ(s.v[0].x, 200 * 16);
}

}  // namespace
}  // namespace rastersim
