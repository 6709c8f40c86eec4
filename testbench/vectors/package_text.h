// The text files of a test-vector package, written from what package.cpp computed: the
// testbench's parameter file, the two run scripts and the README. (The testbench itself,
// rastersim_vectors_tb.v, is a file of this folder, the same for every package.) Internal to testbench/vectors/.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "model/profile.h"
#include "model/widths.h"
#include "testbench/vectors/package.h"

namespace rastersim::vectors {

struct PackageFacts {
  Profile profile;
  Widths widths;
  Layouts layouts;
  int64_t triangles = 0, drawn = 0, fragments = 0, cycles = 0, words = 0;
  int log2_texture_width = 0, log2_texture_height = 0;  // texture.hex's texture (texture unit)
  TextureFilter texture_filter = TextureFilter::Nearest;
  TextureWrap texture_wrap = TextureWrap::Repeat;
  std::string source_text;        // "the built-in scene default", "500 random triangles (seed 1)", ...
  std::string regenerate_command; // rastersim vectors ... --out DIR
  std::string rtl_folder;         // the RTL folder relative to the package: "rtl" or options.rtl_path
  bool rtl_included = true;
  bool external_memory = false;  // rastersim_core with rastersim_memory_model.v, not rastersim_top
  std::string testbench_folder;   // the testbench's folder relative to the package: "." when copied
};

// File names inside the package.
inline const char* const kTestbenchFile = "rastersim_vectors_tb.v";
inline const char* const kTestbenchTop = "rastersim_vectors_tb";
inline const char* const kParamsFile = "rastersim_vectors_params.vh";
inline const char* const kMemoryModelFile = "rastersim_memory_model.v";
inline const char* const kSelftestFile = "rastersim_selftest.v";
inline const char* const kSelftestCrcFile = "selftest.hex";
inline const char* const kSelftestPinFile = "selftest_hx8k.pcf";
inline const char* const kLintWaiverFile = "lint_waivers.vlt";  // the testbench's; rtl/ has its own

// The parameter file the testbench includes: profile, widths, vector counts, field places.
std::string params_text(const PackageFacts& facts);
std::string icarus_script(const PackageFacts& facts);
std::string verilator_script(const PackageFacts& facts);
// Verilator -Wall lint of the testbench and the board self-test with the shipped waivers.
std::string lint_script(const PackageFacts& facts, bool selftest);
std::string readme_text(const PackageFacts& facts);
// The board self-test's files: its expected CRC-32s (depth words as ceil(z_bits / 8) bytes, colour
// words as 3, least significant byte first), its pin file, and its Icarus and iCE40 scripts.
std::string selftest_crcs(const PackageFacts& facts, const std::vector<uint32_t>& depth, const std::vector<uint32_t>& color);
std::string selftest_pins();
std::string selftest_icarus_script(const PackageFacts& facts);
std::string selftest_hx8k_script(const PackageFacts& facts);

// The vector files in package order: name, layout, what one word is.
struct VectorFile {
  std::string path;
  const WordLayout* layout;
  std::string meaning;
};
std::vector<VectorFile> vector_files(const Layouts& layouts);
// The words (lines) of a vector file of the package, by its path.
int64_t vector_words(const PackageFacts& facts, const std::string& path);

}  // namespace rastersim::vectors
