`timescale 1ns / 1ps
// Board self-test of a rastersim test-vector package (docs/vectors.md): the package's frame,
// replayed on the FPGA without a host. rastersim_top renders the commands of commands.hex (a ROM,
// $readmemh) into its frame memory (zbuffer_memory, block RAM); after the frame the depth and
// colour memories are read word by word through the read-back port into two CRC-32s, which are compared with the package's expected ones
// (selftest.hex). Two pins give the verdict: done rises when the check is over, pass with it when
// both CRCs match. The package's rastersim_vectors_params.vh (included inside the module) gives the
// profile and the cfg_* values; selftest.hex holds the expected CRCs:
//   line 0: CRC-32 of the depth memory, words in address order (y * WIDTH + x), each as its
//           ceil(Z_BITS / 8) bytes, least significant first
//   line 1: CRC-32 of the colour memory, each word as 3 bytes: blue, green, red
// (CRC-32/ISO-HDLC: reflected polynomial 0xEDB88320, initial and final XOR 0xFFFFFFFF, as zlib).
// Plain Verilog-2005: yosys synthesizes it (build_selftest_hx8k.sh); Icarus and Verilator simulate
// it with rastersim_selftest_sim below, which prints the verdict (run_selftest_icarus.sh).
module rastersim_selftest (
  input  wire clk,
  output reg  done,   // the check is over
  output reg  pass    // ... and both CRCs matched (valid with done)
);
`include "rastersim_vectors_params.vh"
  localparam integer COMMAND_SLOTS = TRIANGLES > 0 ? TRIANGLES : 1;
  localparam integer DEPTH_BYTES = (Z_BITS + 7) / 8;
  // verilator lint_off WIDTH
  localparam [2:0] FIRST_COLOR_BYTE = DEPTH_BYTES;      // byte_index of the colour's first byte
  localparam [2:0] LAST_BYTE = DEPTH_BYTES + 2;         // ... and of its last
  localparam [ADDR_BITS:0] LAST_WORD = WIDTH * HEIGHT - 1;
  // verilator lint_on WIDTH
  localparam integer COUNT_BITS = 32;

  // Power-on reset: 16 cycles (block RAM and the ROM are ready from configuration).
  reg [4:0] reset_count = 5'd0;
  wire rst = !reset_count[4];
  always @(posedge clk) if (rst) reset_count <= reset_count + 5'd1;

  // ---- Commands from the ROM --------------------------------------------------------------------
  reg [COMMAND_BITS-1:0] commands [0:COMMAND_SLOTS-1];
  reg [31:0] expected_crc [0:1];
  initial begin
    $readmemh("commands.hex", commands, 0, COMMAND_SLOTS - 1);
    $readmemh("selftest.hex", expected_crc, 0, 1);
  end
  reg [COUNT_BITS-1:0] next_command;
  reg [COUNT_BITS-1:0] command_plus_1_q;  // next_command + 1
  reg more_after_q;                       // next_command + 1 < TRIANGLES
  reg cmd_valid_q;  // next_command < TRIANGLES
  reg [COMMAND_BITS-1:0] command_q;  // the ROM word of next_command (a synchronous read)
  wire cmd_valid = cmd_valid_q;
  wire cmd_ready, frame_ready;
  wire accept = cmd_valid && cmd_ready;
  // The next cycle's count, validity and ROM address for both outcomes of the handshake, kept in
  // registers a command ahead: the handshake only selects (no compare or increment behind the
  // core's ready, nor before the ROM's address).
  wire [COUNT_BITS-1:0] command_plus_2 = command_plus_1_q + {{(COUNT_BITS-1){1'b0}}, 1'b1};
  wire [COUNT_BITS-1:0] address_stay = cmd_valid_q ? next_command : {COUNT_BITS{1'b0}};
  wire [COUNT_BITS-1:0] address_move = more_after_q ? command_plus_1_q : {COUNT_BITS{1'b0}};
  always @(posedge clk) begin
    if (rst) begin
      next_command <= {COUNT_BITS{1'b0}};
      command_plus_1_q <= {{(COUNT_BITS-1){1'b0}}, 1'b1};
      more_after_q <= TRIANGLES > 1;
      cmd_valid_q <= TRIANGLES > 0;
    end else if (accept) begin
      next_command <= command_plus_1_q;
      command_plus_1_q <= command_plus_2;
      more_after_q <= command_plus_2 < TRIANGLES;
      cmd_valid_q <= more_after_q;
    end
    command_q <= commands[accept ? address_move : address_stay];
  end
  // The command's fields (rastersim_vectors_params.vh), 64 bits each: field k at [64 k +: 64].
  wire [64*COMMAND_FIELDS-1:0] command_fields;
  genvar f;
  generate
    for (f = 0; f < COMMAND_FIELDS; f = f + 1) begin : fields
      wire [COMMAND_BITS-1:0] shifted = command_q >> COMMAND_FIELD_LSB[16*f +: 16];
      assign command_fields[64*f +: 64] = shifted[63:0];
    end
  endgenerate

  // ---- The pipeline with its frame memory (rastersim_top) ---------------------------------------
  wire trace_setup_decided, trace_setup_busy, trace_setup_stall, trace_setup_done;
  wire [2:0] trace_setup_status;
  wire trace_walker_load, trace_walker_busy, trace_walker_candidate, trace_walker_last;
  wire trace_frag_valid, trace_frag_ready, trace_result_valid, trace_result_pass, trace_zbuffer_busy;
  wire trace_zbuffer_stall;
  wire [X_BITS-1:0] trace_frag_x;
  wire [Y_BITS-1:0] trace_frag_y;
  wire [Z_BITS-1:0] trace_frag_z;
  wire [23:0] trace_frag_rgb;
  reg [ADDR_BITS-1:0] readback_addr;
  wire [Z_BITS-1:0] readback_depth;
  wire [23:0] readback_rgb;
  wire trace_walker_frag_valid, trace_walker_frag_ready, trace_texture_busy, trace_texture_stall;
  rastersim_top #(`RS_CORE_PARAMETERS_PASSED) top (
    .clk(clk), .rst(rst),
    .cfg_depth_func(CFG_DEPTH_FUNC), .cfg_depth_write(CFG_DEPTH_WRITE), .cfg_depth_clear(CFG_DEPTH_CLEAR),
    .cfg_cull(CFG_CULL), .cfg_front_face(CFG_FRONT_FACE), .cfg_traversal(CFG_TRAVERSAL), .cfg_shading(CFG_SHADING),
    .cfg_memory_latency(CFG_MEMORY_LATENCY), .cfg_setup_fifo_depth(CFG_SETUP_FIFO_DEPTH),
    // Built without the texture unit: its ports tied off.
    .cfg_texture_latency(7'd1), .cfg_texture_log2_width(4'd0), .cfg_texture_log2_height(4'd0),
    .cfg_texture_bilinear(1'b0), .cfg_texture_clamp(1'b0),
    .cfg_depth_bias_constant(CFG_DEPTH_BIAS_CONSTANT), .cfg_depth_bias_slope(CFG_DEPTH_BIAS_SLOPE),
    .texture_load_en(1'b0), .texture_load_x(10'd0), .texture_load_y(10'd0), .texture_load_rgb(24'd0),
    .texture_refuse(1'b0),
    .frame_ready(frame_ready),
    .cmd_valid(cmd_valid), .cmd_ready(cmd_ready),
    .cmd_x0(command_fields[64*0 +: COORD_BITS]), .cmd_y0(command_fields[64*1 +: COORD_BITS]),
    .cmd_x1(command_fields[64*2 +: COORD_BITS]), .cmd_y1(command_fields[64*3 +: COORD_BITS]),
    .cmd_x2(command_fields[64*4 +: COORD_BITS]), .cmd_y2(command_fields[64*5 +: COORD_BITS]),
    .cmd_z0(command_fields[64*6 +: DEPTH_PLANE_BITS]), .cmd_z1(command_fields[64*7 +: DEPTH_PLANE_BITS]),
    .cmd_z2(command_fields[64*8 +: DEPTH_PLANE_BITS]),
    .cmd_rgb0(command_fields[64*9 +: 24]), .cmd_rgb1(command_fields[64*10 +: 24]), .cmd_rgb2(command_fields[64*11 +: 24]),
    .cmd_textured(1'b0), .cmd_texture0(150'd0), .cmd_texture1(150'd0), .cmd_texture2(150'd0),
    .trace_setup_decided(trace_setup_decided), .trace_setup_status(trace_setup_status),
    .trace_setup_busy(trace_setup_busy), .trace_setup_stall(trace_setup_stall), .trace_setup_done(trace_setup_done),
    .trace_walker_load(trace_walker_load), .trace_walker_busy(trace_walker_busy),
    .trace_walker_candidate(trace_walker_candidate), .trace_walker_last(trace_walker_last),
    .trace_walker_frag_valid(trace_walker_frag_valid), .trace_walker_frag_ready(trace_walker_frag_ready),
    .trace_texture_busy(trace_texture_busy), .trace_texture_stall(trace_texture_stall),
    .trace_frag_valid(trace_frag_valid), .trace_frag_ready(trace_frag_ready),
    .trace_frag_x(trace_frag_x), .trace_frag_y(trace_frag_y), .trace_frag_z(trace_frag_z),
    .trace_frag_rgb(trace_frag_rgb), .trace_result_valid(trace_result_valid),
    .trace_result_pass(trace_result_pass), .trace_zbuffer_busy(trace_zbuffer_busy),
    .trace_zbuffer_stall(trace_zbuffer_stall),
    .readback_addr(readback_addr), .readback_depth(readback_depth), .readback_rgb(readback_rgb));

  // ---- The end of the frame (as the package testbench sees it) ------------------------------------
  reg [COUNT_BITS-1:0] frame_cycle;   // the current cycle, from cycle 0 (the first with frame_ready)
  reg [COUNT_BITS-1:0] frame_cycles;  // 1 + the last cycle with setup, walker or z-buffer busy
  reg [COUNT_BITS-1:0] in_flight;     // fragments awaiting their depth-test result
  wire pipeline_idle = !cmd_valid && !trace_setup_busy && !trace_walker_busy && !trace_zbuffer_busy &&
                       !trace_frag_valid && in_flight == {COUNT_BITS{1'b0}};

  // ---- CRC-32 of both memories, one byte per cycle -----------------------------------------------
  function [31:0] crc_byte;  // CRC-32/ISO-HDLC register after one more byte (reflected)
    input [31:0] crc;
    input [7:0] data;
    integer b;
    begin
      crc_byte = crc ^ {24'd0, data};
      for (b = 0; b < 8; b = b + 1) crc_byte = crc_byte[0] ? (crc_byte >> 1) ^ 32'hEDB88320 : crc_byte >> 1;
    end
  endfunction

  localparam [2:0] S_FRAME = 3'd0, S_ADDRESS = 3'd1, S_WAIT = 3'd2, S_BYTES = 3'd3, S_DONE = 3'd4;
  reg [2:0] state;
  reg [ADDR_BITS:0] word;       // the word being read back
  reg [2:0] byte_index;         // 0 .. DEPTH_BYTES + 2: depth bytes, then blue, green, red
  reg [Z_BITS-1:0] depth_word;
  reg [23:0] color_word;
  reg [31:0] depth_crc, color_crc;
  wire [Z_BITS+7:0] depth_shifted = {8'd0, depth_word} >> (8 * byte_index);
  wire [2:0] color_byte = byte_index - FIRST_COLOR_BYTE;
  wire [23:0] color_shifted = color_word >> (8 * color_byte);

  always @(posedge clk) begin
    if (rst) begin
      frame_cycle <= {COUNT_BITS{1'b0}};
      frame_cycles <= {COUNT_BITS{1'b0}};
      in_flight <= {COUNT_BITS{1'b0}};
      state <= S_FRAME;
      readback_addr <= {ADDR_BITS{1'b0}};
      word <= {(ADDR_BITS+1){1'b0}};
      byte_index <= 3'd0;
      depth_crc <= 32'hFFFFFFFF;
      color_crc <= 32'hFFFFFFFF;
      done <= 1'b0;
      pass <= 1'b0;
    end else begin
      in_flight <= in_flight + {{(COUNT_BITS-1){1'b0}}, trace_frag_valid && trace_frag_ready}
                             - {{(COUNT_BITS-1){1'b0}}, trace_result_valid};
      case (state)
        S_FRAME:
          if (frame_ready) begin
            frame_cycle <= frame_cycle + 1;
            if (trace_setup_busy || trace_walker_busy || trace_zbuffer_busy) frame_cycles <= frame_cycle + 1;
            if (pipeline_idle) state <= S_ADDRESS;
          end
        S_ADDRESS: begin  // readback_addr = word; its data is there in the next cycle
          readback_addr <= word[ADDR_BITS-1:0];
          state <= S_WAIT;
        end
        S_WAIT: state <= S_BYTES;
        S_BYTES: begin
          if (byte_index == 3'd0) begin
            depth_word <= readback_depth;
            color_word <= readback_rgb;
            depth_crc <= crc_byte(depth_crc, readback_depth[7:0]);
          end else if (byte_index < FIRST_COLOR_BYTE) begin
            depth_crc <= crc_byte(depth_crc, depth_shifted[7:0]);
          end else begin
            color_crc <= crc_byte(color_crc, color_shifted[7:0]);
          end
          if (byte_index == LAST_BYTE) begin
            byte_index <= 3'd0;
            if (word == LAST_WORD) begin
              state <= S_DONE;
            end else begin
              word <= word + 1;
              state <= S_ADDRESS;
            end
          end else begin
            byte_index <= byte_index + 3'd1;
          end
        end
        default: begin  // S_DONE: the verdict, held
          done <= 1'b1;
          pass <= ~depth_crc == expected_crc[0] && ~color_crc == expected_crc[1];
        end
      endcase
    end
  end
endmodule

`ifndef SYNTHESIS
// Simulation of the self-test: a 10 ns clock, the verdict printed when done rises (run by
// Icarus in run_selftest_icarus.sh, or by Verilator).
module rastersim_selftest_sim;
  reg clk = 1'b0;
  // verilator lint_off BLKSEQ
  always #5 clk = ~clk;
  // verilator lint_on BLKSEQ
  wire done, pass;
  rastersim_selftest selftest (.clk(clk), .done(done), .pass(pass));
  initial begin : watch
    integer cycles;
    cycles = 0;
    while (done !== 1'b1 && cycles < 10000000) begin
      @(posedge clk);
      cycles = cycles + 1;
    end
    @(negedge clk);
    $display("selftest: frame of %0d cycles (the model: %0d); depth CRC 0x%08h (expected 0x%08h), colour CRC 0x%08h (expected 0x%08h)",
             selftest.frame_cycles, selftest.CYCLES, ~selftest.depth_crc, selftest.expected_crc[0], ~selftest.color_crc,
             selftest.expected_crc[1]);
    if (done !== 1'b1) $display("selftest: FAIL (done did not rise)");
    else if (pass === 1'b1) $display("selftest: PASS");
    else $display("selftest: FAIL");
    $finish(0);
  end
endmodule
`endif
