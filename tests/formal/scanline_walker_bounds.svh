// Included at the end of rtl/scanline_walker.sv by scripts/formal.sh, after
// scanline_walker_inputs.svh. The walker never leaves the bounding box it was given, nor the
// screen: every fragment it presents, in either traversal, has x0 <= x <= x1 < WIDTH and
// y0 <= y <= y1 < HEIGHT; the plane registers' span offset stays inside the box too.
  always @* begin
    if (frag_valid) begin
      assert(f_loaded);
      assert(f_x0 <= frag_x && frag_x <= f_x1 && f_y0 <= frag_y && frag_y <= f_y1);
      assert(frag_x <= WIDTH - 1 && frag_y <= HEIGHT - 1);
    end
    if (adder_row_enter && span_nonempty) assert(adder_row_offset <= f_x1 - f_x0);
    if (adder_load && cfg_traversal && span_nonempty) assert(adder_row_offset <= in_x1 - in_x0);
  end
