// Feline engine co-simulation (docs/blocks/feline.md "RTL"). Cycles per pixel depend on the
// probe count and the level, so the engine is not in the fixed-latency Cosim suite: 0 mismatches
// with 30 % stalls on golden/stiff/random (2,000 random here), the scoreboard catches a corrupted
// value, and the cycle model feline::EngineModel equals Verilator's count on stall-free streams.
// In the texture-unit top (the default Verilated unit, HasFeline = 1): docs/scenes/feline_floor.json
// and the default scene with every material Feline equal to the C model with 30 % stalls, and
// cycles = ewa::texture_unit_cycles without.
#include <gtest/gtest.h>

#include <cstdio>

#include "cosim_checks.hpp"
#include "ewa/ewa_cycles.hpp"
#include "texture_unit_rtl.hpp"

namespace {
using namespace tu;

using cosim::checks::with_stalls;

TEST(FelineCosim, GoldenStiffRandomWithStalls) {
  cosim::checks::for_each_set_with_stalls(blocks::find("feline"), [](const vec::VectorFile&, const cosim::Report&) {}, 2000);
}

TEST(FelineCosim, DetectsACorruptedExpectedValue) { cosim::checks::expect_corruption_detected("feline"); }

// The engine's stream (texel-RAM top, no front): the unit's StreamModel with every pixel on the
// Feline engine from cycle 0, from the C model's probes and levels (256 x 256 texture, top 8).
TEST(FelineCosim, CyclesMatchPrediction) {
  for (const std::string set : {"golden", "stiff", "random"}) {
    const auto vf = blocks::generate(blocks::find("feline"), set, 2000, 7);
    const auto rep = cosim::run(vf, with_stalls(0));
    cosim::checks::expect_stream_clean(rep);
    const auto in_idx = vf.indices(vec::Role::In), out_idx = vf.indices(vec::Role::Out);
    std::vector<ewa::PixelCost> costs;
    double probes = 0;
    for (const auto& row : vf.rows) {
      const auto in = cosim::glue::in_feline(blocks::pick(row, in_idx));
      const auto out = cosim::glue::out_feline(blocks::pick(row, out_idx));
      ewa::PixelCost c;
      c.engine = ewa::Engine::Feline;
      c.guard = in.guard != 0;
      c.probes = c.guard ? 1 : static_cast<int>(out.probes);
      c.one_level = ewa::trilinear_one_level(c.guard, static_cast<int>(out.level), 8);
      probes += static_cast<double>(c.probes);
      costs.push_back(c);
    }
    const uint64_t predicted = ewa::stream_cycles(costs);
    std::printf("feline %s: %zu px, %.2f probes/px, cycles measured %llu predicted %llu (%.2f cycles/px)\n", set.c_str(),
                vf.rows.size(), probes / double(vf.rows.size()), (unsigned long long)rep.sim_cycles,
                (unsigned long long)predicted, double(rep.sim_cycles) / double(vf.rows.size()));
    EXPECT_EQ(rep.sim_cycles, predicted) << set;
  }
}

// The unit on a scene with every pixel's work checked against render_cmodel: 30 % stalls, then
// stall-free with cycles = the prediction.
void expect_unit_equal(const scene::Scene& s, const std::optional<scene::Filter>& filter, const char* what) {
  cosim::RtlRenderOptions o;
  o.filter = filter;
  o.stall_prob = 0.3;
  const auto r = cosim::render_rtl(s, o);
  EXPECT_TRUE(r.ok()) << what << ": " << r.first_mismatch;
  EXPECT_EQ(r.mismatches, 0u) << what << ": " << r.first_mismatch;
  EXPECT_GT(r.frame.pixels.size(), 1000u) << what;
  o.stall_prob = 0;
  const auto q = cosim::render_rtl(s, o);
  EXPECT_TRUE(q.ok()) << what << ": " << q.first_mismatch;
  EXPECT_EQ(q.cycles, q.predicted_cycles) << what;
  double probes = 0;
  for (const auto& p : q.frame.pixels) probes += p.probes;
  const double n = double(q.frame.pixels.size());
  std::printf("%s: %zu px, %.2f probes/px; 30 %% stalls: %llu mismatches; cycles measured %llu predicted %llu (%.2f/px)\n",
              what, q.frame.pixels.size(), probes / n, (unsigned long long)r.mismatches, (unsigned long long)q.cycles,
              (unsigned long long)q.predicted_cycles, double(q.cycles) / n);
}

TEST(FelineUnit, FloorSceneEqualsCModel) {
  auto s = scene::load(std::string(TU_SOURCE_DIR) + "/docs/scenes/feline_floor.json");
  s.camera.width = 64, s.camera.height = 48;  // the scene's geometry, a quarter of its pixels
  expect_unit_equal(s, std::nullopt, "feline_floor 64x48");
}

TEST(FelineUnit, DefaultSceneForcedFelineEqualsCModel) {
  auto s = scene::without_relief(scene::default_scene());
  s.camera.width = 64, s.camera.height = 48;
  for (auto& [name, m] : s.materials) m.feline_max_probes = 16;  // every probe count
  expect_unit_equal(s, scene::Filter::Feline, "default 64x48, every material feline (Nmax 16)");
}

}  // namespace
