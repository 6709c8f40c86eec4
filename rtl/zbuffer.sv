// Z-buffer unit (model/zbuffer.h): read, compare, conditional write of depth and colour behind a
// memory port of read latency L = cfg_memory_latency (1 .. MAX_MEMORY_LATENCY).
// A fragment accepted in cycle c issues its depth read in c (on-chip memory, synchronous read,
// then L-1 data delay registers); in c+L its data arrives, the depth test runs and the depth (if
// cfg_depth_write) and colour (on pass) are written at the end of c+L.
// Read-after-write hazard: a fragment is accepted in c only if no fragment to the same address
// was accepted in c-L .. c-1 (frag_ready low meanwhile), so every read sees all earlier writes.
// Fast clear: each memory word has a "written since the clear" bit, 64 bits per bitmap row; after
// reset the unit zeroes one row of both bitmaps per cycle (ceil(W H / 64) cycles), then raises
// clear_done: the frame starts (cycle 0) in the first cycle with clear_done high. A word whose bit
// is 0 reads as cfg_depth_clear (depth) or 0 (colour); writes set the bit (per-bit write enable).
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
  input  wire [Z_BITS-1:0] cfg_depth_clear,
  input  wire [rs_ubits32(MAX_MEMORY_LATENCY)-1:0] cfg_memory_latency,
  output reg  clear_done,
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
  // Read-back port for the final memories (synchronous: data in the next cycle).
  input  wire [rs_ubits32(WIDTH * HEIGHT - 1)-1:0] readback_addr,
  output reg  [Z_BITS-1:0] readback_depth,
  output reg  [23:0]       readback_rgb
);
`include "rastersim_widths.vh"

  localparam integer XB = rs_ubits32(WIDTH - 1);
  localparam integer AB = rs_ubits32(WIDTH * HEIGHT - 1);
  localparam integer WORDS = WIDTH * HEIGHT;
  localparam [AB-1:0] WIDTH_A = WIDTH[AB-1:0];

  // Readable from C++ (public_flat_rd): the co-simulation reads the final memories directly
  // instead of W H cycles through the read-back port (which a test checks against them).
  reg [Z_BITS-1:0] depth_mem [0:WORDS-1] /*verilator public_flat_rd*/;
  reg [23:0]       color_mem [0:WORDS-1] /*verilator public_flat_rd*/;

  localparam integer ROWS = (WORDS + 63) / 64;
  localparam integer RAB = rs_ubits32(ROWS - 1);  // bitmap row address
  localparam integer LAST_ROW = ROWS - 1;
  localparam [RAB-1:0] LAST_ROW_A = LAST_ROW[RAB-1:0];
  reg [63:0] depth_written [0:ROWS-1] /*verilator public_flat_rd*/;
  reg [63:0] color_written [0:ROWS-1] /*verilator public_flat_rd*/;

  // Bitmap row and bit of a word address (address / 64, address % 64).
  /* verilator lint_off UNUSEDSIGNAL */
  function automatic [RAB-1:0] row_of(input [AB-1:0] address);
    reg [AB+5:0] wide;
    begin
      wide = {6'd0, address};
      row_of = wide[RAB+5:6];
    end
  endfunction
  function automatic [5:0] bit_of(input [AB-1:0] address);
    reg [AB+5:0] wide;
    begin
      wide = {6'd0, address};
      bit_of = wide[5:0];
    end
  endfunction
  /* verilator lint_on UNUSEDSIGNAL */

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
  // The memory port's read data: read_q (and its written bit) is the synchronous read of the
  // fragment accepted in the previous cycle; ring_data keeps older reads until their data cycle
  // (the read latency L).
  reg [Z_BITS-1:0] read_q;
  reg              read_written_q;
  wire [Z_BITS-1:0] read_value = read_written_q ? read_q : cfg_depth_clear;
  reg [Z_BITS-1:0] ring_data [0:RING-1];

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

  reg [RAB-1:0] clear_row;

  wire [AB-1:0] frag_addr = frag_y * WIDTH_A + {{(AB-XB){1'b0}}, frag_x};

  reg hazard;
  reg in_flight;
  integer k;
  reg [LB-1:0] age;
  reg [RB-1:0] slot;
  always @(*) begin
    hazard = 1'b0;
    in_flight = 1'b0;
    for (k = 1; k <= MAX_MEMORY_LATENCY; k = k + 1) begin
      age = k[LB-1:0];
      slot = slot_of_age(now_slot, age);
      if (age <= cfg_memory_latency && ring_valid[slot]) begin
        in_flight = 1'b1;
        if (ring_addr[slot] == frag_addr) hazard = 1'b1;
      end
    end
  end

  assign frag_ready = clear_done && !hazard;
  wire accept = frag_valid && frag_ready;
  assign busy = accept || in_flight;

  // The fragment in its data cycle c+L.
  wire [RB-1:0]     done_slot = slot_of_age(now_slot, cfg_memory_latency);
  wire              done_valid = ring_valid[done_slot];
  wire [AB-1:0]     done_addr = ring_addr[done_slot];
  wire [Z_BITS-1:0] done_z = ring_z[done_slot];
  wire [23:0]       done_rgb = ring_rgb[done_slot];
  // Read data of the fragment accepted L cycles ago: read_q when L = 1, else kept in the ring.
  wire [Z_BITS-1:0] stored = cfg_memory_latency == 1 ? read_value : ring_data[done_slot];
  reg pass;
  always @(*) begin
    case (cfg_depth_func)
      3'd0: pass = 1'b0;
      3'd1: pass = done_z < stored;
      3'd2: pass = done_z == stored;
      3'd3: pass = done_z <= stored;
      3'd4: pass = done_z > stored;
      3'd5: pass = done_z != stored;
      3'd6: pass = done_z >= stored;
      default: pass = 1'b1;
    endcase
  end
  assign result_valid = done_valid;
  assign result_pass = pass;

  // Memories: one write port (clear sweep, then depth-test writes), the fragment read port and the
  // read-back port.
  always @(posedge clk) begin
    if (!clear_done) begin
      depth_written[clear_row] <= 64'd0;
      color_written[clear_row] <= 64'd0;
    end else if (done_valid && pass) begin
      if (cfg_depth_write) begin
        depth_mem[done_addr] <= done_z;
        depth_written[row_of(done_addr)][bit_of(done_addr)] <= 1'b1;
      end
      color_mem[done_addr] <= done_rgb;
      color_written[row_of(done_addr)][bit_of(done_addr)] <= 1'b1;
    end
  end
  always @(posedge clk) begin
    read_q <= depth_mem[frag_addr];
    read_written_q <= depth_written[row_of(frag_addr)][bit_of(frag_addr)];
    readback_depth <= depth_written[row_of(readback_addr)][bit_of(readback_addr)] ? depth_mem[readback_addr]
                                                                                  : cfg_depth_clear;
    readback_rgb <= color_written[row_of(readback_addr)][bit_of(readback_addr)] ? color_mem[readback_addr] : 24'd0;
  end

  always @(posedge clk) begin
    if (rst) begin
      clear_done <= 1'b0;
      clear_row <= {RAB{1'b0}};
    end else if (!clear_done) begin
      clear_row <= clear_row + 1'b1;
      if (clear_row == LAST_ROW_A) clear_done <= 1'b1;
    end
  end

  // The slot of the previous cycle's fragment, whose read data read_q holds now.
  wire [RB-1:0] previous_slot = slot_of_age(now_slot, {{(LB-1){1'b0}}, 1'b1});
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
    ring_data[previous_slot] <= read_value;
  end
endmodule
