// Command FIFO (SystemC): triangles from a host, written into an sc_fifo through the `in` export
// (blocking when full), presented one per valid/ready handshake on the command port of
// rastersim_core (cmd_*). The head of the FIFO sits in an output register: a triangle taken in
// cycle c is replaced by the next one in c+1, faster than the setup unit can take commands (at
// most one every two cycles), so a FIFO that the host keeps filled never delays the pipeline and
// the cycle model's "the command input is always valid" holds. Reset empties it.
#pragma once

#include <systemc>

#include <cstdint>
#include <ostream>

#include "model/triangle.h"
#include "model/widths.h"

namespace rastersim {
// sc_fifo prints its contents (sc_fifo::print); one line per triangle.
std::ostream& operator<<(std::ostream& out, const SnappedTriangle& t);
}  // namespace rastersim

namespace rastersim::systemc {

class CommandFifo : public sc_core::sc_module {
 public:
  sc_core::sc_in<bool> clk;
  sc_core::sc_in<bool> rst;
  // The host side: bind an sc_fifo_out<SnappedTriangle> port, or write through in->write(t).
  sc_core::sc_export<sc_core::sc_fifo_out_if<SnappedTriangle>> in;
  // The core side (rastersim_core's cmd_* ports); coordinates in two's complement of coord_bits.
  sc_core::sc_out<bool> cmd_valid;
  sc_core::sc_in<bool> cmd_ready;
  sc_core::sc_out<uint32_t> cmd_x0, cmd_y0, cmd_x1, cmd_y1, cmd_x2, cmd_y2;
  sc_core::sc_out<uint32_t> cmd_z0, cmd_z1, cmd_z2;
  sc_core::sc_out<uint32_t> cmd_rgb0, cmd_rgb1, cmd_rgb2;
  // Texture coordinates (a core with the texture unit reads them): cmd_textureK = {Q, T, S} of
  // vertex K, kTextureVertexBits each, two's complement.
  sc_core::sc_out<bool> cmd_textured;
  sc_core::sc_out<sc_dt::sc_bv<3 * kTextureVertexBits>> cmd_texture0, cmd_texture1, cmd_texture2;

  SC_HAS_PROCESS(CommandFifo);
  // depth: FIFO entries; coord_bits: the core's COORD_BITS (Vrastersim_sc_rastersim_core::COORD_BITS).
  CommandFifo(sc_core::sc_module_name name, int depth, int coord_bits);

  int64_t taken() const { return taken_; }  // triangles the core took since the last reset

 private:
  void clocked();

  sc_core::sc_fifo<SnappedTriangle> fifo_;
  int coord_bits_;
  bool holding_ = false;  // the output register holds a triangle
  int64_t taken_ = 0;
};

}  // namespace rastersim::systemc
