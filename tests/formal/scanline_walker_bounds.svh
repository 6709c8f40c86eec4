// Included at the end of rtl/scanline_walker.sv by scripts/formal.sh, after
// scanline_walker_inputs.svh. The walker never leaves the bounding box it was given, nor the
// screen: every fragment it presents, in either traversal, has x0 <= x <= x1 < WIDTH and
// y0 <= y <= y1 < HEIGHT; the plane registers enter a row at a left edge's slot only when that
// slot holds a left edge (slot 1: the triangle has two).
  // The edges' sides, of the entry at a load and of the registers at a next row.
  wire [2:0] f_left = mid_walk_q ? left_q : in_entry[LSB_LEFT +: 3];
  always @* begin
    if (frag_valid) begin
      assert(f_loaded);
      assert(f_x0 <= frag_x && frag_x <= f_x1 && f_y0 <= frag_y && frag_y <= f_y1);
      assert(frag_x <= WIDTH - 1 && frag_y <= HEIGHT - 1);
    end
    if (((adder_row_enter && span_nonempty) || (adder_load && cfg_traversal && !in_entry[LSB_ROW_EMPTY])) && adder_enter_left)
      assert(adder_enter_slot ? 2'(f_left[0]) + 2'(f_left[1]) + 2'(f_left[2]) >= 2'd2 : |f_left);
  end
