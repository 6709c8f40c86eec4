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
  input  wire [2:0] cfg_depth_func,  // never, less, equal, lequal, greater, notequal, gequal, always
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

  localparam integer XB = rs_ubits32(WIDTH - 1);
  localparam integer AB = rs_ubits32(WIDTH * HEIGHT - 1);
  localparam [AB-1:0] WIDTH_A = WIDTH[AB-1:0];

  // In-flight fragments: a ring of 2^RB >= MAX_MEMORY_LATENCY entries, one written every cycle;
  // the entry of age k (1 .. L) holds the fragment accepted k cycles ago (valid: it was accepted).
  localparam integer RB = MAX_MEMORY_LATENCY > 2 ? $clog2(MAX_MEMORY_LATENCY) : 1;
  localparam integer RING = 1 << RB;
  localparam integer LB = rs_ubits32(MAX_MEMORY_LATENCY);
  reg [RB-1:0]     now_slot;  // the slot written at the end of this cycle
  reg              ring_valid [0:RING-1];
  reg [AB-1:0]     ring_addr [0:RING-1];
  reg [Z_BITS-1:0] ring_z [0:RING-1];
  reg [23:0]       ring_rgb [0:RING-1];

  // Ages are taken modulo the ring size: the high bits of wide_age are not needed.
  /* verilator lint_off UNUSEDSIGNAL */
  function automatic [RB-1:0] slot_of_age(input [RB-1:0] now, input [LB-1:0] age);
    reg [LB:0] wide_age;
    begin
      wide_age = {1'b0, age};
      slot_of_age = now - wide_age[RB-1:0];  // modulo RING (a power of two)
    end
  endfunction
  /* verilator lint_on UNUSEDSIGNAL */

  wire [AB-1:0] frag_addr = frag_y * WIDTH_A + {{(AB-XB){1'b0}}, frag_x};

  // Hazard and in-flight checks compare every ring slot in place, so their cost grows linearly
  // with the ring: slot s holds the fragment accepted age(s) = now_slot - s cycles ago (modulo
  // RING; 0 reads as RING, the slot overwritten at the end of this cycle).
  localparam integer CB = RB + 1 > LB ? RB + 1 : LB;  // ages 1 .. RING and latencies 1 .. MAX
  wire [CB-1:0] latency = CB'(cfg_memory_latency);
  reg hazard;
  reg in_flight;
  integer k;
  reg [RB-1:0] slot_age;
  reg [CB-1:0] age;
  always @(*) begin
    hazard = 1'b0;
    in_flight = 1'b0;
    for (k = 0; k < RING; k = k + 1) begin
      slot_age = now_slot - k[RB-1:0];
      age = slot_age == {RB{1'b0}} ? CB'(RING) : CB'(slot_age);
      if (age <= latency && ring_valid[k]) begin
        in_flight = 1'b1;
        if (ring_addr[k] == frag_addr) hazard = 1'b1;
      end
    end
  end

  // The read request does not depend on mem_rd_ready; the fragment is taken with it.
  wire can_accept = mem_clear_done && !hazard;
  assign clear_done = mem_clear_done;
  assign mem_rd_valid = frag_valid && can_accept;
  assign mem_rd_addr = frag_addr;
  assign frag_ready = can_accept && mem_rd_ready;
  wire accept = frag_valid && frag_ready;
  assign busy = accept || in_flight;

  // The fragment in its data cycle c+L: its word is on mem_rd_depth.
  wire [RB-1:0]     done_slot = slot_of_age(now_slot, cfg_memory_latency);
  wire              done_valid = ring_valid[done_slot];
  wire [Z_BITS-1:0] done_z = ring_z[done_slot];
  reg pass;
  always @(*) begin
    case (cfg_depth_func)
      3'd0: pass = 1'b0;
      3'd1: pass = done_z < mem_rd_depth;
      3'd2: pass = done_z == mem_rd_depth;
      3'd3: pass = done_z <= mem_rd_depth;
      3'd4: pass = done_z > mem_rd_depth;
      3'd5: pass = done_z != mem_rd_depth;
      3'd6: pass = done_z >= mem_rd_depth;
      default: pass = 1'b1;
    endcase
  end
  assign result_valid = done_valid;
  assign result_pass = pass;
  assign mem_wr_depth_en = done_valid && pass && cfg_depth_write;
  assign mem_wr_color_en = done_valid && pass;
  assign mem_wr_addr = ring_addr[done_slot];
  assign mem_wr_depth = done_z;
  assign mem_wr_rgb = ring_rgb[done_slot];

  always @(posedge clk) begin
    if (rst) begin
      now_slot <= {RB{1'b0}};
      for (k = 0; k < RING; k = k + 1) ring_valid[k] <= 1'b0;
    end else begin
      now_slot <= now_slot + 1'b1;
      ring_valid[now_slot] <= accept;
    end
  end
  always @(posedge clk) begin
    ring_addr[now_slot] <= frag_addr;
    ring_z[now_slot] <= frag_z;
    ring_rgb[now_slot] <= frag_rgb;
  end
endmodule
