// Visibility engine co-simulation (rtl/ewa/tu_afvis.sv, docs/blocks/afvis-appendix.md §5): cycles per pixel
// depend on the box and the traces, so the engine is not in the fixed-latency Cosim suite: 0
// mismatches (colour, level, counts, flags, kept, traced, depth reads) with 30 % stalls on the
// golden, stiff and random sets, the scoreboard catches a corrupted value, and the cycle model
// (ewa::StreamModel with PixelCost::afv_walk = afvis::Out::clocks) equals Verilator's count on
// stall-free streams. The long run: scripts/cosim_full.sh afvis.
#include <gtest/gtest.h>

#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>

#include "afvis_block.hpp"
#include "cosim_checks.hpp"
#include "ewa/ewa_cycles.hpp"
#include "texture_unit_rtl.hpp"
#include "texunit/render.hpp"
#include "texunit/scene.hpp"

namespace {
using namespace tu;

using cosim::checks::with_stalls;

TEST(AfvisCosim, GoldenStiffRandomWithStalls) {
  cosim::checks::for_each_set_with_stalls(blocks::find("afvis"), [](const vec::VectorFile&, const cosim::Report&) {}, 600);
}

TEST(AfvisCosim, DetectsACorruptedExpectedValue) { cosim::checks::expect_corruption_detected("afvis"); }

// Per-pixel cycle costs of a vector file's rows (the block's texture: top level 8).
std::vector<ewa::PixelCost> costs_of(const vec::VectorFile& vf) {
  const auto in_idx = vf.indices(vec::Role::In);
  std::vector<ewa::PixelCost> c;
  for (const auto& row : vf.rows) {
    const auto in = blocks::pick(row, in_idx);
    const afvis::Out o = blocks::afvis_block_model(in);
    ewa::fx::In px;
    px.b2.lod = static_cast<uint32_t>(cosim::glue::in_afvis(in).lod);
    c.push_back(ewa::pixel_cost(px, o.ewa.level, o.ewa.flags, o.ewa.texels_visited, 8));
    c.back().afv_walk = o.clocks;
  }
  return c;
}

TEST(AfvisCosim, CyclesMatchPrediction) {
  for (const std::string set : {"golden", "stiff", "random"}) {
    const auto vf = blocks::generate(blocks::find("afvis"), set, 300, 7);
    const auto rep = cosim::run(vf, with_stalls(0));
    cosim::checks::expect_stream_clean(rep);
    const uint64_t predicted = ewa::stream_cycles(costs_of(vf));
    std::printf("afvis %s: %zu px, cycles measured %llu predicted %llu (%.2f cycles/px)\n", set.c_str(),
                vf.rows.size(), (unsigned long long)rep.sim_cycles, (unsigned long long)predicted,
                double(rep.sim_cycles) / double(vf.rows.size()));
    EXPECT_EQ(rep.sim_cycles, predicted) << set;
  }
}

}  // namespace

// Inside the texture-unit top (the full unit, HasAfvis = 1): docs/scenes/af_visibility.json at
// 32 x 24 with relief, every pixel == render_cmodel (colour, level, texel counts, flags, relief
// results) with 30 % stalls; without stalls the cycles are the unit's cycle model
// (ewa::texture_unit_cycles with PixelCost::afv_walk). Visibility is really on: most pixels go
// through tu_afvis and the C model's picture without visibility differs from the unit's.
TEST(TextureUnitRtl, AfVisibilitySceneEqualsCModelWithCyclesPredicted) {
  auto s = scene::load(std::string(TU_SOURCE_DIR) + "/docs/scenes/af_visibility.json");
  s.camera.width = 32;
  s.camera.height = 24;
  render::CmodelOptions co;
  const render::Frame c = render::render_cmodel(s, std::nullopt, co);
  co.afvis = render::AfvisMode::Off;
  const render::Frame plain = render::render_cmodel(s, std::nullopt, co);
  size_t afv = 0;
  for (const auto& p : c.pixels) afv += p.afv_clocks > 0;
  EXPECT_GT(afv, c.pixels.size() / 2);
  cosim::RtlRenderOptions o;
  o.relief = true;
  o.stall_prob = 0.3;
  const auto r = cosim::render_rtl(s, o);
  EXPECT_TRUE(r.ok()) << r.first_mismatch;
  size_t differ = 0;
  for (size_t i = 0; i < r.frame.pixels.size() && i < plain.pixels.size(); ++i)
    differ += !(r.frame.pixels[i].color == plain.pixels[i].color);
  EXPECT_GT(differ, afv / 4);
  o.stall_prob = 0;
  const auto r0 = cosim::render_rtl(s, o);
  EXPECT_TRUE(r0.ok()) << r0.first_mismatch;
  EXPECT_EQ(r0.cycles, r0.predicted_cycles);
  std::printf("af_visibility 32x24: %zu px, %zu through tu_afvis, %zu differ from plain EWA (C model); cycles measured "
              "%llu predicted %llu (%.1f per px)\n",
              r0.frame.pixels.size(), afv, differ, (unsigned long long)r0.cycles, (unsigned long long)r0.predicted_cycles,
              double(r0.cycles) / double(r0.frame.pixels.size()));
}

// What the unit cannot do is refused naming the field (exit 2 from the CLI): border weights with
// visibility, and the corridor unit (no visibility engine).
TEST(TextureUnitRtl, AfVisibilityRefusals) {
  auto s = scene::load(std::string(TU_SOURCE_DIR) + "/docs/scenes/af_visibility.json");
  s.camera.width = 8;
  s.camera.height = 6;
  cosim::RtlRenderOptions o;
  o.relief = true;
  auto clip = s;
  clip.materials.at("floor").clip = "mm_p1";
  try {
    cosim::render_rtl(clip, o);
    ADD_FAILURE() << "clip with af_visibility accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("/materials/floor/relief/af_visibility"), std::string::npos) << e.what();
  }
  o.corridor_unit = true;  // its other limits met: the 1-D weight table, iterative relief
  o.weights = scene::WeightSource::Table1d;
  for (auto& [n, m] : s.materials) m.relief->method = scene::ReliefMethod::Iterative;
  try {
    cosim::render_rtl(s, o);
    ADD_FAILURE() << "the corridor unit accepted af_visibility";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("relief/af_visibility: the corridor unit"), std::string::npos) << e.what();
  }
}
