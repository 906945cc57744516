// Renders of the default scene (256x192): C-model pixels per second on one thread and on every
// core, the float reference, and the visibility pass alone, side by side in one run
// (docs/performance.md). Items = covered pixels.
// Run: build/<dir>/testbench/bench/tu_render_bench --benchmark_min_time=1
#include <benchmark/benchmark.h>

#include "texunit/parallel.hpp"
#include "texunit/render.hpp"

namespace {
using namespace tu;

const scene::Scene& scn() {
  static const auto s = scene::default_scene();
  return s;
}

// arg 0: threads (0: every core); arg 1: 1 = the texture path alone (relief off)
void BM_CmodelEwa(benchmark::State& st) {
  render::CmodelOptions opt;
  opt.threads = static_cast<int>(st.range(0));
  opt.relief = st.range(1) == 0;
  size_t n = 0;
  for (auto _ : st) n += render::render_cmodel(scn(), scene::Filter::Ewa, opt).pixels.size();
  st.SetItemsProcessed(static_cast<int64_t>(n));
  st.counters["threads"] = par::resolve_threads(opt.threads);
}
BENCHMARK(BM_CmodelEwa)->ArgNames({"threads", "flat"})->Args({1, 1})->Args({0, 1})->Args({1, 0})->Args({0, 0})
    ->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_RefEwa(benchmark::State& st) {
  size_t n = 0;
  for (auto _ : st) n += render::render_ref(scn(), scene::Filter::Ewa).pixels.size();
  st.SetItemsProcessed(static_cast<int64_t>(n));
  st.counters["threads"] = 1;  // every benchmark has the same counters (the CSV reporter needs it)
}
BENCHMARK(BM_RefEwa)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_Visibility(benchmark::State& st) {
  size_t n = 0;
  for (auto _ : st) n += render::covered(render::visibility(scn(), static_cast<int>(st.range(0))));
  st.SetItemsProcessed(static_cast<int64_t>(n));
  st.counters["threads"] = par::resolve_threads(static_cast<int>(st.range(0)));
}
BENCHMARK(BM_Visibility)->ArgName("threads")->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime();
}  // namespace

BENCHMARK_MAIN();
