// Z-buffer unit (model/zbuffer.h): read, compare, conditional write of depth and colour through a
// memory port of read latency L = cfg_memory_latency (1 .. MAX_MEMORY_LATENCY). The memory is a
// separate unit behind the port: rtl/zbuffer_memory.sv on chip (rastersim_top), or any memory with
// the same contract on the ports of rastersim_core (the SystemC memory model, testbench/systemc/).
// A fragment is accepted in cycle c when frag_valid, no hazard and the memory takes its read
// request (mem_rd_valid & mem_rd_ready); its depth word arrives on mem_rd_depth in c+L, the depth
// test runs and the depth (if cfg_depth_write) and colour (on pass) writes go out in c+L.
// Read-after-write hazard: a fragment is accepted in c only if no fragment to the same address
// was accepted in c-L .. c-1 (frag_ready low meanwhile), so every read sees all earlier writes and
// the memory never needs to forward a pending write.
// Memory port contract (docs/rtl.md): after reset the memory clears itself (every word reads as
// the depth clear value, colour 0) and raises mem_clear_done, which starts the frame; a read
// request taken in c returns its word in exactly c+L; writes are always taken (no back-pressure)
// and land at the end of their cycle; mem_rd_ready may be low in any cycle (back-pressure).
module zbuffer #(
  parameter integer WIDTH = 640,
  parameter integer HEIGHT = 480,
  parameter integer Z_BITS = 24,
  parameter integer MAX_MEMORY_LATENCY = 64
) (
  input  wire clk,
  input  wire rst,
  input  wire [2:0] cfg_depth_func,  // RS_DEPTH_* (rastersim_widths.vh)
  input  wire       cfg_depth_write,
  input  wire [rs_ubits32(MAX_MEMORY_LATENCY)-1:0] cfg_memory_latency,
  output wire clear_done,            // the memory is cleared: the frame may start
  // Fragment from the walker (x, y) and the Z adder (z, rgb).
  input  wire frag_valid,
  output wire frag_ready,
  input  wire [rs_ubits32(WIDTH - 1)-1:0]  frag_x,
  input  wire [rs_ubits32(HEIGHT - 1)-1:0] frag_y,
  input  wire [Z_BITS-1:0] frag_z,
  input  wire [23:0]       frag_rgb,
  // Depth test result of the fragment accepted L cycles ago (its write cycle).
  output wire result_valid,
  output wire result_pass,
  output wire busy,  // a fragment accepted this cycle or in flight
  // Memory port: word address y * WIDTH + x.
  input  wire mem_clear_done,
  output wire mem_rd_valid,
  input  wire mem_rd_ready,
  output wire [rs_ubits32(WIDTH * HEIGHT - 1)-1:0] mem_rd_addr,
  input  wire [Z_BITS-1:0] mem_rd_depth,  // the word of the read taken L cycles ago
  output wire mem_wr_depth_en,
  output wire mem_wr_color_en,
  output wire [rs_ubits32(WIDTH * HEIGHT - 1)-1:0] mem_wr_addr,
  output wire [Z_BITS-1:0] mem_wr_depth,
  output wire [23:0]       mem_wr_rgb
);
`include "rastersim_widths.vh"
  `RS_REQUIRE(illegal_width, WIDTH >= 1 && WIDTH <= 4096, "zbuffer: WIDTH must be 1..4096")
  `RS_REQUIRE(illegal_height, HEIGHT >= 1 && HEIGHT <= 4096, "zbuffer: HEIGHT must be 1..4096")
  `RS_REQUIRE(illegal_z_bits, Z_BITS >= 1 && Z_BITS <= 32, "zbuffer: Z_BITS must be 1..32")  // the formal proofs use 2
  `RS_REQUIRE(illegal_latency, MAX_MEMORY_LATENCY >= 1 && MAX_MEMORY_LATENCY <= 64, "zbuffer: MAX_MEMORY_LATENCY must be 1..64")

  localparam integer X_BITS = rs_ubits32(WIDTH - 1);
  localparam integer Y_BITS = rs_ubits32(HEIGHT - 1);
  localparam integer ADDR_BITS = rs_ubits32(WIDTH * HEIGHT - 1);
  localparam [ADDR_BITS-1:0] WIDTH_A = WIDTH[ADDR_BITS-1:0];

  // In-flight fragments: a ring of RING = 2^RING_BITS >= MAX_MEMORY_LATENCY slots, one written every
  // cycle (slot now_slot_q). A slot is live from the cycle after its fragment was accepted through
  // that fragment's data cycle (accepted in c: live in c+1 .. c+L), exactly the window in which a
  // fragment to the same address must wait; its pixel (y, x) stays in flip-flops for the hazard
  // compare (no address adder on that path), its depth, colour and address for the write go
  // through a RAM (block RAM on an FPGA) read a cycle ahead.
  localparam integer RING_BITS = MAX_MEMORY_LATENCY > 2 ? $clog2(MAX_MEMORY_LATENCY) : 1;
  localparam integer RING = 1 << RING_BITS;
  localparam integer LATENCY_BITS = rs_ubits32(MAX_MEMORY_LATENCY);
  localparam integer DATA_BITS = ADDR_BITS + Z_BITS + 24;  // {address, depth, rgb}
  reg [RING_BITS-1:0] now_slot_q;     // the slot written at the end of this cycle
  reg [RING-1:0]      live_q;         // live slots but the last cycle's
  reg                 accepted_q;     // the last cycle's accept: its slot is live from now on
  reg [RING-1:0]      last_onehot_q;  // the slot written in the last cycle, one-hot
  // The live slots: the last cycle's accept enters through one flip-flop, so that the accept does
  // not fan out to every slot's live bit in its own cycle.
  wire [RING-1:0] live = live_q | (accepted_q ? last_onehot_q : {RING{1'b0}});
  localparam integer PIXEL_BITS = Y_BITS + X_BITS;  // {y, x}: one pixel, one address
  reg [PIXEL_BITS-1:0] ring_pixel_q [0:RING-1];
  reg [DATA_BITS-1:0] ring_data_q [0:RING-1];

  // Ages are taken modulo the ring size: the high bits of the latency are not needed for a slot.
  /* verilator lint_off UNUSEDSIGNAL */
  function automatic [RING_BITS-1:0] slot_of_age(input [RING_BITS-1:0] now, input [LATENCY_BITS-1:0] age);
    reg [LATENCY_BITS:0] wide_age;
    begin
      wide_age = {1'b0, age};
      slot_of_age = now - wide_age[RING_BITS-1:0];  // modulo RING (a power of two)
    end
  endfunction
  /* verilator lint_on UNUSEDSIGNAL */

  wire [ADDR_BITS-1:0] frag_addr = frag_y * WIDTH_A + {{(ADDR_BITS-X_BITS){1'b0}}, frag_x};
  wire [PIXEL_BITS-1:0] frag_pixel = {frag_y, frag_x};

  // Hazard: a live slot with the fragment's pixel; one comparator per slot, no age arithmetic.
  reg hazard;
  integer k;
  always @(*) begin
    hazard = 1'b0;
    for (k = 0; k < RING; k = k + 1)
      if (live[k] && ring_pixel_q[k] == frag_pixel) hazard = 1'b1;
  end
  wire in_flight = |live;

  // The read request does not depend on mem_rd_ready; the fragment is taken with it.
  wire can_accept = mem_clear_done && !hazard;
  assign clear_done = mem_clear_done;
  assign mem_rd_valid = frag_valid && can_accept;
  assign mem_rd_addr = frag_addr;
  assign frag_ready = can_accept && mem_rd_ready;
  wire accept = frag_valid && frag_ready;
  assign busy = accept || in_flight;

  // The fragment in its data cycle c+L: slot done_slot, live until the end of this cycle; its word
  // is on mem_rd_depth. Its data was read from the RAM in the cycle before (slot next_done_slot
  // then), or, at L = 1, is the fragment accepted in that cycle, kept in latest_q.
  wire [RING_BITS-1:0] done_slot = slot_of_age(now_slot_q, cfg_memory_latency);
  wire [RING_BITS-1:0] next_done_slot = done_slot + 1'b1;  // the same age one cycle on
  wire                 done_valid = live[done_slot];
  wire [RING-1:0]      done_onehot = {{(RING-1){1'b0}}, 1'b1} << done_slot;
  reg  [DATA_BITS-1:0] ram_read_q, latest_q;
  wire [DATA_BITS-1:0] frag_data = {frag_addr, frag_z, frag_rgb};
  wire [DATA_BITS-1:0] done_data = cfg_memory_latency == LATENCY_BITS'(1) ? latest_q : ram_read_q;
  wire [ADDR_BITS-1:0] done_addr = done_data[Z_BITS + 24 +: ADDR_BITS];
  wire [Z_BITS-1:0]    done_z = done_data[24 +: Z_BITS];
  wire [23:0]          done_rgb = done_data[23:0];
  reg pass;
  always @(*) begin
    case (cfg_depth_func)
      RS_DEPTH_NEVER: pass = 1'b0;
      RS_DEPTH_LESS: pass = done_z < mem_rd_depth;
      RS_DEPTH_EQUAL: pass = done_z == mem_rd_depth;
      RS_DEPTH_LEQUAL: pass = done_z <= mem_rd_depth;
      RS_DEPTH_GREATER: pass = done_z > mem_rd_depth;
      RS_DEPTH_NOTEQUAL: pass = done_z != mem_rd_depth;
      RS_DEPTH_GEQUAL: pass = done_z >= mem_rd_depth;
      default: pass = 1'b1;  // RS_DEPTH_ALWAYS
    endcase
  end
  assign result_valid = done_valid;
  assign result_pass = pass;
  assign mem_wr_depth_en = done_valid && pass && cfg_depth_write;
  assign mem_wr_color_en = done_valid && pass;
  assign mem_wr_addr = done_addr;
  assign mem_wr_depth = done_z;
  assign mem_wr_rgb = done_rgb;

  always @(posedge clk) begin
    if (rst) begin
      now_slot_q <= {RING_BITS{1'b0}};
      live_q <= {RING{1'b0}};
      accepted_q <= 1'b0;
    end else begin
      now_slot_q <= now_slot_q + 1'b1;
      // The done slot retires; the slot written now (the same one at L = RING) takes the accept,
      // one cycle later through accepted_q.
      live_q <= live & ~done_onehot;
      accepted_q <= accept;
    end
  end
  // Data (no reset: a slot's data is read only while it is live).
  always @(posedge clk) begin
    ring_pixel_q[now_slot_q] <= frag_pixel;
    ring_data_q[now_slot_q] <= frag_data;
    ram_read_q <= ring_data_q[next_done_slot];
    last_onehot_q <= {{(RING-1){1'b0}}, 1'b1} << now_slot_q;
    latest_q <= frag_data;
  end
endmodule
