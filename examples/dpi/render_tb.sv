// The model through DPI-C alone (docs/library.md): a SystemVerilog testbench with no design that
// renders a .tri file (+tri=FILE, lines of 12 or 18 values as `rastersim render --dump-tri` writes them;
// +profile=FILE, a profile JSON file) as a scoreboard would use the model: every triangle submitted,
// every fragment read back (written as `rastersim render --fragments` does with +fragments=FILE),
// the frame's cycles at the end, the final buffers (+buffers=FILE: "depth rrggbb" per pixel). It first shows that misuse is an error code with a message. scripts/library-bench.sh
// times it; scripts/check-install.sh compares its fragments with the CLI's.
module render_tb;
  import rastersim_dpi::*;
  initial begin
    string path, line, profile;
    chandle model;
    int fd, values, x, y, pass, status;
    int c [9];
    int unsigned vertex_rgb [3];
    int unsigned z, rgb;
    real v [9];
    longint index, setup_accept, setup_done, walker_load, walker_end, fragments, last_write, cycle, cycles;
    longint triangles = 0, total = 0;
    string fragments_path, buffers_path, profile_path;
    int width, height;
    int unsigned depth;
    int out = 0;
    if (!$value$plusargs("tri=%s", path)) $fatal(1, "render_tb: +tri=FILE is required");
    profile = "";
    if ($value$plusargs("profile=%s", profile_path)) begin
      fd = $fopen(profile_path, "r");
      if (fd == 0) $fatal(1, "render_tb: cannot open %s", profile_path);
      while ($fgets(line, fd) != 0) profile = {profile, line};
      $fclose(fd);
    end
    // Misuse: an error code and a message, no crash.
    if (rastersim_create("{\"width\": 5000}", model) == RASTERSIM_OK) $fatal(1, "render_tb: a bad profile was accepted");
    $display("render_tb: a bad profile is refused: %s", rastersim_last_error());
    if (rastersim_create(profile, model) != RASTERSIM_OK) $fatal(1, "render_tb: %s", rastersim_last_error());
    if (rastersim_dpi_read_triangle(model, 0, status, setup_accept, setup_done, walker_load, walker_end, fragments,
                                    last_write) == RASTERSIM_OK)
      $fatal(1, "render_tb: reading a triangle before submitting one succeeded");
    $display("render_tb: reading before submitting is refused: %s", rastersim_last_error());
    if (rastersim_dpi_submit_screen(model, 0.0, 0.0, 0.0, 0, 1.0e6, 0.0, 0.0, 0, 0.0, 1.0, 0.0, 0, index) == RASTERSIM_OK)
      $fatal(1, "render_tb: a triangle outside the guard band was accepted");
    $display("render_tb: a triangle outside the guard band is refused: %s", rastersim_last_error());
    if ($value$plusargs("fragments=%s", fragments_path)) begin
      out = $fopen(fragments_path, "w");
      if (out == 0) $fatal(1, "render_tb: cannot write %s", fragments_path);
      $fwrite(out, "tri,x,y,z,pass,r,g,b,cycle\n");
    end
    fd = $fopen(path, "r");
    if (fd == 0) $fatal(1, "render_tb: cannot open %s", path);
    while ($fgets(line, fd) != 0) begin
      if (line.len() == 0 || line[0] == "#") continue;
      values = $sscanf(line, "%f %f %f %f %f %f %f %f %f %d %d %d %d %d %d %d %d %d", v[0], v[1], v[2], v[3], v[4],
                       v[5], v[6], v[7], v[8], c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], c[8]);
      if (values != 12 && values != 18) $fatal(1, "render_tb: %s: a line with %0d values, not 12 or 18", path, values);
      for (int k = 0; k < 3; k++) begin
        int base = values == 12 ? 0 : 3 * k;
        vertex_rgb[k] = {8'(c[base]), 8'(c[base + 1]), 8'(c[base + 2])};
      end
      if (rastersim_dpi_submit_screen(model, v[0], v[1], v[2], vertex_rgb[0], v[3], v[4], v[5], vertex_rgb[1], v[6], v[7],
                                      v[8], vertex_rgb[2], index) != RASTERSIM_OK)
        $fatal(1, "render_tb: %s", rastersim_last_error());
      void'(rastersim_dpi_read_triangle(model, index, status, setup_accept, setup_done, walker_load, walker_end,
                                        fragments, last_write));
      for (longint k = 0; k < fragments; k++) begin
        void'(rastersim_dpi_read_fragment(model, index, k, x, y, z, rgb, pass, cycle));
        if (out != 0) $fwrite(out, "%0d,%0d,%0d,%0d,%0d,%0d,%0d,%0d,%0d\n", index, x, y, z, pass, rgb[23:16], rgb[15:8],
                              rgb[7:0], cycle);
      end
      total += fragments;
      triangles++;
    end
    void'(rastersim_dpi_frame_cycles(model, cycles));
    if (out != 0) $fclose(out);
    $display("render_tb: %0d triangles, %0d fragments", triangles, total);
    $display("cycles %0d", cycles);
    if ($value$plusargs("buffers=%s", buffers_path)) begin
      out = $fopen(buffers_path, "w");
      if (out == 0) $fatal(1, "render_tb: cannot write %s", buffers_path);
      void'(rastersim_width(model, width));
      void'(rastersim_height(model, height));
      for (int py = 0; py < height; py++)
        for (int px = 0; px < width; px++) begin
          void'(rastersim_dpi_read_buffers(model, px, py, depth, rgb));
          $fwrite(out, "%0d %06h\n", depth, rgb[23:0]);
        end
      $fclose(out);
    end
    rastersim_destroy(model);
    $finish;
  end
endmodule
