// Counts the clock cycles of a test-vector package's testbench (vectors/*/rastersim_vectors_tb.v)
// and prints them when the simulation ends: compiled as a second top module by
// scripts/performance.sh, so that Icarus and Verilator report the cycles they simulated.
module perf_clock_count;
  integer cycles = 0;
  always @(posedge rastersim_vectors_tb.clk) cycles = cycles + 1;
  final $display("perf_clock_count: %0d clock cycles", cycles);
endmodule
