// Assertions inside the units: properties of a unit's own signals that hold in every cycle out of
// reset (docs/rtl.md, "Assertions"). Included inside a module body that has clk and rst.
//  - Verilator checks them when it verilates with --assert (the co-simulation builds do): a failure
//    prints "Assertion failed in SCOPE: NAME" and ends the frame as a failure in that cycle.
//  - Other simulators (Icarus, the vector packages' testbenches) print the same with $error.
//  - The formal proofs (scripts/formal.sh: yosys -formal defines FORMAL) prove them beside the
//    properties of tests/formal/.
//  - Synthesis (yosys defines SYNTHESIS) leaves them out: no logic, no area.
// RS_ASSERT(name, condition): condition holds in every cycle out of reset.
// RS_ASSERT_HELD(name, valid, ready, payload): a handshake's offer, once made, stays until taken:
// valid and not ready in one cycle is followed by valid with the same payload in the next.
`ifndef RS_ASSERT
`ifdef FORMAL
`define RS_ASSERT(name, condition) always @* if (!rst) assert (condition);
`elsif SYNTHESIS
`define RS_ASSERT(name, condition)
`elsif VERILATOR
`define RS_ASSERT(name, condition) \
  always @(posedge clk) if (!rst) assert (condition) else $error("%s", `"name`");
`else
`define RS_ASSERT(name, condition) \
  always @(posedge clk) if (!rst && !(condition)) $error("Assertion failed in %m: %s", `"name`");
`endif
`ifdef SYNTHESIS
`ifndef FORMAL
`define RS_ASSERT_HELD(name, valid, ready, payload)
`endif
`endif
`ifndef RS_ASSERT_HELD
`define RS_ASSERT_HELD(name, valid, ready, payload) \
  if (1) begin : name \
    reg offered_q = 1'b0; \
    reg [$bits(payload)-1:0] payload_q; \
    always @(posedge clk) begin \
      offered_q <= !rst && (valid) && !(ready); \
      payload_q <= payload; \
    end \
    `RS_ASSERT(held, !offered_q || ((valid) && (payload) == payload_q)) \
  end
`endif
`endif
