// Record FIFO between triangle_setup and scanline_walker (docs/cycle-model.md, "Record FIFO").
// ENTRIES records of RECORD_BITS bits; a record pushed in cycle c is at the head from c+1 when it is the
// oldest. Push and pop may happen in the same cycle. The core's record credits guarantee that a
// push never meets a full FIFO, so there is no full flag.
`include "rastersim_pkg.sv"
module setup_fifo #(
  parameter integer RECORD_BITS = 8,
  parameter integer ENTRIES = 2
) (
  input  wire clk,
  input  wire rst,
  input  wire push,
  input  wire [RECORD_BITS-1:0] push_data,
  input  wire pop,
  output wire empty,
  output wire [RECORD_BITS-1:0] head
);
`include "rastersim_widths.vh"
  `RS_REQUIRE(illegal_entries, ENTRIES >= 1 && RECORD_BITS >= 1, "setup_fifo: ENTRIES and RECORD_BITS must be at least 1")
  localparam integer INDEX_BITS = ENTRIES > 1 ? $clog2(ENTRIES) : 1;
  localparam integer COUNT_BITS = $clog2(ENTRIES + 1);
  localparam integer LAST_INDEX = ENTRIES - 1;
  localparam [INDEX_BITS-1:0] LAST = LAST_INDEX[INDEX_BITS-1:0];

  reg [RECORD_BITS-1:0] entries_q [0:ENTRIES-1];
  reg [INDEX_BITS-1:0] read_index_q, write_index_q;
  reg [COUNT_BITS-1:0] count_q;

  assign empty = count_q == {COUNT_BITS{1'b0}};
  assign head = entries_q[read_index_q];

  always @(posedge clk) begin
    if (rst) begin
      read_index_q <= {INDEX_BITS{1'b0}};
      write_index_q <= {INDEX_BITS{1'b0}};
      count_q <= {COUNT_BITS{1'b0}};
    end else begin
      if (push) write_index_q <= write_index_q == LAST ? {INDEX_BITS{1'b0}} : write_index_q + 1'b1;
      if (pop) read_index_q <= read_index_q == LAST ? {INDEX_BITS{1'b0}} : read_index_q + 1'b1;
      if (push && !pop) count_q <= count_q + 1'b1;
      else if (pop && !push) count_q <= count_q - 1'b1;
    end
  end

  // The record credits keep it from overflowing; the walker reads only a record that is there.
`include "rastersim_assert.vh"
  `RS_ASSERT(no_push_when_full, !push || pop || count_q != COUNT_BITS'(ENTRIES))
  `RS_ASSERT(no_pop_when_empty, !pop || !empty)

  // Storage (no reset: an entry is written before it is read).
  always @(posedge clk) if (push) entries_q[write_index_q] <= push_data;
endmodule
