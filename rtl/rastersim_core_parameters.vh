// rastersim_core's build parameters, declared here once for every module that takes them all and
// passes them on: rastersim_core, rastersim_top, the vector testbench and the board self-test.
//   module m #(`RASTERSIM_CORE_PARAMETERS) (...);        declares them, with these defaults
//   rastersim_core #(`RASTERSIM_CORE_PARAMETERS_PASSED) core (...);   passes each by its name
// The order is the profile table's (model/profile.cpp), which maps a profile to these values
// (model/core_parameters.h, docs/rtl.md "The profile in the RTL"); a test holds the two lists equal.
//   WIDTH, HEIGHT         the screen in pixels, 1..4096
//   SUBPIXEL_BITS         S, vertex fraction bits, 1..8
//   Z_BITS                N, the depth buffer word, 16..32
//   Z_GUARD_BITS          F, the plane registers' fraction bits; 0 derives the proven minimum
//   DEPTH_EXPONENT_BITS   Ne: 0 (or 1) the fixed-point depth word, 2..4 floating point
//   DEPTH_BIAS            1: the depth bias of cfg_depth_bias_*
//   MAX_MEMORY_LATENCY    the largest cfg_memory_latency, 1..64
//   MAX_SETUP_FIFO_DEPTH  the record FIFO's entries, the largest cfg_setup_fifo_depth, 1..16
//   SETUP_INTERVAL        0: the serial setup; 2..64: pipelined, a triangle every I cycles
//   TEXTURE               1: the texture unit (and in rastersim_top its memory)
//   MAX_TEXTURE_LATENCY   the largest cfg_texture_latency, 1..64
//   PIXEL_CENTER          rastersim_pkg::PIXEL_CENTER_*: the sample point
//   FILL_RULE             rastersim_pkg::FILL_*: the edges that own samples lying on them
//   DEPTH_ROUNDING        rastersim_pkg::ROUNDING_*: the depth plane's output
//   COLOR_ROUNDING        rastersim_pkg::ROUNDING_*: the colour planes' outputs
`ifndef RASTERSIM_CORE_PARAMETERS_VH
`define RASTERSIM_CORE_PARAMETERS_VH
`define RASTERSIM_CORE_PARAMETERS \
  parameter integer WIDTH = 640, \
  parameter integer HEIGHT = 480, \
  parameter integer SUBPIXEL_BITS = 4, \
  parameter integer Z_BITS = 24, \
  parameter integer Z_GUARD_BITS = 0, \
  parameter integer DEPTH_EXPONENT_BITS = 0, \
  parameter integer DEPTH_BIAS = 0, \
  parameter integer MAX_MEMORY_LATENCY = 64, \
  parameter integer MAX_SETUP_FIFO_DEPTH = 16, \
  parameter integer SETUP_INTERVAL = 0, \
  parameter integer TEXTURE = 0, \
  parameter integer MAX_TEXTURE_LATENCY = 64, \
  parameter integer PIXEL_CENTER = 0, \
  parameter integer FILL_RULE = 0, \
  parameter integer DEPTH_ROUNDING = 0, \
  parameter integer COLOR_ROUNDING = 0
`define RASTERSIM_CORE_PARAMETERS_PASSED \
  .WIDTH(WIDTH), .HEIGHT(HEIGHT), .SUBPIXEL_BITS(SUBPIXEL_BITS), .Z_BITS(Z_BITS), .Z_GUARD_BITS(Z_GUARD_BITS), \
  .DEPTH_EXPONENT_BITS(DEPTH_EXPONENT_BITS), .DEPTH_BIAS(DEPTH_BIAS), .MAX_MEMORY_LATENCY(MAX_MEMORY_LATENCY), \
  .MAX_SETUP_FIFO_DEPTH(MAX_SETUP_FIFO_DEPTH), .SETUP_INTERVAL(SETUP_INTERVAL), .TEXTURE(TEXTURE), \
  .MAX_TEXTURE_LATENCY(MAX_TEXTURE_LATENCY), .PIXEL_CENTER(PIXEL_CENTER), .FILL_RULE(FILL_RULE), \
  .DEPTH_ROUNDING(DEPTH_ROUNDING), .COLOR_ROUNDING(COLOR_ROUNDING)
`endif
