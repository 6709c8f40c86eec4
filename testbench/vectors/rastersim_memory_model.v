`timescale 1ns / 1ps
// Frame memory model for the test-vector packages of rastersim_core (docs/vectors.md): the depth
// and colour words behind the core's memory port (contract in rtl/zbuffer.sv), with read latency
// LATENCY and the model's back-pressure pattern (rastersim_stall_pattern below): in frame cycle c,
// rd_ready is low when the pattern of (STALL_SEED, STALL_PERCENT) stalls c. The same seed gives the same refused cycles as the model and
// the SystemC memory model, so a package of the core stays cycle-exact under back-pressure.
// Simulation only (plain Verilog-2005, Icarus and Verilator): a board puts its own memory here.
//
// Timing (as the SystemC model): the words are cleared during reset; clear_done rises in the first
// cycle after rst falls, which is frame cycle 0. A read taken in cycle c (rd_valid && rd_ready)
// reads the word before c's write and has it on rd_depth in c + LATENCY. Writes land at the end of
// their cycle. The read-back port gives the word of readback_addr one cycle later.
module rastersim_memory_model #(
  parameter integer WIDTH = 64,
  parameter integer HEIGHT = 48,
  parameter integer Z_BITS = 24,
  parameter integer ADDR_BITS = 12,       // bits of a word address y * WIDTH + x
  parameter integer LATENCY = 1,          // 1 .. 64
  parameter integer STALL_PERCENT = 0,    // 0 .. 90
  parameter integer STALL_SEED = 1        // 0 .. 2^31 - 1
) (
  input  wire clk,
  input  wire rst,
  input  wire [Z_BITS-1:0] depth_clear,   // what every depth word reads as after the clear
  output reg  clear_done,
  input  wire rd_valid,
  output reg  rd_ready,
  input  wire [ADDR_BITS-1:0] rd_addr,
  output wire [Z_BITS-1:0] rd_depth,
  input  wire wr_depth_en,
  input  wire wr_color_en,
  input  wire [ADDR_BITS-1:0] wr_addr,
  input  wire [Z_BITS-1:0] wr_depth,
  input  wire [23:0] wr_rgb,
  input  wire [ADDR_BITS-1:0] readback_addr,
  output reg  [Z_BITS-1:0] readback_depth,
  output reg  [23:0] readback_rgb,
  output reg  [31:0] refused_reads,       // cycles with rd_valid high and rd_ready low
  output reg  [31:0] bad_accesses         // reads or writes outside the memory (a bug of the port)
);
  localparam integer WORDS = WIDTH * HEIGHT;
  // verilator lint_off WIDTH
  localparam [ADDR_BITS:0] WORDS_A = WORDS;  // word addresses are below this
  // verilator lint_on WIDTH

  reg [Z_BITS-1:0] depth_mem [0:WORDS-1];
  reg [23:0] color_mem [0:WORDS-1];
  reg [Z_BITS-1:0] read_pipe [1:LATENCY];  // read_pipe[k]: the word read k cycles ago
  reg [63:0] frame_cycle;                  // the frame cycle now running (valid with clear_done)
  integer a, k;

  // Whether the next frame cycle (0 until clear_done) refuses reads.
  wire next_stalls;
  rastersim_stall_pattern #(.SEED(STALL_SEED), .PERCENT(STALL_PERCENT)) pattern (
    .frame_cycle(clear_done ? frame_cycle + 64'd1 : 64'd0), .stalls(next_stalls));

  wire read_in_range = {1'b0, rd_addr} < WORDS_A;
  wire write_in_range = {1'b0, wr_addr} < WORDS_A;
  wire readback_in_range = {1'b0, readback_addr} < WORDS_A;
  assign rd_depth = read_pipe[LATENCY];

  // The words and the read pipeline change with blocking assignments in this one process, in the
  // order of the cycle: a simulation model, not synthesizable RTL (lint_waivers.vlt).
  always @(posedge clk) begin
    if (rst) begin
      for (a = 0; a < WORDS; a = a + 1) begin
        depth_mem[a] = depth_clear;
        color_mem[a] = 24'd0;
      end
      for (k = 1; k <= LATENCY; k = k + 1) read_pipe[k] = {Z_BITS{1'b0}};
      clear_done <= 1'b0;
      rd_ready <= 1'b0;
      frame_cycle <= 64'd0;
      refused_reads <= 32'd0;
      bad_accesses <= 32'd0;
    end else if (!clear_done) begin
      clear_done <= 1'b1;  // frame cycle 0 starts
      rd_ready <= !next_stalls;
    end else begin
      // The cycle frame_cycle ends at this edge: its read (of the words before its write), its write.
      for (k = LATENCY; k >= 2; k = k - 1) read_pipe[k] = read_pipe[k - 1];
      read_pipe[1] = rd_valid && rd_ready && read_in_range ? depth_mem[rd_addr] : {Z_BITS{1'b0}};
      if (rd_valid && !rd_ready) refused_reads <= refused_reads + 32'd1;
      if ((rd_valid && rd_ready && !read_in_range) || ((wr_depth_en || wr_color_en) && !write_in_range)) begin
        $display("rastersim_memory_model: an access outside the memory in cycle %0d (read %b of word %0d, write %b of word %0d)",
                 frame_cycle, rd_valid && rd_ready, rd_addr, wr_depth_en || wr_color_en, wr_addr);
        bad_accesses <= bad_accesses + 32'd1;
      end
      if (wr_depth_en && write_in_range) depth_mem[wr_addr] = wr_depth;
      if (wr_color_en && write_in_range) color_mem[wr_addr] = wr_rgb;
      frame_cycle <= frame_cycle + 64'd1;
      rd_ready <= !next_stalls;
    end
    readback_depth <= readback_in_range ? depth_mem[readback_addr] : {Z_BITS{1'b0}};
    readback_rgb <= readback_in_range ? color_mem[readback_addr] : 24'd0;
  end
endmodule

// The model's back-pressure pattern (model/zbuffer_memory.h, memory_stalls): frame cycle c stalls
// when splitmix64's finalizer of SEED * 0x9E3779B97F4A7C15 + c, modulo 100, is below PERCENT. The
// frame memory model and the testbench's texture memory (texture_refuse) use it.
module rastersim_stall_pattern #(
  parameter integer SEED = 1,     // 0 .. 2^31 - 1
  parameter integer PERCENT = 0   // 0 .. 90
) (
  input  wire [63:0] frame_cycle,
  output wire stalls
);
  // verilator lint_off WIDTH
  localparam [63:0] SEED64 = SEED;  // non-negative: zero-extended
  localparam [63:0] PERCENT64 = PERCENT;
  // verilator lint_on WIDTH
  wire [63:0] x0 = SEED64 * 64'h9E3779B97F4A7C15 + frame_cycle;
  wire [63:0] x1 = (x0 ^ (x0 >> 30)) * 64'hBF58476D1CE4E5B9;
  wire [63:0] x2 = (x1 ^ (x1 >> 27)) * 64'h94D049BB133111EB;
  wire [63:0] x3 = x2 ^ (x2 >> 31);
  assign stalls = PERCENT64 > 64'd0 && (x3 % 64'd100) < PERCENT64;
endmodule
