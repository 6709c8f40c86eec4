// Clock for scoreboard_tb.sv (the DPI scoreboard example): runs until the testbench is done, exits
// 1 when it found a mismatch or did not finish.
#include <cstdio>
#include <memory>

#include <rastersim/rastersim.h>  // the C API beside the imports' declarations: their C names differ

#include "Vscoreboard_tb.h"
#include "Vscoreboard_tb__Dpi.h"
#include "verilated.h"

int main(int argc, char** argv) {
  auto context = std::make_unique<VerilatedContext>();
  context->commandArgs(argc, argv);
  auto tb = std::make_unique<Vscoreboard_tb>(context.get());
  const long long max_cycles = 10'000'000;
  long long cycles = 0;
  for (tb->clk = 0; !tb->done && cycles < max_cycles; ++cycles) {
    tb->clk = 1;
    tb->eval();
    tb->clk = 0;
    tb->eval();
  }
  tb->final();
  if (!tb->done) {
    std::fprintf(stderr, "scoreboard: the testbench did not finish within %lld cycles\n", max_cycles);
    return 1;
  }
  return tb->failed ? 1 : 0;
}
