// EWA engine and texture-unit top co-simulation (docs/blocks/ewa.md "RTL"). Cycles per pixel
// depend on the box and the levels tried, so the engine is not in the fixed-latency Cosim suite:
// 0 mismatches with 30 % stalls on golden/stiff/random (3,000 random here; scripts/cosim_full.sh
// ewa for the long run), the scoreboard catches a corrupted value, and the cycle model
// ewa::stream_cycles equals Verilator's count on stall-free streams (engine and full top).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <optional>

#include "cosim_checks.hpp"
#include "ewa/ewa_cycles.hpp"
#include "pom/relief.hpp"
#include "texture_unit_rtl.hpp"

namespace {
using namespace tu;

using cosim::checks::with_stalls;

TEST(EwaCosim, GoldenStiffRandomWithStalls) {
  cosim::checks::for_each_set_with_stalls(blocks::find("ewa"), [](const vec::VectorFile&, const cosim::Report&) {}, 3000);
}

TEST(EwaCosim, DetectsACorruptedExpectedValue) { cosim::checks::expect_corruption_detected("ewa"); }

// Per-pixel cycle costs of a vector file's rows (block "ewa": 256 x 256 texture, top level 8).
std::vector<ewa::PixelCost> costs_of(const vec::VectorFile& vf) {
  const auto in_idx = vf.indices(vec::Role::In), out_idx = vf.indices(vec::Role::Out);
  std::vector<ewa::PixelCost> c;
  for (const auto& row : vf.rows) {
    const auto in = blocks::pick(row, in_idx);
    const auto i = cosim::glue::in_ewa(in);
    const auto o = cosim::glue::out_ewa(blocks::pick(row, out_idx));
    ewa::fx::In px;
    px.b2.lod = static_cast<uint32_t>(i.lod);
    c.push_back(ewa::pixel_cost(px, static_cast<int>(o.level), static_cast<uint32_t>(o.flags), o.visited, 8));
    c.back().clip = i.clip != 0;
    c.back().blocks = blocks::ewa_lane_blocks(in);
  }
  return c;
}

TEST(EwaCosim, CyclesMatchPrediction) {
  for (const std::string set : {"golden", "stiff", "random"}) {
    const auto vf = blocks::generate(blocks::find("ewa"), set, 2000, 7);
    const auto rep = cosim::run(vf, with_stalls(0));
    cosim::checks::expect_stream_clean(rep);
    const uint64_t predicted = ewa::stream_cycles(costs_of(vf));
    std::printf("ewa %s: %zu px, cycles measured %llu predicted %llu (%.2f cycles/px)\n", set.c_str(),
                vf.rows.size(), (unsigned long long)rep.sim_cycles, (unsigned long long)predicted,
                double(rep.sim_cycles) / double(vf.rows.size()));
    EXPECT_EQ(rep.sim_cycles, predicted) << set;
  }
}

// The multi-texel engine (tu_ewa Lanes = 4, Setups = 2, border weights in: RTL "ewa_k4") on the
// block ewa's vectors: the same outputs with 30 % stalls, and stall-free cycles = ewa::stream_cycles
// with EngineParams lanes 4 (every pixel through the border pipeline's depth: lane_clip).
ewa::EngineParams lanes4_block_params() {
  ewa::EngineParams p;
  p.lanes = 4;
  p.setup_units = 2;
  p.lane_clip = true;  // Vtu_ewa_k4: HasClip = 1
  return p;
}

TEST(EwaCosim, Lanes4GoldenStiffRandomWithStalls) {
  cosim::checks::for_each_set_with_stalls(blocks::find("ewa"), [](const vec::VectorFile&, const cosim::Report&) {}, 3000,
                                          "ewa_k4");
}

TEST(EwaCosim, Lanes4CyclesMatchPrediction) {
  for (const std::string set : {"golden", "stiff", "random"}) {
    const auto vf = blocks::generate(blocks::find("ewa"), set, 2000, 7);
    auto opt = with_stalls(0);
    opt.rtl = "ewa_k4";
    const auto rep = cosim::run(vf, opt);
    cosim::checks::expect_stream_clean(rep);
    const auto costs = costs_of(vf);
    const uint64_t predicted = ewa::stream_cycles(costs, 0, lanes4_block_params());
    uint64_t box = 0, blk = 0;
    for (const auto& c : costs) box += c.box, blk += c.blocks;
    std::printf("ewa_k4 %s: %zu px, %.2f texels and %.2f 2x2 blocks per px, cycles measured %llu predicted %llu "
                "(%.2f cycles/px; K = 1: %llu)\n",
                set.c_str(), vf.rows.size(), double(box) / double(costs.size()), double(blk) / double(costs.size()),
                (unsigned long long)rep.sim_cycles, (unsigned long long)predicted,
                double(rep.sim_cycles) / double(vf.rows.size()), (unsigned long long)ewa::stream_cycles(costs));
    EXPECT_EQ(rep.sim_cycles, predicted) << set;
  }
}

// The bank ports' broadcast and border routing on the RTL: the multi-texel engine with a 64 x 16
// texture (levels 4 x 1, 2 x 1, 1 x 1: lanes folding onto one texel along y, then both axes) in
// each wrap mode, the block ewa's golden, stiff and 1,000 random inputs, 30 % stalls: every output
// equals the C model's with that texture (the sequential walk's).
TEST(EwaCosim, Lanes4WrapModesAndThinLevels) {
  img::Rgba8Image im(64, 16);
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x)
      im.at(x, y) = {static_cast<uint8_t>(x * 37 + y * 11), static_cast<uint8_t>(x * 5 + y * 53),
                     static_cast<uint8_t>((x ^ y) * 29), static_cast<uint8_t>(255 - x - y)};
  const auto& b = blocks::find("ewa");
  std::vector<cosim::Row> rows;
  for (const std::string set : {"golden", "stiff", "random"})
    for (const auto& r : b.inputs(set, 1000, 5)) rows.push_back(r);
  for (auto w : {tex::Wrap::Repeat, tex::Wrap::Mirror, tex::Wrap::Clamp, tex::Wrap::Border, tex::Wrap::MirrorOnce}) {
    const auto t = tex::Texture::build("thin", im, tex::Addressing{w, w == tex::Wrap::Border ? tex::Wrap::Clamp : w,
                                                                    {10, 20, 30, 40}});
    cosim::RunOptions ro;
    ro.stall_prob = 0.3;
    ro.seed = 3;
    const auto rr = cosim::rtl_ewa_k4_with(t).run(rows, ro);
    SCOPED_TRACE(static_cast<int>(w));
    ASSERT_FALSE(rr.hung);
    ASSERT_EQ(rr.outputs.size(), rows.size());
    EXPECT_EQ(rr.extra_outputs, 0u);
    size_t bad = 0;
    for (size_t i = 0; i < rows.size(); ++i)
      if (rr.outputs[i] != blocks::ewa_model_with(rows[i], t) && bad++ < 3) ADD_FAILURE() << "row " << i;
    EXPECT_EQ(bad, 0u);
  }
}

// The default scene at 64 x 48 pixels (same geometry, fewer pixels: seconds of simulation).
scene::Scene small_scene() {
  auto s = scene::default_scene();
  s.camera.width = 64;
  s.camera.height = 48;
  return s;
}

TEST(TextureUnitRtl, SmallSceneEqualsCModelWithStalls) {
  const auto s = small_scene();
  for (auto w : {scene::WeightSource::Formula, scene::WeightSource::Table1d, scene::WeightSource::Table2d}) {
    cosim::RtlRenderOptions o;
    o.weights = w;
    o.stall_prob = 0.3;
    const auto r = cosim::render_rtl(s, o);
    EXPECT_TRUE(r.ok()) << r.first_mismatch;
    EXPECT_EQ(r.mismatches, 0u) << r.first_mismatch;
    EXPECT_GT(r.frame.pixels.size(), 1000u);
    std::printf("texture unit %s: %zu px in %llu spans, %llu mismatches\n", scene::to_string(w),
                r.frame.pixels.size(), (unsigned long long)r.spans, (unsigned long long)r.mismatches);
  }
}

TEST(TextureUnitRtl, CyclesMatchPrediction) {
  const auto r = cosim::render_rtl(small_scene());
  EXPECT_TRUE(r.ok()) << r.first_mismatch;
  std::printf("texture unit: %zu px, cycles measured %llu predicted %llu (%.2f cycles/px)\n",
              r.frame.pixels.size(), (unsigned long long)r.cycles, (unsigned long long)r.predicted_cycles,
              double(r.cycles) / double(r.frame.pixels.size()));
  EXPECT_EQ(r.cycles, r.predicted_cycles);
}

TEST(TextureUnitRtl, BilinearOnlyTopEqualsCModelWithStalls) {
  cosim::RtlRenderOptions o;
  o.has_ewa = false;
  o.filter = scene::Filter::Bilinear;
  o.stall_prob = 0.3;
  const auto r = cosim::render_rtl(small_scene(), o);
  EXPECT_TRUE(r.ok()) << r.first_mismatch;
  EXPECT_GT(r.frame.pixels.size(), 1000u);
  o.stall_prob = 0;
  const auto q = cosim::render_rtl(small_scene(), o);
  EXPECT_TRUE(q.ok()) << q.first_mismatch;
  EXPECT_EQ(q.cycles, q.predicted_cycles);
  // The bilinear-only unit cannot take an EWA material: a message naming it, no render.
  o.filter.reset();
  try {
    cosim::render_rtl(small_scene(), o);
    ADD_FAILURE() << "EWA material accepted by the bilinear-only unit";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("/materials/ground/filter: ewa, but the unit is bilinear-only"), std::string::npos)
        << e.what();
  }
}

// Per-material filters on the full unit: ground bilinear, wall EWA. The engines take turns at
// material changes; cycles = ewa::stream_cycles with the drain rule; 30% stalls lose nothing.
TEST(TextureUnitRtl, MixedFiltersPerSpan) {
  auto s = small_scene();
  s.materials.at("ground").filter = scene::Filter::Bilinear;
  cosim::RtlRenderOptions o;
  const auto r = cosim::render_rtl(s, o);
  EXPECT_TRUE(r.ok()) << r.first_mismatch;
  EXPECT_EQ(r.cycles, r.predicted_cycles);
  o.stall_prob = 0.3;
  const auto q = cosim::render_rtl(s, o);
  EXPECT_TRUE(q.ok()) << q.first_mismatch;
  // Both engines were used: the ground's pixels report bilinear's four texels, the wall's EWA's.
  size_t bil = 0, ewa = 0;
  for (const auto& p : r.frame.pixels) (p.object == 0 ? bil : ewa) += 1;
  EXPECT_GT(bil, 500u);
  EXPECT_GT(ewa, 100u);
  std::printf("mixed: %zu bilinear + %zu EWA px, cycles %llu = predicted %llu\n", bil, ewa,
              (unsigned long long)r.cycles, (unsigned long long)r.predicted_cycles);
}

// One engine on every span (30% stalls, then stall-free: cycles = ewa::stream_cycles), then the
// ground and the wall on two engines taking turns (stall-free, cycles = ewa::stream_cycles); every
// pixel == the C model.
// Renders s with 30 % stalls (every pixel == the C model) and without (also cycles = predicted);
// returns the stall-free render.
cosim::RtlRender render_checked(const scene::Scene& s, cosim::RtlRenderOptions o) {
  o.stall_prob = 0.3;
  const auto r = cosim::render_rtl(s, o);
  EXPECT_TRUE(r.ok()) << r.first_mismatch;
  o.stall_prob = 0;
  auto q = cosim::render_rtl(s, o);
  EXPECT_TRUE(q.ok()) << q.first_mismatch;
  EXPECT_EQ(q.cycles, q.predicted_cycles);
  return q;
}

void check_engine(scene::Filter every, scene::Filter ground, scene::Filter wall) {
  auto s = small_scene();
  cosim::RtlRenderOptions o;
  o.filter = every;
  const auto q = render_checked(s, o);
  s.materials.at("ground").filter = ground;
  s.materials.at("wall").filter = wall;
  o.filter.reset();
  const auto m = cosim::render_rtl(s, o);
  EXPECT_TRUE(m.ok()) << m.first_mismatch;
  EXPECT_EQ(m.cycles, m.predicted_cycles);
  std::printf("%s: %zu px, %llu cycles = predicted %llu; ground %s + wall %s: %llu = %llu\n", scene::to_string(every),
              q.frame.pixels.size(), (unsigned long long)q.cycles, (unsigned long long)q.predicted_cycles,
              scene::to_string(ground), scene::to_string(wall), (unsigned long long)m.cycles,
              (unsigned long long)m.predicted_cycles);
}

// tu_trilinear (tu_bilinear at floor(lod) and the next level, blended by the lod's fraction) ==
// tex::trilinear; with EWA taking turns.
TEST(TextureUnitRtl, TrilinearEqualsCModel) {
  check_engine(scene::Filter::Trilinear, scene::Filter::Trilinear, scene::Filter::Ewa);
}

// Trilinear's GL LOD rule with a material's bias and [min lod, max lod] (tu_ellipse tlod) ==
// tex::trilinear_lod: bias 1.25 / [0.5, 3] on the ground, -0.75 / [0, 12] on the wall.
TEST(TextureUnitRtl, TrilinearLodBiasAndClampEqualCModel) {
  auto s = small_scene();
  s.materials.at("ground").lod_bias = 1.25;
  s.materials.at("ground").min_lod = 0.5;
  s.materials.at("ground").max_lod = 3;
  s.materials.at("wall").lod_bias = -0.75;
  cosim::RtlRenderOptions o;
  o.filter = scene::Filter::Trilinear;
  const auto q = render_checked(s, o);
  // The bias and clamps change the picture.
  const auto plain = cosim::render_rtl(small_scene(), o);
  size_t differ = 0;
  for (size_t i = 0; i < q.frame.pixels.size(); ++i) differ += !(q.frame.pixels[i].color == plain.frame.pixels[i].color);
  EXPECT_GT(differ, 500u);
  std::printf("biased trilinear: %zu px, %zu differ from the default rule, %llu cycles = predicted %llu\n",
              q.frame.pixels.size(), differ, (unsigned long long)q.cycles, (unsigned long long)q.predicted_cycles);
}

// The recurrence ellipse (EllRecurrence = 1: tu_ellipse_rec, fed by the span walk's q + G, q + H
// registers) renders the small scene equal to the C model (fx::recurrence): EWA without stalls
// with cycles as predicted (its latency sets the front), trilinear with 30 % stalls (the LOD of
// both engines comes from B2).
TEST(TextureUnitRtl, RecurrenceEllipseEqualsCModel) {
  auto s = small_scene();
  s.footprint = scene::Footprint::Recurrence;
  for (auto f : {scene::Filter::Ewa, scene::Filter::Trilinear}) {
    cosim::RtlRenderOptions o;
    o.filter = f;
    o.stall_prob = f == scene::Filter::Ewa ? 0 : 0.3;
    const auto r = cosim::render_rtl(s, o);
    EXPECT_TRUE(r.ok()) << r.first_mismatch;
    EXPECT_GT(r.frame.pixels.size(), 1000u);
    if (o.stall_prob == 0) EXPECT_EQ(r.cycles, r.predicted_cycles);
    std::printf("recurrence ellipse, %s, stalls %.1f: %zu px, %llu mismatches, cycles %llu (predicted %llu)\n",
                scene::to_string(f), o.stall_prob, r.frame.pixels.size(), (unsigned long long)r.mismatches,
                (unsigned long long)r.cycles, (unsigned long long)r.predicted_cycles);
  }
  cosim::RtlRenderOptions bil;
  bil.has_ewa = false;
  bil.filter = scene::Filter::Bilinear;
  EXPECT_THROW(cosim::render_rtl(s, bil), std::invalid_argument);  // the bilinear-only unit is analytic
}

// tu_nearest == tex::nearest; with trilinear taking turns (two short engines).
TEST(TextureUnitRtl, NearestEqualsCModel) {
  check_engine(scene::Filter::Nearest, scene::Filter::Nearest, scene::Filter::Trilinear);
}

// The default scene with its relief (wall: adaptive POM, 32 layers) through the full unit's
// relief stage: every pixel == render_cmodel with relief (colour, shifted uv's filter result,
// layers used), 30% stalls; the wall's pixels are really shifted (layers > 0).
TEST(TextureUnitRtl, ReliefSceneEqualsCModelWithStalls) {
  const auto s = small_scene();
  cosim::RtlRenderOptions o;
  o.relief = true;
  o.stall_prob = 0.3;
  const auto r = cosim::render_rtl(s, o);
  EXPECT_TRUE(r.ok()) << r.first_mismatch;
  size_t shifted = 0;
  for (const auto& p : r.frame.pixels) shifted += p.relief_n > 0;
  EXPECT_GT(shifted, 300u);
  // Relief changes the picture: the same unit without it differs on the wall.
  o.relief = false;
  const auto flat = cosim::render_rtl(s, o);
  size_t differ = 0;
  for (size_t i = 0; i < r.frame.pixels.size(); ++i) differ += !(r.frame.pixels[i].color == flat.frame.pixels[i].color);
  EXPECT_GT(differ, 100u);
  std::printf("relief: %zu px, %zu shifted, %zu differ from the flat render, %llu cycles (30%% stalls)\n",
              r.frame.pixels.size(), shifted, differ, (unsigned long long)r.cycles);
  // Without stalls the cycles are those of the unit's cycle model (front, relief stage, filter).
  o.relief = true;
  o.stall_prob = 0;
  const auto r0 = cosim::render_rtl(s, o);
  EXPECT_TRUE(r0.ok()) << r0.first_mismatch;
  std::printf("relief (pom_adaptive 32): cycles measured %llu predicted %llu\n", (unsigned long long)r0.cycles,
              (unsigned long long)r0.predicted_cycles);
  EXPECT_EQ(r0.cycles, r0.predicted_cycles);
}

// Iterative parallax (seed 002) through the relief stage's iterative engine: the default scene's
// wall with iterative relief (cap 8 and 32), every pixel == render_cmodel (colour, layers, steps,
// relief flags incl. non-convergence), 30 % stalls; without stalls the cycles are predicted.
TEST(TextureUnitRtl, IterativeReliefSceneEqualsCModelWithCyclesPredicted) {
  auto s = small_scene();
  s.materials.at("wall").relief->method = scene::ReliefMethod::Iterative;
  for (int cap : {8, 32}) {
    s.materials.at("wall").relief->layers = cap;
    cosim::RtlRenderOptions o;
    o.relief = true;
    o.stall_prob = 0.3;
    const auto r = cosim::render_rtl(s, o);
    EXPECT_TRUE(r.ok()) << r.first_mismatch;
    size_t shifted = 0, nonconv = 0, steps = 0;
    for (const auto& p : r.frame.pixels) {
      shifted += p.relief_n > 0;
      steps += static_cast<size_t>(p.relief_steps);
      nonconv += (p.relief_flags & relief::kReliefNonConv) != 0;
    }
    EXPECT_GT(shifted, 300u);
    EXPECT_GT(nonconv, 0u);  // the flag reaches the unit's output
    o.stall_prob = 0;
    const auto r0 = cosim::render_rtl(s, o);
    EXPECT_TRUE(r0.ok()) << r0.first_mismatch;
    EXPECT_EQ(r0.cycles, r0.predicted_cycles);
    std::printf("iterative cap %d: %zu px, %zu shifted (%.2f iterations each), %zu non-converged; cycles measured "
                "%llu predicted %llu\n",
                cap, r.frame.pixels.size(), shifted, double(steps) / double(std::max<size_t>(1, shifted)), nonconv,
                (unsigned long long)r0.cycles, (unsigned long long)r0.predicted_cycles);
  }
}

// Distance-map relief (seed 003 §7) through the relief stage's tracer (tu_dm_trace): the default
// scene's wall with method distance_map / distance_map_refined (a 64-texel bricks map, 16 map
// layers, cap 32), every pixel == render_cmodel (colour, cap, map steps + finish reads, flags), 30 %
// stalls (the classic map; the refined one runs the same RTL on other codes: without stalls only);
// without stalls the cycles are predicted (ewa::texture_unit_cycles).
TEST(TextureUnitRtl, DistanceMapReliefSceneEqualsCModelWithCyclesPredicted) {
  auto s = small_scene();
  s.textures.at("bricks").size = 64;  // the map (64 x 64 x 16) and the colour texture
  for (auto method : {scene::ReliefMethod::DistanceMap, scene::ReliefMethod::DistanceMapRefined}) {
    s.materials.at("wall").relief->method = method;
    cosim::RtlRenderOptions o;
    o.relief = true;
    if (method == scene::ReliefMethod::DistanceMap) {
      o.stall_prob = 0.3;
      const auto r = cosim::render_rtl(s, o);
      EXPECT_TRUE(r.ok()) << r.first_mismatch;
    }
    o.stall_prob = 0;
    const auto r0 = cosim::render_rtl(s, o);
    EXPECT_TRUE(r0.ok()) << r0.first_mismatch;
    size_t shifted = 0, steps = 0;
    for (const auto& p : r0.frame.pixels) {
      shifted += p.relief_n > 0;
      steps += static_cast<size_t>(p.relief_steps);
    }
    EXPECT_GT(shifted, 300u);
    EXPECT_EQ(r0.cycles, r0.predicted_cycles);
    std::printf("%s cap 32: %zu px, %zu shifted (%.2f map steps + finish reads each); cycles measured %llu "
                "predicted %llu\n",
                scene::to_string(method), r0.frame.pixels.size(), shifted, double(steps) / double(std::max<size_t>(1, shifted)),
                (unsigned long long)r0.cycles, (unsigned long long)r0.predicted_cycles);
  }
}

// EWA sub-texel border weights in the walk (tu_ewa_border, HasEwaClip, EwaClipVariant 0 = mm_p1;
// docs/blocks/ewa.md "Border weights"): the small scene with border weights on every material, and
// with them on the ground only (pixels with and without, the drain differs per pixel), every pixel
// == render_cmodel with 30 % stalls, and stall-free cycles = ewa::texture_unit_cycles; the grown box
// walks more texels than the plain render. A variant the unit does not have, or the corridor unit
// (no border weights), is refused naming the material's field.
TEST(TextureUnitRtl, BorderWeightsEqualCModelWithCyclesPredicted) {
  const auto plain = cosim::render_rtl(small_scene(), {});
  EXPECT_TRUE(plain.ok()) << plain.first_mismatch;
  auto texels = [](const cosim::RtlRender& r) {
    uint64_t t = 0;
    for (const auto& p : r.frame.pixels) t += static_cast<uint64_t>(p.texels);
    return t;
  };
  const auto every = render_checked(scene::with_clip(small_scene(), "mm_p1"), {});
  auto ground = small_scene();
  ground.materials.at("ground").clip = "mm_p1";
  const auto some = render_checked(ground, {});
  EXPECT_GT(texels(every), texels(some));
  EXPECT_GT(texels(some), texels(plain));
  EXPECT_GT(every.cycles, some.cycles);
  std::printf("border weights (mm_p1): every material %zu px, %.2f texels/px, %llu cycles = predicted %llu; ground only "
              "%llu = %llu; off: %.2f texels/px, %llu cycles\n",
              every.frame.pixels.size(), double(texels(every)) / double(every.frame.pixels.size()),
              (unsigned long long)every.cycles, (unsigned long long)every.predicted_cycles,
              (unsigned long long)some.cycles, (unsigned long long)some.predicted_cycles,
              double(texels(plain)) / double(plain.frame.pixels.size()), (unsigned long long)plain.cycles);
  for (const auto& [v, corridor] : {std::pair{"mm_p3", false}, {"mm_p1", true}}) {
    cosim::RtlRenderOptions o;
    o.corridor_unit = corridor;
    if (corridor) o.filter = scene::Filter::Ewa, o.weights = scene::WeightSource::Table1d;  // what it has
    try {
      cosim::render_rtl(scene::with_clip(small_scene(), v), o);
      ADD_FAILURE() << v << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("/materials/ground/clip: " + std::string(v) + ", but the"), std::string::npos)
          << e.what();
    }
  }
}

// The other clip volumes of the border weights (EwaClipVariant 1 = mm_p3 Horner, 2 = mm_p3 Estrin,
// ewa::kRtlClipVariants): every pixel == render_cmodel with 30 % stalls, stall-free cycles =
// ewa::texture_unit_cycles with their longer border pipelines. Their units are verilated only with
// -DTU_COSIM_CLIP_VARIANTS=ON (scripts/cosim_clip_variants.sh); without, render_rtl refuses them
// by name instead of running the mm_p1 unit.
TEST(TextureUnitRtl, ClipVariantsEqualCModel) {
  for (const char* v : {"mm_p3", "mm_p3_estrin"}) {
    cosim::RtlRenderOptions o;
    o.clip_variant = v;
    const auto s = scene::with_clip(small_scene(), v);
#if TU_COSIM_CLIP_VARIANTS
    const auto q = render_checked(s, o);
    std::printf("border weights (%s, EwaClipVariant %d, border latency %d): %zu px, %llu cycles = predicted %llu\n", v,
                ewa::rtl_clip_code(v), ewa::border_latency(ewa::rtl_clip_code(v)), q.frame.pixels.size(),
                (unsigned long long)q.cycles, (unsigned long long)q.predicted_cycles);
#else
    try {
      cosim::render_rtl(s, o);
      ADD_FAILURE() << v << " ran on the mm_p1 unit";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("clip volume " + std::string(v) + " (EwaClipVariant"), std::string::npos)
          << e.what();
    }
#endif
  }
}

// docs/scenes/corridor.json on its planned unit (`texunit plan docs/scenes/corridor.json`: EWA with
// the 1-D weight table on every material, iterative parallax, no POM march;
// Vtu_texture_unit_corridor): every pixel ==
// render_cmodel with the walls' iterative relief, with 30 % stalls and without (cycles predicted).
TEST(TextureUnitRtl, CorridorPlannedUnitEqualsCModelWithCyclesPredicted) {
  const auto s = scene::load(std::string(TU_SOURCE_DIR) + "/docs/scenes/corridor.json");
  cosim::RtlRenderOptions o;
  o.corridor_unit = true;
  o.filter = scene::Filter::Ewa;  // the plan's filter and weight source on every material
  o.weights = scene::WeightSource::Table1d;
  o.relief = true;
  o.stall_prob = 0.3;
  const auto r = cosim::render_rtl(s, o);
  EXPECT_TRUE(r.ok()) << r.first_mismatch;
  size_t shifted = 0, nonconv = 0;
  for (const auto& p : r.frame.pixels) {
    shifted += p.relief_n > 0;
    nonconv += (p.relief_flags & relief::kReliefNonConv) != 0;
  }
  EXPECT_GT(shifted, 1000u);
  o.stall_prob = 0;
  const auto r0 = cosim::render_rtl(s, o);
  EXPECT_TRUE(r0.ok()) << r0.first_mismatch;
  EXPECT_EQ(r0.cycles, r0.predicted_cycles);
  std::printf("corridor, planned unit: %zu px, %zu shifted, %zu non-converged, cycles measured %llu predicted %llu\n",
              r.frame.pixels.size(), shifted, nonconv, (unsigned long long)r0.cycles,
              (unsigned long long)r0.predicted_cycles);
  // A material the planned unit has no engine for is refused, naming the field.
  o.filter.reset();  // the authored trilinear ceiling
  EXPECT_THROW(cosim::render_rtl(s, o), std::invalid_argument);
}

// Issue 23's goal: the default scene's EWA (texture path, the corridor unit's 1-D weight table) on
// the K = 4 engine (tu_ewa_walk_lanes, three set-up units) in <= 20 clocks per pixel, every pixel
// equal to the C model's sequential walk, stall-free cycles = ewa::texture_unit_cycles. The same
// frame on the one-texel walk costs 64.3 clocks per pixel (docs/blocks/ewa.md).
TEST(TextureUnitRtl, DefaultSceneOnTheFourLaneEngineWithinTwentyClocksPerPixel) {
  cosim::RtlRenderOptions o;
  o.corridor_unit = true;
  o.filter = scene::Filter::Ewa;
  o.weights = scene::WeightSource::Table1d;
  const auto r = cosim::render_rtl(scene::default_scene(), o);
  ASSERT_TRUE(r.ok()) << r.first_mismatch;
  EXPECT_EQ(r.cycles, r.predicted_cycles);
  const double per_px = double(r.cycles) / double(r.frame.pixels.size());
  std::printf("default scene, K = 4 EWA (3 set-up units): %zu px, %llu cycles = predicted %llu, %.2f clocks/px\n",
              r.frame.pixels.size(), (unsigned long long)r.cycles, (unsigned long long)r.predicted_cycles, per_px);
  EXPECT_LE(per_px, 20.0);
}

// docs/scenes/ui_quad.json (no relief, no minification): `texunit plan` writes a bilinear-only
// unit without relief hardware (HasEwa = 0, HasRelief = 0; TexunitCli.plan_ui_quad, and the Yosys
// cells drop: TexunitCli.plan_area_ui_quad). That unit renders the scene bit-exactly as the full
// unit (EWA, bilinear and relief stage in) does with the plan's filter on every span.
TEST(TextureUnitRtl, SpecialisedUnitRendersSceneWithoutReliefAsTheFullUnit) {
  const auto s = scene::load(std::string(TU_SOURCE_DIR) + "/docs/scenes/ui_quad.json");
  cosim::RtlRenderOptions full, spec;
  full.filter = spec.filter = scene::Filter::Bilinear;
  full.relief = true;  // the scene has none: the stage passes every pixel through
  spec.has_ewa = false;
  const auto a = cosim::render_rtl(s, full), b = cosim::render_rtl(s, spec);
  EXPECT_TRUE(a.ok()) << a.first_mismatch;
  EXPECT_TRUE(b.ok()) << b.first_mismatch;
  ASSERT_EQ(a.frame.pixels.size(), b.frame.pixels.size());
  EXPECT_GT(a.frame.pixels.size(), 5000u);
  size_t differ = 0;
  for (size_t i = 0; i < a.frame.pixels.size(); ++i)
    differ += !(a.frame.pixels[i].color == b.frame.pixels[i].color && a.frame.pixels[i].x == b.frame.pixels[i].x &&
                a.frame.pixels[i].y == b.frame.pixels[i].y);
  EXPECT_EQ(differ, 0u);
  std::printf("ui_quad: %zu px, full unit %llu cycles, specialised %llu cycles\n", a.frame.pixels.size(),
              (unsigned long long)a.cycles, (unsigned long long)b.cycles);
}

// docs/scenes/wrap_modes.json: one quad per wrap mode (repeat, mirror, clamp, border, mirror once,
// and border along u with mirror along v), uv over [-1, 2], each material on another engine (EWA,
// trilinear, bilinear, nearest): every pixel == the C model without stalls (cycles as predicted)
// and with 30 % stalls, then every engine on every mode (--filter). The border colour shows.
TEST(TextureUnitRtl, WrapModesSceneEqualsCModelCyclesPredicted) {
  const auto s = scene::load(std::string(TU_SOURCE_DIR) + "/docs/scenes/wrap_modes.json");
  std::vector<std::optional<scene::Filter>> filters = {std::nullopt, scene::Filter::Ewa, scene::Filter::Trilinear,
                                                       scene::Filter::Bilinear, scene::Filter::Nearest};
  for (const auto& f : filters)
    for (double stall : {0.0, 0.3}) {
      if (f && stall == 0) continue;
      cosim::RtlRenderOptions o;
      o.filter = f;
      o.stall_prob = stall;
      const auto r = cosim::render_rtl(s, o);
      EXPECT_TRUE(r.ok()) << r.first_mismatch;
      EXPECT_GT(r.frame.pixels.size(), 2000u);
      if (stall == 0) EXPECT_EQ(r.cycles, r.predicted_cycles);
      size_t border = 0;  // the border quad's magenta, unfiltered (beyond the edge)
      for (const auto& p : r.frame.pixels) border += p.color == img::Rgba8{255, 0, 255, 255};
      if (!f || *f == scene::Filter::Nearest) EXPECT_GT(border, 50u);
      std::printf("wrap modes, %s, stalls %.1f: %zu px, %llu mismatches, %zu border px, cycles %llu (predicted %llu)\n",
                  f ? scene::to_string(*f) : "as authored", stall, r.frame.pixels.size(),
                  (unsigned long long)r.mismatches, border, (unsigned long long)r.cycles,
                  (unsigned long long)r.predicted_cycles);
    }
}

// Sampler LOD state (docs/blocks/texture.md "LOD state"): docs/scenes/lod_state.json, one floor
// strip per material with non-default lod_bias / min_lod / max_lod / base_level / max_level and
// the stiff states (min_lod > max_lod, bias +-16, base_level > max_level), through every engine
// of the top: pixels = C model, cycles = ewa::stream_cycles; the states' documented levels.
TEST(TextureUnitRtl, LodStateSceneEqualsCModelCyclesPredicted) {
  auto s = scene::load(std::string(TU_SOURCE_DIR) + "/docs/scenes/lod_state.json");
  std::vector<std::optional<scene::Filter>> filters = {std::nullopt, scene::Filter::Ewa, scene::Filter::Trilinear,
                                                       scene::Filter::Bilinear, scene::Filter::Nearest};
  for (const auto& f : filters)
    for (double stall : {0.0, 0.3}) {
      if (f && stall > 0) continue;
      cosim::RtlRenderOptions o;
      o.filter = f;
      o.stall_prob = stall;
      const auto r = cosim::render_rtl(s, o);
      EXPECT_TRUE(r.ok()) << r.first_mismatch;
      EXPECT_GT(r.frame.pixels.size(), 2000u);
      if (stall == 0) EXPECT_EQ(r.cycles, r.predicted_cycles);
      std::printf("lod state, %s, stalls %.1f: %zu px, %llu mismatches, cycles %llu (predicted %llu)\n",
                  f ? scene::to_string(*f) : "as authored", stall, r.frame.pixels.size(),
                  (unsigned long long)r.mismatches, (unsigned long long)r.cycles, (unsigned long long)r.predicted_cycles);
    }
  // The documented levels of each state (C model = RTL above).
  const auto c = render::render_cmodel(s, std::nullopt, render::texture_path_only());
  std::map<std::string, std::pair<double, double>> range;  // material -> min, max lod
  for (const auto& p : c.pixels) {
    const std::string& m = s.objects[static_cast<size_t>(p.object)].material;
    auto [it, fresh] = range.try_emplace(m, p.lod, p.lod);
    it->second.first = std::min(it->second.first, p.lod), it->second.second = std::max(it->second.second, p.lod);
  }
  EXPECT_EQ(range.at("tri_stiff"), std::make_pair(2.5, 2.5));   // min_lod > max_lod: min_lod wins
  EXPECT_EQ(range.at("ewa_stiff"), std::make_pair(5.0, 5.0));   // base 5 > max 2: level 5 alone
  EXPECT_GE(range.at("tri_bias").first, 1.5);                   // base 1 + min_lod 0.5
  EXPECT_LE(range.at("tri_bias").second, 4.5);                  // base 1 + max_lod 3.5 (< max_level 5)
  EXPECT_GE(range.at("ewa_base").first, 2.0);                   // never below the base level
  for (const auto& [m, r] : range) std::printf("  %s: lod %.3f .. %.3f\n", m.c_str(), r.first, r.second);
  // The state changes the picture: with every field at its default, most pixels differ.
  auto plain = s;
  for (auto& [name, m] : plain.materials) m.lod_bias = 0, m.min_lod = 0, m.max_lod = 12, m.base_level = 0, m.max_level = 1000;
  const auto d = render::render_cmodel(plain, std::nullopt, render::texture_path_only());
  ASSERT_EQ(d.pixels.size(), c.pixels.size());
  size_t differ = 0;
  for (size_t i = 0; i < c.pixels.size(); ++i) differ += !(c.pixels[i].color == d.pixels[i].color);
  std::printf("  %zu of %zu px differ from the default state\n", differ, c.pixels.size());
  EXPECT_GT(differ, c.pixels.size() / 2);
  // The recurrence footprint unit applies the same rule.
  s.footprint = scene::Footprint::Recurrence;
  const auto rr = cosim::render_rtl(s, {});
  EXPECT_TRUE(rr.ok()) << rr.first_mismatch;
  EXPECT_EQ(rr.cycles, rr.predicted_cycles);
}
}  // namespace

// The shading stage (docs/blocks/brdf.md §6): the docs' shaded sphere (one point light, vertex
// normals, F_MSH highlight) through the full unit equals the C model on every pixel, cycles as
// predicted (the stage's latency added once), and with 30% stalls on both sides; a material
// naming another model than the unit's, or a light on the unit without the stage, is refused.
TEST(TextureUnitRtl, ShadedSphereEqualsCModelCyclesPredicted) {
  const auto s = scene::load(std::string(TU_SOURCE_DIR) + "/docs/scenes/shaded_sphere.json");
  ASSERT_FALSE(s.lights.empty());
  cosim::RtlRenderOptions o;
  const auto r = cosim::render_rtl(s, o);
  EXPECT_TRUE(r.ok()) << r.first_mismatch;
  EXPECT_GT(r.frame.pixels.size(), 3000u);
  EXPECT_EQ(r.cycles, r.predicted_cycles);
  // Shading changed the picture: the unshaded C model differs on most pixels.
  auto dark = s;
  dark.lights.clear();
  const auto plain = render::render_cmodel(dark, std::nullopt, render::texture_path_only());
  size_t differ = 0;
  for (size_t i = 0; i < plain.pixels.size() && i < r.frame.pixels.size(); ++i)
    differ += !(plain.pixels[i].color == r.frame.pixels[i].color);
  EXPECT_GT(differ, r.frame.pixels.size() / 2);
  std::printf("shaded sphere: %zu px, %zu shaded differently from the texture, cycles %llu predicted %llu\n",
              r.frame.pixels.size(), differ, (unsigned long long)r.cycles, (unsigned long long)r.predicted_cycles);
  o.stall_prob = 0.3;
  const auto q = cosim::render_rtl(s, o);
  EXPECT_TRUE(q.ok()) << q.first_mismatch;
  auto pinned = s;
  pinned.materials.at("ball").specular->model = "blinn";
  EXPECT_THROW(cosim::render_rtl(pinned, {}), std::invalid_argument);
  cosim::RtlRenderOptions bil;
  bil.has_ewa = false;
  bil.filter = scene::Filter::Bilinear;
  EXPECT_THROW(cosim::render_rtl(s, bil), std::invalid_argument);
}

namespace {
// A scene through the Verilated unit: RTL = C model on every pixel, without and with 30 % stalls,
// clocks without stalls = the prediction; returns the clocks.
uint64_t expect_rtl_equals_cmodel(const scene::Scene& s, const char* what, size_t min_pixels) {
  const auto r = cosim::render_rtl(s, {});
  EXPECT_TRUE(r.ok()) << what << ": " << r.first_mismatch;
  EXPECT_GT(r.frame.pixels.size(), min_pixels) << what;
  EXPECT_EQ(r.cycles, r.predicted_cycles) << what;
  std::printf("%s: %zu px, cycles measured %llu predicted %llu\n", what, r.frame.pixels.size(),
              (unsigned long long)r.cycles, (unsigned long long)r.predicted_cycles);
  cosim::RtlRenderOptions o;
  o.stall_prob = 0.3;
  const auto q = cosim::render_rtl(s, o);
  EXPECT_TRUE(q.ok()) << what << " with stalls: " << q.first_mismatch;
  EXPECT_EQ(q.mismatches, 0u) << q.first_mismatch;
  return r.cycles;
}
}  // namespace

// The noise unit in the top (docs/blocks/noise-appendix.md §5 "In the RTL unit"): docs/scenes/procedural.json
// at 64 x 48 (fbm ground, smoke wall), then with time, fewer octaves and no footprint limit, then
// with the wall textured (engine turns between the noise unit and EWA): RTL = C model on every
// pixel with 30 % stalls, cycles = ewa::texture_unit_cycles without.
TEST(TextureUnitRtl, ProceduralSceneEqualsCModelCyclesPredicted) {
  auto s = scene::load(std::string(TU_SOURCE_DIR) + "/docs/scenes/procedural.json");
  s.camera.width = 64;
  s.camera.height = 48;
  auto timed = s;
  timed.materials.at("smoke").procedural->time = 1.3;
  timed.materials.at("marble").procedural->octaves = 3;
  timed.materials.at("marble").procedural->footprint_limit = false;
  auto mixed = s;
  mixed.materials.at("smoke").procedural.reset();
  for (const auto* sc : {&s, &timed, &mixed}) expect_rtl_equals_cmodel(*sc, "procedural", 1000);
  // The bilinear-only unit has no noise unit.
  cosim::RtlRenderOptions bil;
  bil.has_ewa = false;
  bil.filter = scene::Filter::Bilinear;
  EXPECT_THROW(cosim::render_rtl(s, bil), std::invalid_argument);
}

// Water in the noise unit (docs/blocks/noise-appendix.md §5 "Water on the RTL"): docs/scenes/water.json at
// 48 x 36 (three octave sums per pixel, normal, square root, divide), at the amplitude's largest
// code without the footprint limit (steepest normals), and docs/scenes/procedural.json with its
// smoke wall as water (turns between fbm and water pixels in the noise unit): RTL = C model on
// every pixel with 30 % stalls, cycles = ewa::texture_unit_cycles without.
TEST(TextureUnitRtl, WaterEqualsCModelCyclesPredicted) {
  auto water = scene::load(std::string(TU_SOURCE_DIR) + "/docs/scenes/water.json");
  water.camera.width = 48;
  water.camera.height = 36;
  auto steep = water;
  steep.materials.at("water").procedural->amplitude = 31.99;
  steep.materials.at("water").procedural->footprint_limit = false;
  auto mixed = scene::load(std::string(TU_SOURCE_DIR) + "/docs/scenes/procedural.json");
  mixed.camera.width = 48;
  mixed.camera.height = 36;
  mixed.materials.at("smoke").procedural->kind = scene::ProceduralKind::Water;
  expect_rtl_equals_cmodel(water, "water", 500);
  expect_rtl_equals_cmodel(steep, "water, a = 31.99, all octaves", 500);
  expect_rtl_equals_cmodel(mixed, "fbm ground, water wall", 500);
}

// The octave-serial noise unit (NoiseScheme = 1: one core, NoiseOctaves clocks per octave sum, the
// recurrence-ellipse model Vtu_texture_unit_rec carries it): docs/scenes/procedural.json at
// 40 x 30 with the smoke wall as water, fbm, smoke and water pixels, the same bits as the C model
// (the pipelined unit's) on every pixel with 30 % stalls, cycles = ewa::stream_cycles with
// noise_slots = 4 (II 4 per sum, 12 per water pixel) without.
TEST(TextureUnitRtl, OctaveSerialNoiseUnitEqualsCModelCyclesPredicted) {
  auto s = scene::load(std::string(TU_SOURCE_DIR) + "/docs/scenes/procedural.json");
  s.camera.width = 40;
  s.camera.height = 30;
  s.footprint = scene::Footprint::Recurrence;
  auto water = s;
  water.materials.at("smoke").procedural->kind = scene::ProceduralKind::Water;
  const uint64_t fbm_smoke = expect_rtl_equals_cmodel(s, "octave-serial: fbm, smoke", 300);
  const uint64_t fbm_water = expect_rtl_equals_cmodel(water, "octave-serial: fbm, water", 300);
  // A water pixel takes three octave sums (12 clocks), a smoke pixel one (4).
  EXPECT_GT(fbm_water, fbm_smoke);
}
