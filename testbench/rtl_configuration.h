// A verilated rastersim_top (class V) as a runnable configuration, with the compile-time checks
// that the RTL's derived widths and encodings equal the model's. Included by the generated table of
// built configurations (rtl_configs.cpp) and by a module built on demand (testbench/ondemand/).
#pragma once

#include "model/widths.h"
#include "testbench/built_parameters.h"
#include "testbench/rtl_harness.h"

namespace rastersim::rtl::detail {

// The RTL core publishes its derived widths (rastersim_core.sv, /*verilator public*/ localparams);
// they must equal rastersim::derive_widths of the same profile parameters, field by field.
template <class Top>
constexpr bool widths_agree() {
  constexpr int plane_bits = depth_plane_bits(int(Top::P_Z_BITS), int(Top::P_DEPTH_EXPONENT_BITS));
  static_assert(int(Top::DEPTH_PLANE_BITS) == plane_bits, "RTL depth plane bits differ from the profile's");
  constexpr Widths w = derive_widths(int(Top::P_WIDTH), int(Top::P_HEIGHT), int(Top::P_SUBPIXEL_BITS), plane_bits,
                                     int(Top::P_Z_GUARD_BITS));
  static_assert(int(Top::GUARD_BITS) == w.guard_bits, "RTL guard_bits differs from derive_widths");
  static_assert(int(Top::COORD_BITS) == w.coord_bits, "RTL coord_bits differs from derive_widths");
  static_assert(int(Top::DELTA_BITS) == w.delta_bits, "RTL delta_bits differs from derive_widths");
  static_assert(int(Top::AREA_BITS) == w.area_bits, "RTL area_bits differs from derive_widths");
  static_assert(int(Top::EDGE_BITS) == w.edge_bits, "RTL edge_bits differs from derive_widths");
  static_assert(int(Top::EDGE_STEP_X_BITS) == w.edge_step_x_bits, "RTL edge_step_x_bits differs from derive_widths");
  static_assert(int(Top::EDGE_STEP_Y_BITS) == w.edge_step_y_bits, "RTL edge_step_y_bits differs from derive_widths");
  static_assert(int(Top::SPAN_REM_BITS) == w.span_rem_bits, "RTL span_rem_bits differs from derive_widths");
  static_assert(int(Top::DIVIDER_BITS) == w.divider_bits, "RTL divider_bits differs from derive_widths");
  static_assert(int(Top::Z_REG_BITS) == w.z_reg_bits, "RTL z_reg_bits differs from derive_widths");
  static_assert(int(Top::COLOR_REG_BITS) == w.color_reg_bits, "RTL color_reg_bits differs from derive_widths");
  static_assert(int(Top::X_BITS) == w.x_bits, "RTL x_bits differs from derive_widths");
  static_assert(int(Top::Y_BITS) == w.y_bits, "RTL y_bits differs from derive_widths");
  static_assert(int(Top::ADDR_BITS) == w.addr_bits, "RTL addr_bits differs from derive_widths");
  constexpr SetupTiming t = setup_timing(w, int(Top::P_SUBPIXEL_BITS), plane_bits, int(Top::P_SETUP_INTERVAL),
                                         int(Top::P_TEXTURE) != 0);
  static_assert(int(Top::SETUP_DRAWN_LATENCY) == t.drawn_latency, "RTL setup latency differs from setup_timing");
  static_assert(int(Top::SETUP_TEXTURED_DRAWN_LATENCY) == t.textured_drawn_latency,
                "RTL textured setup latency differs from setup_timing");
  static_assert(int(Top::TEXTURE_REG_BITS) == w.texture_reg_bits, "RTL texture_reg_bits differs from derive_widths");
  static_assert(int(Top::SETUP_REJECTED_LATENCY) == t.rejected_latency, "RTL rejected latency differs from setup_timing");
  static_assert(int(Top::WALKER_LOAD_CYCLES) == w.walker_load_cycles, "RTL walker_load_cycles differs");
  return true;
}

// The encodings of rastersim_pkg (rtl/rastersim_pkg.sv), as rastersim_core publishes them in one word
// (ENCODINGS), laid out from the C++ enums they stand for.
constexpr uint64_t enum_encodings() {
  uint64_t word = 0;
  int at = 0;
  auto put = [&](int value, int bits) {
    word |= uint64_t(value) << at;
    at += bits;
  };
  for (DepthFunc f : {DepthFunc::Never, DepthFunc::Less, DepthFunc::Equal, DepthFunc::LEqual, DepthFunc::Greater,
                      DepthFunc::NotEqual, DepthFunc::GEqual, DepthFunc::Always})
    put(int(f), 3);
  for (CullMode c : {CullMode::None, CullMode::Back, CullMode::Front}) put(int(c), 2);
  put(int(FrontFace::CCW), 1), put(int(FrontFace::CW), 1);
  put(int(Traversal::BBox), 1), put(int(Traversal::Span), 1);
  put(int(Shading::Flat), 1), put(int(Shading::Gouraud), 1);
  for (SetupStatus s : {SetupStatus::Drawn, SetupStatus::Degenerate, SetupStatus::Culled, SetupStatus::Offscreen,
                       SetupStatus::NoCentre})
    put(int(s), 3);
  put(int(PixelCenter::Half), 1), put(int(PixelCenter::Corner), 1);
  for (FillRule f : {FillRule::TopLeft, FillRule::TopRight, FillRule::BottomLeft, FillRule::BottomRight}) put(int(f), 2);
  put(int(Rounding::Nearest), 1), put(int(Rounding::Truncate), 1);
  return word;
}

template <class V>
RtlResult run_configuration(const Profile& p, const std::vector<SnappedTriangle>& tris, const RtlOptions& options) {
  static_assert(widths_agree<CoreOf<V>>());
  static_assert(uint64_t(CoreOf<V>::ENCODINGS) == enum_encodings(),
                "an RTL encoding (rastersim_pkg) differs from its C++ enum");
  return run_verilated<V>(p, tris, options);
}

}  // namespace rastersim::rtl::detail
