// tu::Fixed against SystemC sc_fixed and against the same kernel written by hand on int64_t (the
// reciprocal's Horner step: two multiplies, two adds, four narrowing casts with
// truncation/rounding), in one binary. Exits non-zero unless tu::Fixed is at least --min-ratio
// (default 20) times faster than sc_fixed and at most --max-int64-ratio (default 1.3) times
// slower than the int64 kernel, or if the three kernels disagree on one item.
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

// The same arithmetic with the formats resolved by hand: shifts, masks and sign extensions.
uint64_t int64_item(uint64_t c0u, uint64_t c1u, uint64_t c2u, uint64_t dxu) {
  const int64_t c0 = static_cast<int64_t>(c0u);                          // u32.30
  const int64_t c1 = static_cast<int64_t>(c1u << 39) >> 39;              // s25.22
  const int64_t c2 = static_cast<int64_t>(c2u), dx = static_cast<int64_t>(dxu);  // u14.12, u15.23
  const int64_t t1 = ((c2 * dx) >> 13) & ((int64_t(1) << 18) - 1);      // u29.35 -> u18.22
  const int64_t s = static_cast<int64_t>(static_cast<uint64_t>(c1 + t1) << 39) >> 39;  // s25.22
  const int64_t t2 = static_cast<int64_t>(static_cast<uint64_t>((s * dx) >> 15) << 38) >> 38;
  int64_t y = (c0 + t2 + 32) >> 6;  // s34.30 -> u25.24, half up, saturate
  y = y < 0 ? 0 : y > (int64_t(1) << 25) - 1 ? (int64_t(1) << 25) - 1 : y;
  return static_cast<uint64_t>(y);
}

uint64_t fixed_item(uint64_t c0u, uint64_t c1u, uint64_t c2u, uint64_t dxu) {
  const auto c0 = UFixed<32, 30>::from_bits(c0u);
  const auto c1 = SFixed<25, 22>::from_bits(c1u);
  const auto c2 = UFixed<14, 12>::from_bits(c2u);
  const auto dx = UFixed<15, 23>::from_bits(dxu);
  const auto t1 = (c2 * dx).cast<18, 22, false>();
  const auto s = (c1 + t1).cast<25, 22, true>();
  const auto t2 = (s * dx).cast<26, 30, true>();
  const auto y = (c0 + t2).cast<25, 24, false, Round::HalfUp, Ovf::Sat>();
  return y.bits();
}

uint64_t sc_item(uint64_t c0u, uint64_t c1u, uint64_t c2u, uint64_t dxu) {
  using namespace sc_dt;
  sc_ufixed<32, 2> c0;
  c0.range(31, 0) = static_cast<uint64>(c0u);
  sc_fixed<25, 3> c1;
  c1.range(24, 0) = static_cast<uint64>(c1u);
  sc_ufixed<14, 2> c2;
  c2.range(13, 0) = static_cast<uint64>(c2u);
  sc_ufixed<15, -8> dx;
  dx.range(14, 0) = static_cast<uint64>(dxu);
  const sc_ufixed<18, -4> t1 = c2 * dx;
  const sc_fixed<25, 3> s = c1 + t1;
  const sc_fixed<26, -4> t2 = s * dx;
  const sc_ufixed<25, 1, SC_RND, SC_SAT> y = c0 + t2;
  return y.range(24, 0).to_uint64();
}

// The same loop for the three kernels: 4096 items per iteration (a template argument, so each
// kernel is inlined into its loop).
template <uint64_t (*Item)(uint64_t, uint64_t, uint64_t, uint64_t)>
void run_kernel(benchmark::State& st) {
  const auto& in = inputs();
  for (auto _ : st) {
    uint64_t acc = 0;
    for (int i = 0; i < kN; ++i) acc += Item(in.c0[i], in.c1[i], in.c2[i], in.dx[i]);
    benchmark::DoNotOptimize(acc);
  }
  st.SetItemsProcessed(st.iterations() * kN);
}
void BM_Int64(benchmark::State& st) { run_kernel<int64_item>(st); }
void BM_TuFixed(benchmark::State& st) { run_kernel<fixed_item>(st); }
void BM_ScFixed(benchmark::State& st) { run_kernel<sc_item>(st); }

BENCHMARK(BM_Int64);
BENCHMARK(BM_TuFixed);
BENCHMARK(BM_ScFixed);

// Collects per-item times while printing the usual console table.
class Collect : public benchmark::ConsoleReporter {
 public:
  std::map<std::string, double> ns_per_iter;
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const auto& r : runs) ns_per_iter[r.benchmark_name()] = r.GetAdjustedCPUTime();  // shared machine
    ConsoleReporter::ReportRuns(runs);
  }
};
}  // namespace

int main(int argc, char** argv) {
  double min_ratio = 20, max_int64_ratio = 1.3;
  std::vector<char*> args;
  for (int i = 0; i < argc; ++i) {
    if (std::strncmp(argv[i], "--min-ratio=", 12) == 0) min_ratio = std::stod(argv[i] + 12);
    else if (std::strncmp(argv[i], "--max-int64-ratio=", 18) == 0)
      max_int64_ratio = std::stod(argv[i] + 18);
    else args.push_back(argv[i]);
  }
  // The three kernels must agree on every item before their speeds mean anything.
  const auto& in = inputs();
  for (int i = 0; i < kN; ++i) {
    const uint64_t f = fixed_item(in.c0[i], in.c1[i], in.c2[i], in.dx[i]);
    if (f != int64_item(in.c0[i], in.c1[i], in.c2[i], in.dx[i]) ||
        f != sc_item(in.c0[i], in.c1[i], in.c2[i], in.dx[i])) {
      std::fprintf(stderr, "kernels disagree on item %d\n", i);
      return 1;
    }
  }
  int n = static_cast<int>(args.size());
  benchmark::Initialize(&n, args.data());
  Collect rep;
  benchmark::RunSpecifiedBenchmarks(&rep);
  benchmark::Shutdown();
  const double ours = rep.ns_per_iter["BM_TuFixed"], theirs = rep.ns_per_iter["BM_ScFixed"];
  const double raw = rep.ns_per_iter["BM_Int64"];
  if (ours <= 0 || theirs <= 0 || raw <= 0) {
    std::fprintf(stderr, "benchmarks did not run\n");
    return 1;
  }
  const double ratio = theirs / ours, vs_int64 = ours / raw;
  std::printf("tu::Fixed is %.1fx faster than sc_fixed on the Horner kernel (%.2f vs %.2f ns/item); "
              "required >= %.0fx\n", ratio, ours / kN, theirs / kN, min_ratio);
  std::printf("tu::Fixed takes %.2fx the time of the hand-written int64 kernel (%.2f vs %.2f "
              "ns/item); required <= %.2fx\n", vs_int64, ours / kN, raw / kN, max_int64_ratio);
  return ratio >= min_ratio && vs_int64 <= max_int64_ratio ? 0 : 1;
}
