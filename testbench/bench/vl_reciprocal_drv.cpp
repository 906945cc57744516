// Cycles/s of a Verilated tu_reciprocal under 30% random stalls (the co-simulation harness's
// loop without its scoreboard), built by scripts/verilator_options.sh once per Verilator option
// set (MODE names it); prints the rate and the output checksum (equal across builds).
#include <chrono>
#include <cstdio>
#include <memory>
#include <random>
#include "Vtu_reciprocal.h"
#include "verilated.h"
int main() {
  auto ctx = std::make_unique<VerilatedContext>();
  Vtu_reciprocal d(ctx.get());
  std::mt19937_64 rng(1);
  std::bernoulli_distribution stall(0.3);
  d.rst_ni = 0; d.clk_i = 0;
  for (int i = 0; i < 4; ++i) { d.clk_i = 1; d.eval(); d.clk_i = 0; d.eval(); }
  d.rst_ni = 1;
  uint64_t outs = 0, acc = 0;
  const auto t0 = std::chrono::steady_clock::now();
  const uint64_t N = 4000000;
  for (uint64_t c = 0; c < N; ++c) {
    d.in_valid_i = !stall(rng);
    d.q_i = rng() & 0xffffff;
    d.out_ready_i = !stall(rng);
    d.eval();
    if (d.out_valid_o && d.out_ready_i) ++outs, acc += d.mant_o;
    d.clk_i = 1; d.eval(); d.clk_i = 0; d.eval();
  }
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const std::clock_t cpu = std::clock();
  std::printf("%s: %.3f Mcycles/s wall, cpu %.2f s, outs %llu acc %llu\n", MODE, N / s / 1e6, cpu / double(CLOCKS_PER_SEC), (unsigned long long)outs, (unsigned long long)acc);
}
