// Included at the end of rtl/zbuffer.sv by scripts/formal.sh (formal runs only). The input buffer
// and the read-after-write hazard logic, against a shadow queue of the fragments taken and not yet
// read, a history of the reads kept here by age and a shadow depth memory written from that
// history, with any memory behind the port that keeps its contract (modelled here: the word of a
// read taken in c, as it is at the end of c, arrives in c + L; the memory may refuse reads in any
// cycle and clear for any number of cycles):
//  - a fragment is taken exactly when fewer than two are held; reads go out in the order taken,
//    each with its fragment's address;
//  - the oldest held fragment is read only if no fragment to the same address was read in the
//    last L cycles (L = cfg_memory_latency), and whenever that holds, the memory is cleared and
//    it takes the read (no needless stall); the stall output says exactly when it waits;
//  - its depth test result comes exactly L cycles after its read, and the writes it makes
//    (address, depth, enables) are those of its result;
//  - the depth it is compared with is the last depth written to its address (or the clear value
//    when none was): every read sees all earlier writes, without forwarding in the memory.
// The proof starts with one reset cycle (rst high, no fragment offered) from all registers zero,
// then rst stays low; the configuration is constant and 1 <= L <= MAX_MEMORY_LATENCY.
  localparam integer F_MAX = MAX_MEMORY_LATENCY;
  localparam integer F_WORDS = WIDTH * HEIGHT;
  reg                f_valid [1:F_MAX];
  reg [ADDR_BITS-1:0]       f_addr [1:F_MAX];
  reg [Z_BITS-1:0]   f_z [1:F_MAX];
  reg [Z_BITS-1:0]   f_depth [0:F_WORDS-1];    // last depth written by the accepted fragments
  reg                f_written [0:F_WORDS-1];
  reg [Z_BITS-1:0]   f_mem [0:F_WORDS-1];      // the memory behind the port
  reg                f_mem_written [0:F_WORDS-1];
  reg [Z_BITS-1:0]   f_read [1:F_MAX];         // words read, by age
  reg                f_started;
  reg [LATENCY_BITS-1:0]       f_latency;
  reg                f_depth_write;
  reg [2:0]          f_depth_func;
  wire [Z_BITS-1:0]  f_clear_value = {Z_BITS{1'b0}};  // the memory's clear value
  wire [ADDR_BITS-1:0] f_frag_addr = frag_y * WIDTH + frag_x;
  // The fragments taken and not yet read, oldest first.
  reg [1:0]           f_held;
  reg [ADDR_BITS-1:0] f_held_addr [0:1];
  reg [Z_BITS-1:0]    f_held_z [0:1];
  wire f_take = frag_valid && frag_ready;
  wire f_read_taken = mem_rd_valid && mem_rd_ready;
  wire [ADDR_BITS-1:0] f_head_addr = f_held_addr[0];

  integer f_k;
  reg f_conflict;
  always @* begin
    f_conflict = 1'b0;
    for (f_k = 1; f_k <= F_MAX; f_k = f_k + 1)
      if (f_k <= cfg_memory_latency && f_valid[f_k] && f_addr[f_k] == f_head_addr) f_conflict = 1'b1;
  end
  integer f_j;
  reg f_in_flight;  // a fragment read in the last L cycles
  always @* begin
    f_in_flight = 1'b0;
    for (f_j = 1; f_j <= F_MAX; f_j = f_j + 1)
      if (f_j <= cfg_memory_latency && f_valid[f_j]) f_in_flight = 1'b1;
  end
  wire f_done_valid = f_valid[cfg_memory_latency];
  wire [ADDR_BITS-1:0] f_done_addr = f_addr[cfg_memory_latency];
  wire [Z_BITS-1:0] f_done_z = f_z[cfg_memory_latency];
  reg f_pass;
  always @* begin
    case (cfg_depth_func)
      3'd0: f_pass = 1'b0;
      3'd1: f_pass = f_done_z < mem_rd_depth;
      3'd2: f_pass = f_done_z == mem_rd_depth;
      3'd3: f_pass = f_done_z <= mem_rd_depth;
      3'd4: f_pass = f_done_z > mem_rd_depth;
      3'd5: f_pass = f_done_z != mem_rd_depth;
      3'd6: f_pass = f_done_z >= mem_rd_depth;
      default: f_pass = 1'b1;
    endcase
  end

  always @(posedge clk) begin
    f_started <= 1'b1;
    f_latency <= cfg_memory_latency;
    f_depth_write <= cfg_depth_write;
    f_depth_func <= cfg_depth_func;
    f_valid[1] <= f_read_taken;
    f_addr[1] <= f_head_addr;
    f_z[1] <= f_held_z[0];
    if (f_read_taken) begin
      f_held_addr[0] <= f_held_addr[1];
      f_held_z[0] <= f_held_z[1];
    end
    if (f_take && f_held - {1'b0, f_read_taken} == 2'd0) begin
      f_held_addr[0] <= f_frag_addr;
      f_held_z[0] <= frag_z;
    end else if (f_take) begin
      f_held_addr[1] <= f_frag_addr;
      f_held_z[1] <= frag_z;
    end
    f_held <= f_held + {1'b0, f_take} - {1'b0, f_read_taken};
    // The memory: a taken read sees the word before this cycle's write.
    f_read[1] <= f_mem_written[mem_rd_addr] ? f_mem[mem_rd_addr] : f_clear_value;
    for (f_k = 2; f_k <= F_MAX; f_k = f_k + 1) begin
      f_valid[f_k] <= f_valid[f_k - 1];
      f_addr[f_k] <= f_addr[f_k - 1];
      f_z[f_k] <= f_z[f_k - 1];
      f_read[f_k] <= f_read[f_k - 1];
    end
    if (mem_wr_depth_en) begin
      f_mem[mem_wr_addr] <= mem_wr_depth;
      f_mem_written[mem_wr_addr] <= 1'b1;
    end
    if (f_done_valid && result_pass && cfg_depth_write) begin
      f_depth[f_done_addr] <= f_done_z;
      f_written[f_done_addr] <= 1'b1;
    end
  end

  always @* begin
    assume(rst == !f_started);
    if (!f_started) assume(!frag_valid);
    assume(cfg_memory_latency >= 1 && cfg_memory_latency <= MAX_MEMORY_LATENCY);
    assume(frag_x <= WIDTH - 1 && frag_y <= HEIGHT - 1);
    if (f_started) begin
      assume(cfg_memory_latency == f_latency && cfg_depth_write == f_depth_write && cfg_depth_func == f_depth_func);
      // The memory's contract: the word read L cycles ago, once the clear is done.
      assume(mem_rd_depth == f_read[cfg_memory_latency]);
      assume(mem_clear_done);
    end
    assert(f_held <= 2'd2);
    if (f_started) assert(frag_ready == (f_held < 2'd2));
    if (mem_rd_valid) assert(f_held != 2'd0 && !f_conflict && mem_rd_addr == f_head_addr);
    if (f_held != 2'd0 && mem_clear_done && !f_conflict) assert(mem_rd_valid);
    assert(stall == (f_held != 2'd0 && !f_read_taken));
    if (f_started) assert(busy == (f_take || f_held != 2'd0 || f_in_flight));
    assert(result_valid == f_done_valid);
    if (f_done_valid) begin
      assert(result_pass == f_pass);
      assert(mem_wr_color_en == f_pass && mem_wr_depth_en == (f_pass && cfg_depth_write));
      assert(mem_wr_addr == f_done_addr && mem_wr_depth == f_done_z);
      assert(mem_rd_depth == (f_written[f_done_addr] ? f_depth[f_done_addr] : f_clear_value));
    end else begin
      assert(!mem_wr_color_en && !mem_wr_depth_en);
    end
  end
