// The library's cost per call through DPI-C (scripts/library-bench.sh, docs/performance.md): a
// SystemVerilog testbench with no design that renders a .tri file (+tri=FILE, the 12-value lines
// of `rastersim render --dump-tri`) through the model as a scoreboard would use it: every triangle
// submitted, every fragment read back, the frame's cycles at the end.
module dpi_render_tb;
  import rastersim_dpi::*;
  initial begin
    string path, line, profile;
    chandle model;
    int fd, values, r, g, b, x, y, pass, status;
    int unsigned z, rgb;
    real v [9];
    longint index, setup_accept, setup_done, walker_load, walker_end, fragments, last_write, cycle, cycles;
    longint triangles = 0, total = 0;
    if (!$value$plusargs("tri=%s", path)) $fatal(1, "dpi_render_tb: +tri=FILE is required");
    if (!$value$plusargs("profile=%s", profile)) profile = "";
    if (rastersim_create(profile, model) != RASTERSIM_OK) $fatal(1, "dpi_render_tb: %s", rastersim_last_error());
    fd = $fopen(path, "r");
    if (fd == 0) $fatal(1, "dpi_render_tb: cannot open %s", path);
    while ($fgets(line, fd) != 0) begin
      if (line.len() == 0 || line[0] == "#") continue;
      values = $sscanf(line, "%f %f %f %f %f %f %f %f %f %d %d %d", v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7],
                       v[8], r, g, b);
      if (values != 12) $fatal(1, "dpi_render_tb: %s: a line with %0d values, not 12", path, values);
      rgb = {8'(r), 8'(g), 8'(b)};
      if (rastersim_dpi_submit_screen(model, v[0], v[1], v[2], rgb, v[3], v[4], v[5], rgb, v[6], v[7], v[8], rgb,
                                      index) != RASTERSIM_OK)
        $fatal(1, "dpi_render_tb: %s", rastersim_last_error());
      void'(rastersim_dpi_read_triangle(model, index, status, setup_accept, setup_done, walker_load, walker_end,
                                        fragments, last_write));
      for (longint k = 0; k < fragments; k++) void'(rastersim_dpi_read_fragment(model, index, k, x, y, z, rgb, pass, cycle));
      total += fragments;
      triangles++;
    end
    void'(rastersim_dpi_frame_cycles(model, cycles));
    $display("dpi_render_tb: %0d triangles, %0d fragments, %0d cycles", triangles, total, cycles);
    rastersim_destroy(model);
    $finish;
  end
endmodule
