// The setup record of the unit-level interfaces (docs/verification.md "Checking one unit: cosim
// --unit"): what a setup unit hands on for a drawn triangle and a walker takes. `cosim --unit`
// verilates this package before the unit's files (do not list it); a simulation of your own
// compiles it first. The fields in this order, the first the most significant, are those of
// testbench/dut/unit_records.h unit_record_fields().
package rastersim_unit_pkg;
  typedef struct packed {
    logic [15:0] x0, x1, y0, y1;              // candidate pixels, inclusive: the bounding box clipped to the screen
    logic signed [63:0] edge0_start;          // edge function at the centre of (x0, y0), s.2S, biased
    logic signed [63:0] edge0_step_x;         // its change per pixel in x (-dy 2^S), s.2S
    logic signed [63:0] edge0_step_y;         // its change per pixel in y (dx 2^S), s.2S
    logic               edge0_owns_samples;   // 1: the edge owns the samples on it (bias 0), 0: bias 1
    logic signed [63:0] edge1_start, edge1_step_x, edge1_step_y;
    logic               edge1_owns_samples;
    logic signed [63:0] edge2_start, edge2_step_x, edge2_step_y;
    logic               edge2_owns_samples;
    logic signed [63:0] depth_start, depth_step_x, depth_step_y;  // s(N+1).F plane register, sign-extended
    logic signed [63:0] red_start, red_step_x, red_step_y;        // s9.F plane registers, sign-extended
    logic signed [63:0] green_start, green_step_x, green_step_y;
    logic signed [63:0] blue_start, blue_step_x, blue_step_y;
    logic [23:0] flat_rgb;                    // vertex 0's colour {r, g, b}
  } setup_record_t;
  localparam integer SETUP_RECORD_BITS = 4 * 16 + 3 * (3 * 64 + 1) + 12 * 64 + 24;  // 1435
endpackage
