// Debug signals for waveforms, bound into rastersim_top by the co-simulation builds (never part of
// rtl/, never synthesized): the frame cycle of docs/cycle-model.md and, per unit, the submission
// index of the triangle it is handling, so that a waveform can be read in the model's terms.
// All ones means "none yet".
module rastersim_debug (
  input wire       clk,
  input wire       rst,
  input wire       frame_ready,
  input wire       cmd_valid,
  input wire       cmd_ready,
  input wire       trace_setup_decided,
  input wire [2:0] trace_setup_status,
  input wire       trace_walker_load,
  input wire       trace_frag_valid,
  input wire       trace_frag_ready
);
  // 0 in the first cycle after the memory clear (the first cycle a command can be taken).
  reg [31:0] frame_cycle;
  reg [31:0] accepted_q, decided_q, drawn_q, loaded_q, walker_q, zbuffer_q;
  // Submission index of drawn triangle k at k mod 64 (far more than a record FIFO holds).
  reg [31:0] drawn_index [0:63];

  wire accept = cmd_valid && cmd_ready;
  wire take = trace_frag_valid && trace_frag_ready;
  // The triangle the setup unit accepted last (in its accept cycle already).
  wire [31:0] setup_triangle = accept ? accepted_q : accepted_q - 32'd1;
  // The triangle of the walker's current candidate (from the cycle after its load: a load can be in
  // the previous triangle's last candidate cycle).
  wire [31:0] walker_triangle = walker_q;
  // The triangle of the last fragment the z-buffer accepted.
  wire [31:0] zbuffer_triangle = take ? walker_triangle : zbuffer_q;

  always @(posedge clk) begin
    if (rst) begin
      frame_cycle <= 32'd0;
      accepted_q <= 32'd0;
      decided_q <= 32'd0;
      drawn_q <= 32'd0;
      loaded_q <= 32'd0;
      walker_q <= ~32'd0;
      zbuffer_q <= ~32'd0;
    end else begin
      frame_cycle <= frame_ready ? frame_cycle + 32'd1 : 32'd0;
      if (accept) accepted_q <= accepted_q + 32'd1;
      if (trace_setup_decided) begin
        decided_q <= decided_q + 32'd1;
        if (trace_setup_status == 3'd0) begin
          drawn_index[drawn_q[5:0]] <= decided_q;
          drawn_q <= drawn_q + 32'd1;
        end
      end
      if (trace_walker_load) loaded_q <= loaded_q + 32'd1;
      if (trace_walker_load) walker_q <= drawn_index[loaded_q[5:0]];
      zbuffer_q <= zbuffer_triangle;
    end
  end
endmodule

bind rastersim_top rastersim_debug debug (
  .clk(clk), .rst(rst), .frame_ready(frame_ready), .cmd_valid(cmd_valid), .cmd_ready(cmd_ready),
  .trace_setup_decided(trace_setup_decided), .trace_setup_status(trace_setup_status),
  .trace_walker_load(trace_walker_load), .trace_frag_valid(trace_frag_valid),
  .trace_frag_ready(trace_frag_ready)
);
