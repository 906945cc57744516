// EWA filter: pixels per second of the bit-accurate C model (ewa::fx::filter, incremental and
// direct Q, each weight source) and of the double-precision float reference on the same B2
// outputs (ewa::fx::filter_ref_b2), on the random pixels of the vector set (bricks 256x256).
// Run: build/<dir>/testbench/bench/tu_ewa_bench   (configure with -DTU_BENCH=ON)
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "ewa/ewa_fx.hpp"

namespace {
using namespace tu::ewa;

const tu::tex::Texture& texture() {
  static const auto t = tu::tex::Texture::build("bricks", tu::tex::bricks(256).color, tu::tex::Wrap::Repeat);
  return t;
}
const std::vector<fx::In>& pixels() {
  static const auto p = [] {
    std::vector<fx::In> v;
    std::mt19937_64 rng(1);
    for (int i = 0; i < 2048; ++i) v.push_back(fx::random_in(rng));
    return v;
  }();
  return p;
}

void BM_Fixed(benchmark::State& st) {  // arg: weight source; arg 1: direct Q
  const fx::Config cfg{static_cast<fx::Weights>(st.range(0)), 1024};
  const bool direct = st.range(1) != 0;
  for (auto _ : st)
    for (const auto& in : pixels()) benchmark::DoNotOptimize(fx::filter(in, texture(), cfg, direct));
  st.SetItemsProcessed(static_cast<int64_t>(st.iterations() * pixels().size()));
}
BENCHMARK(BM_Fixed)->ArgNames({"weights", "direct"})->Args({0, 0})->Args({1, 0})->Args({2, 0})->Args({0, 1});

void BM_FloatRef(benchmark::State& st) {
  for (auto _ : st)
    for (const auto& in : pixels()) benchmark::DoNotOptimize(fx::filter_ref_b2(in, texture(), 1024));
  st.SetItemsProcessed(static_cast<int64_t>(st.iterations() * pixels().size()));
}
BENCHMARK(BM_FloatRef);
}  // namespace

BENCHMARK_MAIN();
