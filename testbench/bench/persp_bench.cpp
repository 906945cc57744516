// Perspective divide C model: pixels per second for each traversal (direct, sequential
// incremental, k-lane, two-ended) and for the double-precision float reference on the same spans.
// Run: build/<dir>/testbench/bench/tu_persp_bench   (configure with -DTU_BENCH=ON)
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "persp/persp.hpp"

namespace {
using namespace tu::persp;

struct Spans {
  std::vector<Coef9> k;
  std::vector<Unit::Coefs> c;
  std::vector<int> y;
};
constexpr int kLen = 1024;

const Spans& spans() {
  static const Spans s = [] {
    Spans s;
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> U(0, 1);
    while (s.k.size() < 64) {
      const int y = static_cast<int>(rng() % 4096);
      const auto k = random_span_map(rng, y, 0, kLen - 1, 1.0, std::pow(1000.0, -U(rng)));
      try {
        s.c.push_back(Unit::quantise(k, "bench"));
        Unit::setup(s.c.back(), y, 0, kLen - 1, "bench");
      } catch (const SetupError&) {
        s.c.pop_back();
        continue;
      }
      s.k.push_back(k);
      s.y.push_back(y);
    }
    return s;
  }();
  return s;
}

template <class F>
void run(benchmark::State& st, F f) {
  const auto& s = spans();
  std::vector<Pixel> out(kLen);
  size_t i = 0;
  for (auto _ : st) {
    f(s.c[i], s.y[i], out.data());
    benchmark::DoNotOptimize(out.data());
    i = (i + 1) % s.c.size();
  }
  st.SetItemsProcessed(static_cast<int64_t>(st.iterations()) * kLen);
}

void BM_Direct(benchmark::State& st) {
  run(st, [](const Unit::Coefs& c, int y, Pixel* o) { Unit::span_direct(c, y, 0, kLen, o); });
}
void BM_Incremental(benchmark::State& st) {
  run(st, [](const Unit::Coefs& c, int y, Pixel* o) { Unit::span_incremental(c, y, 0, kLen, o); });
}
template <int K>
void BM_KLane(benchmark::State& st) {
  run(st, [](const Unit::Coefs& c, int y, Pixel* o) { Unit::span_klane<K>(c, y, 0, kLen, o); });
}
void BM_TwoEnded(benchmark::State& st) {
  run(st, [](const Unit::Coefs& c, int y, Pixel* o) { Unit::span_two_ended(c, y, 0, kLen, o); });
}
void BM_FloatReference(benchmark::State& st) {
  const auto& s = spans();
  std::vector<double> u(kLen), v(kLen);
  size_t i = 0;
  for (auto _ : st) {
    const Coef9& k = s.k[i];
    const double y = s.y[i];
    for (int x = 0; x < kLen; ++x) {  // direct, two divides, double
      const double q = k.g * x + k.h * y + k.i;
      u[x] = (k.a * x + k.b * y + k.c) / q;
      v[x] = (k.d * x + k.e * y + k.f) / q;
    }
    benchmark::DoNotOptimize(u.data());
    benchmark::DoNotOptimize(v.data());
    i = (i + 1) % s.k.size();
  }
  st.SetItemsProcessed(static_cast<int64_t>(st.iterations()) * kLen);
}
BENCHMARK(BM_Direct);
BENCHMARK(BM_Incremental);
BENCHMARK_TEMPLATE(BM_KLane, 2);
BENCHMARK_TEMPLATE(BM_KLane, 4);
BENCHMARK_TEMPLATE(BM_KLane, 8);
BENCHMARK(BM_TwoEnded);
BENCHMARK(BM_FloatReference);
}  // namespace

BENCHMARK_MAIN();
