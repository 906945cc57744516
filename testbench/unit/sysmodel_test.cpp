// SystemC system model (tlm/): exact cycle counts on small synthetic streams whose answer follows
// from the stage descriptions alone.
#include <gtest/gtest.h>

#include "texunit/sysmodel.hpp"
#include "texunit/texture_unit_model.hpp"

namespace {
using namespace tu::sysmodel;

// One span of n pixels with per-pixel work `texels`.
Workload one_span(const std::vector<uint32_t>& texels) {
  Workload w;
  w.spans.push_back(Span{0, 0, 0, 0, 0, static_cast<uint32_t>(texels.size())});
  for (uint32_t t : texels) w.pixels.push_back(PixelWork{t, 1, 0, false});
  return w;
}

Workload spans_of(const std::vector<uint32_t>& counts) {
  Workload w;
  for (uint32_t c : counts) {
    w.spans.push_back(Span{0, 0, 0, 0, static_cast<uint32_t>(w.pixels.size()), c});
    w.pixels.resize(w.pixels.size() + c);
  }
  return w;
}

StageSpec pipe(const std::string& name, int lat, bool expand = false) {
  StageSpec s;
  s.name = name;
  s.lat0 = lat, s.ii0 = 1, s.capacity = std::max(lat, 1), s.expand = expand;
  return s;
}

TEST(Sysmodel, FixedLatencyChainIsLatencyPlusNMinusOne) {
  for (uint32_t n : {1u, 2u, 17u, 1000u}) {
    Pipeline p{"chain", {pipe("a", 8, true), pipe("b", 5), pipe("c", 3)}};
    const auto r = simulate(p, one_span(std::vector<uint32_t>(n, 0)));
    EXPECT_EQ(r.total_cycles, 8u + 5 + 3 + n - 1) << n;
    EXPECT_EQ(r.pixels, n);
    for (const auto& b : r.blocks) EXPECT_EQ(b.busy, n) << b.name;  // II 1: one issue cycle each
    EXPECT_EQ(r.blocks[0].stalled, 0u);
  }
}

TEST(Sysmodel, SpanSetupInFrontCostsItsLatencyOnce) {
  // Spans of 10, 1, 5 pixels: the set-up (latency 2, II 1) runs ahead of the pixel walker, so
  // only the first span's set-up shows; the walker issues one pixel per clock.
  Pipeline p{"setup", {pipe("setup", 2), pipe("walk", 8, true)}};
  p.stages[0].fifo_depth = 4;
  const auto r = simulate(p, spans_of({10, 1, 5}));
  EXPECT_EQ(r.total_cycles, 2u + 8 + 16 - 1);
  EXPECT_EQ(r.blocks[0].items, 3u);
  EXPECT_EQ(r.blocks[1].items, 16u);
}

TEST(Sysmodel, DataDependentEngineAddsItsWork) {
  // Engine: one pixel in flight, ii = 3 + k, latency = 2 + k (the POM march's k + 3 cycles per
  // pixel). Behind a II-1 pipe it is the bottleneck: total = first arrival + sum of ii - 1.
  const std::vector<uint32_t> k = {0, 5, 1, 7, 2, 2, 9};
  StageSpec e;
  e.name = "engine";
  e.lat0 = 2, e.ii0 = 3, e.lat_per_work = 1, e.ii_per_work = 1, e.work = Work::Texels;
  e.capacity = 1;
  Pipeline p{"engine", {pipe("walk", 4, true), e}};
  const auto r = simulate(p, one_span(k));
  uint64_t sum_ii = 0;
  for (uint32_t x : k) sum_ii += 3 + x;
  // Pixel i is accepted at 4 + sum of earlier ii; the last leaves 2 + k_last later.
  EXPECT_EQ(r.total_cycles, 4 + (sum_ii - (3 + k.back())) + 2 + k.back());
  EXPECT_EQ(r.blocks[1].busy, sum_ii);
  EXPECT_EQ(r.blocks[1].work, 26u);
  // The walker is held back by the engine: its outputs waited.
  EXPECT_GT(r.blocks[0].stalled, 0u);
}

TEST(Sysmodel, FifoAbsorbsBurstsAndLinkRegistersAddLatency) {
  // Work alternates 0 and 3 clocks (ii = max(1, work)); mean ii = 2 > 1, so the engine limits.
  std::vector<uint32_t> k;
  for (int i = 0; i < 100; ++i) k.push_back(i % 2 ? 3 : 1);
  StageSpec e;
  e.name = "walker";
  e.lat0 = 0, e.ii0 = 0, e.lat_per_work = 1, e.ii_per_work = 1, e.work = Work::Texels;
  e.capacity = 1, e.fifo_depth = 4, e.link_latency = 1;
  Pipeline p{"fifo", {pipe("front", 5, true), e}};
  const auto r = simulate(p, one_span(k));
  // First pixel at 5 (+1 link register); then back to back: 200 clocks of work in all, the last
  // pixel (work 3) leaves 3 clocks after its acceptance.
  EXPECT_EQ(r.total_cycles, 5u + 1 + 200 - 3 + 3);
}

TEST(Sysmodel, ReliefOnlyStageLetsOtherPixelsPass) {
  // A POM-like engine (k + 3 clocks per pixel, one in flight) used by relief pixels only; the
  // others pass in `bypass_latency` at one per clock, in order behind the relief pixel in flight.
  Workload w = one_span({0, 0, 0, 0});
  w.pixels[1].relief = true, w.pixels[1].steps = 6;
  StageSpec e;
  e.name = "relief";
  e.lat0 = 2, e.ii0 = 3, e.lat_per_work = 1, e.ii_per_work = 1, e.work = Work::Steps;
  e.capacity = 1, e.relief_only = true, e.bypass_latency = 1;
  Pipeline p{"relief", {pipe("walk", 1, true), e}};
  const auto r = simulate(p, w);
  // px0 in at 1, out at 2; px1 in at 2 (ii 1 of the bypass), out at 2 + 2 + 6 = 10, next accepted
  // at 2 + 9 = 11; px2 out at 12, px3 in at 12, out at 13.
  EXPECT_EQ(r.total_cycles, 13u);
  EXPECT_EQ(r.blocks[1].work, 6u);
  EXPECT_EQ(r.blocks[1].busy, 1u + 9 + 1 + 1);
}

TEST(Sysmodel, HandOverBetweenTwoEnginesFollowsTheRecurrence) {
  // A set-up FSM (S cycles, accepts again one clock after the hand-over) feeding a walker
  // (W cycles to its output, free the clock after) over a direct link: pixel i+1's set-up
  // overlaps pixel i's walk. Known answer: the recurrence
  //   h_i = max(a_i + S_i, walker_free), o_i = h_i + W_i, a_{i+1} = h_i + 1, walker_free = o_i + 1.
  std::vector<uint32_t> texels = {40, 3, 3, 3, 90, 1, 0, 25, 7, 60};
  Workload w = one_span(texels);
  for (size_t i = 0; i < texels.size(); ++i) w.pixels[i].levels = 1 + static_cast<uint32_t>(i % 3);
  auto S = [](const PixelWork& p) { return 10 + 5 * static_cast<int>(p.levels); };
  auto W = [](const PixelWork& p) { return 12 + static_cast<int>(p.texels); };
  StageSpec su;
  su.name = "setup";
  su.capacity = 1, su.fifo_depth = 64, su.release = 1, su.work = Work::Levels;
  su.timing = [&](const PixelWork& p) { return Timing{S(p), S(p) + 1}; };
  StageSpec wk;
  wk.name = "walker";
  wk.capacity = 1, wk.direct = true, wk.fifo_depth = 1, wk.work = Work::Texels;
  wk.timing = [&](const PixelWork& p) { return Timing{W(p), W(p) + 1}; };
  Pipeline p{"engine", {pipe("front", 3, true), su, wk}};
  p.stages[0].capacity = 16;
  const auto r = simulate(p, w);
  uint64_t a = 3, walker_free = 0, o = 0;  // the first pixel reaches the set-up at cycle 3
  for (const auto& px : w.pixels) {
    const uint64_t h = std::max<uint64_t>(a + S(px), walker_free);
    o = h + W(px);
    a = h + 1, walker_free = o + 1;
  }
  EXPECT_EQ(r.total_cycles, o);
  EXPECT_GT(r.blocks[1].stalled, 0u);  // the 90-texel walk holds the next record back
}

TEST(Sysmodel, RejectsMalformedPipelines) {
  Pipeline none{"none", {pipe("a", 3)}};
  EXPECT_THROW(simulate(none, one_span({0})), std::invalid_argument);
  Pipeline cap{"cap", {pipe("a", 3, true)}};
  cap.stages[0].capacity = 0;
  EXPECT_THROW(simulate(cap, one_span({0})), std::invalid_argument);
  Workload bad = one_span({0, 0});
  bad.pixels.pop_back();
  EXPECT_THROW(simulate(Pipeline{"ok", {pipe("a", 3, true)}}, bad), std::invalid_argument);
}

}  // namespace

namespace {

TEST(Sysmodel, DefaultSceneStreamCoversEveryPixelOnce) {
  // The default scene's geometry at 128 x 96: every span kind, a fraction of the C-model time
  // (the full scene: `texunit sysmodel default`).
  auto s = tu::scene::default_scene();
  s.camera.width = 128;
  s.camera.height = 96;
  const auto frame = tu::render::render_cmodel(s, tu::scene::Filter::Ewa, tu::render::texture_path_only());
  const auto wl = scene_workload(s, frame);
  ASSERT_FALSE(wl.spans.empty());
  ASSERT_EQ(wl.pixels.size(), frame.pixels.size());
  uint64_t walked = 0;
  for (size_t i = 0; i < wl.spans.size(); ++i) {
    const auto& sp = wl.spans[i];
    for (uint32_t k = 0; k < sp.count; ++k) {
      const auto& p = frame.pixels[sp.first + k];
      EXPECT_EQ(p.y, sp.y);
      EXPECT_EQ(p.x, sp.x0 + static_cast<int>(k));
    }
    if (i > 0 && wl.spans[i - 1].y == sp.y) {  // a new span on the same row: a new triangle or a gap
      EXPECT_TRUE(wl.spans[i - 1].x0 + static_cast<int>(wl.spans[i - 1].count) < sp.x0 ||
                  wl.spans[i - 1].triangle != sp.triangle || wl.spans[i - 1].object != sp.object);
    }
  }
  std::vector<tu::ewa::PixelCost> costs;
  for (const auto& p : wl.pixels) {
    walked += p.texels;
    costs.push_back(cost_of(p));
  }
  const UnitConfig cfg;  // the full unit (relief stage in)
  const auto r = simulate(texture_unit(cfg), wl);
  // The filter walks one texel per clock with one pixel in flight: it bounds the run from below.
  EXPECT_GE(r.total_cycles, walked);
  // The EWA engine's own stream recurrence (ewa::stream_cycles: pixels always waiting, the first
  // after the front-end latency; it counts to the cycle after the last output). The front end
  // (5 pixels per 8 clocks at worst) always keeps the FIFO ahead of a >= 12-clock walk, so the
  // whole-unit model must land on it exactly.
  EXPECT_EQ(r.total_cycles + 1,
            tu::ewa::stream_cycles(costs, static_cast<uint64_t>(tu::ewa::texture_unit_front_latency(cfg.relief_stage))));
  std::printf("default scene: %zu spans, %zu pixels, %llu texels, %llu cycles, %.3f s\n",
              wl.spans.size(), wl.pixels.size(), (unsigned long long)walked,
              (unsigned long long)r.total_cycles, r.sim_seconds);
  std::fputs(table(r).c_str(), stdout);
}

}  // namespace
