// Z-buffer memory model (SystemC) behind the memory port of rastersim_core (contract in
// rtl/zbuffer.sv and docs/systemc.md): the words of rastersim::ZBufferMemory (model/zbuffer_memory.h),
// read latency L = memory_latency, and back-pressure from the seeded stall pattern: in frame cycle
// c, rd_ready is low when memory_stalls(memory_stall_seed, memory_stall_percent, c). Cycle 0 is the
// first cycle with clear_done high; the clear itself takes one cycle after reset.
// The runtime settings (latency, stall pattern, depth clear value) come from configure() and take
// effect at the next reset, as the core samples its cfg_* ports during reset.
#pragma once

#include <systemc>

#include <cstdint>
#include <string>
#include <vector>

#include "model/profile.h"
#include "model/zbuffer_memory.h"

namespace rastersim::systemc {

class ZBufferMemoryModel : public sc_core::sc_module {
 public:
  sc_core::sc_in<bool> clk;
  sc_core::sc_in<bool> rst;
  sc_core::sc_out<bool> clear_done;
  // Read port: a read taken in c (rd_valid & rd_ready) has its word on rd_depth in c + L.
  sc_core::sc_in<bool> rd_valid;
  sc_core::sc_out<bool> rd_ready;
  sc_core::sc_in<uint32_t> rd_addr;
  sc_core::sc_out<uint32_t> rd_depth;
  // Write port: always taken, lands at the end of the cycle.
  sc_core::sc_in<bool> wr_depth_en, wr_color_en;
  sc_core::sc_in<uint32_t> wr_addr, wr_depth, wr_rgb;

  SC_HAS_PROCESS(ZBufferMemoryModel);
  // The profile's width and height size the memory; its runtime settings are the first configure().
  ZBufferMemoryModel(sc_core::sc_module_name name, const Profile& profile);

  // Latency, stall pattern and clear value for the frames after the next reset. The geometry must
  // be the constructor's.
  void configure(const Profile& profile);

  const ZBufferMemory& memory() const { return memory_; }
  int64_t refused_reads() const { return refused_; }  // cycles with rd_valid high and rd_ready low
  // An access outside the memory since the last reset (an RTL bug), or empty.
  const std::string& error() const { return error_; }

 private:
  void clocked();

  Profile pending_, active_;
  ZBufferMemory memory_;
  struct Read {
    uint32_t depth = 0;
  };
  std::vector<Read> in_flight_;  // by data cycle modulo L + 1
  bool in_reset_ = false;
  bool cleared_ = false;
  int64_t cycle_ = 0;            // frame cycle that starts at the current edge
  bool ready_ = false;           // rd_ready during cycle_
  int64_t refused_ = 0;
  std::string error_;
};

}  // namespace rastersim::systemc
