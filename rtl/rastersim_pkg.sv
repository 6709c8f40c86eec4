// rastersim_pkg: the encodings and the fixed-width records of the pipeline's ports, defined once
// for every unit, the top and the testbenches. Widths that follow the profile (coordinates,
// depth, the setup record) cannot live in a package, whose types take no parameters: they are
// functions of rastersim_widths.vh, and the setup record is one packed vector laid out by its
// rs_rec_lsb / rs_rec_field_bits.
//
// Every file that uses the package includes this one first; the guard makes any file order work,
// with or without this file on the tool's list. Constants are named by scope in all three tools
// (rastersim_pkg::DEPTH_LESS). Types go through RS_TYPE, and a module that uses them opens with
// RS_IMPORT: Icarus 11 takes a package type only through an import, yosys 0.23 only by scope.
`ifndef RASTERSIM_PKG_SV
`define RASTERSIM_PKG_SV

package rastersim_pkg;
  /* verilator lint_off UNUSEDPARAM */
  // Encodings of the run-time settings (cfg_* ports), the setup decision (trace_setup_status) and
  // the conventions (build parameters PIXEL_CENTER, FILL_RULE, DEPTH_ROUNDING, COLOR_ROUNDING),
  // numbered as the C++ enums of model/profile.h and model/triangle_setup.h. rastersim_core
  // publishes them in one word (ENCODINGS) that the C++ build static_asserts against the enums.
  localparam logic [2:0] DEPTH_NEVER = 3'd0, DEPTH_LESS = 3'd1, DEPTH_EQUAL = 3'd2,
                         DEPTH_LEQUAL = 3'd3, DEPTH_GREATER = 3'd4, DEPTH_NOTEQUAL = 3'd5,
                         DEPTH_GEQUAL = 3'd6, DEPTH_ALWAYS = 3'd7;
  localparam logic [1:0] CULL_NONE = 2'd0, CULL_BACK = 2'd1, CULL_FRONT = 2'd2;
  localparam logic [0:0] FRONT_CCW = 1'b0, FRONT_CW = 1'b1;
  localparam logic [0:0] TRAVERSAL_BBOX = 1'b0, TRAVERSAL_SPAN = 1'b1;
  localparam logic [0:0] SHADING_FLAT = 1'b0, SHADING_GOURAUD = 1'b1;
  localparam logic [2:0] STATUS_DRAWN = 3'd0, STATUS_DEGENERATE = 3'd1, STATUS_CULLED = 3'd2,
                         STATUS_OFFSCREEN = 3'd3, STATUS_NO_CENTRE = 3'd4;
  localparam integer PIXEL_CENTER_HALF = 0, PIXEL_CENTER_CORNER = 1;
  localparam integer ROUNDING_NEAREST = 0, ROUNDING_TRUNCATE = 1;
  localparam integer FILL_TOP_LEFT = 0, FILL_TOP_RIGHT = 1, FILL_BOTTOM_LEFT = 2, FILL_BOTTOM_RIGHT = 3;
  typedef logic [2:0] depth_func_t;  // DEPTH_*
  typedef logic [1:0] cull_t;        // CULL_*
  typedef logic [2:0] status_t;      // STATUS_*

  // A triangle's edges, k = 0..2 (edge k from vertex k to vertex k + 1): ports of per-edge flags.
  localparam integer TRIANGLE_EDGES = 3;
  // The left-edge slots of the plane registers (docs/cycle-model.md): a triangle has at most two
  // left edges, each with its DDA carry.
  localparam integer LEFT_EDGE_SLOTS = 2;

  // The depth bias's run-time inputs (DEPTH_BIAS builds): the constant c in plane LSBs, two's
  // complement, and the slope factor f, s4.4 (16 x the factor).
  localparam integer DEPTH_BIAS_CONSTANT_BITS = 33;
  localparam integer DEPTH_BIAS_SLOPE_BITS = 8;

  // A colour, u8 per channel: the vertex colours of a command, a fragment's, a texel, a written word.
  typedef struct packed {
    logic [7:0] r, g, b;
  } rgb_t;
  localparam integer RGB_BITS = 24;  // an rgb_t, where a port packs several (3 vertices, 4 banks)

  // A vertex's texture coordinates (model/triangle.h SnappedVertex): S and T s8.P, Q u1.P with
  // leading zeros, P = TEXTURE_FRACTION_BITS; the command's cmd_texture0..2, S in the low bits.
  localparam integer TEXTURE_FRACTION_BITS = 41;
  // The perspective divide keeps this many of the registers' Ft guard bits (model/widths.h).
  localparam integer TEXTURE_DIVIDE_GUARD_BITS = 4;
  localparam integer TEXTURE_VERTEX_BITS = TEXTURE_FRACTION_BITS + 9;
  typedef struct packed {
    logic signed [TEXTURE_VERTEX_BITS-1:0] q, t, s;
  } texture_vertex_t;
  localparam integer TEXTURE_COMMAND_BITS = 3 * TEXTURE_VERTEX_BITS;

  // The texture memory's read port (rtl/texture_memory.sv): a word address and a texel per bank,
  // bank b at [b*W +: W]; bank 2 (j mod 2) + (i mod 2) holds texel (i, j). (Flat vectors: neither
  // Icarus 11 nor yosys 0.23 takes a packed-array type on a port.)
  localparam integer TEXTURE_BANKS = 4;
  localparam integer TEXEL_WORD_BITS = 18;  // {row >> 1, column >> 1} of a side of up to 1024 texels
  localparam integer TEXEL_BITS = RGB_BITS;
  // A texture's side is 2^0 .. 2^10 texels: its log2 on 4 bits, a texel's column or row on 10.
  localparam integer TEXTURE_LOG2_BITS = 4;
  localparam integer TEXTURE_COORD_BITS = 10;
  localparam integer TEXTURE_WEIGHT_BITS = 8;  // a bilinear weight, in 1/256
  // The texture coordinates u, v after the perspective divide, s8.20.
  localparam integer UV_BITS = 28, UV_FRAC_BITS = 20;
  // cfg_texture_latency holds 1 .. 64, the largest MAX_TEXTURE_LATENCY, so that a core's ports do
  // not change with the bound.
  localparam integer TEXTURE_LATENCY_BITS = 7;
  // The texture unit's registered stages (docs/cycle-model.md "Texture unit"): texture_address's
  // between u, v and the read, texture_filter's between the texels and the modulated colour.
  localparam integer TEXTURE_ADDRESS_STAGES = 3, TEXTURE_FILTER_STAGES = 6;
  // The bias unit's stages (depth_bias.sv; model DepthOutput::kBiasStages).
  localparam integer DEPTH_BIAS_STAGES = 7;
  /* verilator lint_on UNUSEDPARAM */
endpackage

`ifdef YOSYS
`define RS_TYPE(name) rastersim_pkg::name
`define RS_IMPORT
`else
`define RS_TYPE(name) name
`define RS_IMPORT import rastersim_pkg::*;
`endif

`endif
