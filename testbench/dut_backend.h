// A user's design behind the verification interface (docs/verification.md): its file list read,
// verilated on demand into the module cache (modules.h dut_library) and run frame by frame.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "model/profile.h"
#include "testbench/dut/dut_run.h"
#include "testbench/modules.h"

namespace rastersim::dut {

// The design's files from a `.f` file list or a folder (every .sv and .v file in it, sorted, the
// folder an include folder). A file list holds one item a line: a source file, `+incdir+DIR`,
// `-F LIST` or `-f LIST` (a nested list); `//` and `#` start comments; paths are relative to the
// list that names them. Throws InputError naming the list, the line and the problem (a missing
// file, an unknown option).
modules::DutDesign read_design(const std::string& list_or_folder, const std::string& top);

// The -G options the harness gives every design: the interface's parameters from the profile
// (WIDTH, HEIGHT, SUBPIXEL_BITS, Z_BITS), then the user's NAME=value options in order (a user's
// option for one of them replaces it). Throws InputError for an option that is not NAME=value.
std::vector<std::string> design_parameters(const Profile& profile, const std::vector<std::string>& options);
// The same for a unit (docs/verification.md "Checking one unit"): also FRACTION_BITS (F, the plane
// registers' fraction bits) and, for the walker, AUX_BITS (the width of rec_aux).
std::vector<std::string> unit_parameters(Unit unit, const Profile& profile, const std::vector<std::string>& options);
std::optional<Unit> parse_unit(const std::string& text);

// Empty when a design behind the verification interface can be checked at `profile`; otherwise
// why not (the interface carries the fixed-point depth word, no texture and no depth bias).
std::string interface_error(const Profile& profile);

class Design {
 public:
  // Loads a library built by dut_library; throws std::runtime_error when it is not one of this
  // program (or, with `unit`, not built for that unit).
  explicit Design(const std::string& library_path, std::optional<Unit> unit = std::nullopt);
  // One frame; throws std::runtime_error with the harness's sentence when the design stalls.
  rtl::RtlResult run(const Profile& profile, const std::vector<SnappedTriangle>& triangles,
                     const DutRunOptions& options = {}) const;
  // One unit's frame (a library built for a unit); throws as run does.
  UnitResult run_unit(const UnitFrame& frame, const DutRunOptions& options = {}) const;
  // The design's top has the memory port (docs/verification.md "The memory port"): the harness's
  // memory holds its buffers; otherwise it keeps them and has the read-back port.
  bool has_memory_port() const { return memory_port_; }

 private:
  bool memory_port_ = false;
  RunFunction run_ = nullptr;
  UnitRunFunction run_unit_ = nullptr;
};

}  // namespace rastersim::dut
