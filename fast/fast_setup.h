// The setup's fast path: the specification's front stage (TriangleSetup::front), then the depth
// and colour planes from the vertex differences in 64-bit arithmetic where the triangle's values
// allow it, and no planes along the left edges (the fast walks enter rows with
// ZAdder::enter_row_at). Every other field equals TriangleSetup::run's, and so does every
// WidthOverflow it throws; tests/test_fast_path.cpp checks both.
#pragma once

// Relative, as in model/: installed, these headers are reached as <rastersim/fast/...>.
#include "../model/triangle_setup.h"

namespace rastersim {

void fast_set_up(const TriangleSetup& setup, const SnappedTriangle& tri, SetupResult& r);

}  // namespace rastersim
