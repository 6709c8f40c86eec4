// Register widths of the pipeline as constant functions of the profile parameters: the same
// formulas as model/widths.h (derive_widths), written independently. Included inside the body of
// every module that needs them (functions cannot be shared through a package in yosys 0.23).
// Arithmetic is done on 128-bit values: the largest bound (the depth dividend) needs 102 bits.
// rastersim_core republishes the results as /*verilator public*/ localparams so that the C++ build
// static_asserts them against rastersim::derive_widths (testbench/rtl_configuration.h).

// Parameter legality, checked when a unit is elaborated: a generate block that stops Verilator
// (USERERROR: the lint is -Wall, the builds pass -Werror-USERERROR) and yosys with the message.
// Icarus has no elaboration tasks: there the unit stops at time 0 instead.
`ifndef RS_REQUIRE
`ifdef __ICARUS__
`define RS_REQUIRE(label, condition, message) initial if (!(condition)) $fatal(1, message);
`else
`define RS_REQUIRE(label, condition, message) if (!(condition)) begin : label $error(message); end
`endif
`endif

// Smallest unsigned width b >= 1 with v < 2^b.
function automatic integer rs_ubits(input [127:0] v);
  integer i;
  begin
    rs_ubits = 1;
    for (i = 1; i < 127; i = i + 1)
      if ((v >> i) != 128'd0) rs_ubits = i + 1;
  end
endfunction

// rs_ubits for a 32-bit argument v >= 0 (counters, addresses).
function automatic integer rs_ubits32(input integer v);
  reg [127:0] wide;
  begin
    wide = {96'd0, v};
    rs_ubits32 = rs_ubits(wide);
  end
endfunction

// Smallest two's-complement width b holding -v .. v for v >= 0: v < 2^(b-1).
function automatic integer rs_sbits(input [127:0] v);
  begin
    rs_sbits = rs_ubits(v) + 1;
  end
endfunction

// Smallest b with 2^b >= v, v >= 1.
function automatic integer rs_ceil_log2(input [127:0] v);
  integer i;
  begin
    rs_ceil_log2 = 0;
    for (i = 126; i >= 0; i = i - 1)
      if ((128'd1 << i) >= v) rs_ceil_log2 = i;
  end
endfunction

// F: fraction (guard) bits of the plane registers; 2^F >= 2 (W + H - 1) unless the profile sets it.
function automatic integer rs_guard_bits(input integer w, input integer h, input integer z_guard_bits);
  integer f;
  integer sum;
  reg [127:0] wide;
  begin
    sum = w + h - 1;
    wide = {96'd0, sum};
    f = rs_ceil_log2(wide << 1);
    if (z_guard_bits > 0) rs_guard_bits = z_guard_bits;
    else rs_guard_bits = f < 1 ? 1 : f;
  end
endfunction

// W * H * M^2 with M = 2^S.
function automatic [127:0] rs_area_unit(input integer w, input integer h, input integer s);
  reg [127:0] acc;
  begin
    acc = {96'd0, w};
    acc = acc * {96'd0, h};
    rs_area_unit = acc << (2 * s);
  end
endfunction

function automatic integer rs_coord_bits(input integer w, input integer h, input integer s);
  reg [127:0] big;
  integer larger;
  begin
    larger = w > h ? w : h;
    big = {96'd0, larger};
    rs_coord_bits = rs_sbits((128'd2 * big) << s);
  end
endfunction

function automatic integer rs_delta_bits(input integer w, input integer h, input integer s);
  reg [127:0] big;
  integer larger;
  begin
    larger = w > h ? w : h;
    big = {96'd0, larger};
    rs_delta_bits = rs_sbits((128'd3 * big) << s);
  end
endfunction

function automatic integer rs_area_bits(input integer w, input integer h, input integer s);
  begin
    rs_area_bits = rs_sbits(128'd9 * rs_area_unit(w, h, s));
  end
endfunction

function automatic integer rs_edge_bits(input integer w, input integer h, input integer s);
  begin
    rs_edge_bits = rs_sbits(128'd12 * rs_area_unit(w, h, s) + 128'd1);
  end
endfunction

function automatic integer rs_edge_step_x_bits(input integer h, input integer s);
  reg [127:0] v;
  begin
    v = {96'd0, h};
    rs_edge_step_x_bits = rs_sbits((128'd3 * v) << (2 * s));
  end
endfunction

function automatic integer rs_edge_step_y_bits(input integer w, input integer s);
  reg [127:0] v;
  begin
    v = {96'd0, w};
    rs_edge_step_y_bits = rs_sbits((128'd3 * v) << (2 * s));
  end
endfunction

function automatic integer rs_span_rem_bits(input integer h, input integer s);
  reg [127:0] v;
  begin
    v = {96'd0, h};
    rs_span_rem_bits = rs_ubits((128'd3 * v) << (2 * s));
  end
endfunction

// The depth plane's bits Np (docs/arithmetic.md section 6): z_bits for the fixed-point depth word
// (exponent bits 0), z_bits - Ne + 2^Ne - 1 for the floating-point one.
function automatic integer rs_depth_plane_bits(input integer word_bits, input integer exponent_bits);
  rs_depth_plane_bits = exponent_bits == 0 ? word_bits : word_bits - exponent_bits + (1 << exponent_bits) - 1;
endfunction

// Widest dividend magnitude, 36 Zmax W H M^2 2^F: also the divider's cycle count.
function automatic integer rs_divider_bits(input integer w, input integer h, input integer s,
                                           input integer z_bits, input integer z_guard_bits);
  reg [127:0] z_max;
  begin
    z_max = (128'd1 << z_bits) - 128'd1;
    rs_divider_bits = rs_ubits(((128'd36 * z_max) * rs_area_unit(w, h, s)) << rs_guard_bits(w, h, z_guard_bits));
  end
endfunction

// Texturing (docs/arithmetic.md section 5, model/widths.h): P attribute fraction bits, the S, T, Q
// registers s9.(P + Ft) with Ft the derived guard bits whatever Z_GUARD_BITS (u and v s8.20:
// rastersim_pkg::UV_BITS), and the perspective divide's stages (docs/cycle-model.md, "Texture unit").
/* verilator lint_off UNUSEDPARAM */
localparam integer RS_TEXTURE_DIVIDE_STAGES = 29;
/* verilator lint_on UNUSEDPARAM */
function automatic integer rs_texture_reg_bits(input integer w, input integer h);
  rs_texture_reg_bits = rastersim_pkg::TEXTURE_FRACTION_BITS + rs_guard_bits(w, h, 0) + 9;
endfunction
// The register bits the perspective divide drops: Ft - min(Ft, TEXTURE_DIVIDE_GUARD_BITS).
function automatic integer rs_texture_divide_shift(input integer w, input integer h);
  rs_texture_divide_shift = rs_guard_bits(w, h, 0) > rastersim_pkg::TEXTURE_DIVIDE_GUARD_BITS
                                ? rs_guard_bits(w, h, 0) - rastersim_pkg::TEXTURE_DIVIDE_GUARD_BITS : 0;
endfunction

// The texture record beside the setup record (builds with TEXTURE = 1; model/triangle_setup.h
// SetupResult::textured, texture, left[j].texture): bit 0 the textured flag, then 21 registers of
// rs_texture_reg_bits, register 3 g + c at 1 + (3 g + c) TR, c = 0 S, 1 T, 2 Q, and the groups g:
// 0 start, 1 step x, 2 step y, 3 left-edge slot 0 start, 4 its step, 5 slot 1 start, 6 its step.
function automatic integer rs_texture_record_bits(input integer w, input integer h);
  rs_texture_record_bits = 1 + 21 * rs_texture_reg_bits(w, h);
endfunction

// The pipelined setup unit's schedule (SETUP_INTERVAL I >= 2; model/widths.h setup_timing): slots
// of edge, numerator, divide and product steps, at most 4 steps of one multiply or divide chained
// in a cycle.
function automatic integer rs_setup_edge_stages(input integer coord_bits, input integer interval);
  rs_setup_edge_stages = (coord_bits + 1 + interval * 4 - 1) / (interval * 4);
endfunction

function automatic integer rs_setup_numer_stages(input integer z_bits, input integer interval);
  rs_setup_numer_stages = (z_bits + interval * 4 - 1) / (interval * 4);
endfunction

function automatic integer rs_setup_divide_stages(input integer divider_bits, input integer interval);
  rs_setup_divide_stages = (divider_bits + interval * 4 - 1) / (interval * 4);
endfunction

// PB: the multiplier bits of a plane along a left edge (model/widths.h setup_product_bits).
function automatic integer rs_setup_product_bits(input integer w, input integer h, input integer s,
                                                 input integer z_bits, input integer z_guard_bits);
  integer z_reg_bits;
  begin
    z_reg_bits = z_bits + rs_guard_bits(w, h, z_guard_bits) + 1;
    rs_setup_product_bits = z_reg_bits < rs_edge_bits(w, h, s) ? z_reg_bits : rs_edge_bits(w, h, s);
  end
endfunction

function automatic integer rs_setup_product_stages(input integer product_bits, input integer interval);
  rs_setup_product_stages = (product_bits + interval * 4 - 1) / (interval * 4);
endfunction

// The serial setup unit (SETUP_INTERVAL 0; model/widths.h serial_setup_drawn_latency): its
// accumulator width above the multiplier bits, and its program of operations, each a load cycle and
// its steps (docs/cycle-model.md tables them).
function automatic integer rs_setup_serial_bits(input integer w, input integer h, input integer s);
  rs_setup_serial_bits = rs_edge_bits(w, h, s) + 3;
endfunction

function automatic integer rs_setup_serial_latency(input integer w, input integer h, input integer s,
                                                   input integer z_bits, input integer z_guard_bits);
  integer d, c, hb, f;
  begin
    d = rs_delta_bits(w, h, s);
    c = rs_coord_bits(w, h, s);
    hb = rs_setup_serial_bits(w, h, s);
    f = rs_guard_bits(w, h, z_guard_bits);
    rs_setup_serial_latency = 1 + (1 + 2 * d) + 1 + 3 * (1 + 2 * (c + 1)) + 3 * (1 + hb + 1) + 3 * (1 + hb + s + 1)
        + 3 * (1 + 3 * z_bits) + (1 + hb + z_bits + f) + 2 * (1 + hb + z_bits + f + s)
        + 3 * (3 * (1 + 3 * 8) + (1 + hb + 8 + f) + 2 * (1 + hb + 8 + f + s))
        + 16 * (1 + rs_setup_product_bits(w, h, s, z_bits, z_guard_bits) + 1) + 1;
  end
endfunction

// Accept -> the record in the output register, for a drawn triangle; accept -> the decision.
function automatic integer rs_setup_drawn_latency(input integer w, input integer h, input integer s,
                                                  input integer z_bits, input integer z_guard_bits,
                                                  input integer interval);
  rs_setup_drawn_latency = interval == 0 ? rs_setup_serial_latency(w, h, s, z_bits, z_guard_bits)
      : interval * (1 + rs_setup_edge_stages(rs_coord_bits(w, h, s), interval) + rs_setup_numer_stages(z_bits, interval)
                    + rs_setup_divide_stages(rs_divider_bits(w, h, s, z_bits, z_guard_bits), interval)
                    + rs_setup_product_stages(rs_setup_product_bits(w, h, s, z_bits, z_guard_bits), interval));
endfunction

function automatic integer rs_setup_rejected_latency(input integer w, input integer h, input integer s,
                                                     input integer interval);
  rs_setup_rejected_latency = interval == 0 ? 2 + 2 * rs_delta_bits(w, h, s) : 1;
endfunction

// The setup units with the texture planes (TEXTURE = 1; docs/cycle-model.md, "The setup units with
// the texture unit"; model/widths.h): the S, T, Q dividends' width 36 2^(P+7) W H M^2 2^Ft, PBt,
// and what a textured triangle adds to the serial program.
function automatic integer rs_texture_divider_bits(input integer w, input integer h, input integer s);
  rs_texture_divider_bits = rs_ubits(((128'd36 << (rastersim_pkg::TEXTURE_FRACTION_BITS + 7)) * rs_area_unit(w, h, s))
                                     << rs_guard_bits(w, h, 0));
endfunction

function automatic integer rs_setup_texture_product_bits(input integer w, input integer h, input integer s);
  rs_setup_texture_product_bits = rs_texture_reg_bits(w, h) < rs_edge_bits(w, h, s) ? rs_texture_reg_bits(w, h)
                                                                                     : rs_edge_bits(w, h, s);
endfunction

function automatic integer rs_setup_serial_texture_cycles(input integer w, input integer h, input integer s);
  integer hb, m, ft;
  begin
    hb = rs_setup_serial_bits(w, h, s);
    m = rastersim_pkg::TEXTURE_VERTEX_BITS;
    ft = rs_guard_bits(w, h, 0);
    rs_setup_serial_texture_cycles = 3 * (3 * (1 + 3 * m) + (1 + hb + m + ft) + 2 * (1 + hb + m + ft + s))
                                     + 12 * (rs_setup_texture_product_bits(w, h, s) + 2);
  end
endfunction

// Accept -> the record in the output register for a drawn triangle, in a unit built with TEXTURE =
// texture, the triangle textured or not: the serial unit adds the texture program for a textured
// triangle only; the pipelined unit's slots are sized for the texture planes for every triangle.
// texture 0 is rs_setup_drawn_latency.
function automatic integer rs_setup_texture_drawn_latency(input integer w, input integer h, input integer s,
                                                          input integer z_bits, input integer z_guard_bits,
                                                          input integer interval, input integer texture,
                                                          input integer textured);
  integer numer_bits, divide_bits, product_bits;
  begin
    numer_bits = z_bits > rastersim_pkg::TEXTURE_VERTEX_BITS ? z_bits : rastersim_pkg::TEXTURE_VERTEX_BITS;
    divide_bits = rs_divider_bits(w, h, s, z_bits, z_guard_bits) > rs_texture_divider_bits(w, h, s)
                  ? rs_divider_bits(w, h, s, z_bits, z_guard_bits) : rs_texture_divider_bits(w, h, s);
    product_bits = rs_setup_product_bits(w, h, s, z_bits, z_guard_bits) > rs_setup_texture_product_bits(w, h, s)
                   ? rs_setup_product_bits(w, h, s, z_bits, z_guard_bits) : rs_setup_texture_product_bits(w, h, s);
    if (texture == 0) rs_setup_texture_drawn_latency = rs_setup_drawn_latency(w, h, s, z_bits, z_guard_bits, interval);
    else if (interval == 0)
      rs_setup_texture_drawn_latency = rs_setup_serial_latency(w, h, s, z_bits, z_guard_bits)
                                       + (textured != 0 ? rs_setup_serial_texture_cycles(w, h, s) : 0);
    else
      rs_setup_texture_drawn_latency = interval * (1 + rs_setup_edge_stages(rs_coord_bits(w, h, s), interval)
                                                   + rs_setup_numer_stages(numer_bits, interval)
                                                   + rs_setup_divide_stages(divide_bits, interval)
                                                   + rs_setup_product_stages(product_bits, interval));
  end
endfunction

// The setup record as one packed vector (the model's SetupResult; the C++ side's field table is
// testbench/setup_record.h). Fields from the least significant bit up, by number:
//   0 x0 (X_BITS)  1 x1 (X_BITS)  2 y0 (Y_BITS)  3 y1 (Y_BITS)
//   4 edge_start (3 x EDGE_BITS)  5 edge_step_x (3 x EDGE_STEP_X_BITS)
//   6 edge_step_y (3 x EDGE_STEP_Y_BITS)  7 span_quot (3 x EDGE_BITS)  8 span_rem (3 x SPAN_REM_BITS)
//   9 span_step_quot (3 x EDGE_STEP_Y_BITS)  10 span_step_rem (3 x SPAN_REM_BITS)
//  11 depth_start (Z_REG_BITS)  12 depth_step_x  13 depth_step_y
//  14 color_start (3 x COLOR_REG_BITS)  15 color_step_x  16 color_step_y  17 flat_rgb (24)
//  18 left_start (2 x (Z_REG_BITS + 3 x COLOR_REG_BITS))  19 left_step
// with Z_REG_BITS = N + F + 1, COLOR_REG_BITS = 9 + F and the edge widths above; three-edge fields
// hold edge k at [k*B +: B], colour fields r, g, b at [c*COLOR_REG_BITS +: COLOR_REG_BITS], the
// left-edge fields slot j at [j*B +: B], its depth plane first, then r, g, b. rs_rec_lsb(20, ...)
// is the record's width.
// triangle_setup packs it, the record FIFO carries it, the walker takes fields 0..10 (the walker
// part, whose widths do not depend on the depth), the Z adder the planes.
// Every unit that includes this header gets the field names; most use a few.
/* verilator lint_off UNUSEDPARAM */
localparam integer RS_REC_X0 = 0, RS_REC_X1 = 1, RS_REC_Y0 = 2, RS_REC_Y1 = 3, RS_REC_EDGE_START = 4,
                   RS_REC_EDGE_STEP_X = 5, RS_REC_EDGE_STEP_Y = 6, RS_REC_SPAN_QUOT = 7, RS_REC_SPAN_REM = 8,
                   RS_REC_SPAN_STEP_QUOT = 9, RS_REC_SPAN_STEP_REM = 10, RS_REC_DEPTH_START = 11,
                   RS_REC_DEPTH_STEP_X = 12, RS_REC_DEPTH_STEP_Y = 13, RS_REC_COLOR_START = 14,
                   RS_REC_COLOR_STEP_X = 15, RS_REC_COLOR_STEP_Y = 16, RS_REC_FLAT_RGB = 17,
                   RS_REC_LEFT_START = 18, RS_REC_LEFT_STEP = 19;
/* verilator lint_on UNUSEDPARAM */

function automatic integer rs_rec_field_bits(input integer field, input integer w, input integer h,
                                             input integer s, input integer z_bits, input integer z_guard_bits);
  case (field)
    0, 1: rs_rec_field_bits = rs_ubits32(w - 1);
    2, 3: rs_rec_field_bits = rs_ubits32(h - 1);
    4, 7: rs_rec_field_bits = 3 * rs_edge_bits(w, h, s);
    5: rs_rec_field_bits = 3 * rs_edge_step_x_bits(h, s);
    6, 9: rs_rec_field_bits = 3 * rs_edge_step_y_bits(w, s);
    8, 10: rs_rec_field_bits = 3 * rs_span_rem_bits(h, s);
    11, 12, 13: rs_rec_field_bits = z_bits + rs_guard_bits(w, h, z_guard_bits) + 1;
    14, 15, 16: rs_rec_field_bits = 3 * (9 + rs_guard_bits(w, h, z_guard_bits));
    18, 19: rs_rec_field_bits = 2 * (z_bits + rs_guard_bits(w, h, z_guard_bits) + 1 + 3 * (9 + rs_guard_bits(w, h, z_guard_bits)));
    default: rs_rec_field_bits = 24;  // 17
  endcase
endfunction

// The field's least significant bit; rs_rec_lsb(20, ...) is the record's width.
function automatic integer rs_rec_lsb(input integer field, input integer w, input integer h, input integer s,
                                      input integer z_bits, input integer z_guard_bits);
  integer f;
  begin
    rs_rec_lsb = 0;
    for (f = 0; f < field; f = f + 1) rs_rec_lsb = rs_rec_lsb + rs_rec_field_bits(f, w, h, s, z_bits, z_guard_bits);
  end
endfunction

// The walker part, fields 0..10 (their widths need no depth widths: z_bits 0 stands in).
function automatic integer rs_rec_walker_bits(input integer w, input integer h, input integer s);
  rs_rec_walker_bits = rs_rec_lsb(11, w, h, s, 0, 0);
endfunction

// The walker's entry: its state at a load, which scanline_walker_entry forms from the walker part
// of a setup record as the record is pushed into the record FIFO (docs/cycle-model.md, "Record
// FIFO"), so that the walker's load takes registers only. Fields from the least significant bit up:
//   0 x0 (X_BITS)  1 x1 (X_BITS)  2 y0 (Y_BITS)  3 y1 (Y_BITS)  4 last_offset x1 - x0 (X_BITS)
//   5 left (3: edge k's step_x > 0)  6 right (3: step_x < 0)
//   7 step_y (3 x EDGE_STEP_Y_BITS)  8 span_step_quot (3 x EDGE_STEP_Y_BITS)
//   9 span_step_rem (3 x SPAN_REM_BITS)  10 span_step_rem_less: span_step_rem - d (3 x REM_BITS)
//  11 edge_row: the edge values at x0 of the second row (3 x EDGE_BITS)
//  12 quot, 13 rem_less: the span DDA of the second row (3 x EDGE_BITS, 3 x REM_BITS; rem - d)
//  14 span_start, 15 span_end (X_BITS each), 16 row_empty (1): the first row's span
//  17 enter_left (1: a left edge bounds the first row's span start), 18 enter_slot (1: its slot)
//  19 left_carry (2: each left-edge slot's DDA carry into the second row)
// with d = |step_x| and REM_BITS = SPAN_REM_BITS + 1 (signed: rem - d lies in [-d, -1]).
/* verilator lint_off UNUSEDPARAM */
localparam integer RS_ENTRY_X0 = 0, RS_ENTRY_X1 = 1, RS_ENTRY_Y0 = 2, RS_ENTRY_Y1 = 3, RS_ENTRY_LAST_OFFSET = 4,
                   RS_ENTRY_LEFT = 5, RS_ENTRY_RIGHT = 6, RS_ENTRY_STEP_Y = 7, RS_ENTRY_STEP_QUOT = 8,
                   RS_ENTRY_STEP_REM = 9, RS_ENTRY_STEP_REM_LESS = 10, RS_ENTRY_EDGE_ROW = 11, RS_ENTRY_QUOT = 12,
                   RS_ENTRY_REM_LESS = 13, RS_ENTRY_SPAN_START = 14, RS_ENTRY_SPAN_END = 15,
                   RS_ENTRY_ROW_EMPTY = 16, RS_ENTRY_ENTER_LEFT = 17, RS_ENTRY_ENTER_SLOT = 18,
                   RS_ENTRY_LEFT_CARRY = 19;
/* verilator lint_on UNUSEDPARAM */

function automatic integer rs_entry_field_bits(input integer field, input integer w, input integer h, input integer s);
  case (field)
    0, 1, 4, 14, 15: rs_entry_field_bits = rs_ubits32(w - 1);
    2, 3: rs_entry_field_bits = rs_ubits32(h - 1);
    5, 6: rs_entry_field_bits = 3;
    7, 8: rs_entry_field_bits = 3 * rs_edge_step_y_bits(w, s);
    9: rs_entry_field_bits = 3 * rs_span_rem_bits(h, s);
    10, 13: rs_entry_field_bits = 3 * (rs_span_rem_bits(h, s) + 1);
    11, 12: rs_entry_field_bits = 3 * rs_edge_bits(w, h, s);
    19: rs_entry_field_bits = 2;
    default: rs_entry_field_bits = 1;  // 16, 17, 18
  endcase
endfunction

// The field's least significant bit; rs_entry_lsb(20, ...) is the entry's width.
function automatic integer rs_entry_lsb(input integer field, input integer w, input integer h, input integer s);
  integer f;
  begin
    rs_entry_lsb = 0;
    for (f = 0; f < field; f = f + 1) rs_entry_lsb = rs_entry_lsb + rs_entry_field_bits(f, w, h, s);
  end
endfunction
