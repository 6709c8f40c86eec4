// The profile's run-time keys on a verilated top's cfg_* inputs that rastersim's core and the
// verification interface share (depth test, clear value, culling, shading), in their encodings.
#pragma once

#include "model/profile.h"

namespace rastersim {

template <class Top>
void drive_frame_config(Top& top, const Profile& p) {
  top.cfg_depth_func = uint8_t(p.depth_func);
  top.cfg_depth_write = p.depth_write;
  top.cfg_depth_clear = p.depth_clear_value();
  top.cfg_cull = uint8_t(p.cull);
  top.cfg_front_face = p.front_face == FrontFace::CW;
  top.cfg_shading = p.shading == Shading::Gouraud;
}

}  // namespace rastersim
