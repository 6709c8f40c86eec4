`timescale 1ns / 1ps
// Self-checking testbench of rastersim test-vector packages (docs/vectors.md). One file serves every
// package: the package's rastersim_vectors_params.vh, included inside the module, gives the
// profile, the port widths, the number of vectors and every field's place in its word.
// Plain Verilog-2005: Icarus Verilog 11 (-g2012) and Verilator 5 (--binary) run it.
//
// It resets the pipeline with the profile's cfg_* values, waits for frame_ready (cycle 0), offers
// the commands of commands.hex one per cmd_valid/cmd_ready handshake, observes the trace_* ports
// every cycle, reads the final memories through the read-back port and then compares what it saw
// with the expected files: triangles.hex, setup.hex, fragments.hex, depth.hex, color.hex, frame.hex.
// With the texture unit (TEXTURE 1) it loads texture.hex into the texture memory during reset and
// drives texture_refuse with the profile's texture stall pattern.
// Fragments are compared per triangle as sets (matched by pixel), so a missing or extra fragment is
// one mismatch. Mismatches are printed earliest first (by the cycle where they show) as
// "<file> vector <line from 0> field <name>: expected .., actual .. (context)"; the last line is
// "N passed, M failed".
//
// Plusargs:
//   +package=DIR      the folder of the .hex files (default: the folder the simulation runs in)
//   +functional       compare functionally, for a port with another micro-architecture: per triangle
//                     the decision, the setup record and the set of fragments (any order, any cycle),
//                     the final memories and the decision and fragment counters; cycles are
//                     reported, not required. A difference that follows from an earlier one (a
//                     triangle's counts from its fragments, a memory word or a later depth-test
//                     result at a pixel where a fragment differed, the frame's counters) is counted
//                     apart, not as another failure. Default: cycle-exact, every field required.
//                     +functional=0 is the default (FuseSoC passes a bool plusarg as =1 or =0).
//   +max_shown=N      print the first N mismatches (default 20, 0: the summary alone, at most 1000)
//   +dump=FILE        write a VCD of the run (reset and memory clear included)
//   +dump_from=C      with +dump: start the VCD at frame cycle C (its rising edge and later)
//   +dump_to=C        with +dump: end the VCD after frame cycle C
//   +cycle_bound=N    abandon the frame after N cycles (default 4 CYCLES + 1000)
//
// Compile-time options:
//   RASTERSIM_VECTORS_PARAMS  the package's parameter file as a string (default
//                       "rastersim_vectors_params.vh" on the include path); with +package, any
//                       package runs from one build folder (rastersim.core's sim target)
//   RS_NO_SETUP_RECORD  a port without the setup unit's record wires (RS_RECORD_PATH.rec_*):
//                       setup.hex is skipped ("N passed, M failed, K skipped")
//   RS_RECORD_PATH      where the record wires are (default dut.core; dut with RS_EXTERNAL_MEMORY)
//   RS_EXTERNAL_MEMORY  the package tests rastersim_core with rastersim_memory_model.v on its memory
//                       port instead of rastersim_top (the parameter file defines it for such packages)
module rastersim_vectors_tb;
`ifdef RASTERSIM_VECTORS_PARAMS
`include `RASTERSIM_VECTORS_PARAMS
`else
`include "rastersim_vectors_params.vh"
`endif
`ifndef RS_RECORD_PATH
`ifdef RS_EXTERNAL_MEMORY
`define RS_RECORD_PATH dut
`else
`define RS_RECORD_PATH dut.core
`endif
`endif

  localparam integer CLEAR_BOUND = WORDS + 16;  // cycles the memory clear after reset may take
  localparam integer SHOWN = 20;                // mismatches printed unless +max_shown=N says otherwise
  localparam integer LIST_SLOTS = 1000;         // the most mismatches +max_shown can print
  localparam integer EXTRA_SLOTS = 1024;        // unexpected fragments kept for the report
  localparam integer TRIANGLE_SLOTS = TRIANGLES > 0 ? TRIANGLES : 1;  // array sizes, at least 1
  localparam integer DRAWN_SLOTS = DRAWN > 0 ? DRAWN : 1;
  localparam integer FRAGMENT_SLOTS = FRAGMENTS > 0 ? FRAGMENTS : 1;
  localparam integer OBSERVED_SLOTS = FRAGMENT_SLOTS + EXTRA_SLOTS;
  localparam integer NO_CYCLE = 32'h7fffffff;   // sort key of what has no cycle: after the frame

  reg clk = 1'b0;
  // verilator lint_off BLKSEQ
  always #5 clk = ~clk;  // the testbench's clock
  // verilator lint_on BLKSEQ
  reg rst = 1'b1;
  reg cmd_valid = 1'b0;
  reg [COORD_BITS-1:0] cmd_x0 = 0, cmd_y0 = 0, cmd_x1 = 0, cmd_y1 = 0, cmd_x2 = 0, cmd_y2 = 0;
  reg [DEPTH_PLANE_BITS-1:0] cmd_z0 = 0, cmd_z1 = 0, cmd_z2 = 0;
  reg [23:0] cmd_rgb0 = 0, cmd_rgb1 = 0, cmd_rgb2 = 0;
  reg cmd_textured = 1'b0;
  reg [149:0] cmd_texture0 = 0, cmd_texture1 = 0, cmd_texture2 = 0;  // {Q, T, S}, 50 bits each
  reg [ADDR_BITS-1:0] readback_addr = 0;
  wire frame_ready, cmd_ready;
  wire trace_setup_decided, trace_setup_busy, trace_setup_stall, trace_setup_done;
  wire [2:0] trace_setup_status;
  wire trace_walker_load, trace_walker_busy, trace_walker_candidate, trace_walker_last;
  wire trace_frag_valid, trace_frag_ready;
  wire [X_BITS-1:0] trace_frag_x;
  wire [Y_BITS-1:0] trace_frag_y;
  wire [Z_BITS-1:0] trace_frag_z;
  wire [23:0] trace_frag_rgb;
  wire trace_result_valid, trace_result_pass, trace_zbuffer_busy, trace_zbuffer_stall;
  // The texture unit's traces (without it the walker's handshake is the z-buffer's).
  wire trace_walker_frag_valid, trace_walker_frag_ready, trace_texture_busy, trace_texture_stall;
  // The texture memory: loaded through texture_load_* during reset (TEXTURE 1); it refuses reads in
  // frame cycle c when the profile's texture stall pattern says so (model/zbuffer_memory.h
  // memory_stalls(texture_stall_seed, texture_stall_percent, c)), as the model's texture memory.
  reg texture_load_en = 1'b0;
  reg [9:0] texture_load_x = 0, texture_load_y = 0;
  reg [23:0] texture_load_rgb = 0;
  reg [63:0] texture_cycle = 64'd0;  // the frame cycle now running (with texture_cycle_valid)
  reg texture_cycle_valid = 1'b0;
  wire texture_stalls;
  rastersim_stall_pattern #(.SEED(TEXTURE_STALL_SEED), .PERCENT(TEXTURE_STALL_PERCENT)) texture_pattern (
    .frame_cycle(texture_cycle), .stalls(texture_stalls));
  wire texture_refuse = texture_cycle_valid && texture_stalls;
  wire [Z_BITS-1:0] readback_depth;
  wire [23:0] readback_rgb;

  // The pipeline under test, with the ports every package drives and observes.
`define RS_PIPELINE_PORTS \
    .clk(clk), .rst(rst), \
    .cfg_depth_func(CFG_DEPTH_FUNC), .cfg_depth_write(CFG_DEPTH_WRITE), .cfg_cull(CFG_CULL), \
    .cfg_front_face(CFG_FRONT_FACE), .cfg_traversal(CFG_TRAVERSAL), .cfg_shading(CFG_SHADING), \
    .cfg_memory_latency(CFG_MEMORY_LATENCY), .cfg_setup_fifo_depth(CFG_SETUP_FIFO_DEPTH), \
    .frame_ready(frame_ready), \
    .cmd_valid(cmd_valid), .cmd_ready(cmd_ready), \
    .cmd_x0(cmd_x0), .cmd_y0(cmd_y0), .cmd_x1(cmd_x1), .cmd_y1(cmd_y1), .cmd_x2(cmd_x2), .cmd_y2(cmd_y2), \
    .cmd_z0(cmd_z0), .cmd_z1(cmd_z1), .cmd_z2(cmd_z2), .cmd_rgb0(cmd_rgb0), .cmd_rgb1(cmd_rgb1), .cmd_rgb2(cmd_rgb2), \
    .trace_setup_decided(trace_setup_decided), .trace_setup_status(trace_setup_status), \
    .trace_setup_busy(trace_setup_busy), .trace_setup_stall(trace_setup_stall), \
    .trace_setup_done(trace_setup_done), \
    .trace_walker_load(trace_walker_load), .trace_walker_busy(trace_walker_busy), \
    .trace_walker_candidate(trace_walker_candidate), .trace_walker_last(trace_walker_last), \
    .trace_frag_valid(trace_frag_valid), .trace_frag_ready(trace_frag_ready), \
    .trace_frag_x(trace_frag_x), .trace_frag_y(trace_frag_y), .trace_frag_z(trace_frag_z), \
    .trace_frag_rgb(trace_frag_rgb), \
    .trace_result_valid(trace_result_valid), .trace_result_pass(trace_result_pass), \
    .trace_zbuffer_busy(trace_zbuffer_busy), .trace_zbuffer_stall(trace_zbuffer_stall), \
    .cfg_texture_latency(CFG_TEXTURE_LATENCY), .cfg_texture_log2_width(CFG_TEXTURE_LOG2_WIDTH), \
    .cfg_texture_log2_height(CFG_TEXTURE_LOG2_HEIGHT), .cfg_texture_bilinear(CFG_TEXTURE_BILINEAR), \
    .cfg_texture_clamp(CFG_TEXTURE_CLAMP), \
    .cfg_depth_bias_constant(CFG_DEPTH_BIAS_CONSTANT), .cfg_depth_bias_slope(CFG_DEPTH_BIAS_SLOPE), \
    .cmd_textured(cmd_textured), .cmd_texture0(cmd_texture0), .cmd_texture1(cmd_texture1), .cmd_texture2(cmd_texture2), \
    .trace_walker_frag_valid(trace_walker_frag_valid), .trace_walker_frag_ready(trace_walker_frag_ready), \
    .trace_texture_busy(trace_texture_busy), .trace_texture_stall(trace_texture_stall)
`ifdef RS_EXTERNAL_MEMORY
  // rastersim_core (or a port with its parameters and ports) with the frame memory outside: the
  // memory model with the profile's latency and back-pressure pattern on its memory port.
  wire mem_clear_done, mem_rd_valid, mem_rd_ready, mem_wr_depth_en, mem_wr_color_en;
  wire [ADDR_BITS-1:0] mem_rd_addr, mem_wr_addr;
  wire [Z_BITS-1:0] mem_rd_depth, mem_wr_depth;
  wire [23:0] mem_wr_rgb;
  wire [31:0] refused_reads, bad_accesses;
  wire tex_rd_valid, tex_rd_ready;
  wire [4*18-1:0] tex_rd_addr;
  wire [4*24-1:0] tex_rd_texels;
  rastersim_core #(`RS_CORE_PARAMETERS_PASSED) dut (
    `RS_PIPELINE_PORTS,
    .mem_clear_done(mem_clear_done), .mem_rd_valid(mem_rd_valid), .mem_rd_ready(mem_rd_ready),
    .mem_rd_addr(mem_rd_addr), .mem_rd_depth(mem_rd_depth), .mem_wr_depth_en(mem_wr_depth_en),
    .mem_wr_color_en(mem_wr_color_en), .mem_wr_addr(mem_wr_addr), .mem_wr_depth(mem_wr_depth),
    .mem_wr_rgb(mem_wr_rgb), .tex_rd_valid(tex_rd_valid), .tex_rd_ready(tex_rd_ready), .tex_rd_addr(tex_rd_addr),
    .tex_rd_texels(tex_rd_texels));
  // The texture memory of rastersim_top beside the core (its read port has no board-side variant).
  generate
    if (TEXTURE != 0) begin : texturing
      texture_memory #(.MAX_TEXTURE_LATENCY(TEXTURE_LATENCY)) tmem (
        .clk(clk), .rst(rst), .cfg_texture_latency(CFG_TEXTURE_LATENCY), .refuse(texture_refuse),
        .rd_valid(tex_rd_valid), .rd_ready(tex_rd_ready), .rd_addr(tex_rd_addr), .rd_texels(tex_rd_texels),
        .load_en(texture_load_en), .load_x(texture_load_x), .load_y(texture_load_y), .load_rgb(texture_load_rgb));
    end else begin : no_texture
      assign tex_rd_ready = 1'b0;
      assign tex_rd_texels = 96'd0;
    end
  endgenerate
  rastersim_memory_model #(
    .WIDTH(WIDTH), .HEIGHT(HEIGHT), .Z_BITS(Z_BITS), .ADDR_BITS(ADDR_BITS), .LATENCY(MEMORY_LATENCY),
    .STALL_PERCENT(MEMORY_STALL_PERCENT), .STALL_SEED(MEMORY_STALL_SEED)
  ) memory (
    .clk(clk), .rst(rst), .depth_clear(CFG_DEPTH_CLEAR), .clear_done(mem_clear_done),
    .rd_valid(mem_rd_valid), .rd_ready(mem_rd_ready), .rd_addr(mem_rd_addr), .rd_depth(mem_rd_depth),
    .wr_depth_en(mem_wr_depth_en), .wr_color_en(mem_wr_color_en), .wr_addr(mem_wr_addr),
    .wr_depth(mem_wr_depth), .wr_rgb(mem_wr_rgb),
    .readback_addr(readback_addr), .readback_depth(readback_depth), .readback_rgb(readback_rgb),
    .refused_reads(refused_reads), .bad_accesses(bad_accesses));
`else
  // rastersim_top (or a port with its parameters and ports): the frame memory on chip.
  rastersim_top #(`RS_CORE_PARAMETERS_PASSED) dut (
    `RS_PIPELINE_PORTS,
    .cfg_depth_clear(CFG_DEPTH_CLEAR),
    .texture_load_en(texture_load_en), .texture_load_x(texture_load_x), .texture_load_y(texture_load_y),
    .texture_load_rgb(texture_load_rgb), .texture_refuse(texture_refuse),
    .readback_addr(readback_addr), .readback_depth(readback_depth), .readback_rgb(readback_rgb));
`endif

  // ---- Words and their fields ------------------------------------------------------------------
  // The field functions are called a few hundred times: Verilator keeps them as calls
  // (no_inline_task) instead of inlining each into the initial block, which g++ then cannot
  // compile in reasonable time.
  // A field's slot of a word (zero-extended to 64 bits), and a value put into a field's slot.
  function [63:0] slot_of;
    /*verilator no_inline_task*/
    input [MAX_WORD_BITS-1:0] word;
    input integer lsb, slot;
    reg [MAX_WORD_BITS-1:0] shifted;
    begin
      shifted = word >> lsb;
      slot_of = shifted[63:0];
      if (slot < 64) slot_of = slot_of & ((64'd1 << slot) - 64'd1);
    end
  endfunction
  // value (bits wide, two's complement when is_signed) as it sits in a slot: sign- or zero-extended.
  function [63:0] as_slot;
    /*verilator no_inline_task*/
    input [63:0] value;
    input integer bits, slot, is_signed;
    begin
      as_slot = value;
      if (bits < 64) begin
        as_slot = as_slot & ((64'd1 << bits) - 64'd1);
        if (is_signed != 0 && value[bits - 1]) as_slot = as_slot | ~((64'd1 << bits) - 64'd1);
      end
      if (slot < 64) as_slot = as_slot & ((64'd1 << slot) - 64'd1);
    end
  endfunction
  function [MAX_WORD_BITS-1:0] with_slot;
    input [MAX_WORD_BITS-1:0] word;
    input integer lsb, slot;
    input [63:0] value;  // already as_slot
    reg [MAX_WORD_BITS-1:0] mask, wide;
    begin
      mask = {MAX_WORD_BITS{1'b0}};
      mask[63:0] = slot < 64 ? (64'd1 << slot) - 64'd1 : ~64'd0;
      wide = {MAX_WORD_BITS{1'b0}};
      wide[63:0] = value;
      with_slot = (word & ~(mask << lsb)) | (wide << lsb);
    end
  endfunction

  // Field k's place in a file's layout: its slot's lowest bit (P_LSB), the slot's bits (P_SLOT),
  // its own width (P_BITS). The params file packs 16 bits per field, field 0 at the low end.
  localparam integer P_LSB = 0, P_SLOT = 1, P_BITS = 2;
  function integer field_place;
    /*verilator no_inline_task*/
    input integer file, what, k;
    reg [16*128-1:0] places;  // at most 128 fields (the params file checks it)
    begin
      case (file)
        0: places = what == P_LSB ? COMMAND_FIELD_LSB : what == P_SLOT ? COMMAND_FIELD_SLOT : COMMAND_FIELD_BITS;
        1: places = what == P_LSB ? TRIANGLE_FIELD_LSB : what == P_SLOT ? TRIANGLE_FIELD_SLOT : TRIANGLE_FIELD_BITS;
        2: places = what == P_LSB ? SETUP_FIELD_LSB : what == P_SLOT ? SETUP_FIELD_SLOT : SETUP_FIELD_BITS;
        3: places = what == P_LSB ? FRAGMENT_FIELD_LSB : what == P_SLOT ? FRAGMENT_FIELD_SLOT : FRAGMENT_FIELD_BITS;
        default: places = what == P_LSB ? FRAME_FIELD_LSB : what == P_SLOT ? FRAME_FIELD_SLOT : FRAME_FIELD_BITS;
      endcase
      field_place = places[16*k +: 16];
    end
  endfunction
  function integer field_signed;
    /*verilator no_inline_task*/
    input integer file, k;
    begin
      case (file)
        0: field_signed = COMMAND_FIELD_SIGNED[k];
        1: field_signed = TRIANGLE_FIELD_SIGNED[k];
        2: field_signed = SETUP_FIELD_SIGNED[k];
        3: field_signed = FRAGMENT_FIELD_SIGNED[k];
        default: field_signed = FRAME_FIELD_SIGNED[k];
      endcase
    end
  endfunction
  localparam integer F_COMMANDS = 0, F_TRIANGLES = 1, F_SETUP = 2, F_FRAGMENTS = 3, F_FRAME = 4;
  // Field numbers in the layouts' fixed order (docs/vectors.md).
  localparam integer T_STATUS = 0, T_ACCEPT = 1, T_DONE = 2, T_LOAD = 3, T_END = 4, T_FRAGMENTS = 5,
                     T_PASS = 6, T_LAST_WRITE = 7;
  localparam integer G_TRI = 0, G_CYCLE = 1, G_X = 2, G_Y = 3, G_Z = 4, G_RGB = 5, G_PASS = 6;
  localparam integer R_TRIANGLES = 1, R_DECISIONS_LAST = 6, R_FRAGMENTS = 8, R_DEPTH_FAIL = 10;

  function [63:0] field_of;  // field k of a word of a file, as its slot holds it
    /*verilator no_inline_task*/
    input integer file;
    input [MAX_WORD_BITS-1:0] word;
    input integer k;
    begin
      field_of = slot_of(word, field_place(file, P_LSB, k), field_place(file, P_SLOT, k));
    end
  endfunction
  function [63:0] slot_value;  // a value as field k of a file holds it
    /*verilator no_inline_task*/
    input integer file, k;
    input [63:0] value;
    begin
      slot_value = as_slot(value, field_place(file, P_BITS, k), field_place(file, P_SLOT, k), field_signed(file, k));
    end
  endfunction

  // ---- Expected words ($readmemh, one word per line; the line number from 0 is the vector index) ----
  reg [COMMAND_BITS-1:0] commands [0:TRIANGLE_SLOTS-1];
  reg [TRIANGLE_BITS-1:0] triangles [0:TRIANGLE_SLOTS-1];
  reg [SETUP_BITS-1:0] setups [0:DRAWN_SLOTS-1];
  reg [FRAGMENT_BITS-1:0] fragments [0:FRAGMENT_SLOTS-1];
  reg [Z_BITS-1:0] depth [0:WORDS-1];
  reg [23:0] color [0:WORDS-1];
  reg [FRAME_BITS-1:0] frame [0:0];
  reg [23:0] texels [0:TEXELS-1];  // texture.hex, row by row (TEXTURE 1)

  // ---- What the pipeline did ------------------------------------------------------------------
  integer seen_status [0:TRIANGLE_SLOTS-1];
  integer seen_accept [0:TRIANGLE_SLOTS-1];
  integer seen_done [0:TRIANGLE_SLOTS-1];
  integer seen_load [0:TRIANGLE_SLOTS-1];
  integer seen_end [0:TRIANGLE_SLOTS-1];
  integer seen_fragments_of [0:TRIANGLE_SLOTS-1];
  integer seen_pass_of [0:TRIANGLE_SLOTS-1];
  integer seen_last_write [0:TRIANGLE_SLOTS-1];
  reg [SETUP_BITS-1:0] seen_setups [0:DRAWN_SLOTS-1];
  integer seen_setup_tri [0:DRAWN_SLOTS-1];
  // Fragments in the order the z-buffer accepted them; pass is 2 until the depth-test result.
  integer obs_tri [0:OBSERVED_SLOTS-1];
  integer obs_cycle [0:OBSERVED_SLOTS-1];
  integer obs_x [0:OBSERVED_SLOTS-1];
  integer obs_y [0:OBSERVED_SLOTS-1];
  reg [Z_BITS-1:0] obs_z [0:OBSERVED_SLOTS-1];
  reg [23:0] obs_rgb [0:OBSERVED_SLOTS-1];
  reg [1:0] obs_pass [0:OBSERVED_SLOTS-1];
  reg [Z_BITS-1:0] seen_depth [0:WORDS-1];
  reg [23:0] seen_color [0:WORDS-1];

  integer cycle, clear_wait, cycle_bound, next_command, next_decided, n_done, n_loaded, in_setup, in_walker;
  integer last_busy, i, j, k, t, d, a;
  integer drawn_tri [0:DRAWN_SLOTS-1];  // triangle index of each drawn triangle, in order
  integer seen_setup_count, seen_fragment_count, seen_result_count;
  integer n_triangles, n_drawn, n_degenerate, n_culled, n_offscreen, n_no_centre, n_candidates, n_pass, n_fail;
  integer setup_busy, setup_stall, walker_busy, walker_stall, zbuffer_busy, zbuffer_stall, texture_busy, texture_stall;
  // The triangle of each fragment the walker handed on, in order: the texture unit keeps the order,
  // so the z-buffer's k-th fragment is the walker's k-th.
  integer walker_tri [0:OBSERVED_SLOTS-1];
  integer walker_handed;
  reg submitting, busy, finished, functional;
  reg [8*256:1] dump_file;
  integer dump_from, dump_to;  // +dump_from, +dump_to: frame cycles (-1, NO_CYCLE: unbounded)
  reg dumping;
  reg [8*1024:1] package_dir;  // +package
  integer functional_value;    // +functional=N

  // Vertex v's cmd_texture word of command n: {Q, T, S}, 50 bits each.
  function [149:0] texture_word;
    input integer n, v;
    reg [63:0] s_field, t_field, q_field;
    begin
      s_field = field_of(F_COMMANDS, commands[n], 13 + 3 * v);
      t_field = field_of(F_COMMANDS, commands[n], 14 + 3 * v);
      q_field = field_of(F_COMMANDS, commands[n], 15 + 3 * v);
      texture_word = {q_field[49:0], t_field[49:0], s_field[49:0]};
    end
  endfunction

  // Offers command n (cmd_valid low after the last one).
  task drive_command;
    input integer n;
    begin
      cmd_valid = n < TRIANGLES;
      if (n < TRIANGLES) begin
        cmd_x0 = field_of(F_COMMANDS, commands[n], 0);
        cmd_y0 = field_of(F_COMMANDS, commands[n], 1);
        cmd_x1 = field_of(F_COMMANDS, commands[n], 2);
        cmd_y1 = field_of(F_COMMANDS, commands[n], 3);
        cmd_x2 = field_of(F_COMMANDS, commands[n], 4);
        cmd_y2 = field_of(F_COMMANDS, commands[n], 5);
        cmd_z0 = field_of(F_COMMANDS, commands[n], 6);
        cmd_z1 = field_of(F_COMMANDS, commands[n], 7);
        cmd_z2 = field_of(F_COMMANDS, commands[n], 8);
        cmd_rgb0 = field_of(F_COMMANDS, commands[n], 9);
        cmd_rgb1 = field_of(F_COMMANDS, commands[n], 10);
        cmd_rgb2 = field_of(F_COMMANDS, commands[n], 11);
        if (TEXTURE != 0) begin  // textured, then S, T, Q of each vertex
          cmd_textured = field_of(F_COMMANDS, commands[n], 12) != 0;
          cmd_texture0 = texture_word(n, 0);
          cmd_texture1 = texture_word(n, 1);
          cmd_texture2 = texture_word(n, 2);
        end
      end
    end
  endtask

  // The record the setup unit makes, in the setup.hex layout (field order of docs/vectors.md).
  reg [SETUP_BITS-1:0] record_word;
  integer record_field;
  task put_record_field;
    input [63:0] value;
    begin
      record_word = with_slot(record_word, field_place(F_SETUP, P_LSB, record_field), field_place(F_SETUP, P_SLOT, record_field),
                              slot_value(F_SETUP, record_field, value));
      record_field = record_field + 1;
    end
  endtask
`ifndef RS_NO_SETUP_RECORD
  task observe_record;
    input integer triangle_index;
    integer e, c;
    begin
      record_word = {SETUP_BITS{1'b0}};
      record_field = 0;
      put_record_field(triangle_index);
      put_record_field(`RS_RECORD_PATH.rec_x0);
      put_record_field(`RS_RECORD_PATH.rec_x1);
      put_record_field(`RS_RECORD_PATH.rec_y0);
      put_record_field(`RS_RECORD_PATH.rec_y1);
      for (e = 0; e < 3; e = e + 1) begin
        put_record_field(`RS_RECORD_PATH.rec_edge_start[e*EDGE_BITS +: EDGE_BITS]);
        put_record_field(`RS_RECORD_PATH.rec_edge_step_x[e*EDGE_STEP_X_BITS +: EDGE_STEP_X_BITS]);
        put_record_field(`RS_RECORD_PATH.rec_edge_step_y[e*EDGE_STEP_Y_BITS +: EDGE_STEP_Y_BITS]);
        put_record_field(`RS_RECORD_PATH.rec_span_quot[e*EDGE_BITS +: EDGE_BITS]);
        put_record_field(`RS_RECORD_PATH.rec_span_rem[e*SPAN_REM_BITS +: SPAN_REM_BITS]);
        put_record_field(`RS_RECORD_PATH.rec_span_step_quot[e*EDGE_STEP_Y_BITS +: EDGE_STEP_Y_BITS]);
        put_record_field(`RS_RECORD_PATH.rec_span_step_rem[e*SPAN_REM_BITS +: SPAN_REM_BITS]);
      end
      put_record_field(`RS_RECORD_PATH.rec_depth_start);
      put_record_field(`RS_RECORD_PATH.rec_depth_step_x);
      put_record_field(`RS_RECORD_PATH.rec_depth_step_y);
      if (CFG_SHADING != 0) begin  // the colour planes are in the layout with Gouraud shading only
        for (e = 0; e < 3; e = e + 1) begin
          put_record_field(`RS_RECORD_PATH.rec_color_start[e*COLOR_REG_BITS +: COLOR_REG_BITS]);
          put_record_field(`RS_RECORD_PATH.rec_color_step_x[e*COLOR_REG_BITS +: COLOR_REG_BITS]);
          put_record_field(`RS_RECORD_PATH.rec_color_step_y[e*COLOR_REG_BITS +: COLOR_REG_BITS]);
        end
      end
      put_record_field(`RS_RECORD_PATH.rec_flat_rgb);
      for (e = 0; e < 2; e = e + 1) begin  // left-edge slot e: depth, then r, g, b
        put_record_field(`RS_RECORD_PATH.rec_left_start[e*(Z_REG_BITS + 3*COLOR_REG_BITS) +: Z_REG_BITS]);
        put_record_field(`RS_RECORD_PATH.rec_left_step[e*(Z_REG_BITS + 3*COLOR_REG_BITS) +: Z_REG_BITS]);
        if (CFG_SHADING != 0) begin
          for (c = 0; c < 3; c = c + 1) begin
            put_record_field(`RS_RECORD_PATH.rec_left_start[e*(Z_REG_BITS + 3*COLOR_REG_BITS) + Z_REG_BITS + c*COLOR_REG_BITS +: COLOR_REG_BITS]);
            put_record_field(`RS_RECORD_PATH.rec_left_step[e*(Z_REG_BITS + 3*COLOR_REG_BITS) + Z_REG_BITS + c*COLOR_REG_BITS +: COLOR_REG_BITS]);
          end
        end
      end
      if (TEXTURE != 0) begin  // the texture record: its flag, then register r at 1 + r TEXTURE_REG_BITS
        put_record_field(`RS_RECORD_PATH.rec_texture[0]);
        for (e = 0; e < 21; e = e + 1) put_record_field(`RS_RECORD_PATH.rec_texture[1 + e*TEXTURE_REG_BITS +: TEXTURE_REG_BITS]);
      end
    end
  endtask
`endif

  // ---- The report: mismatches kept earliest first ----------------------------------------------
  integer list_key [0:LIST_SLOTS-1];
  reg [8*320:1] list_text [0:LIST_SLOTS-1];
  integer listed, hidden, max_shown, list_limit;
  integer passed, failed, skipped, followed;
  reg [8*320:1] text;
  reg [8*96:1] context_text;
  reg [8*96:1] bound_text;    // the cycle-bound message, with the cycle it was reached in
  integer word_key;          // the cycle where the current vector's mismatch shows
  reg word_ok, word_follows;  // the vector matched; its differences all follow from earlier ones

  task report;  // keeps the text if it is among the list_limit earliest
    input integer key;
    input [8*320:1] line;
    integer p;
    begin
      if (list_limit == 0) begin
        hidden = hidden + 1;
      end else if (listed == list_limit && key >= list_key[listed - 1]) begin
        hidden = hidden + 1;
      end else begin
        if (listed == list_limit) begin
          listed = listed - 1;
          hidden = hidden + 1;
        end
        p = listed;
        while (p > 0 && list_key[p - 1] > key) begin
          list_key[p] = list_key[p - 1];
          list_text[p] = list_text[p - 1];
          p = p - 1;
        end
        list_key[p] = key;
        list_text[p] = line;
        listed = listed + 1;
      end
    end
  endtask

  // Starts a vector: key is the cycle where its mismatch would show; follows: its differences
  // follow from earlier mismatches (functional mode) and are counted apart.
  reg vector_differs;
  task begin_vector;
    input integer key;
    input follows;
    begin
      word_key = key;
      word_ok = 1'b1;
      word_follows = follows;
      vector_differs = 1'b0;
    end
  endtask
  task end_vector;
    begin
      if (!word_ok) failed = failed + 1;
      else if (vector_differs) followed = followed + 1;
      else passed = passed + 1;
    end
  endtask
  reg [8*128:1] values_text;
  // One field of the current vector: a difference is a mismatch unless it follows.
  task compare;
    input [8*16:1] file;
    input integer index;
    input [8*24:1] field;
    input [63:0] expected;
    input [63:0] actual;
    begin
      if (expected !== actual) begin
        $sformat(values_text, "expected 0x%0h, actual 0x%0h", expected, actual);
        field_differs(file, index, field, values_text);
      end
    end
  endtask
  // One field of the current vector that the pipeline never produced (`why` says so).
  task compare_absent;
    input [8*16:1] file;
    input integer index;
    input [8*24:1] field;
    input [63:0] expected;
    input [8*64:1] why;
    begin
      $sformat(values_text, "expected 0x%0h, actual: none (%0s)", expected, why);
      field_differs(file, index, field, values_text);
    end
  endtask
  task field_differs;  // a mismatch unless it follows from an earlier one
    input [8*16:1] file;
    input integer index;
    input [8*24:1] field;
    input [8*128:1] values;
    begin
      if (word_follows) begin
        vector_differs = 1'b1;
      end else begin
        word_ok = 1'b0;
        $sformat(text, "%0s vector %0d field %0s: %0s%0s", file, index, field, values, context_text);
        report(word_key, text);
      end
    end
  endtask

  // Something the pipeline did that no vector expects (one failure).
  task unexpected;
    input integer key;
    input [8*16:1] file;
    input [8*320:1] what;
    begin
      failed = failed + 1;
      $sformat(text, "%0s: %0s", file, what);
      report(key, text);
    end
  endtask

  function integer earliest;  // the earlier of two cycles; -1 (did not happen) counts as never
    /*verilator no_inline_task*/
    input integer p, q;
    begin
      if (p < 0) earliest = q < 0 ? NO_CYCLE : q;
      else if (q < 0) earliest = p;
      else earliest = p < q ? p : q;
    end
  endfunction

  // ---- Fragments matched per triangle ----------------------------------------------------------
  integer exp_first [0:TRIANGLE_SLOTS-1];  // fragments.hex lines of each triangle (a list)
  integer exp_next [0:FRAGMENT_SLOTS-1];
  integer exp_last [0:TRIANGLE_SLOTS-1];
  integer obs_first [0:TRIANGLE_SLOTS-1];
  integer obs_next [0:OBSERVED_SLOTS-1];
  integer obs_last [0:TRIANGLE_SLOTS-1];
  integer exp_match [0:FRAGMENT_SLOTS-1];  // observed fragment matched to each expected one, or -1
  reg obs_matched [0:OBSERVED_SLOTS-1];
  integer pixel_owner [0:WORDS-1];         // observed fragment of the triangle at the pixel
  integer pixel_owner_tri [0:WORDS-1];
  integer pixel_disturbed [0:WORDS-1];     // earliest triangle with a fragment mismatch here, or -1
  integer tri_disturbed [0:TRIANGLE_SLOTS-1];
  integer leftover_exp [0:FRAGMENT_SLOTS-1];
  integer leftover_obs [0:OBSERVED_SLOTS-1];
  integer n_leftover_exp, n_leftover_obs, kept_observed, any_root;
  integer ex, ey, et, ecycle, address;

  function integer pixel_address;  // -1 off the screen
    /*verilator no_inline_task*/
    input integer x, y;
    begin
      pixel_address = (x >= 0 && x < WIDTH && y >= 0 && y < HEIGHT) ? y * WIDTH + x : -1;
    end
  endfunction

  // Expected fragment e against observed fragment o (o = -1: missing) as one vector.
  task compare_fragment;
    input integer e, o;
    reg follows;
    begin
      ex = field_of(F_FRAGMENTS, fragments[e], G_X);
      ey = field_of(F_FRAGMENTS, fragments[e], G_Y);
      et = field_of(F_FRAGMENTS, fragments[e], G_TRI);
      ecycle = field_of(F_FRAGMENTS, fragments[e], G_CYCLE);  // the low 32 bits: -1 stays -1
      address = pixel_address(ex, ey);
      if (o < 0) begin
        begin_vector(ecycle, 1'b0);
        failed = failed + 1;
        any_root = 1;
        $sformat(text, "fragments.hex vector %0d: missing: triangle %0d, pixel (%0d, %0d), expected at cycle %0d", e,
                 et, ex, ey, ecycle);
        report(ecycle, text);
        if (address >= 0 && pixel_disturbed[address] < 0) pixel_disturbed[address] = et;
        if (et >= 0 && et < TRIANGLES) tri_disturbed[et] = 1;
      end else begin
        // A pass-only difference at a pixel where an earlier triangle's fragment differed follows
        // from that one (functional mode).
        follows = functional && address >= 0 && pixel_disturbed[address] >= 0 && pixel_disturbed[address] < et &&
                  field_of(F_FRAGMENTS, fragments[e], G_TRI) === slot_value(F_FRAGMENTS, G_TRI, obs_tri[o]) &&
                  field_of(F_FRAGMENTS, fragments[e], G_Z) === slot_value(F_FRAGMENTS, G_Z, obs_z[o]) &&
                  field_of(F_FRAGMENTS, fragments[e], G_RGB) === slot_value(F_FRAGMENTS, G_RGB, obs_rgb[o]);
        begin_vector(earliest(ecycle, obs_cycle[o]), follows);
        $sformat(context_text, " (triangle %0d, pixel (%0d, %0d), cycle %0d)", et, ex, ey, ecycle);
        compare("fragments.hex", e, "tri", field_of(F_FRAGMENTS, fragments[e], G_TRI),
                slot_value(F_FRAGMENTS, G_TRI, obs_tri[o]));
        if (!functional)
          compare("fragments.hex", e, "cycle", field_of(F_FRAGMENTS, fragments[e], G_CYCLE),
                  slot_value(F_FRAGMENTS, G_CYCLE, obs_cycle[o]));
        compare("fragments.hex", e, "x", field_of(F_FRAGMENTS, fragments[e], G_X), slot_value(F_FRAGMENTS, G_X, obs_x[o]));
        compare("fragments.hex", e, "y", field_of(F_FRAGMENTS, fragments[e], G_Y), slot_value(F_FRAGMENTS, G_Y, obs_y[o]));
        compare("fragments.hex", e, "z", field_of(F_FRAGMENTS, fragments[e], G_Z), slot_value(F_FRAGMENTS, G_Z, obs_z[o]));
        compare("fragments.hex", e, "rgb", field_of(F_FRAGMENTS, fragments[e], G_RGB),
                slot_value(F_FRAGMENTS, G_RGB, obs_rgb[o]));
        if (obs_pass[o] == 2'd2)
          compare_absent("fragments.hex", e, "pass", field_of(F_FRAGMENTS, fragments[e], G_PASS),
                         "no depth-test result before the frame ended");
        else
          compare("fragments.hex", e, "pass", field_of(F_FRAGMENTS, fragments[e], G_PASS),
                  slot_value(F_FRAGMENTS, G_PASS, obs_pass[o]));
        if (!word_ok || vector_differs) begin
          if (!word_ok) any_root = 1;
          if (address >= 0 && pixel_disturbed[address] < 0) pixel_disturbed[address] = et;
          if (et >= 0 && et < TRIANGLES) tri_disturbed[et] = 1;
        end
        end_vector;
        context_text = "";
      end
    end
  endtask

  task unexpected_fragment;
    input integer o;
    begin
      $sformat(text, "an unexpected fragment: triangle %0d, pixel (%0d, %0d), cycle %0d", obs_tri[o], obs_x[o],
               obs_y[o], obs_cycle[o]);
      unexpected(obs_cycle[o], "fragments.hex", text);
      any_root = 1;
      address = pixel_address(obs_x[o], obs_y[o]);
      if (address >= 0 && pixel_disturbed[address] < 0) pixel_disturbed[address] = obs_tri[o];
      if (obs_tri[o] >= 0 && obs_tri[o] < TRIANGLES) tri_disturbed[obs_tri[o]] = 1;
    end
  endtask

  initial begin
    max_shown = SHOWN;
    if ($value$plusargs("max_shown=%d", max_shown) && max_shown < 0) begin
      $display("error: +max_shown=%0d: the number of mismatches to print is 0 or more", max_shown);
      $finish;
    end
    list_limit = max_shown < LIST_SLOTS ? max_shown : LIST_SLOTS;
    cycle_bound = 4 * CYCLES + 1000;
    if ($value$plusargs("cycle_bound=%d", cycle_bound) && cycle_bound < 1) begin
      $display("error: +cycle_bound=%0d: the frame needs at least one cycle", cycle_bound);
      $finish;
    end
    functional = $test$plusargs("functional") != 0;
    if ($value$plusargs("functional=%d", functional_value)) functional = functional_value != 0;
    if (!$value$plusargs("package=%s", package_dir)) package_dir = ".";
    dump_from = -1;
    dump_to = NO_CYCLE;
    if ($value$plusargs("dump_from=%d", dump_from) && dump_from < 0) begin
      $display("error: +dump_from=%0d: the first frame cycle dumped is 0 or more", dump_from);
      $finish;
    end
    if ($value$plusargs("dump_to=%d", dump_to) && dump_to < dump_from) begin
      $display("error: +dump_to=%0d: the last frame cycle dumped is not before +dump_from", dump_to);
      $finish;
    end
    dumping = $value$plusargs("dump=%s", dump_file) != 0;
    if (dumping) begin
      $dumpfile(dump_file);
      if (dump_from <= 0) $dumpvars(0, rastersim_vectors_tb);
    end else if (dump_from >= 0 || dump_to != NO_CYCLE) begin
      $display("error: +dump_from and +dump_to need +dump=FILE");
      $finish;
    end
    $readmemh({package_dir, "/commands.hex"}, commands, 0, TRIANGLE_SLOTS - 1);
    $readmemh({package_dir, "/triangles.hex"}, triangles, 0, TRIANGLE_SLOTS - 1);
    $readmemh({package_dir, "/setup.hex"}, setups, 0, DRAWN_SLOTS - 1);
    $readmemh({package_dir, "/fragments.hex"}, fragments, 0, FRAGMENT_SLOTS - 1);
    $readmemh({package_dir, "/depth.hex"}, depth, 0, WORDS - 1);
    $readmemh({package_dir, "/color.hex"}, color, 0, WORDS - 1);
    $readmemh({package_dir, "/frame.hex"}, frame, 0, 0);
    if (^frame[0] === 1'bx) begin
      $display("error: %0s/frame.hex: no such file, or not a package's", package_dir);
      $finish;
    end
    if (TEXTURE != 0) $readmemh({package_dir, "/texture.hex"}, texels, 0, TEXELS - 1);
    for (t = 0; t < TRIANGLE_SLOTS; t = t + 1) begin
      seen_status[t] = -1; seen_accept[t] = -1; seen_done[t] = -1; seen_load[t] = -1; seen_end[t] = -1;
      seen_fragments_of[t] = 0; seen_pass_of[t] = 0; seen_last_write[t] = -1;
      exp_first[t] = -1; exp_last[t] = -1; obs_first[t] = -1; obs_last[t] = -1; tri_disturbed[t] = 0;
    end
    for (d = 0; d < DRAWN_SLOTS; d = d + 1) begin
      seen_setups[d] = {SETUP_BITS{1'b1}};
      seen_setup_tri[d] = -1;
    end
    for (a = 0; a < WORDS; a = a + 1) begin
      pixel_owner[a] = -1; pixel_owner_tri[a] = -1; pixel_disturbed[a] = -1;
    end
    next_command = 0; next_decided = 0; n_done = 0; n_loaded = 0;
    in_setup = -1; in_walker = -1; last_busy = -1; clear_wait = 0; cycle = -1;
    seen_setup_count = 0; seen_fragment_count = 0; seen_result_count = 0;
    n_triangles = 0; n_drawn = 0; n_degenerate = 0; n_culled = 0; n_offscreen = 0; n_no_centre = 0;
    n_candidates = 0; n_pass = 0; n_fail = 0;
    setup_busy = 0; setup_stall = 0; walker_busy = 0; walker_stall = 0; zbuffer_busy = 0; zbuffer_stall = 0;
    texture_busy = 0; texture_stall = 0; walker_handed = 0;
    passed = 0; failed = 0; skipped = 0; followed = 0; listed = 0; hidden = 0; any_root = 0;
    finished = 1'b0; context_text = "";

    // Reset: rst high for four rising edges (the cfg_* inputs are sampled meanwhile).
    // Inputs change 1 ns after a rising edge and outputs are sampled at the falling edge, so that
    // what is sampled is what the next rising edge sees: one clock period is one cycle.
    // With the texture unit, rst stays high while the texels are loaded, one per cycle, row by row.
    repeat (4) @(posedge clk);
    #1;
    if (TEXTURE != 0) begin
      texture_load_en = 1'b1;
      for (a = 0; a < TEXELS; a = a + 1) begin
        texture_load_x = a % (1 << CFG_TEXTURE_LOG2_WIDTH);
        texture_load_y = a >> CFG_TEXTURE_LOG2_WIDTH;
        texture_load_rgb = texels[a];
        @(posedge clk);
        #1;
      end
      texture_load_en = 1'b0;
    end
    rst = 1'b0;
    drive_command(0);

    // Cycle 0 is the first cycle with frame_ready high (the memory clear is done).
    while (!finished) begin
      @(negedge clk);
      // The dump window: from the middle of cycle dump_from - 1 to the middle of cycle dump_to + 1,
      // so that every edge of cycles dump_from..dump_to is in it. The dump starts late rather than
      // being switched off, and ends by closing the file: Verilator 5.006 ignores $dumpoff/$dumpon.
      if (dumping && dump_from > 0 && cycle == dump_from - 1) $dumpvars(0, rastersim_vectors_tb);
      if (dumping && dump_to != NO_CYCLE && cycle == dump_to + 1) begin
`ifdef VERILATOR
        $c("\n#if VM_TRACE\nvlSymsp->_traceDumpClose();\n#endif\n");
`else
        $dumpoff;
`endif
        dumping = 1'b0;
      end
      if (cycle < 0) begin
        if (frame_ready) begin
          cycle = 0;
        end else if (clear_wait == CLEAR_BOUND) begin
          unexpected(0, "frame.hex", "frame_ready stayed low: the memory clear did not finish");
          finished = 1'b1;
        end else begin
          clear_wait = clear_wait + 1;
        end
      end
      if (cycle >= 0) begin
        submitting = cmd_valid;
        if (cmd_valid && cmd_ready) begin
          seen_accept[next_command] = cycle;
          next_command = next_command + 1;
          n_triangles = n_triangles + 1;
        end
        // Triangles pass each stage in order: decision, record made (drawn ones), walker load.
        if (trace_setup_decided && next_decided < next_command) begin
          seen_status[next_decided] = trace_setup_status;
          case (trace_setup_status)
            3'd0: begin if (n_drawn < DRAWN_SLOTS) drawn_tri[n_drawn] = next_decided; n_drawn = n_drawn + 1; end
            3'd1: begin n_degenerate = n_degenerate + 1; seen_done[next_decided] = cycle; end
            3'd2: begin n_culled = n_culled + 1; seen_done[next_decided] = cycle; end
            3'd3: begin n_offscreen = n_offscreen + 1; seen_done[next_decided] = cycle; end
            default: begin n_no_centre = n_no_centre + 1; seen_done[next_decided] = cycle; end
          endcase
          next_decided = next_decided + 1;
        end
        if (trace_setup_done && n_done < n_drawn && n_done < DRAWN_SLOTS) begin
          seen_done[drawn_tri[n_done]] = cycle;
          // The record, in the setup unit's output register in setup_done.
          if (seen_setup_count < DRAWN_SLOTS) begin
`ifndef RS_NO_SETUP_RECORD
            observe_record(drawn_tri[n_done]);
            seen_setups[seen_setup_count] = record_word;
`endif
            seen_setup_tri[seen_setup_count] = drawn_tri[n_done];
          end
          seen_setup_count = seen_setup_count + 1;
          n_done = n_done + 1;
        end
        if (trace_walker_load && n_loaded < n_done) begin
          in_setup = drawn_tri[n_loaded];
          n_loaded = n_loaded + 1;
          seen_load[in_setup] = cycle;
        end
        // A fragment belongs to the walker's triangle when the walker hands it on: without the texture
        // unit in the z-buffer's handshake; with it, the z-buffer's k-th is the walker's k-th.
        if (TEXTURE != 0 && trace_walker_frag_valid && trace_walker_frag_ready) begin
          if (walker_handed < OBSERVED_SLOTS) walker_tri[walker_handed] = in_walker;
          walker_handed = walker_handed + 1;
        end
        if (trace_frag_valid && trace_frag_ready) begin
          t = TEXTURE == 0 ? in_walker
            : seen_fragment_count < walker_handed && seen_fragment_count < OBSERVED_SLOTS ? walker_tri[seen_fragment_count] : -1;
          if (t >= 0) seen_fragments_of[t] = seen_fragments_of[t] + 1;
          if (seen_fragment_count < OBSERVED_SLOTS) begin
            obs_tri[seen_fragment_count] = t;
            obs_cycle[seen_fragment_count] = cycle;
            obs_x[seen_fragment_count] = trace_frag_x;
            obs_y[seen_fragment_count] = trace_frag_y;
            obs_z[seen_fragment_count] = trace_frag_z;
            obs_rgb[seen_fragment_count] = trace_frag_rgb;
            obs_pass[seen_fragment_count] = 2'd2;
          end
          seen_fragment_count = seen_fragment_count + 1;
        end
        if (trace_result_valid) begin
          if (seen_result_count >= seen_fragment_count) begin
            unexpected(cycle, "fragments.hex", "a depth-test result (trace_result_valid) with no fragment in flight");
          end else begin
            if (seen_result_count < OBSERVED_SLOTS) begin
              obs_pass[seen_result_count] = {1'b0, trace_result_pass};
              t = obs_tri[seen_result_count];
              if (t >= 0) begin
                seen_pass_of[t] = seen_pass_of[t] + (trace_result_pass ? 1 : 0);
                seen_last_write[t] = cycle;
              end
            end
            seen_result_count = seen_result_count + 1;
          end
          if (trace_result_pass) n_pass = n_pass + 1; else n_fail = n_fail + 1;
        end
        if (trace_walker_last && in_walker >= 0) seen_end[in_walker] = cycle;
        // The walker's triangle from the cycle after its load: a load can share a cycle with the
        // previous triangle's last candidate, whose fragment and walker_end are counted above.
        in_walker = in_setup;
        if (trace_walker_candidate) n_candidates = n_candidates + 1;
        if (trace_setup_busy) setup_busy = setup_busy + 1;
        if (trace_setup_stall) setup_stall = setup_stall + 1;
        if (trace_walker_busy) walker_busy = walker_busy + 1;
        if (trace_zbuffer_busy) zbuffer_busy = zbuffer_busy + 1;
        if (trace_walker_frag_valid && !trace_walker_frag_ready) walker_stall = walker_stall + 1;
        if (trace_zbuffer_stall) zbuffer_stall = zbuffer_stall + 1;
        if (trace_texture_busy) texture_busy = texture_busy + 1;
        if (trace_texture_stall) texture_stall = texture_stall + 1;
        busy = trace_setup_busy || trace_walker_busy || trace_texture_busy || trace_zbuffer_busy;
        if (busy) last_busy = cycle;
        // A fragment the memory refuses leaves every unit's busy low but is still to come.
        if (!submitting && !busy && !trace_frag_valid && !trace_walker_frag_valid &&
            seen_result_count >= seen_fragment_count) begin
          finished = 1'b1;
        end else if (cycle >= cycle_bound) begin
          // Listed first (key -1): every other mismatch of an unfinished frame may follow from it.
          $sformat(bound_text, "the frame did not finish within the cycle bound (+cycle_bound=N) [cycle %0d]", cycle);
          unexpected(-1, "frame.hex", bound_text);
          finished = 1'b1;
        end
        cycle = cycle + 1;
      end
      @(posedge clk);
      #1;
      drive_command(next_command);
      // The frame cycle about to run: cycle counts on; the first has frame_ready high.
      if (cycle >= 0 || frame_ready) begin
        texture_cycle = cycle >= 0 ? cycle : 0;
        texture_cycle_valid = 1'b1;
      end
    end

    // The final memories through the read-back port: data for readback_addr in cycle c is on
    // readback_depth / readback_rgb in cycle c + 1.
    cmd_valid = 1'b0;
    readback_addr = 0;
    for (i = 0; i <= WORDS; i = i + 1) begin
      @(negedge clk);
      if (i >= 1) begin
        seen_depth[i - 1] = readback_depth;
        seen_color[i - 1] = readback_rgb;
      end
      @(posedge clk);
      #1;
      if (i + 1 < WORDS) readback_addr = i + 1;
    end

`ifdef RS_EXTERNAL_MEMORY
    if (bad_accesses != 0) begin
      $sformat(text, "%0d reads or writes outside the memory (rastersim_memory_model printed each)", bad_accesses);
      unexpected(NO_CYCLE - 1, "frame.hex", text);
    end
`endif

    // ---- Comparison, in time order of the triangles ----
    // The fragments of each triangle, expected and observed, as lists in their order.
    for (i = 0; i < FRAGMENTS; i = i + 1) begin
      exp_next[i] = -1;
      exp_match[i] = -1;
      t = field_of(F_FRAGMENTS, fragments[i], G_TRI);
      if (t >= 0 && t < TRIANGLES) begin
        if (exp_last[t] < 0) exp_first[t] = i; else exp_next[exp_last[t]] = i;
        exp_last[t] = i;
      end else begin
        exp_next[i] = -2;  // a triangle that does not exist: left over
      end
    end
    kept_observed = seen_fragment_count < OBSERVED_SLOTS ? seen_fragment_count : OBSERVED_SLOTS;
    for (j = 0; j < kept_observed; j = j + 1) begin
      obs_next[j] = -1;
      obs_matched[j] = 1'b0;
      t = obs_tri[j];
      if (t >= 0 && t < TRIANGLES) begin
        if (obs_last[t] < 0) obs_first[t] = j; else obs_next[obs_last[t]] = j;
        obs_last[t] = j;
      end
    end
    // Per triangle: the k-th expected and k-th observed fragments when at the same pixel (a changed
    // field of one fragment stays one mismatch), then the rest by pixel (a missing or extra fragment
    // does not shift the others).
    n_leftover_exp = 0;
    n_leftover_obs = 0;
    for (t = 0; t < TRIANGLES; t = t + 1) begin
      j = obs_first[t];
      for (i = exp_first[t]; i >= 0 && j >= 0; i = exp_next[i]) begin
        if (field_of(F_FRAGMENTS, fragments[i], G_X) == obs_x[j] && field_of(F_FRAGMENTS, fragments[i], G_Y) == obs_y[j]) begin
          exp_match[i] = j;
          obs_matched[j] = 1'b1;
        end
        j = obs_next[j];
      end
      for (j = obs_first[t]; j >= 0; j = obs_next[j]) begin
        address = pixel_address(obs_x[j], obs_y[j]);
        if (!obs_matched[j] && address >= 0 && pixel_owner_tri[address] != t) begin
          pixel_owner[address] = j;
          pixel_owner_tri[address] = t;
        end
      end
      for (i = exp_first[t]; i >= 0; i = exp_next[i]) begin
        address = pixel_address(field_of(F_FRAGMENTS, fragments[i], G_X), field_of(F_FRAGMENTS, fragments[i], G_Y));
        if (exp_match[i] < 0 && address >= 0 && pixel_owner_tri[address] == t && !obs_matched[pixel_owner[address]]) begin
          exp_match[i] = pixel_owner[address];
          obs_matched[pixel_owner[address]] = 1'b1;
        end
      end
    end
    for (i = 0; i < FRAGMENTS; i = i + 1)
      if (exp_match[i] < 0) begin
        leftover_exp[n_leftover_exp] = i;
        n_leftover_exp = n_leftover_exp + 1;
      end
    for (j = 0; j < kept_observed; j = j + 1)
      if (!obs_matched[j]) begin
        leftover_obs[n_leftover_obs] = j;
        n_leftover_obs = n_leftover_obs + 1;
      end
    // What no pixel matched is paired in order (a fragment at another pixel or of another triangle
    // is one mismatch); the rest are missing or unexpected.
    for (k = 0; k < n_leftover_exp && k < n_leftover_obs; k = k + 1) exp_match[leftover_exp[k]] = leftover_obs[k];
    for (i = 0; i < FRAGMENTS; i = i + 1) compare_fragment(i, exp_match[i]);
    for (k = n_leftover_exp; k < n_leftover_obs; k = k + 1) unexpected_fragment(leftover_obs[k]);
    if (seen_fragment_count > OBSERVED_SLOTS) begin
      $sformat(text, "%0d more fragments than the testbench keeps (%0d unexpected ones)", seen_fragment_count - kept_observed,
               EXTRA_SLOTS);
      unexpected(NO_CYCLE - 1, "fragments.hex", text);
    end

    // Triangles: the decision and, cycle-exact, every cycle; the counts follow from the fragments.
    for (t = 0; t < TRIANGLES; t = t + 1) begin
      $sformat(context_text, " (triangle %0d)", t);
      begin_vector(earliest(field_of(F_TRIANGLES, triangles[t], T_DONE), seen_done[t]), 1'b0);
      compare("triangles.hex", t, "status", field_of(F_TRIANGLES, triangles[t], T_STATUS),
              slot_value(F_TRIANGLES, T_STATUS, seen_status[t]));
      if (!word_ok) any_root = 1;
      if (!functional) begin
        word_key = earliest(field_of(F_TRIANGLES, triangles[t], T_ACCEPT), seen_accept[t]);
        compare("triangles.hex", t, "setup_accept", field_of(F_TRIANGLES, triangles[t], T_ACCEPT),
                slot_value(F_TRIANGLES, T_ACCEPT, seen_accept[t]));
        word_key = earliest(field_of(F_TRIANGLES, triangles[t], T_DONE), seen_done[t]);
        compare("triangles.hex", t, "setup_done", field_of(F_TRIANGLES, triangles[t], T_DONE),
                slot_value(F_TRIANGLES, T_DONE, seen_done[t]));
        word_key = earliest(field_of(F_TRIANGLES, triangles[t], T_LOAD), seen_load[t]);
        compare("triangles.hex", t, "walker_load", field_of(F_TRIANGLES, triangles[t], T_LOAD),
                slot_value(F_TRIANGLES, T_LOAD, seen_load[t]));
        word_key = earliest(field_of(F_TRIANGLES, triangles[t], T_END), seen_end[t]);
        compare("triangles.hex", t, "walker_end", field_of(F_TRIANGLES, triangles[t], T_END),
                slot_value(F_TRIANGLES, T_END, seen_end[t]));
      end
      word_key = earliest(field_of(F_TRIANGLES, triangles[t], T_LAST_WRITE), seen_last_write[t]);
      word_follows = functional && tri_disturbed[t] != 0;
      compare("triangles.hex", t, "fragments", field_of(F_TRIANGLES, triangles[t], T_FRAGMENTS),
              slot_value(F_TRIANGLES, T_FRAGMENTS, seen_fragments_of[t]));
      compare("triangles.hex", t, "depth_pass", field_of(F_TRIANGLES, triangles[t], T_PASS),
              slot_value(F_TRIANGLES, T_PASS, seen_pass_of[t]));
      word_follows = 1'b0;
      if (!functional)
        compare("triangles.hex", t, "last_write", field_of(F_TRIANGLES, triangles[t], T_LAST_WRITE),
                slot_value(F_TRIANGLES, T_LAST_WRITE, seen_last_write[t]));
      end_vector;
    end
    context_text = "";

    // Setup records, in the order the setup unit made them.
    for (d = 0; d < DRAWN; d = d + 1) begin
`ifdef RS_NO_SETUP_RECORD
      skipped = skipped + 1;
`else
      t = field_of(F_SETUP, setups[d], 0);
      begin_vector(t >= 0 && t < TRIANGLES ? earliest(field_of(F_TRIANGLES, triangles[t], T_DONE),
                                            seen_setup_tri[d] >= 0 ? seen_done[seen_setup_tri[d]] : -1)
                                 : NO_CYCLE, 1'b0);
      if (setups[d] !== seen_setups[d]) begin
        if (d < seen_setup_count)
          $sformat(context_text, " (triangle %0d)", t);
        else
          $sformat(context_text, " (triangle %0d; the setup unit made only %0d records)", t, seen_setup_count);
        for (k = 0; k < SETUP_FIELDS; k = k + 1)
          compare("setup.hex", d, setup_field_name(k), field_of(F_SETUP, setups[d], k), field_of(F_SETUP, seen_setups[d], k));
      end
      if (!word_ok) any_root = 1;
      end_vector;
`endif
    end
    context_text = "";
    if (seen_setup_count > DRAWN) unexpected(NO_CYCLE - 1, "setup.hex", "the setup unit made more records than expected");

    // The final memories: a word at a pixel where a fragment differed follows from that (functional).
    for (a = 0; a < WORDS; a = a + 1) begin
      $sformat(context_text, " (pixel (%0d, %0d))", a % WIDTH, a / WIDTH);
      begin_vector(NO_CYCLE, functional && pixel_disturbed[a] >= 0);
      compare("depth.hex", a, "depth", {{(64 - Z_BITS){1'b0}}, depth[a]}, {{(64 - Z_BITS){1'b0}}, seen_depth[a]});
      end_vector;
    end
    for (a = 0; a < WORDS; a = a + 1) begin
      $sformat(context_text, " (pixel (%0d, %0d))", a % WIDTH, a / WIDTH);
      begin_vector(NO_CYCLE, functional && pixel_disturbed[a] >= 0);
      compare("color.hex", a, "rgb", {40'd0, color[a]}, {40'd0, seen_color[a]});
      end_vector;
    end
    context_text = "";

    // The frame's counters. Functional: the decision and fragment counts (which follow from the
    // mismatches above, if any); the cycles, candidates and busy and stall counts are reported.
    begin_vector(NO_CYCLE, 1'b0);
    for (k = 0; k < FRAME_FIELDS; k = k + 1) begin
      case (k)
        0: j = last_busy + 1;
        1: j = n_triangles;
        2: j = n_drawn;
        3: j = n_degenerate;
        4: j = n_culled;
        5: j = n_offscreen;
        6: j = n_no_centre;
        7: j = n_candidates;
        8: j = n_pass + n_fail;
        9: j = n_pass;
        10: j = n_fail;
        11: j = setup_busy;
        12: j = setup_stall;
        13: j = walker_busy;
        14: j = walker_stall;
        15: j = zbuffer_busy;
        16: j = zbuffer_stall;
        17: j = texture_busy;
        default: j = texture_stall;
      endcase
      word_follows = functional && any_root != 0;
      if (!functional || (k >= R_TRIANGLES && k <= R_DECISIONS_LAST) || (k >= R_FRAGMENTS && k <= R_DEPTH_FAIL))
        compare("frame.hex", 0, frame_field_name(k), field_of(F_FRAME, frame[0], k), slot_value(F_FRAME, k, j));
    end
    end_vector;

    for (k = 0; k < listed; k = k + 1) begin
      if (k == 0) $write("first mismatch: "); else $write("mismatch: ");
      if (list_key[k] < 0 || list_key[k] >= NO_CYCLE - 1) $display("%0s", list_text[k]);
      else $display("%0s [cycle %0d]", list_text[k], list_key[k]);
    end
    if (hidden > 0) $display("(%0d more mismatches not shown)", hidden);
    if (functional)
      $display("functional mode: the frame took %0d cycles (the model: %0d); %0d vectors differ only as a consequence of the mismatches",
               last_busy + 1, CYCLES, followed);
`ifdef RS_NO_SETUP_RECORD
    $display("%0d passed, %0d failed, %0d skipped", passed, failed, skipped);
`else
    $display("%0d passed, %0d failed", passed, failed);
`endif
    $finish(0);
  end
endmodule
