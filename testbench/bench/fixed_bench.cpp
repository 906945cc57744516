// tu::Fixed against SystemC sc_fixed on the same kernel (the reciprocal's Horner step: two
// multiplies, two adds, three narrowing casts with truncation/rounding), in one binary.
// Exits non-zero unless tu::Fixed is at least --min-ratio (default 20) times faster.
#include <benchmark/benchmark.h>
#include <systemc.h>

#include <cstring>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "texunit/fixed.hpp"

namespace {
using namespace tu;

constexpr int kN = 4096;

struct Inputs {
  std::vector<uint64_t> c0, c1, c2, dx;
  Inputs() {
    std::mt19937_64 rng(1);
    for (int i = 0; i < kN; ++i) {
      c0.push_back(rng() & 0xffffffffu);
      c1.push_back(rng() & 0x1ffffffu);
      c2.push_back(rng() & 0x3fffu);
      dx.push_back(rng() & 0x7fffu);
    }
  }
};
const Inputs& inputs() {
  static const Inputs in;
  return in;
}

void BM_TuFixed(benchmark::State& st) {
  const auto& in = inputs();
  for (auto _ : st) {
    uint64_t acc = 0;
    for (int i = 0; i < kN; ++i) {
      const auto c0 = UFixed<32, 30>::from_bits(in.c0[i]);
      const auto c1 = SFixed<25, 22>::from_bits(in.c1[i]);
      const auto c2 = UFixed<14, 12>::from_bits(in.c2[i]);
      const auto dx = UFixed<15, 23>::from_bits(in.dx[i]);
      const auto t1 = (c2 * dx).cast<18, 22, false>();
      const auto s = (c1 + t1).cast<25, 22, true>();
      const auto t2 = (s * dx).cast<26, 30, true>();
      const auto y = (c0 + t2).cast<25, 24, false, Round::HalfUp, Ovf::Sat>();
      acc += y.bits();
    }
    benchmark::DoNotOptimize(acc);
  }
  st.SetItemsProcessed(st.iterations() * kN);
}

void BM_ScFixed(benchmark::State& st) {
  using namespace sc_dt;
  const auto& in = inputs();
  for (auto _ : st) {
    uint64_t acc = 0;
    for (int i = 0; i < kN; ++i) {
      sc_ufixed<32, 2> c0;
      c0.range(31, 0) = static_cast<uint64>(in.c0[i]);
      sc_fixed<25, 3> c1;
      c1.range(24, 0) = static_cast<uint64>(in.c1[i]);
      sc_ufixed<14, 2> c2;
      c2.range(13, 0) = static_cast<uint64>(in.c2[i]);
      sc_ufixed<15, -8> dx;
      dx.range(14, 0) = static_cast<uint64>(in.dx[i]);
      const sc_ufixed<18, -4> t1 = c2 * dx;
      const sc_fixed<25, 3> s = c1 + t1;
      const sc_fixed<26, -4> t2 = s * dx;
      const sc_ufixed<25, 1, SC_RND, SC_SAT> y = c0 + t2;
      acc += y.range(24, 0).to_uint64();
    }
    benchmark::DoNotOptimize(acc);
  }
  st.SetItemsProcessed(st.iterations() * kN);
}

BENCHMARK(BM_TuFixed);
BENCHMARK(BM_ScFixed);

// Collects per-item times while printing the usual console table.
class Collect : public benchmark::ConsoleReporter {
 public:
  std::map<std::string, double> ns_per_iter;
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const auto& r : runs) ns_per_iter[r.benchmark_name()] = r.GetAdjustedRealTime();
    ConsoleReporter::ReportRuns(runs);
  }
};
}  // namespace

int main(int argc, char** argv) {
  double min_ratio = 20;
  std::vector<char*> args;
  for (int i = 0; i < argc; ++i) {
    if (std::strncmp(argv[i], "--min-ratio=", 12) == 0) min_ratio = std::stod(argv[i] + 12);
    else args.push_back(argv[i]);
  }
  int n = static_cast<int>(args.size());
  benchmark::Initialize(&n, args.data());
  Collect rep;
  benchmark::RunSpecifiedBenchmarks(&rep);
  benchmark::Shutdown();
  const double ours = rep.ns_per_iter["BM_TuFixed"], theirs = rep.ns_per_iter["BM_ScFixed"];
  if (ours <= 0 || theirs <= 0) {
    std::fprintf(stderr, "benchmarks did not run\n");
    return 1;
  }
  const double ratio = theirs / ours;
  std::printf("tu::Fixed is %.1fx faster than sc_fixed on the Horner kernel (%.2f vs %.2f ns/item); "
              "required >= %.0fx\n", ratio, ours / kN, theirs / kN, min_ratio);
  return ratio >= min_ratio ? 0 : 1;
}
