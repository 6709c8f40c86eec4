#include "testbench/systemc/texture_memory_model.h"

#include "model/zbuffer_memory.h"

namespace rastersim::systemc {

TextureMemoryModel::TextureMemoryModel(sc_core::sc_module_name name)
    : sc_core::sc_module(name), in_flight_(size_t(pending_profile_.texture_latency) + 1) {
  SC_METHOD(clocked);
  sensitive << clk.pos();
  dont_initialize();
}

void TextureMemoryModel::configure(const Profile& profile, const TextureBinding& texture) {
  pending_profile_ = profile;
  pending_texture_ = texture;
}

uint32_t TextureMemoryModel::texel(int bank, uint32_t address) {
  const int i = int(address & 511u) * 2 + bank % 2, j = int(address >> 9) * 2 + bank / 2;
  const Texture* t = active_texture_.texture.get();
  const int width = t ? 1 << t->log2_width() : 1, height = t ? 1 << t->log2_height() : 1;
  if (i >= width || j >= height) {
    // A bilinear lookup of a texture narrower than two texels reads a bank with no texel; the
    // unit weighs that texel 0. Only a read of a row or column beyond the texture is an error.
    if (i >= std::max(width, 2) || j >= std::max(height, 2)) {
      if (error_.empty())
        error_ = "read of texel (" + std::to_string(i) + ", " + std::to_string(j) + ") of a " + std::to_string(width) +
                 " x " + std::to_string(height) + " texture in cycle " + std::to_string(cycle_);
    }
    return 0;
  }
  return t ? t->texel(i, j) : 0xFFFFFFu;
}

void TextureMemoryModel::clocked() {
  if (rst.read()) {
    if (!in_reset_) {  // first reset cycle: take the new settings (the RTL loads its texels now)
      active_profile_ = pending_profile_;
      active_texture_ = pending_texture_;
      in_flight_.assign(size_t(active_profile_.texture_latency) + 1, sc_dt::sc_bv<kBanks * kTexelBits>());
      refused_ = 0;
      error_.clear();
      in_reset_ = true;
    }
    started_ = false;
    cycle_ = 0;
    ready_ = false;
    rd_ready.write(false);
    return;
  }
  in_reset_ = false;
  const int latency = active_profile_.texture_latency;
  if (!started_) {
    started_ = true;  // frame cycle 0 starts now, as the z-buffer memory model's
  } else {
    // The cycle `cycle_` ends at this edge: take its read.
    if (rd_valid.read()) {
      if (!ready_) {
        ++refused_;
      } else {
        const sc_dt::sc_bv<kBanks * kAddressBits> address = rd_addr.read();
        sc_dt::sc_bv<kBanks * kTexelBits> texels;
        for (int b = 0; b < kBanks; ++b)
          texels.range(kTexelBits * b + kTexelBits - 1, kTexelBits * b) =
              texel(b, uint32_t(address.range(kAddressBits * b + kAddressBits - 1, kAddressBits * b).to_uint()));
        in_flight_[size_t((cycle_ + latency) % (latency + 1))] = texels;
      }
    }
    ++cycle_;
  }
  ready_ = !memory_stalls(uint64_t(active_profile_.texture_stall_seed), active_profile_.texture_stall_percent, cycle_);
  rd_ready.write(ready_);
  rd_texels.write(in_flight_[size_t(cycle_ % (latency + 1))]);
}

}  // namespace rastersim::systemc
