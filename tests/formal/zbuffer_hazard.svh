// Included at the end of rtl/zbuffer.sv by scripts/formal.sh (formal runs only). The read-after-
// write hazard logic, against a history of accepted fragments kept here by age and a shadow depth
// memory written from that history:
//  - a fragment is accepted only if no fragment to the same address was accepted in the last L
//    cycles (L = cfg_memory_latency), and it is accepted whenever that holds (no needless stall);
//  - its depth test result comes exactly L cycles after its acceptance;
//  - the depth it is compared with is the last depth written to its address (or the clear value
//    when none was): every read sees all earlier writes.
// The proof starts in the reset state (all registers zero) with rst low; the configuration is
// constant and 1 <= L <= MAX_MEMORY_LATENCY.
  localparam integer F_MAX = MAX_MEMORY_LATENCY;
  reg                f_valid [1:F_MAX];
  reg [AB-1:0]       f_addr [1:F_MAX];
  reg [Z_BITS-1:0]   f_z [1:F_MAX];
  reg [Z_BITS-1:0]   f_depth [0:WORDS-1];
  reg                f_written [0:WORDS-1];
  reg                f_started;
  reg [LB-1:0]       f_latency;
  reg                f_depth_write;
  reg [2:0]          f_depth_func;
  reg [Z_BITS-1:0]   f_depth_clear;
  wire [AB-1:0] f_frag_addr = frag_y * WIDTH + frag_x;

  integer f_k;
  reg f_conflict;
  always @* begin
    f_conflict = 1'b0;
    for (f_k = 1; f_k <= F_MAX; f_k = f_k + 1)
      if (f_k <= cfg_memory_latency && f_valid[f_k] && f_addr[f_k] == f_frag_addr) f_conflict = 1'b1;
  end
  wire f_done_valid = f_valid[cfg_memory_latency];
  wire [AB-1:0] f_done_addr = f_addr[cfg_memory_latency];

  always @(posedge clk) begin
    f_started <= 1'b1;
    f_latency <= cfg_memory_latency;
    f_depth_write <= cfg_depth_write;
    f_depth_func <= cfg_depth_func;
    f_depth_clear <= cfg_depth_clear;
    f_valid[1] <= frag_valid && frag_ready;
    f_addr[1] <= f_frag_addr;
    f_z[1] <= frag_z;
    for (f_k = 2; f_k <= F_MAX; f_k = f_k + 1) begin
      f_valid[f_k] <= f_valid[f_k - 1];
      f_addr[f_k] <= f_addr[f_k - 1];
      f_z[f_k] <= f_z[f_k - 1];
    end
    if (f_done_valid && result_pass && cfg_depth_write) begin
      f_depth[f_done_addr] <= f_z[cfg_memory_latency];
      f_written[f_done_addr] <= 1'b1;
    end
  end

  always @* begin
    assume(!rst);
    assume(cfg_memory_latency >= 1 && cfg_memory_latency <= MAX_MEMORY_LATENCY);
    assume(frag_x <= WIDTH - 1 && frag_y <= HEIGHT - 1);
    if (f_started)
      assume(cfg_memory_latency == f_latency && cfg_depth_write == f_depth_write &&
             cfg_depth_func == f_depth_func && cfg_depth_clear == f_depth_clear);
    if (frag_valid && frag_ready) assert(!f_conflict);
    if (frag_valid && clear_done && !f_conflict) assert(frag_ready);
    assert(result_valid == f_done_valid);
    if (f_done_valid) assert(stored == (f_written[f_done_addr] ? f_depth[f_done_addr] : cfg_depth_clear));
  end
