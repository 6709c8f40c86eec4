// The setup record's field positions (rs_rec_lsb of rastersim_widths.vh) as constants of the
// including unit's profile parameters (WIDTH, HEIGHT, SUBPIXEL_BITS, Z_GUARD_BITS) and its
// RECORD_Z_BITS (the depth plane's bits), so that a simulator does not evaluate the sums at run
// time. Included after rastersim_widths.vh by the units that pack or unpack the whole record
// (triangle_setup, rastersim_core).
/* verilator lint_off UNUSEDPARAM */
localparam integer LSB_X0 =
    rs_rec_lsb(RS_REC_X0, WIDTH, HEIGHT, SUBPIXEL_BITS, RECORD_Z_BITS, Z_GUARD_BITS);
localparam integer LSB_X1 =
    rs_rec_lsb(RS_REC_X1, WIDTH, HEIGHT, SUBPIXEL_BITS, RECORD_Z_BITS, Z_GUARD_BITS);
localparam integer LSB_Y0 =
    rs_rec_lsb(RS_REC_Y0, WIDTH, HEIGHT, SUBPIXEL_BITS, RECORD_Z_BITS, Z_GUARD_BITS);
localparam integer LSB_Y1 =
    rs_rec_lsb(RS_REC_Y1, WIDTH, HEIGHT, SUBPIXEL_BITS, RECORD_Z_BITS, Z_GUARD_BITS);
localparam integer LSB_EDGE_START =
    rs_rec_lsb(RS_REC_EDGE_START, WIDTH, HEIGHT, SUBPIXEL_BITS, RECORD_Z_BITS, Z_GUARD_BITS);
localparam integer LSB_EDGE_STEP_X =
    rs_rec_lsb(RS_REC_EDGE_STEP_X, WIDTH, HEIGHT, SUBPIXEL_BITS, RECORD_Z_BITS, Z_GUARD_BITS);
localparam integer LSB_EDGE_STEP_Y =
    rs_rec_lsb(RS_REC_EDGE_STEP_Y, WIDTH, HEIGHT, SUBPIXEL_BITS, RECORD_Z_BITS, Z_GUARD_BITS);
localparam integer LSB_SPAN_QUOT =
    rs_rec_lsb(RS_REC_SPAN_QUOT, WIDTH, HEIGHT, SUBPIXEL_BITS, RECORD_Z_BITS, Z_GUARD_BITS);
localparam integer LSB_SPAN_REM =
    rs_rec_lsb(RS_REC_SPAN_REM, WIDTH, HEIGHT, SUBPIXEL_BITS, RECORD_Z_BITS, Z_GUARD_BITS);
localparam integer LSB_SPAN_STEP_QUOT =
    rs_rec_lsb(RS_REC_SPAN_STEP_QUOT, WIDTH, HEIGHT, SUBPIXEL_BITS, RECORD_Z_BITS, Z_GUARD_BITS);
localparam integer LSB_SPAN_STEP_REM =
    rs_rec_lsb(RS_REC_SPAN_STEP_REM, WIDTH, HEIGHT, SUBPIXEL_BITS, RECORD_Z_BITS, Z_GUARD_BITS);
localparam integer LSB_DEPTH_START =
    rs_rec_lsb(RS_REC_DEPTH_START, WIDTH, HEIGHT, SUBPIXEL_BITS, RECORD_Z_BITS, Z_GUARD_BITS);
localparam integer LSB_DEPTH_STEP_X =
    rs_rec_lsb(RS_REC_DEPTH_STEP_X, WIDTH, HEIGHT, SUBPIXEL_BITS, RECORD_Z_BITS, Z_GUARD_BITS);
localparam integer LSB_DEPTH_STEP_Y =
    rs_rec_lsb(RS_REC_DEPTH_STEP_Y, WIDTH, HEIGHT, SUBPIXEL_BITS, RECORD_Z_BITS, Z_GUARD_BITS);
localparam integer LSB_COLOR_START =
    rs_rec_lsb(RS_REC_COLOR_START, WIDTH, HEIGHT, SUBPIXEL_BITS, RECORD_Z_BITS, Z_GUARD_BITS);
localparam integer LSB_COLOR_STEP_X =
    rs_rec_lsb(RS_REC_COLOR_STEP_X, WIDTH, HEIGHT, SUBPIXEL_BITS, RECORD_Z_BITS, Z_GUARD_BITS);
localparam integer LSB_COLOR_STEP_Y =
    rs_rec_lsb(RS_REC_COLOR_STEP_Y, WIDTH, HEIGHT, SUBPIXEL_BITS, RECORD_Z_BITS, Z_GUARD_BITS);
localparam integer LSB_FLAT_RGB =
    rs_rec_lsb(RS_REC_FLAT_RGB, WIDTH, HEIGHT, SUBPIXEL_BITS, RECORD_Z_BITS, Z_GUARD_BITS);
localparam integer LSB_LEFT_START =
    rs_rec_lsb(RS_REC_LEFT_START, WIDTH, HEIGHT, SUBPIXEL_BITS, RECORD_Z_BITS, Z_GUARD_BITS);
localparam integer LSB_LEFT_STEP =
    rs_rec_lsb(RS_REC_LEFT_STEP, WIDTH, HEIGHT, SUBPIXEL_BITS, RECORD_Z_BITS, Z_GUARD_BITS);
/* verilator lint_on UNUSEDPARAM */
