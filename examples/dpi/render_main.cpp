// Runs render_tb.sv (the DPI-C render example) to its $finish; exits 1 if it never finishes.
#include <memory>

#include "Vrender_tb.h"
#include "verilated.h"

int main(int argc, char** argv) {
  auto context = std::make_unique<VerilatedContext>();
  context->commandArgs(argc, argv);
  auto tb = std::make_unique<Vrender_tb>(context.get());
  tb->eval();  // the initial block runs to its $finish
  tb->final();
  return context->gotFinish() ? 0 : 1;
}
