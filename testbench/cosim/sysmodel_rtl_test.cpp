// SystemC system model (tlm/) against the RTL: the same scene's pixel stream through the model and
// through the Verilated tu_texture_unit in one process; cycle totals within 5%, the model at least
// 10x faster (docs/systemc.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "texture_unit_rtl.hpp"
#include "texunit/render.hpp"
#include "texunit/texture_unit_model.hpp"

namespace {
using namespace tu;

TEST(SysmodelRtl, SceneCyclesWithinFivePercentAndTenTimesFaster) {
  // The default scene's geometry at 128 x 96 (about 8,500 pixels, 0.5 M cycles): a whole scene's
  // stream, seconds of RTL simulation.
  auto s = scene::default_scene();
  s.camera.width = 128;
  s.camera.height = 96;
  const auto rtl = cosim::render_rtl(s);
  ASSERT_TRUE(rtl.ok()) << rtl.first_mismatch;
  const auto wl = sysmodel::scene_workload(s, render::render_cmodel(s, tu::scene::Filter::Ewa, tu::render::texture_path_only()));
  ASSERT_EQ(wl.pixels.size(), rtl.frame.pixels.size());
  // Fastest of three runs: the speed claim is about the model, not about the machine's load.
  sysmodel::Result r;
  double best = 1e9;
  for (int i = 0; i < 3; ++i) {
    r = sysmodel::simulate(sysmodel::texture_unit(), wl);
    best = std::min(best, r.sim_seconds);
  }
  // The RTL count runs to the cycle after the last output.
  const double ratio = static_cast<double>(r.total_cycles + 1) / static_cast<double>(rtl.cycles);
  std::printf("%zu px: RTL %llu cycles in %.3f s, model %llu cycles in %.4f s: ratio %.5f, %.1fx faster\n",
              wl.pixels.size(), (unsigned long long)rtl.cycles, rtl.sim_wall_s,
              (unsigned long long)(r.total_cycles + 1), best, ratio, rtl.sim_wall_s / best);
  EXPECT_LT(std::abs(ratio - 1), 0.05);
  EXPECT_GE(rtl.sim_wall_s / best, 10.0);
}

// With relief: the wall's pixels are shifted by the relief stage (the C model's march steps drive
// the model's relief stage). The default relief (adaptive, 32 layers) hides under the EWA walk; a
// heavy one (fixed 63 layers, scale 0.2, the wall's anisotropy clamped to 1 so its walks are short)
// makes the stage matter. Both within 1% of the RTL.
TEST(SysmodelRtl, ReliefSceneCyclesWithinOnePercent) {
  auto s = scene::default_scene();
  s.camera.width = 128;
  s.camera.height = 96;
  auto heavy = s;
  auto& rel = *heavy.materials.at("wall").relief;
  rel.method = scene::ReliefMethod::PomFixed, rel.layers = 63, rel.scale = 0.2;
  heavy.materials.at("wall").max_aniso = 1;
  for (const auto* sc : {&s, &heavy}) {
    cosim::RtlRenderOptions o;
    o.filter = scene::Filter::Ewa;
    o.relief = true;
    const auto rtl = cosim::render_rtl(*sc, o);
    ASSERT_TRUE(rtl.ok()) << rtl.first_mismatch;
    render::CmodelOptions c = render::texture_path_only();
    c.relief = true;
    const auto wl = sysmodel::scene_workload(*sc, render::render_cmodel(*sc, scene::Filter::Ewa, c));
    uint64_t shifted = 0, steps = 0;
    for (const auto& p : wl.pixels) shifted += p.relief, steps += p.steps;
    EXPECT_GT(shifted, 1000u);
    const auto r = sysmodel::simulate(sysmodel::texture_unit(), wl);
    const double ratio = static_cast<double>(r.total_cycles + 1) / static_cast<double>(rtl.cycles);
    std::printf("relief %s: %llu shifted px, %llu march steps: RTL %llu cycles, model %llu: ratio %.5f\n",
                sc == &s ? "default" : "heavy", (unsigned long long)shifted, (unsigned long long)steps,
                (unsigned long long)rtl.cycles, (unsigned long long)(r.total_cycles + 1), ratio);
    EXPECT_LT(std::abs(ratio - 1), 0.01);
  }
}

}  // namespace
