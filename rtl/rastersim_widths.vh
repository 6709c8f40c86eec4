// Register widths of the pipeline as constant functions of the profile parameters: the same
// formulas as model/widths.h (derive_widths), written independently. Included inside the body of
// every module that needs them (functions cannot be shared through a package in yosys 0.23).
// Arithmetic is done on 128-bit values: the largest bound (the depth dividend) needs 102 bits.
// The top module republishes the results as /*verilator public*/ localparams so that the C++ build
// static_asserts them against rastersim::derive_widths (testbench/rtl_widths_check.cpp).

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

// Widest dividend magnitude, 36 Zmax W H M^2 2^F: also the divider's cycle count.
function automatic integer rs_divider_bits(input integer w, input integer h, input integer s,
                                           input integer z_bits, input integer z_guard_bits);
  reg [127:0] z_max;
  begin
    z_max = (128'd1 << z_bits) - 128'd1;
    rs_divider_bits = rs_ubits(((128'd36 * z_max) * rs_area_unit(w, h, s)) << rs_guard_bits(w, h, z_guard_bits));
  end
endfunction

// The pipelined setup unit's schedule (SETUP_INTERVAL I >= 2; model/widths.h setup_timing): slots
// of numerator and divide steps, at most 4 steps of one multiply or divide chained in a cycle.
function automatic integer rs_setup_numer_stages(input integer z_bits, input integer interval);
  rs_setup_numer_stages = (z_bits + interval * 4 - 1) / (interval * 4);
endfunction

function automatic integer rs_setup_divide_stages(input integer divider_bits, input integer interval);
  rs_setup_divide_stages = (divider_bits + interval * 4 - 1) / (interval * 4);
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
        + 3 * (3 * (1 + 3 * 8) + (1 + hb + 8 + f) + 2 * (1 + hb + 8 + f + s)) + 1;
  end
endfunction

// Accept -> the record in the output register, for a drawn triangle; accept -> the decision.
function automatic integer rs_setup_drawn_latency(input integer w, input integer h, input integer s,
                                                  input integer z_bits, input integer z_guard_bits,
                                                  input integer interval);
  rs_setup_drawn_latency = interval == 0 ? rs_setup_serial_latency(w, h, s, z_bits, z_guard_bits)
      : interval * (1 + rs_setup_numer_stages(z_bits, interval)
                    + rs_setup_divide_stages(rs_divider_bits(w, h, s, z_bits, z_guard_bits), interval));
endfunction

function automatic integer rs_setup_rejected_latency(input integer w, input integer h, input integer s,
                                                     input integer interval);
  rs_setup_rejected_latency = interval == 0 ? 2 + 2 * rs_delta_bits(w, h, s) : 1;
endfunction
