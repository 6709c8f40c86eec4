// Included at the end of rtl/scanline_walker.sv by scripts/formal.sh, after
// scanline_walker_inputs.svh. The walker never leaves the bounding box it was given: every
// fragment it presents, in either traversal, has x0 <= x <= x1 and y0 <= y <= y1 of the record it
// loaded. The proof also proves the walker's own assertions (rtl/scanline_walker.sv: the fragment
// on the screen and held until taken, the left-edge slots).
  always @* begin
    if (frag_valid) begin
      assert(f_loaded);
      assert(f_x0 <= frag_x && frag_x <= f_x1 && f_y0 <= frag_y && frag_y <= f_y1);
    end
  end
