// Test-vector packages for FPGA ports (docs/vectors.md): the model's expected words for one frame
// as $readmemh files, a manifest, a self-checking Verilog testbench of rastersim_top, scripts that
// run it with Icarus Verilog and Verilator, and a README. Everything here is deterministic: the same
// profile, triangles and source give the same bytes.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "model/profile.h"
#include "model/texture_unit.h"
#include "model/triangle.h"
#include "testbench/vectors/word_layout.h"

namespace rastersim::vectors {

// Bumped when a file, a layout or the testbench's contract changes incompatibly (docs/vectors.md).
constexpr int kFormatVersion = 8;  // 2: check_manifest.py added; 3: status no_centre, its counter;
                                   // 4: one testbench with a parameter file, +functional;
                                   // 5: the planes along the left edges in setup.hex, setup cycles;
                                   // 6: commands' depths in the depth plane's bits, the depth word's
                                   //    and the depth bias's parameters; the texture unit (texture.hex,
                                   //    S, T, Q commands, the texture record), two frame counters;
                                   // 7: the conventions' parameters PIXEL_CENTER, FILL_RULE,
                                   //    DEPTH_ROUNDING and COLOR_ROUNDING
                                   // 8: every rastersim_core parameter under its own name
                                   //    (MAX_MEMORY_LATENCY ...), RS_CORE_PARAMETERS_PASSED

// Where the triangles came from, recorded in the manifest and in the regeneration command.
struct Source {
  std::string kind;   // "scene", "file", "random" or "suite"
  std::string name;   // scene or suite name, or the input file's name (without its folder)
  int64_t count = 0;  // random: triangles
  uint64_t seed = 0;  // random: seed
  std::string camera; // scene or file: the camera flags given (3D inputs), as command-line words
  std::string texture; // scene or file with the texture unit: the texture flags given, as command-line words
  // The words of `rastersim vectors` that select these triangles (a file by its bare name).
  std::string arguments() const;
};

struct PackageOptions {
  // Empty: the RTL sources are copied into rtl/ (self-contained). Otherwise the package refers to
  // the RTL folder at this path relative to the package (vectors/ in this repository: ../../rtl).
  std::string rtl_path;
  // Empty: the testbench (rastersim_vectors_tb.v, the same for every package) is copied into the
  // package. Otherwise its scripts use the one in this folder relative to the package (vectors/ in
  // this repository: ../../testbench/vectors, so that the repository keeps one copy).
  std::string testbench_path;
  // true: the package tests rastersim_core with rastersim_memory_model.v (the profile's latency and
  // back-pressure pattern) on its memory port; false: rastersim_top with its on-chip memory, which
  // has no back-pressure (memory_stall_percent must be 0).
  bool external_memory = false;
};

// The word layouts of the vector files for one profile; texture.hex (the texture memory image)
// only in a package with the texture unit.
struct Layouts {
  WordLayout commands, texture, triangles, setup, fragments, depth, color, frame;
  bool texture_unit = false;
};
Layouts make_layouts(const Profile& profile);

struct PackageFile {
  std::string path;     // relative, '/' separated
  std::string content;
  bool executable = false;
};

struct Package {
  std::vector<PackageFile> files;  // manifest.json last
  int64_t triangles = 0, drawn = 0, fragments = 0, cycles = 0;
};

// Runs the model on the triangles (checked and snapped) and assembles every file in memory. With
// the profile's texture unit the texture unit samples `texture` (none: one white texel).
Package build_package(const Profile& profile, const std::vector<SnappedTriangle>& triangles, const Source& source,
                      const PackageOptions& options, const TextureBinding& texture = {});

// Throws InputError (naming --out) unless out_dir can receive a package: its parent folder exists
// and out_dir is missing, an empty folder, or (with `force`) a folder holding a package.
void check_package_dir(const std::string& out_dir, bool force);

// Checks as above, then writes the package into a temporary folder beside out_dir and renames it into place, so that a
// failure leaves nothing behind. out_dir may be missing or empty; an existing package (a folder
// with a rastersim-vectors manifest.json) is replaced only with `force`. Throws InputError naming
// --out and the problem. `temporary_folder` (optional) is told of each hidden folder the write
// makes (true) and when it is gone or renamed into place (false), so that an interrupted process
// can remove it (the CLI's signal handler: cli/outputs.h remember_temporary_folder).
using TemporaryFolderHook = void (*)(const std::string& path, bool exists);
void write_package(const Package& package, const std::string& out_dir, bool force,
                   TemporaryFolderHook temporary_folder = nullptr);

// The most fragments a package may hold. A package carries every expected fragment, in memory while
// it is built (about 175 bytes each: 1.4 GB peak for 8 million) and on disk (about 35 bytes each),
// and a Verilog simulator replays them all; beyond this a frame is split into several packages.
constexpr int64_t kMaxPackageFragments = 8'000'000;

// CRC-32 (IEEE 802.3, reflected, as zlib and `gzip -l`), written as in the manifest: "0x%08x".
uint32_t crc32(const std::string& bytes);

// The generator, as the manifest names it: "rastersim <project version>".
std::string generator_name();

}  // namespace rastersim::vectors
