#include "testbench/systemc/command_fifo.h"

#include "testbench/core_ports.h"

namespace rastersim {

std::ostream& operator<<(std::ostream& out, const SnappedTriangle& t) {
  for (int k = 0; k < 3; ++k)
    out << (k ? " " : "") << t.v[k].x << " " << t.v[k].y << " " << t.v[k].z << " #" << std::hex
        << rtl::rgb_word(t.v[k].color) << std::dec;
  return out;
}

}  // namespace rastersim

namespace rastersim::systemc {

CommandFifo::CommandFifo(sc_core::sc_module_name name, int depth, int coord_bits)
    : sc_core::sc_module(name), fifo_("fifo", depth), coord_bits_(coord_bits) {
  in.bind(fifo_);
  SC_METHOD(clocked);
  sensitive << clk.pos();
  dont_initialize();
}

void CommandFifo::clocked() {
  SnappedTriangle head;
  if (rst.read()) {
    while (fifo_.nb_read(head)) {
    }
    holding_ = false;
    taken_ = 0;
  } else if (holding_ && cmd_valid.read() && cmd_ready.read()) {
    holding_ = false;  // taken in the cycle that ends now
    ++taken_;
  }
  if (!rst.read() && !holding_ && fifo_.nb_read(head)) {
    holding_ = true;
    rtl::drive_command(*this, head, coord_bits_);
    cmd_textured.write(head.textured);
    sc_core::sc_out<sc_dt::sc_bv<3 * kTextureVertexBits>>* words[3] = {&cmd_texture0, &cmd_texture1, &cmd_texture2};
    for (int k = 0; k < 3; ++k) {
      sc_dt::sc_bv<3 * kTextureVertexBits> word;
      const int64_t values[3] = {head.v[k].s, head.v[k].t, head.v[k].q};
      for (int c = 0; c < 3; ++c)
        word.range(c * kTextureVertexBits + kTextureVertexBits - 1, c * kTextureVertexBits) =
            sc_dt::sc_uint<kTextureVertexBits>(uint64_t(values[c]));
      words[k]->write(word);
    }
  }
  cmd_valid.write(holding_);
}

}  // namespace rastersim::systemc
