// The .tri reader and writer, in process: good inputs, every kind of bad line (each error names
// file:line and the reason), and exact round trips through the writer.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <sstream>
#include <string>

#include "model/input_error.h"
#include "tri_reader.h"

namespace rastersim {
namespace {

Profile small_profile() {
  Profile p;
  p.width = 32;
  p.height = 24;
  return p;
}

std::vector<ScreenTriangle> read_text(const std::string& text, const Profile& profile = small_profile()) {
  std::istringstream in(text);
  return read_tri(in, "scene.tri", profile);
}

// The InputError message for `text`, or "no error".
std::string error_of(const std::string& text, const Profile& profile = small_profile()) {
  try {
    read_text(text, profile);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

uint64_t bits(double v) {
  uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

TEST(TriReader, ReadsNineNumbersAsWhiteTriangle) {
  const auto tris = read_text("1 2 0 3.5 4 0.25 5 6e0 1\n");
  ASSERT_EQ(tris.size(), 1u);
  EXPECT_EQ(tris[0].v[0].x, 1.0);
  EXPECT_EQ(tris[0].v[0].y, 2.0);
  EXPECT_EQ(tris[0].v[0].z, 0.0);
  EXPECT_EQ(tris[0].v[1].x, 3.5);
  EXPECT_EQ(tris[0].v[1].z, 0.25);
  EXPECT_EQ(tris[0].v[2].y, 6.0);
  EXPECT_EQ(tris[0].v[2].z, 1.0);
  for (const ScreenVertex& v : tris[0].v) EXPECT_EQ(v.color, (Rgb{255, 255, 255}));
}

TEST(TriReader, ReadsFlatAndPerVertexColours) {
  const auto tris = read_text(
      "0 0 0.5 10 0 0.5 0 10 0.5 1 2 3\n"
      "0 0 0.5 10 0 0.5 0 10 0.5 10 20 30 40 50 60 70 80 255\n");
  ASSERT_EQ(tris.size(), 2u);
  for (const ScreenVertex& v : tris[0].v) EXPECT_EQ(v.color, (Rgb{1, 2, 3}));
  EXPECT_EQ(tris[1].v[0].color, (Rgb{10, 20, 30}));
  EXPECT_EQ(tris[1].v[1].color, (Rgb{40, 50, 60}));
  EXPECT_EQ(tris[1].v[2].color, (Rgb{70, 80, 255}));
}

TEST(TriReader, SkipsCommentsBlankLinesAndCarriageReturns) {
  const auto tris = read_text(
      "# a comment line\n"
      "\n"
      "   \t  \n"
      "0 0 0.1 10 0 0.1 0 10 0.1   # trailing comment 1 2 3\r\n"
      "#0 0 0 1 1 1 2 2 2\n"
      "\t1 1 0.2\t11 1 0.2 1 11 0.2 9 8 7\r\n");
  ASSERT_EQ(tris.size(), 2u);
  EXPECT_EQ(tris[0].v[0].color, (Rgb{255, 255, 255}));  // the comment's numbers are not colours
  EXPECT_EQ(tris[1].v[0].x, 1.0);
  EXPECT_EQ(tris[1].v[2].color, (Rgb{9, 8, 7}));
}

// Lines may end in a lone CR (the second line's coordinates were read as colours of the first).
TEST(TriReader, ALoneCarriageReturnEndsALine) {
  const auto tris = read_text("0 0 0.1 10 0 0.1 0 10 0.1\r1 1 0.2 11 1 0.2 1 11 0.2\r\r2 2 0.3 12 2 0.3 2 12 0.3");
  ASSERT_EQ(tris.size(), 3u);
  EXPECT_EQ(tris[0].v[0].color, (Rgb{255, 255, 255}));
  EXPECT_EQ(tris[1].v[0].x, 1.0);
  EXPECT_EQ(tris[2].v[2].y, 12.0);
  EXPECT_EQ(error_of("0 0 0.1 10 0 0.1 0 10 0.1\r\r1 1 0.2 11 1 0.2 1 11"), "scene.tri:3: expected 9 numbers "
            "'x0 y0 z0 x1 y1 z1 x2 y2 z2', optionally followed by 3 colour values 'r g b' or 9 "
            "'r0 g0 b0 r1 g1 b1 r2 g2 b2', but the line has 8 values");
}

// A file of more triangles than the limit ends at the first one past it, not in bad_alloc (40
// million lines did); the limit is a scene's.
TEST(TriReader, MoreTrianglesThanTheLimitAreRefusedAtTheLineOfTheFirstPastIt) {
  EXPECT_EQ(kMaxTriTriangles, size_t(4000000));
  std::istringstream in("# three\n0 0 0.1 10 0 0.1 0 10 0.1\n0 0 0.1 10 0 0.1 0 10 0.1\n\n0 0 0.1 10 0 0.1 0 10 0.1\n"
                        "0 0 0.1 10 0 0.1 0 10 0.1\n");
  try {
    read_tri(in, "many.tri", small_profile(), 3);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "many.tri:6: more than 3 triangles, the limit of a .tri file");
  }
}

// A UTF-8 byte-order mark before the first line is skipped (x0 was '\xEF\xBB\xBF10', "not a number").
TEST(TriReader, SkipsAByteOrderMark) {
  const auto tris = read_text("\xEF\xBB\xBF" "10 0 0.1 20 0 0.1 10 10 0.1\n");
  ASSERT_EQ(tris.size(), 1u);
  EXPECT_EQ(tris[0].v[0].x, 10.0);
}

// The texture divide's w ratio (at most 16384) is a limit of the texture unit: without it the
// coordinates, and their w, are ignored.
TEST(TriReader, WRatioBeyondTheTextureUnitsLimitIsBadInputWithTheUnit) {
  const std::string line = "0 0 0.5 10 0 0.5 0 10 0.5 uvw 0 0 0.5 1 0 8192.5 0 1 1\n";
  Profile with_unit = small_profile();
  with_unit.texture_unit = true;
  EXPECT_EQ(error_of(line, with_unit), "scene.tri:1: the largest w 8192.5 is more than 16384 times the smallest, 0.5");
  EXPECT_EQ(error_of("0 0 0.5 10 0 0.5 0 10 0.5 uvw 0 0 0.5 1 0 8192 0 1 1\n", with_unit), "no error");
  EXPECT_EQ(error_of(line), "no error");
}

TEST(TriReader, ReadsTheTextureSectionAfterAnyColours) {
  const auto tris = read_text(
      "1 2 0 3 4 0 5 6 1 uvw 0.5 -0.25 1 127.5 0 2 -127.5 3 1.25e-4\n"
      "1 2 0 3 4 0 5 6 1 9 8 7 uvw 0 0 1 1 0 1 0 1 1\n"
      "1 2 0 3 4 0 5 6 1 1 2 3 4 5 6 7 8 9 uvw 0 0 1 1 0 1 0 1 1\n"
      "1 2 0 3 4 0 5 6 1\n");
  ASSERT_EQ(tris.size(), 4u);
  EXPECT_TRUE(tris[0].textured);
  EXPECT_EQ(tris[0].v[0].u, 0.5);
  EXPECT_EQ(tris[0].v[0].v, -0.25);
  EXPECT_EQ(tris[0].v[0].w, 1.0);
  EXPECT_EQ(tris[0].v[1].u, 127.5);
  EXPECT_EQ(tris[0].v[1].w, 2.0);
  EXPECT_EQ(tris[0].v[2].u, -127.5);
  EXPECT_EQ(tris[0].v[2].v, 3.0);
  EXPECT_EQ(tris[0].v[2].w, 1.25e-4);
  EXPECT_EQ(tris[0].v[2].color, (Rgb{255, 255, 255}));
  EXPECT_TRUE(tris[1].textured);
  EXPECT_EQ(tris[1].v[2].color, (Rgb{9, 8, 7}));
  EXPECT_EQ(tris[1].v[1].u, 1.0);
  EXPECT_TRUE(tris[2].textured);
  EXPECT_EQ(tris[2].v[2].color, (Rgb{7, 8, 9}));
  EXPECT_EQ(tris[2].v[2].v, 1.0);
  EXPECT_FALSE(tris[3].textured);  // version 1 lines read as before
}

TEST(TriReader, EmptyInputHasNoTriangles) {
  EXPECT_TRUE(read_text("").empty());
  EXPECT_TRUE(read_text("# nothing\n\n").empty());
}

TEST(TriReader, GuardBandIsHalfOpen) {
  // Guard band for 32x24: x in [-32, 64), y in [-24, 48) (docs/formats.md, check_screen_triangle).
  EXPECT_EQ(read_text("-32 -24 0 63.999 -24 0 -32 47.999 1\n").size(), 1u);
  EXPECT_NE(error_of("-32 -24 0 64 -24 0 -32 47 1\n").find("scene.tri:1: second vertex x 64"), std::string::npos);
  EXPECT_NE(error_of("-32 -24 0 63 -24 0 -32 48 1\n").find("scene.tri:1: third vertex y 48"), std::string::npos);
  EXPECT_NE(error_of("-32.001 -24 0 63 -24 0 -32 47 1\n").find("scene.tri:1: first vertex x -32.001"), std::string::npos);
}

struct BadLine {
  const char* name;
  std::string line;  // may hold a NUL byte
  const char* reason;  // must appear in the message
};

class TriReaderBadLine : public ::testing::TestWithParam<BadLine> {};

TEST_P(TriReaderBadLine, NamesFileLineAndReason) {
  const BadLine& bad = GetParam();
  // Two good lines and a comment first, so the bad line is line 4.
  const std::string text = std::string("0 0 0.5 10 0 0.5 0 10 0.5\n# comment\n1 1 0.5 9 1 0.5 1 9 0.5 1 2 3\n") +
                           bad.line + "\n0 0 0 1 0 0 0 1 0\n";
  const std::string message = error_of(text);
  EXPECT_EQ(message.rfind("scene.tri:4: ", 0), 0u) << message;
  EXPECT_NE(message.find(bad.reason), std::string::npos) << message;
}

INSTANTIATE_TEST_SUITE_P(
    AllKinds, TriReaderBadLine,
    ::testing::Values(
        BadLine{"NotANumber", "0 0 0.5 10 zero 0.5 0 10 0.5", "y1 'zero' is not a number"},
        BadLine{"TrailingGarbage", "0 0 0.5 10 0 0.5 0 10x 0.5", "y2 '10x' is not a number"},
        BadLine{"CommaSeparated", "0,0 0 0.5 10 0 0.5 0 10 0.5", "x0 '0,0' is not a number"},
        BadLine{"Truncated", "0 0 0.5 10 0 0.5 0 10", "the line has 8 values"},
        BadLine{"OneValue", "7", "the line has 1 value"},
        BadLine{"TenValues", "0 0 0.5 10 0 0.5 0 10 0.5 1", "the line has 10 values"},
        BadLine{"FifteenValues", "0 0 0.5 10 0 0.5 0 10 0.5 1 2 3 4 5 6", "the line has 15 values"},
        BadLine{"NaN", "0 0 0.5 nan 0 0.5 0 10 0.5", "x1 'nan' is not a finite number"},
        BadLine{"NaNDepth", "0 0 NAN 10 0 0.5 0 10 0.5", "z0 'NAN' is not a finite number"},
        BadLine{"Inf", "0 0 0.5 10 0 0.5 0 inf 0.5", "y2 'inf' is not a finite number"},
        BadLine{"MinusInfinity", "-infinity 0 0.5 10 0 0.5 0 10 0.5", "x0 '-infinity' is not a finite number"},
        BadLine{"Overflow", "0 1e999 0.5 10 0 0.5 0 10 0.5", "y0 '1e999' is not a finite number"},
        BadLine{"DepthAboveOne", "0 0 0.5 10 0 1.0000001 0 10 0.5", "z1 1.0000001 is outside the depth range [0, 1]"},
        BadLine{"DepthNegative", "0 0 -0.1 10 0 0.5 0 10 0.5", "z0 -0.1 is outside the depth range [0, 1]"},
        BadLine{"XOutsideGuardBand", "0 0 0.5 65 0 0.5 0 10 0.5", "second vertex x 65"},
        BadLine{"XBelowGuardBand", "0 0 0.5 10 0 0.5 -32.5 10 0.5", "third vertex x -32.5"},
        BadLine{"YOutsideGuardBand", "0 48.5 0.5 10 0 0.5 0 10 0.5", "first vertex y 48.5"},
        BadLine{"FarOutside", "0 0 0.5 1e300 0 0.5 0 10 0.5", "outside the guard band"},
        BadLine{"ColourAbove255", "0 0 0.5 10 0 0.5 0 10 0.5 0 256 0", "g 256 is outside the colour range 0..255"},
        BadLine{"ColourNegative", "0 0 0.5 10 0 0.5 0 10 0.5 -1 0 0", "r -1 is outside the colour range 0..255"},
        BadLine{"ColourFraction", "0 0 0.5 10 0 0.5 0 10 0.5 0 0 1.5", "b '1.5' is not an integer colour value"},
        BadLine{"VertexColourNaN", "0 0 0.5 10 0 0.5 0 10 0.5 0 0 0 1 1 1 2 nan 2", "g2 'nan' is not a finite number"},
        BadLine{"VertexColourWord", "0 0 0.5 10 0 0.5 0 10 0.5 0 0 0 red 1 1 2 2 2", "r1 'red' is not a number"},
        // Shown as written: it printed as -32.000000, which reads as inside the guard band.
        BadLine{"JustBelowGuardBand", "0 0 0.5 10 0 0.5 -32.00000001 10 0.5", "third vertex x -32.00000001 is outside"},
        // A NUL byte shown, not the end of the message.
        BadLine{"NulInToken", std::string("0 0 0.5 1") + '\0' + "0 0 0.5 0 10 0.5", "x1 '1\\x000' is not a number"},
        // The texture section (format version 2).
        BadLine{"TextureTruncated", "0 0 0.5 10 0 0.5 0 10 0.5 uvw 0 0 1 1 0 1 0 1",
                "expected 9 numbers 'u0 v0 w0 u1 v1 w1 u2 v2 w2' after 'uvw', but there are 8"},
        BadLine{"TwoTextureSections", "0 0 0.5 10 0 0.5 0 10 0.5 uvw 0 0 1 1 0 1 0 1 1 uvw 0 0 1 1 0 1 0 1 1",
                "after 'uvw', but there are 19"},
        BadLine{"TextureWithoutPositions", "uvw 0 0 1 1 0 1 0 1 1", "the line has 0 values"},
        BadLine{"TextureWord", "0 0 0.5 10 0 0.5 0 10 0.5 uvw 0 0 one 1 0 1 0 1 1", "w0 'one' is not a number"},
        BadLine{"TextureNaN", "0 0 0.5 10 0 0.5 0 10 0.5 1 2 3 uvw 0 0 1 nan 0 1 0 1 1", "u1 'nan' is not a finite number"},
        BadLine{"TextureOutsideRange", "0 0 0.5 10 0 0.5 0 10 0.5 uvw 0 0 1 1 0 1 0 128 1",
                "third vertex texture coordinate v 128 is outside (-128, 128)"},
        BadLine{"TextureBelowRange", "0 0 0.5 10 0 0.5 0 10 0.5 uvw -128 0 1 1 0 1 0 1 1",
                "first vertex texture coordinate u -128 is outside (-128, 128)"},
        BadLine{"WZero", "0 0 0.5 10 0 0.5 0 10 0.5 uvw 0 0 0 1 0 1 0 1 1", "first vertex w 0 is not positive"},
        BadLine{"WNegative", "0 0 0.5 10 0 0.5 0 10 0.5 uvw 0 0 1 1 0 -2 0 1 1", "second vertex w -2 is not positive"}),
    [](const ::testing::TestParamInfo<BadLine>& info) { return info.param.name; });

TEST(TriReader, RandomGarbageIsReadOrRejectedNeverAnythingElse) {
  // Lines built from plausible and hostile tokens: the reader returns triangles or throws
  // InputError with file:line, nothing else (no other exception, no crash).
  const char* const tokens[] = {"0", "1", "0.5", "-3", "12", "255", "256", "1e308", "-1e308", "nan", "inf", "-0",
                                "0x1p-3", "1e-320", "#", "abc", "1,2", "", "\t", "\r", "0.", ".5", "+7", "--1", "\xff"};
  std::mt19937 rng(3);
  for (int n = 0; n < 3000; ++n) {
    std::string line;
    const int count = int(rng() % 20);
    for (int k = 0; k < count; ++k) line += std::string(tokens[rng() % (sizeof tokens / sizeof *tokens)]) + " ";
    try {
      read_text(line + "\n");
    } catch (const InputError& e) {
      // A lone "\r" ends a line: the error is on one of the lines the CRs make.
      const std::string message = e.what();
      const int lines = 1 + int(std::count(line.begin(), line.end(), '\r'));
      bool named = false;
      for (int k = 1; k <= lines; ++k) named |= message.rfind("scene.tri:" + std::to_string(k) + ": ", 0) == 0;
      EXPECT_TRUE(named) << message;
    }
  }
}

TEST(TriReader, ErrorAtFirstLineCountsFromOne) {
  EXPECT_EQ(error_of("1 2 3\n").rfind("scene.tri:1: ", 0), 0u);
}

TEST(TriReader, MissingFileIsAnInputErrorNamingIt) {
  try {
    read_tri_file("/nonexistent/folder/none.tri", small_profile());
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/folder/none.tri: cannot open"), std::string::npos) << e.what();
  }
}

TEST(TriReader, FolderIsAnInputError) {
  EXPECT_THROW(read_tri_file("/tmp", small_profile()), InputError);
}

TEST(TriWriter, RoundTripsBitExactly) {
  Profile p;  // 640x480: guard band x in [-640, 1280), y in [-480, 960)
  std::mt19937_64 rng(7);
  auto unit = [&] { return double(rng() >> 11) * 0x1p-53; };
  std::vector<ScreenTriangle> tris;
  const double special[] = {0.0, -0.0, 0.1, 1.0 / 3.0, 5e-324, 1.0, std::nextafter(1.0, 0.0), 0.5, 2.2250738585072014e-308};
  for (int n = 0; n < 500; ++n) {
    ScreenTriangle t;
    for (int k = 0; k < 3; ++k) {
      ScreenVertex& v = t.v[k];
      v.x = -640 + unit() * 1920;
      v.y = -480 + unit() * 1440;
      v.z = n < 9 ? special[n] : unit();
      if (n < 9) v.x = special[(n + k) % 9] * 100;
      v.color = n % 3 == 0 ? Rgb{} : Rgb{uint8_t(rng()), uint8_t(rng()), uint8_t(rng())};
    }
    if (n % 3 == 1) t.v[1].color = t.v[2].color = t.v[0].color;  // flat
    if (n % 2 == 1) {
      t.textured = true;
      // Any magnitude of w, within a triangle a ratio below 2^14 (3 2^12 at most).
      const int exponent = int(rng() % 200) - 100;
      for (ScreenVertex& v : t.v) {
        v.u = -127.9 + unit() * 255.8;
        v.v = n < 9 ? special[n] : -127.9 + unit() * 255.8;
        v.w = n < 9 ? special[(n + 1) % 9] + 5e-324 : std::ldexp(unit() + 0.5, exponent + int(rng() % 13));
      }
    }
    tris.push_back(t);
  }
  std::ostringstream out;
  write_tri(out, tris, "written by the round-trip test\nsecond comment line");
  const std::string text = out.str();
  EXPECT_EQ(text.rfind("# written by the round-trip test\n# second comment line\n", 0), 0u);
  std::istringstream in(text);
  const auto back = read_tri(in, "roundtrip.tri", p);
  ASSERT_EQ(back.size(), tris.size());
  for (size_t i = 0; i < tris.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(bits(back[i].v[k].x), bits(tris[i].v[k].x)) << i;
      EXPECT_EQ(bits(back[i].v[k].y), bits(tris[i].v[k].y)) << i;
      EXPECT_EQ(bits(back[i].v[k].z), bits(tris[i].v[k].z)) << i;
      EXPECT_EQ(back[i].v[k].color, tris[i].v[k].color) << i;
      EXPECT_EQ(bits(back[i].v[k].u), bits(tris[i].v[k].u)) << i;
      EXPECT_EQ(bits(back[i].v[k].v), bits(tris[i].v[k].v)) << i;
      EXPECT_EQ(bits(back[i].v[k].w), bits(tris[i].v[k].w)) << i;
    }
    EXPECT_EQ(back[i].textured, tris[i].textured) << i;
  }
}

TEST(TriWriter, WritesColourOnlyWhenNeeded) {
  ScreenTriangle white{{{0, 0, 0, {}}, {1, 0, 0, {}}, {0, 1, 0, {}}}};
  ScreenTriangle flat = white;
  for (ScreenVertex& v : flat.v) v.color = Rgb{1, 2, 3};
  ScreenTriangle gouraud = flat;
  gouraud.v[2].color = Rgb{4, 5, 6};
  ScreenTriangle textured = flat;
  textured.textured = true;
  textured.v[0].u = 0.5, textured.v[1].v = -0.25, textured.v[2].w = 2;
  std::ostringstream out;
  write_tri(out, {white, flat, gouraud, textured});
  EXPECT_EQ(out.str(),
            "0 0 0 1 0 0 0 1 0\n"
            "0 0 0 1 0 0 0 1 0 1 2 3\n"
            "0 0 0 1 0 0 0 1 0 1 2 3 1 2 3 4 5 6\n"
            "0 0 0 1 0 0 0 1 0 1 2 3 uvw 0.5 0 1 0 -0.25 1 0 0 2\n");
}

}  // namespace
}  // namespace rastersim
