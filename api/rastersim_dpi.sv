// The golden model for SystemVerilog testbenches through DPI-C (docs/library.md): the C API of
// rastersim.h with the types DPI-C maps (chandle for the pipeline, string, int, longint; output
// arguments for the records). Link the testbench with librastersim_model (static or shared).
// Every function returns 0 (RASTERSIM_OK) or an error code; rastersim_last_error() says why. The
// functions keep the C API's names here; their C names are rastersim_dpi_* (rastersim.h).
package rastersim_dpi;
  localparam int RASTERSIM_OK = 0;
  localparam int RASTERSIM_DRAWN = 0, RASTERSIM_DEGENERATE = 1, RASTERSIM_CULLED = 2, RASTERSIM_OFFSCREEN = 3, RASTERSIM_NO_CENTRE = 4;

  import "DPI-C" rastersim_dpi_version = function string rastersim_version();
  import "DPI-C" rastersim_dpi_last_error = function string rastersim_last_error();
  // A pipeline from a profile's JSON text ("" is the default profile).
  import "DPI-C" rastersim_dpi_create = function int rastersim_create(input string profile_json, output chandle pipeline);
  import "DPI-C" rastersim_dpi_destroy = function void rastersim_destroy(input chandle pipeline);
  import "DPI-C" rastersim_dpi_reset = function int rastersim_reset(input chandle pipeline);
  import "DPI-C" rastersim_dpi_width = function int rastersim_width(input chandle pipeline, output int width);
  import "DPI-C" rastersim_dpi_height = function int rastersim_height(input chandle pipeline, output int height);
  // One screen-space triangle (x, y pixels; z in [0, 1]; rgb {r, g, b}), checked and snapped.
  import "DPI-C" function int rastersim_dpi_submit_screen(
      input chandle pipeline, input real x0, input real y0, input real z0, input int unsigned rgb0,
      input real x1, input real y1, input real z1, input int unsigned rgb1, input real x2, input real y2,
      input real z2, input int unsigned rgb2, output longint triangle);
  // One snapped triangle (x, y subpixels; z uN; rgb {r, g, b}); its index in submission order.
  import "DPI-C" function int rastersim_dpi_submit_snapped(
      input chandle pipeline, input int x0, input int y0, input int unsigned z0, input int unsigned rgb0,
      input int x1, input int y1, input int unsigned z1, input int unsigned rgb1, input int x2, input int y2,
      input int unsigned z2, input int unsigned rgb2, output longint triangle);
  import "DPI-C" function int rastersim_dpi_read_triangle(
      input chandle pipeline, input longint triangle, output int status, output longint setup_accept,
      output longint setup_done, output longint walker_load, output longint walker_end,
      output longint fragments, output longint last_write);
  import "DPI-C" function int rastersim_dpi_read_fragment(
      input chandle pipeline, input longint triangle, input longint k, output int x, output int y,
      output int unsigned z, output int unsigned rgb, output int pass, output longint cycle);
  import "DPI-C" function int rastersim_dpi_frame_cycles(input chandle pipeline, output longint cycles);
  import "DPI-C" function int rastersim_dpi_read_buffers(input chandle pipeline, input int x, input int y,
                                                         output int unsigned depth, output int unsigned rgb);
endpackage
