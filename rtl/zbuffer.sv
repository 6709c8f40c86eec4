// Z-buffer unit (model/zbuffer.h): read, compare, conditional write of depth and colour through a
// memory port of read latency L = cfg_memory_latency (1 .. MAX_MEMORY_LATENCY). The memory is a
// separate unit behind the port: rtl/zbuffer_memory.sv on chip (rastersim_top), or any memory with
// the same contract on the ports of rastersim_core (the SystemC memory model, testbench/systemc/).
// A fragment is taken from the walker (frag_valid & frag_ready) into a two-entry input buffer and
// read from the buffer's head in a later cycle r when it has no hazard and the memory takes its
// read request (mem_rd_valid & mem_rd_ready); its depth word arrives on mem_rd_depth in r+L, the
// depth test runs and the depth (if cfg_depth_write) and colour (on pass) writes go out in r+L.
// Read-after-write hazard: a fragment is read in r only if no fragment to the same address was
// read in r-L .. r-1 (the head waits meanwhile), so every read sees all earlier writes and the
// memory never needs to forward a pending write.
// Memory port contract (docs/rtl.md): after reset the memory clears itself (every word reads as
// the depth clear value, colour 0) and raises mem_clear_done, which starts the frame; a read
// request taken in c returns its word in exactly c+L; writes are always taken (no back-pressure)
// and land at the end of their cycle; mem_rd_ready may be low in any cycle (back-pressure).
`include "rastersim_pkg.sv"
module zbuffer `RS_IMPORT #(
  parameter integer WIDTH = 640,
  parameter integer HEIGHT = 480,
  parameter integer Z_BITS = 24,
  parameter integer DEPTH_EXPONENT_BITS = 0,  // Ne: frag_z is X, Np bits; the stored word Z_BITS (depth_word.sv)
  parameter integer MAX_MEMORY_LATENCY = 64
) (
  input  wire clk,
  input  wire rst,
  input  `RS_TYPE(depth_func_t) cfg_depth_func,  // rastersim_pkg::DEPTH_*
  input  wire       cfg_depth_write,
  input  wire [rs_ubits32(MAX_MEMORY_LATENCY)-1:0] cfg_memory_latency,
  output wire clear_done,            // the memory is cleared: the frame may start
  // Fragment from the walker (x, y) and the Z adder (z, rgb).
  input  wire frag_valid,
  output wire frag_ready,
  input  wire [rs_ubits32(WIDTH - 1)-1:0]  frag_x,
  input  wire [rs_ubits32(HEIGHT - 1)-1:0] frag_y,
  input  wire [rs_depth_plane_bits(Z_BITS, DEPTH_EXPONENT_BITS)-1:0] frag_z,  // X, the plane's output
  input  `RS_TYPE(rgb_t)    frag_rgb,
  // Depth test result of the fragment read L cycles ago (its write cycle).
  output wire result_valid,
  output wire result_pass,
  output wire busy,   // a fragment taken this cycle, held in the input buffer or in flight
  output wire stall,  // the input buffer's head waits (a hazard or the memory's back-pressure)
  // Memory port: word address y * WIDTH + x.
  input  wire mem_clear_done,
  output wire mem_rd_valid,
  input  wire mem_rd_ready,
  output wire [rs_ubits32(WIDTH * HEIGHT - 1)-1:0] mem_rd_addr,
  input  wire [Z_BITS-1:0] mem_rd_depth,  // the word of the read taken L cycles ago
  output wire mem_wr_depth_en,
  output wire mem_wr_color_en,
  output wire [rs_ubits32(WIDTH * HEIGHT - 1)-1:0] mem_wr_addr,
  output wire [Z_BITS-1:0] mem_wr_depth,
  output `RS_TYPE(rgb_t)    mem_wr_rgb
);
`include "rastersim_widths.vh"
  `RS_REQUIRE(illegal_width, WIDTH >= 1 && WIDTH <= 4096, "zbuffer: WIDTH must be 1..4096")
  `RS_REQUIRE(illegal_height, HEIGHT >= 1 && HEIGHT <= 4096, "zbuffer: HEIGHT must be 1..4096")
  `RS_REQUIRE(illegal_z_bits, Z_BITS >= 1 && Z_BITS <= 32, "zbuffer: Z_BITS must be 1..32")  // the formal proofs use 2
  `RS_REQUIRE(illegal_latency, MAX_MEMORY_LATENCY >= 1 && MAX_MEMORY_LATENCY <= 64, "zbuffer: MAX_MEMORY_LATENCY must be 1..64")

  localparam integer X_BITS = rs_ubits32(WIDTH - 1);
  localparam integer Y_BITS = rs_ubits32(HEIGHT - 1);
  localparam integer ADDR_BITS = rs_ubits32(WIDTH * HEIGHT - 1);
  localparam [ADDR_BITS-1:0] WIDTH_A = WIDTH[ADDR_BITS-1:0];

  // Input buffer: the walker's fragment is taken into one of two entries in the cycle t it is
  // offered while fewer than two are held (frag_ready is that flip-flop-only test), and its read
  // is issued from the buffer's head, at the earliest in t + 1 (docs/cycle-model.md). The entries
  // stay in place (head_q names the older one), so an issue moves no data.
  localparam integer PIXEL_BITS = Y_BITS + X_BITS;  // {y, x}: one pixel, one address
  localparam integer DATA_BITS = ADDR_BITS + Z_BITS + 24;  // in flight: {address, depth word, rgb}
  localparam integer PLANE_BITS = rs_depth_plane_bits(Z_BITS, DEPTH_EXPONENT_BITS);
  localparam integer BUF_DATA_BITS = ADDR_BITS + PLANE_BITS + 24;  // buffered: {address, X, rgb}
  // In-flight fragments: a ring of RING = 2^RING_BITS >= MAX_MEMORY_LATENCY slots, one written every
  // cycle (slot now_slot_q) with the buffer's head. A slot is live from the cycle after its read was
  // issued through that fragment's data cycle (issued in r: live in r+1 .. r+L), exactly the window
  // in which a fragment to the same address must wait; its pixel (y, x) stays in flip-flops, its
  // depth, colour and address for the write go through a RAM (block RAM on an FPGA) read a cycle
  // ahead.
  localparam integer RING_BITS = MAX_MEMORY_LATENCY > 2 ? $clog2(MAX_MEMORY_LATENCY) : 1;
  localparam integer RING = 1 << RING_BITS;
  localparam integer LATENCY_BITS = rs_ubits32(MAX_MEMORY_LATENCY);
  reg [RING_BITS-1:0] now_slot_q;     // the slot written at the end of this cycle
  reg [RING-1:0]      now_onehot_q;   // the same, one-hot
  reg [RING-1:0]      live_q;         // live slots but the last cycle's issue
  reg                 issued_q;       // the last cycle issued a read: its slot is live from now on
  reg [RING-1:0]      last_onehot_q;  // the slot written in the last cycle, one-hot
  wire [RING-1:0] live = live_q | (issued_q ? last_onehot_q : {RING{1'b0}});
  reg [PIXEL_BITS-1:0] ring_pixel_q [0:RING-1];
  reg [DATA_BITS-1:0] ring_data_q [0:RING-1];

  // Ages are taken modulo the ring size: the high bits of the latency are not needed for a slot.
  /* verilator lint_off UNUSEDSIGNAL */
  function automatic [RING_BITS-1:0] slot_of_age(input [RING_BITS-1:0] now, input [LATENCY_BITS-1:0] age);
    reg [LATENCY_BITS:0] wide_age;
    begin
      wide_age = {1'b0, age};
      slot_of_age = now - wide_age[RING_BITS-1:0];  // modulo RING (a power of two)
    end
  endfunction
  /* verilator lint_on UNUSEDSIGNAL */

  // The buffer's entries. match_q[e][k]: entry e's pixel equals slot k's, kept true for every live
  // slot: compared with the whole ring when the fragment is taken, and each later slot written
  // while it waits holds the fragment ahead of it (ahead_q[e]: its pixel equals that fragment's).
  reg [1:0]            count_q;  // entries held, 0..2
  reg                  head_q;   // the older entry
  reg                  tail_q;   // the entry the next fragment is taken into
  reg [PIXEL_BITS-1:0] buf_pixel_q [0:1];
  reg [BUF_DATA_BITS-1:0] buf_data_q [0:1];
  reg [RING-1:0]       match_q [0:1];
  reg                  ahead_q [0:1];

  wire [ADDR_BITS-1:0] frag_addr = frag_y * WIDTH_A + {{(ADDR_BITS-X_BITS){1'b0}}, frag_x};
  wire [PIXEL_BITS-1:0] frag_pixel = {frag_y, frag_x};
  wire [BUF_DATA_BITS-1:0] frag_data = {frag_addr, frag_z, frag_rgb};
  assign frag_ready = !count_q[1];
  wire take = frag_valid && frag_ready;
  wire [PIXEL_BITS-1:0] head_pixel = buf_pixel_q[head_q];
  wire [BUF_DATA_BITS-1:0] head_buffered = buf_data_q[head_q];
  // The head's depth word, formed here, a register after the Z adder (docs/cycle-model.md, "Depth
  // output stage").
  wire [Z_BITS-1:0] head_word;
  depth_word #(.Z_BITS(Z_BITS), .DEPTH_EXPONENT_BITS(DEPTH_EXPONENT_BITS)) head_encoder (
    .value(head_buffered[24 +: PLANE_BITS]), .word(head_word));
  wire [DATA_BITS-1:0] head_data = {head_buffered[PLANE_BITS + 24 +: ADDR_BITS], head_word, head_buffered[23:0]};
  wire head_valid = count_q != 2'd0;

  // The incoming fragment against every slot; the slot written this cycle gets the head (its
  // pixel compared with the head's; unused unless the head's read is issued now).
  // (Both entries compared, the head's chosen after: no multiplexer before the compare.)
  wire frag_ahead = head_q ? frag_pixel == buf_pixel_q[1] : frag_pixel == buf_pixel_q[0];
  reg [RING-1:0] frag_match;
  integer k;
  always @(*)
    for (k = 0; k < RING; k = k + 1)
      frag_match[k] = now_onehot_q[k] ? frag_ahead : ring_pixel_q[k] == frag_pixel;

  // Hazard: a live slot with the head's pixel, from flip-flops only (the slot issued in the last
  // cycle held the fragment ahead of the head).
  wire hazard = |(live_q & match_q[head_q]) || (issued_q && ahead_q[head_q]);
  wire in_flight = |live;

  // The read request does not depend on mem_rd_ready; the head is issued with it.
  assign clear_done = mem_clear_done;
  assign mem_rd_valid = head_valid && mem_clear_done && !hazard;
  assign mem_rd_addr = head_data[Z_BITS + 24 +: ADDR_BITS];
  wire issue = mem_rd_valid && mem_rd_ready;
  assign busy = take || head_valid || in_flight;
  assign stall = head_valid && !issue;

  // The fragment in its data cycle r+L: slot done_slot (done_onehot_q), live until the end of this
  // cycle; its word is on mem_rd_depth. Its data is in a register (done_data_q), so the depth test
  // starts from flip-flops: chosen in the cycle before from the RAM's read of two cycles before
  // (slot read_slot then: the same age two cycles on), or, at L = 2, the fragment issued two
  // cycles before (latest_q), or, at L = 1, the head issued in the cycle before. Its live bit is
  // taken in the cycle before (next_done_onehot), or, at L = 1, it is that cycle's issue (issued_q).
  wire [RING_BITS-1:0] done_slot = slot_of_age(now_slot_q, cfg_memory_latency);
  wire [RING_BITS-1:0] read_slot = done_slot + RING_BITS'(2);
  reg  [RING-1:0]      done_onehot_q;
  wire [RING-1:0]      next_done_onehot = {done_onehot_q[RING-2:0], done_onehot_q[RING-1]};
  reg                  done_live_q;  // at L >= 2 the issue of the last cycle is not the done slot's
  wire                 latency_one = cfg_memory_latency == LATENCY_BITS'(1);
  wire                 latency_two = cfg_memory_latency == LATENCY_BITS'(2);
  wire                 done_valid = latency_one ? issued_q : done_live_q;
  reg  [DATA_BITS-1:0] ram_read_q, latest_q, done_data_q;
  wire [ADDR_BITS-1:0] done_addr = done_data_q[Z_BITS + 24 +: ADDR_BITS];
  wire [Z_BITS-1:0]    done_z = done_data_q[24 +: Z_BITS];
  wire [23:0]          done_rgb = done_data_q[23:0];
  reg pass;
  always @(*) begin
    case (cfg_depth_func)
      rastersim_pkg::DEPTH_NEVER: pass = 1'b0;
      rastersim_pkg::DEPTH_LESS: pass = done_z < mem_rd_depth;
      rastersim_pkg::DEPTH_EQUAL: pass = done_z == mem_rd_depth;
      rastersim_pkg::DEPTH_LEQUAL: pass = done_z <= mem_rd_depth;
      rastersim_pkg::DEPTH_GREATER: pass = done_z > mem_rd_depth;
      rastersim_pkg::DEPTH_NOTEQUAL: pass = done_z != mem_rd_depth;
      rastersim_pkg::DEPTH_GEQUAL: pass = done_z >= mem_rd_depth;
      default: pass = 1'b1;  // rastersim_pkg::DEPTH_ALWAYS
    endcase
  end
  assign result_valid = done_valid;
  assign result_pass = pass;
  assign mem_wr_depth_en = done_valid && pass && cfg_depth_write;
  assign mem_wr_color_en = done_valid && pass;
  assign mem_wr_addr = done_addr;
  assign mem_wr_depth = done_z;
  assign mem_wr_rgb = done_rgb;

  always @(posedge clk) begin
    if (rst) begin
      now_slot_q <= {RING_BITS{1'b0}};
      now_onehot_q <= {{(RING-1){1'b0}}, 1'b1};
      live_q <= {RING{1'b0}};
      issued_q <= 1'b0;
      done_onehot_q <= {{(RING-1){1'b0}}, 1'b1} << done_slot;
      done_live_q <= 1'b0;
      count_q <= 2'd0;
      head_q <= 1'b0;
      tail_q <= 1'b0;
    end else begin
      now_slot_q <= now_slot_q + 1'b1;
      now_onehot_q <= {now_onehot_q[RING-2:0], now_onehot_q[RING-1]};
      // The done slot retires; the slot written now (the same one at L = RING) takes the issue,
      // one cycle later through issued_q.
      live_q <= live & ~done_onehot_q;
      done_onehot_q <= next_done_onehot;
      done_live_q <= |(live & next_done_onehot);
      issued_q <= issue;
      count_q <= count_q + {1'b0, take} - {1'b0, issue};
      head_q <= head_q ^ issue;
      tail_q <= tail_q ^ take;
    end
  end
  // Data (no reset: an entry is read only while held, a slot only while it is live).
  integer e;
  always @(posedge clk) begin
    ring_pixel_q[now_slot_q] <= head_pixel;
    ring_data_q[now_slot_q] <= head_data;
    ram_read_q <= ring_data_q[read_slot];
    done_data_q <= latency_one ? head_data : latency_two ? latest_q : ram_read_q;
    last_onehot_q <= now_onehot_q;
    latest_q <= head_data;
    for (e = 0; e < 2; e = e + 1)
      if (take && tail_q == e[0]) begin
        buf_pixel_q[e] <= frag_pixel;
        buf_data_q[e] <= frag_data;
        match_q[e] <= frag_match;
        ahead_q[e] <= frag_ahead;
      end else begin
        // The slot written now holds the head's fragment if its read is issued (else it is not
        // live): for the other entry the fragment ahead; the head's own bit is not used again.
        match_q[e] <= match_q[e] & ~now_onehot_q | (ahead_q[e] ? now_onehot_q : {RING{1'b0}});
      end
  end

`include "rastersim_assert.vh"
  // A read request stays offered, at its address, until the memory takes it (its contract).
  `RS_ASSERT_HELD(read_held, mem_rd_valid, mem_rd_ready, mem_rd_addr)
endmodule
