// Ellipse/LOD C model: pixels per second of the fixed-point analytic unit (production), the
// fixed-point forward-difference unit and the double-precision float reference, on the random
// local maps of the vector set.
// Run: build/<dir>/testbench/bench/tu_ellipse_bench   (configure with -DTU_BENCH=ON)
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "ellipse/ellipse_fx.hpp"

namespace {
using namespace tu::ellipse;

struct Px {
  std::vector<Coef9> k;
  std::vector<fx::In> in;
  std::vector<int64_t> g, h;
};
const Px& pixels() {
  static const Px p = [] {
    Px p;
    std::mt19937_64 rng(1);
    for (int i = 0; i < 4096; ++i) {
      const auto l = fx::random_local(rng);
      p.k.push_back(fx::local_map(l));
      p.in.push_back(fx::in_from_map(p.k.back()));
      p.g.push_back(fx::q_code(l.g));
      p.h.push_back(fx::q_code(l.h));
    }
    return p;
  }();
  return p;
}

void BM_FixedAnalytic(benchmark::State& st) {
  const auto& p = pixels();
  for (auto _ : st)
    for (const auto& in : p.in) benchmark::DoNotOptimize(fx::analytic(in));
  st.SetItemsProcessed(static_cast<int64_t>(st.iterations() * p.in.size()));
}
void BM_FixedForwardDifference(benchmark::State& st) {
  const auto& p = pixels();
  for (auto _ : st)
    for (size_t i = 0; i < p.in.size(); ++i)
      benchmark::DoNotOptimize(fx::forward_difference(p.in[i], p.g[i], p.h[i]));
  st.SetItemsProcessed(static_cast<int64_t>(st.iterations() * p.in.size()));
}
void BM_FloatAnalytic(benchmark::State& st) {
  const auto& p = pixels();
  for (auto _ : st)
    for (const auto& k : p.k) benchmark::DoNotOptimize(footprint_at(k, 0, 0, FootprintParams{}, Deriv::Analytic));
  st.SetItemsProcessed(static_cast<int64_t>(st.iterations() * p.k.size()));
}
BENCHMARK(BM_FixedAnalytic);
BENCHMARK(BM_FixedForwardDifference);
BENCHMARK(BM_FloatAnalytic);
}  // namespace

BENCHMARK_MAIN();
