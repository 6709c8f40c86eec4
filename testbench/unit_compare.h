// One unit of a design checked against the model's twin (docs/verification.md "Checking one
// unit: cosim --unit"): the unit's inputs for a frame, made from the model's run of it, and the
// comparison of what the unit reported with the model's, as a FunctionalReport of mismatches.
#pragma once

#include <string>
#include <vector>

#include "testbench/dut/unit_records.h"
#include "testbench/functional_compare.h"
#include "testbench/rtl_backend.h"

namespace rastersim::verify {

// The compare modes a unit takes: setup stream; walker stream or triangle; zbuffer stream or frame.
// Empty when `mode` is one of them, else why not.
std::string unit_mode_error(dut::Unit unit, CompareMode mode);

// The unit's inputs: setup the frame's triangles; the walker the model's setup records of the
// drawn triangles (the frame's shading); the z-buffer the model's fragments (`model` is
// rtl::run_model's run of the frame). `seed` sets the walker's frag_ready pattern.
dut::UnitFrame unit_frame(dut::Unit unit, const Profile& profile, const std::vector<SnappedTriangle>& triangles,
                          const rtl::RtlResult& model, uint64_t seed);

// setup: each decision's status in order, each record field by field in order (the model's setup
// with the colour planes, whatever the shading); walker: the fragments (triangle, pixel, depth
// word, colour) by `mode`; zbuffer: each fragment's depth-test result in order (not in frame
// mode) and the final buffers word for word.
FunctionalReport compare_unit(const dut::UnitFrame& frame, const rtl::RtlResult& model, const dut::UnitResult& design,
                              CompareMode mode, const Tolerance& tolerance = {}, size_t max_mismatches = 10);

// The unit's cycle (from the first after reset) nearest a mismatch, for its waveform's marker: the
// output the mismatch names (a fragment, a depth-test result, a record, a decision), else the
// frame's end.
int64_t unit_design_cycle(const Mismatch& m, const dut::UnitFrame& frame, const dut::UnitResult& design);

}  // namespace rastersim::verify
