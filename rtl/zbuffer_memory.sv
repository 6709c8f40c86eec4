// Z-buffer memory on chip (model/zbuffer_memory.h): depth and colour words behind the z-buffer's
// memory port (rtl/zbuffer.sv states the port contract), with read latency
// L = cfg_memory_latency (1 .. MAX_MEMORY_LATENCY) and no back-pressure (rd_ready is high once
// cleared). A read taken in c is a synchronous RAM read at the end of c; L-1 delay registers (a
// ring) hold the word until c+L. Writes land at the end of their cycle.
// Fast clear: each word has a "written since the clear" bit, 64 bits per bitmap row; after reset
// the memory zeroes one row of both bitmaps per cycle (ceil(W H / 64) cycles), then raises
// clear_done. A word whose bit is 0 reads as cfg_depth_clear (depth) or 0 (colour); writes set
// the bit (per-bit write enable).
// Every read of the four memories is a plain registered read (the word, or the bitmap row and the
// bit's index); the written-bit select and the clear-value mux come after the register, so that
// synthesis maps the memories to synchronous block RAM (SB_RAM40_4K on an iCE40), a copy per read
// port.
`include "rastersim_pkg.sv"
module zbuffer_memory `RS_IMPORT #(
  parameter integer WIDTH = 640,
  parameter integer HEIGHT = 480,
  parameter integer Z_BITS = 24,
  parameter integer MAX_MEMORY_LATENCY = 64
) (
  input  wire clk,
  input  wire rst,
  // Sampled while rst is high and held for the frame.
  input  wire [Z_BITS-1:0] cfg_depth_clear,
  input  wire [rs_ubits32(MAX_MEMORY_LATENCY)-1:0] cfg_memory_latency,
  output reg  clear_done,
  // Read port: the word of a read taken in c is on rd_depth in c+L.
  input  wire rd_valid,
  output wire rd_ready,
  input  wire [rs_ubits32(WIDTH * HEIGHT - 1)-1:0] rd_addr,
  output wire [Z_BITS-1:0] rd_depth,
  // Write port.
  input  wire wr_depth_en,
  input  wire wr_color_en,
  input  wire [rs_ubits32(WIDTH * HEIGHT - 1)-1:0] wr_addr,
  input  wire [Z_BITS-1:0] wr_depth,
  input  `RS_TYPE(rgb_t)    wr_rgb,
  // Read-back port for the final memories (synchronous: data in the next cycle).
  input  wire [rs_ubits32(WIDTH * HEIGHT - 1)-1:0] readback_addr,
  output wire [Z_BITS-1:0] readback_depth,
  output `RS_TYPE(rgb_t)    readback_rgb
);
  // Release 5.006 of the linter reports the width functions as hiding themselves here despite the
  // file waiver in lint_waivers.vlt (which covers every other module); the names are unique.
  /* verilator lint_off VARHIDDEN */
`include "rastersim_widths.vh"
  `RS_REQUIRE(illegal_latency, MAX_MEMORY_LATENCY >= 1 && MAX_MEMORY_LATENCY <= 64, "zbuffer_memory: MAX_MEMORY_LATENCY must be 1..64")
  /* verilator lint_on VARHIDDEN */

  localparam integer ADDR_BITS = rs_ubits32(WIDTH * HEIGHT - 1);
  localparam integer WORDS = WIDTH * HEIGHT;
  localparam integer LATENCY_BITS = rs_ubits32(MAX_MEMORY_LATENCY);

  reg [Z_BITS-1:0] depth_clear_q;
  reg [LATENCY_BITS-1:0]     latency_q;
  always @(posedge clk) begin
    if (rst) begin
      depth_clear_q <= cfg_depth_clear;
      latency_q <= cfg_memory_latency;
    end
  end

  // Readable from C++ (public_flat_rd): the co-simulation reads the final memories directly
  // instead of W H cycles through the read-back port (which a test checks against them).
  reg [Z_BITS-1:0] depth_mem [0:WORDS-1] /*verilator public_flat_rd*/;
  reg [23:0]       color_mem [0:WORDS-1] /*verilator public_flat_rd*/;

  localparam integer ROWS = (WORDS + 63) / 64;
  localparam integer BITMAP_ROW_BITS = rs_ubits32(ROWS - 1);  // bitmap row address
  localparam integer LAST_ROW = ROWS - 1;
  localparam [BITMAP_ROW_BITS-1:0] LAST_ROW_A = LAST_ROW[BITMAP_ROW_BITS-1:0];
  reg [63:0] depth_written [0:ROWS-1] /*verilator public_flat_rd*/;
  reg [63:0] color_written [0:ROWS-1] /*verilator public_flat_rd*/;

  // Bitmap row and bit of a word address (address / 64, address % 64).
  /* verilator lint_off UNUSEDSIGNAL */
  function automatic [BITMAP_ROW_BITS-1:0] row_of(input [ADDR_BITS-1:0] address);
    reg [ADDR_BITS+5:0] wide;
    begin
      wide = {6'd0, address};
      row_of = wide[BITMAP_ROW_BITS+5:6];
    end
  endfunction
  function automatic [5:0] bit_of(input [ADDR_BITS-1:0] address);
    reg [ADDR_BITS+5:0] wide;
    begin
      wide = {6'd0, address};
      bit_of = wide[5:0];
    end
  endfunction
  /* verilator lint_on UNUSEDSIGNAL */

  reg [BITMAP_ROW_BITS-1:0] clear_row_q;
  always @(posedge clk) begin
    if (rst) begin
      clear_done <= 1'b0;
      clear_row_q <= {BITMAP_ROW_BITS{1'b0}};
    end else if (!clear_done) begin
      clear_row_q <= clear_row_q + 1'b1;
      if (clear_row_q == LAST_ROW_A) clear_done <= 1'b1;
    end
  end
  assign rd_ready = clear_done;

  // One write port (clear sweep, then word writes), the read port and the read-back port.
  always @(posedge clk) begin
    if (!clear_done) begin
      depth_written[clear_row_q] <= 64'd0;
      color_written[clear_row_q] <= 64'd0;
    end else begin
      if (wr_depth_en) begin
        depth_mem[wr_addr] <= wr_depth;
        depth_written[row_of(wr_addr)][bit_of(wr_addr)] <= 1'b1;
      end
      if (wr_color_en) begin
        color_mem[wr_addr] <= wr_rgb;
        color_written[row_of(wr_addr)][bit_of(wr_addr)] <= 1'b1;
      end
    end
  end

  // Read port: read_q and read_row_q are the synchronous reads of the request taken in the
  // previous cycle; read_bit_q picks the word's written bit out of its row.
  reg [Z_BITS-1:0] read_q;
  reg [63:0]       read_row_q;
  reg [5:0]        read_bit_q;
  wire [Z_BITS-1:0] read_value = read_row_q[read_bit_q] ? read_q : depth_clear_q;
  always @(posedge clk) begin
    if (rd_valid) begin
      read_q <= depth_mem[rd_addr];
      read_row_q <= depth_written[row_of(rd_addr)];
      read_bit_q <= bit_of(rd_addr);
    end
  end

  // Read-back port: the same, data in the next cycle.
  reg [Z_BITS-1:0] readback_depth_q;
  reg [23:0]       readback_rgb_q;
  reg [63:0]       readback_depth_row_q, readback_color_row_q;
  reg [5:0]        readback_bit_q;
  assign readback_depth = readback_depth_row_q[readback_bit_q] ? readback_depth_q : depth_clear_q;
  assign readback_rgb = readback_color_row_q[readback_bit_q] ? readback_rgb_q : 24'd0;
  always @(posedge clk) begin
    readback_depth_q <= depth_mem[readback_addr];
    readback_rgb_q <= color_mem[readback_addr];
    readback_depth_row_q <= depth_written[row_of(readback_addr)];
    readback_color_row_q <= color_written[row_of(readback_addr)];
    readback_bit_q <= bit_of(readback_addr);
  end

  // Delay ring for latencies above 1: the entry of age k holds the word read k cycles ago (from
  // age 2; read_value is age 1), one entry written every cycle.
  localparam integer RING_BITS = MAX_MEMORY_LATENCY > 2 ? $clog2(MAX_MEMORY_LATENCY) : 1;
  localparam integer RING = 1 << RING_BITS;
  reg [RING_BITS-1:0]     now_slot_q;
  reg [Z_BITS-1:0] ring_data_q [0:RING-1];
  /* verilator lint_off UNUSEDSIGNAL */
  function automatic [RING_BITS-1:0] slot_of_age(input [RING_BITS-1:0] now, input [LATENCY_BITS-1:0] age);
    reg [LATENCY_BITS:0] wide_age;
    begin
      wide_age = {1'b0, age};
      slot_of_age = now - wide_age[RING_BITS-1:0];  // modulo RING (a power of two)
    end
  endfunction
  /* verilator lint_on UNUSEDSIGNAL */
  wire [RING_BITS-1:0] previous_slot = slot_of_age(now_slot_q, {{(LATENCY_BITS-1){1'b0}}, 1'b1});
  assign rd_depth = latency_q == {{(LATENCY_BITS-1){1'b0}}, 1'b1} ? read_value : ring_data_q[slot_of_age(now_slot_q, latency_q)];
  always @(posedge clk) begin
    if (rst) now_slot_q <= {RING_BITS{1'b0}};
    else now_slot_q <= now_slot_q + 1'b1;
    ring_data_q[previous_slot] <= read_value;
  end
endmodule
