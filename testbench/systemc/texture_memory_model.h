// Texture memory model (SystemC) behind the texture port of rastersim_core built with the texture
// unit (contract in rtl/texture_unit.sv; the RTL's memory is rtl/texture_memory.sv): four banks,
// bank 2 (j mod 2) + (i mod 2) holding texel column i, row j at word {j >> 1, i >> 1} of the
// port's 1024-texel address space; read latency Lt = texture_latency; back-pressure from the
// profile's texture stall pattern: in frame cycle c, rd_ready is low when
// memory_stalls(texture_stall_seed, texture_stall_percent, c) (model/zbuffer_memory.h), the cycles
// the model's texture unit waits in. Frame cycles count as the z-buffer memory model's: cycle 0 is
// the first cycle after reset. The texture (its texels; none bound: one white texel), latency and
// stall pattern come from configure() and take effect at the next reset.
#pragma once

#include <systemc>

#include <cstdint>
#include <string>
#include <vector>

#include "model/profile.h"
#include "model/texture_unit.h"

namespace rastersim::systemc {

class TextureMemoryModel : public sc_core::sc_module {
 public:
  static constexpr int kBanks = 4;
  static constexpr int kAddressBits = 18;  // per bank: {row >> 1, column >> 1}, 9 bits each
  static constexpr int kTexelBits = 24;

  sc_core::sc_in<bool> clk;
  sc_core::sc_in<bool> rst;
  // Read port: a read taken in c (rd_valid & rd_ready) has bank b's texel on
  // rd_texels[24 b +: 24] in c + Lt.
  sc_core::sc_in<bool> rd_valid;
  sc_core::sc_out<bool> rd_ready;
  sc_core::sc_in<sc_dt::sc_bv<kBanks * kAddressBits>> rd_addr;
  sc_core::sc_out<sc_dt::sc_bv<kBanks * kTexelBits>> rd_texels;

  SC_HAS_PROCESS(TextureMemoryModel);
  explicit TextureMemoryModel(sc_core::sc_module_name name);

  // The texture and the profile's texture latency and stall pattern, for the frames after the next reset.
  void configure(const Profile& profile, const TextureBinding& texture);

  int64_t refused_reads() const { return refused_; }  // cycles with rd_valid high and rd_ready low
  // A read outside the loaded texture since the last reset (an RTL bug), or empty.
  const std::string& error() const { return error_; }

 private:
  void clocked();
  // Bank b's word `address` as texels: column, row and the texel there (0 outside the texture).
  uint32_t texel(int bank, uint32_t address);

  Profile pending_profile_, active_profile_;
  TextureBinding pending_texture_, active_texture_;
  std::vector<sc_dt::sc_bv<kBanks * kTexelBits>> in_flight_;  // by data cycle modulo Lt + 1
  bool in_reset_ = false;
  bool started_ = false;
  int64_t cycle_ = 0;   // frame cycle that starts at the current edge
  bool ready_ = false;  // rd_ready during cycle_
  int64_t refused_ = 0;
  std::string error_;
};

}  // namespace rastersim::systemc
