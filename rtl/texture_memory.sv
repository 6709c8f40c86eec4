// Texture memory on chip (docs/design/texturing.md, "Texture memory"): four banks of 24-bit texels,
// bank 2 (j mod 2) + (i mod 2) holding texel column i, row j at word {j >> 1, i >> 1}, so that the
// four texels of a bilinear lookup (columns and rows one apart, or equal) are one read of every
// bank. The texture unit's read port (rtl/texture_unit.sv states its contract): the texels of a
// read taken in c are on rd_texels in c + Lt, Lt = cfg_texture_latency (1 .. MAX_TEXTURE_LATENCY),
// and back-pressure only when `refuse` asks for it (rd_ready = !refuse: a verification hook through
// which a harness applies the profile's stall pattern; tie it to 0). Textures up to 2^MAX_LOG2_SIZE
// texels a side; the load port writes one texel per cycle before the frame.
`include "rastersim_pkg.sv"
module texture_memory `RS_IMPORT #(
  parameter integer MAX_TEXTURE_LATENCY = 64,
  parameter integer MAX_LOG2_SIZE = 10
) (
  input  wire clk,
  input  wire rst,
  input  wire [rastersim_pkg::TEXTURE_LATENCY_BITS-1:0] cfg_texture_latency,  // sampled while rst is high
  input  wire refuse,                     // refuse read requests in this cycle (rd_ready low)
  // Read port: bank b's word address at [18 b +: 18], {row >> 1, column >> 1} of a 1024-texel side.
  input  wire rd_valid,
  output wire rd_ready,
  input  wire [rastersim_pkg::TEXTURE_BANKS*rastersim_pkg::TEXEL_WORD_BITS-1:0] rd_addr,
  output wire [rastersim_pkg::TEXTURE_BANKS*rastersim_pkg::TEXEL_BITS-1:0] rd_texels,   // bank b's texel {r, g, b} at [24 b +: 24], in c + Lt
  // Load port: texel (column load_x, row load_y), written at the end of the cycle.
  input  wire load_en,
  input  wire [rastersim_pkg::TEXTURE_COORD_BITS-1:0] load_x,
  input  wire [rastersim_pkg::TEXTURE_COORD_BITS-1:0] load_y,
  input  `RS_TYPE(rgb_t) load_rgb
);
  // Release 5.006 of the linter reports these functions as hiding themselves when rastersim_top
  // instantiates this unit, out of lint_waivers.vlt's file waiver's reach; they are the same functions.
  /* verilator lint_off VARHIDDEN */
`include "rastersim_widths.vh"
  /* verilator lint_on VARHIDDEN */
  // Parameter legality, as RS_REQUIRE of rastersim_widths.vh checks it.
`ifdef __ICARUS__
  initial if (!(MAX_TEXTURE_LATENCY >= 1 && MAX_TEXTURE_LATENCY <= 64 && MAX_LOG2_SIZE >= 2 && MAX_LOG2_SIZE <= 10))
    $fatal(1, "texture_memory: MAX_TEXTURE_LATENCY must be 1..64, MAX_LOG2_SIZE 2..10");
`else
  if (!(MAX_TEXTURE_LATENCY >= 1 && MAX_TEXTURE_LATENCY <= 64 && MAX_LOG2_SIZE >= 2 && MAX_LOG2_SIZE <= 10)) begin : illegal
    $error("texture_memory: MAX_TEXTURE_LATENCY must be 1..64, MAX_LOG2_SIZE 2..10");
  end
`endif
  localparam integer HALF = MAX_LOG2_SIZE - 1;       // bits of a column or row within its bank
  localparam integer WORD_BITS = 2 * HALF;
  localparam integer WORDS = 1 << (2 * HALF);

  reg [rastersim_pkg::TEXTURE_LATENCY_BITS-1:0] latency_q;
  always @(posedge clk) if (rst) latency_q <= cfg_texture_latency;
  assign rd_ready = !refuse;

  // A bank word's address from the port's {row >> 1, column >> 1} (9 bits each).
  /* verilator lint_off UNUSEDSIGNAL */
  function automatic [WORD_BITS-1:0] word_of(input [8:0] row_half, input [8:0] column_half);
    word_of = {row_half[HALF-1:0], column_half[HALF-1:0]};
  endfunction
  /* verilator lint_on UNUSEDSIGNAL */

  // Delay ring for latencies above 1, as zbuffer_memory's: the entry of age k holds the texels read
  // k cycles ago (from age 2; read_q is age 1), one entry written every cycle.
  localparam integer RING_BITS = MAX_TEXTURE_LATENCY > 2 ? $clog2(MAX_TEXTURE_LATENCY) : 1;
  localparam integer RING = 1 << RING_BITS;
  reg [RING_BITS-1:0] now_slot_q;
  always @(posedge clk) begin
    if (rst) now_slot_q <= {RING_BITS{1'b0}};
    else now_slot_q <= now_slot_q + 1'b1;
  end
  wire [RING_BITS-1:0] previous_slot = now_slot_q - 1'b1;
  wire [RING_BITS-1:0] latency_slot = now_slot_q - latency_q[RING_BITS-1:0];  // modulo RING
  wire latency_one = latency_q == 7'd1;

  genvar b;
  generate
    for (b = 0; b < 4; b = b + 1) begin : banks
      reg [23:0] texels [0:WORDS-1];
      reg [23:0] read_q;
      reg [23:0] ring_q [0:RING-1];
      wire [17:0] address = rd_addr[18*b +: 18];
      always @(posedge clk) begin
        if (load_en && load_x[0] == (b % 2 == 1) && load_y[0] == (b / 2 == 1)) texels[word_of(load_y[9:1], load_x[9:1])] <= load_rgb;
        if (rd_valid) read_q <= texels[word_of(address[17:9], address[8:0])];
        ring_q[previous_slot] <= read_q;
      end
      assign rd_texels[24*b +: 24] = latency_one ? read_q : ring_q[latency_slot];
    end
  endgenerate
endmodule
