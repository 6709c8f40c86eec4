#include "testbench/systemc/zbuffer_memory_model.h"

#include <stdexcept>
#include <string>

namespace rastersim::systemc {

ZBufferMemoryModel::ZBufferMemoryModel(sc_core::sc_module_name name, const Profile& profile)
    : sc_core::sc_module(name), pending_(profile), active_(profile), memory_(profile),
      in_flight_(size_t(profile.memory_latency) + 1) {
  SC_METHOD(clocked);
  sensitive << clk.pos();
  dont_initialize();
}

void ZBufferMemoryModel::configure(const Profile& profile) {
  if (profile.width != active_.width || profile.height != active_.height)
    throw std::invalid_argument("the z-buffer memory model holds " + std::to_string(active_.width) + "x" +
                                std::to_string(active_.height) + " words, not " + std::to_string(profile.width) +
                                "x" + std::to_string(profile.height));
  pending_ = profile;
}

void ZBufferMemoryModel::clocked() {
  if (rst.read()) {
    if (!in_reset_) {  // first reset cycle: take the new settings and clear the words
      active_ = pending_;
      memory_ = ZBufferMemory(active_);
      in_flight_.assign(size_t(active_.memory_latency) + 1, Read{});
      refused_ = 0;
      error_.clear();
      in_reset_ = true;
    }
    cleared_ = false;
    cycle_ = 0;
    ready_ = false;
    clear_done.write(false);
    rd_ready.write(false);
    return;
  }
  in_reset_ = false;
  const int latency = active_.memory_latency;
  if (!cleared_) {
    cleared_ = true;  // the words were cleared at reset: frame cycle 0 starts now
  } else {
    // The cycle `cycle_` ends at this edge: take its read (before its write, which goes to another
    // address: the z-buffer unit never reads a word with a write pending) and its write.
    const uint32_t words = uint32_t(memory_.depth().size());
    if (rd_valid.read()) {
      if (!ready_) {
        ++refused_;
      } else if (rd_addr.read() >= words) {
        if (error_.empty()) error_ = "read of word " + std::to_string(rd_addr.read()) + " in cycle " + std::to_string(cycle_);
      } else {
        in_flight_[size_t((cycle_ + latency) % (latency + 1))].depth = memory_.read_depth(rd_addr.read());
      }
    }
    if (wr_depth_en.read() || wr_color_en.read()) {
      if (wr_addr.read() >= words) {
        if (error_.empty()) error_ = "write of word " + std::to_string(wr_addr.read()) + " in cycle " + std::to_string(cycle_);
      } else {
        memory_.write(wr_addr.read(), wr_depth_en.read(), wr_depth.read(), wr_color_en.read(), wr_rgb.read());
      }
    }
    ++cycle_;
  }
  ready_ = !memory_.stalls(cycle_);
  clear_done.write(true);
  rd_ready.write(ready_);
  rd_depth.write(in_flight_[size_t(cycle_ % (latency + 1))].depth);
}

}  // namespace rastersim::systemc
