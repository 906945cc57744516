// The 2 x 2 (K = 4) EWA walk (cmodel/blocks/ewa/ewa_lanes.hpp, docs/blocks/ewa.md "Multi-texel
// walk"): bit-identical to the sequential walk on every pixel tried (random footprints with each
// weight source, border weights on and off; curated extremes with repeat and clamp; the largest
// boxes), the texel set independent of K, the widths of the K-input sum.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>

#include "ewa/ewa_fx.hpp"
#include "ewa_walk_checks.hpp"
#include "ewa/ewa_lanes.hpp"
#include "gauss/clip.hpp"
#include "texunit/render.hpp"
#include "texunit/scene.hpp"

namespace {
using namespace tu;
namespace efx = ewa::fx;

const tex::Texture& bricks() { return test::bricks_texture(); }

void expect_same(const efx::Out& a, const efx::Out& b) { test::expect_same_walk(a, b); }

TEST(EwaLanes, RandomPixelsEqualTheSequentialWalk) {
  std::mt19937_64 rng(23);
  uint64_t box = 0, blocks = 0, blocks2 = 0, n = 0;
  for (int i = 0; i < 3000; ++i) {
    const efx::In in = efx::random_in(rng);
    for (int w = 0; w < 3; ++w)
      for (const clip::Variant* v : {static_cast<const clip::Variant*>(nullptr), &clip::variant("mm_p1")}) {
        efx::Config cfg{static_cast<efx::Weights>(w), i % 8 == 0 ? static_cast<uint32_t>(1 + rng() % 2048) : 1024u, v};
        const efx::PixelSetup su = efx::setup(in, bricks(), cfg);
        efx::LaneStats st;
        const efx::Out seq = efx::walk(su, bricks(), cfg), lan = efx::walk_lanes(su, bricks(), cfg, &st);
        SCOPED_TRACE(i);
        expect_same(seq, lan);
        EXPECT_EQ(lan.texels_visited, su.box);  // the texel set is the box, whatever K
        EXPECT_EQ(st.blocks, efx::lane_blocks(su.x0, su.x1, su.y0, su.y1));
        EXPECT_EQ(seq.lane_blocks, st.blocks);  // Out::lane_blocks (the cycle model's) = the 2 x 2 walk's clocks
        efx::LaneStats st2;
        expect_same(seq, efx::walk_lanes(su, bricks(), cfg, &st2, 2));  // K = 2 (2 x 1 blocks)
        EXPECT_EQ(st2.blocks, efx::lane_blocks(su.x0, su.x1, su.y0, su.y1, 2));
        box += su.box, blocks += st.blocks, blocks2 += st2.blocks, ++n;
      }
  }
  std::printf("%llu pixel walks: %.2f texels, %.2f 2x2 blocks per pixel (%.2f texels per clock), %.2f 2x1 blocks "
              "(%.2f texels per clock)\n",
              (unsigned long long)n, double(box) / double(n), double(blocks) / double(n), double(box) / double(blocks),
              double(blocks2) / double(n), double(box) / double(blocks2));
}

// The largest boxes (EwaFx.WidthsOnLargestBox's set-ups: a forced level-0 pixel with a = 2^7, round
// at three orientations and the thinnest b = 1 at 45 degrees) with white texels: the K = 4 products
// of one clock sum below 2^26 (4 w 255, w <= 2^16), the result is the sequential walk's.
TEST(EwaLanes, LargestBoxesAndClockSumWidth) {
  const auto white = tex::Texture::build("white", img::Rgba8Image(256, 256, {255, 255, 255, 255}), tex::Wrap::Repeat);
  const efx::Config cfg{efx::Weights::Formula, 1u << 20, nullptr};
  uint64_t max_sum = 0, box = 0;
  for (auto [lmin, be] : {std::pair{9, 0}, {9, 990}, {9, -300}, {0, 1000}}) {
    efx::In in;
    in.u = (int64_t(1) << (fmt::kPerspUvW - 2)) + 127;
    in.v = -(int64_t(1) << (fmt::kPerspUvW - 2)) - 77;
    in.b2.lmaj = 9 << fmt::kEllLogF;
    in.b2.lmin = lmin << fmt::kEllLogF;
    in.b2.ae = lmin == 0 ? 500 : 1000, in.b2.ce = lmin == 0 ? 500 : 10, in.b2.be = be;
    const efx::PixelSetup su = efx::setup(in, white, cfg);
    efx::LaneStats st;
    expect_same(efx::walk(su, white, cfg), efx::walk_lanes(su, white, cfg, &st));
    max_sum = std::max(max_sum, st.max_clock_sum);
    box = std::max(box, su.box);
  }
  std::printf("largest box %llu texels; largest K = 4 clock sum: %llu (< 2^26 = %llu)\n", (unsigned long long)box,
              (unsigned long long)max_sum, 1ull << 26);
  EXPECT_GT(box, 60000u);
  EXPECT_GT(max_sum, 0u);
  EXPECT_LT(max_sum, 1ull << 26);
}

// Curated extremes (as the ewa vector block's stiff set): 1:1000 before the clamp at 16 angles, the
// 1024:1 limit, a line, caps 1 .. 2^17 - 1, texture edges and far coordinates (clamp and repeat),
// magnification extremes; each weight source, border weights off and on.
TEST(EwaLanes, StiffPixelsEqualTheSequentialWalk) {
  std::vector<std::pair<efx::In, uint32_t>> px;  // pixel, cap
  auto add = [&](const ellipse::fx::Local& l, uint32_t cap = 1024, uint32_t laniso = 4 << fmt::kEllLogF) {
    px.push_back({efx::in_from_local(l, laniso), cap});
  };
  for (int t = 0; t < 16; ++t) add(efx::footprint_local(64, 1000, t * M_PI / 16, 50.5 + t, 20.25));
  for (int t = 0; t < 4; ++t) add(efx::footprint_local(2000, 1000, t * 0.7, 9.0, 9.0), 1u << 16, 10 << fmt::kEllLogF);
  add(efx::footprint_local(32, 0, 0.7, 11.0, 12.0));
  for (uint32_t cap : {1u, 2u, 9u, 100u, (1u << fmt::kEwaCountW) - 1}) add(efx::footprint_local(90, 16, 0.5, 60.0, 70.0), cap);
  for (double u : {0.0, 0.01, 255.99, 256.0, -0.5, 1e6, -8e6}) add(efx::footprint_local(5, 2, 0.1, u, 255.9));
  for (double m : {1.0 / 1024, 0.5, 0.999, 1.0, 1.001, 2.0}) add(efx::footprint_local(m, 1.0, 0.0, 31.5, 31.5));
  const tex::Texture clamp = tex::Texture::build("bricks", tex::bricks(256).color, tex::Wrap::Clamp);
  size_t n = 0;
  for (const tex::Texture* t : {&bricks(), &clamp})
    for (const auto& [in, cap] : px)
      for (int w = 0; w < 3; ++w)
        for (const clip::Variant* v : {static_cast<const clip::Variant*>(nullptr), &clip::variant("mm_p1")}) {
          const efx::Config cfg{static_cast<efx::Weights>(w), cap, v};
          const efx::PixelSetup su = efx::setup(in, *t, cfg);
          SCOPED_TRACE(n);
          const efx::Out seq = efx::walk(su, *t, cfg);
          for (int k : {2, 4}) expect_same(seq, efx::walk_lanes(su, *t, cfg, nullptr, k));
          ++n;
        }
  EXPECT_EQ(n, 2 * px.size() * 6);
}

TEST(EwaLanes, ShapesAndBlockCounts) {
  EXPECT_THROW(efx::lane_shape(3), std::invalid_argument);
  EXPECT_EQ(efx::lane_blocks(0, 0, 0, 0, 4), 1u);
  EXPECT_EQ(efx::lane_blocks(1, 2, 1, 2, 4), 4u);  // a 2 x 2 box across block corners: 4 blocks
  EXPECT_EQ(efx::lane_blocks(-3, 2, -1, 0, 4), 4u * 2u);  // blocks of [-4, 3] x [-2, 1]
  EXPECT_EQ(efx::lane_blocks(-3, 2, -1, 0, 2), 4u * 2u);
  EXPECT_EQ(efx::lane_blocks(-3, 2, -1, 0, 1), 6u * 2u);
}

}  // namespace

namespace {
// Every docs scene and the default scene (cameras scaled to 64 pixels wide: the same views, a few
// thousand pixels each) rendered by the C model with EWA on every material at K = 1, 2 and 4
// (CmodelOptions::ewa_lanes): the same frame, pixel for pixel (colour, level, texels visited and
// inside, flags; relief materials with their method, procedural ones with the noise unit).
TEST(EwaLanes, DocsScenesSameFrameForK124) {
  std::vector<tu::scene::Scene> scenes = {tu::scene::default_scene()};
  for (const char* n : {"af_visibility", "clip_floor", "corridor", "distance_map", "hud_floor", "lod_state",
                        "procedural", "procedural_water", "shaded_sphere", "ui_quad", "water", "wrap_modes"})
    scenes.push_back(tu::scene::load(std::string(TU_SOURCE_DIR) + "/docs/scenes/" + n + ".json"));
  size_t px = 0, walked = 0;
  for (auto& s : scenes) {
    const int w = s.camera.width;
    s.camera.width = 64;
    s.camera.height = std::max(1, s.camera.height * 64 / w);
    tu::render::CmodelOptions o;
    const auto f1 = tu::render::render_cmodel(s, tu::scene::Filter::Ewa, o);
    for (int k : {2, 4}) {
      o.ewa_lanes = k;
      const auto fk = tu::render::render_cmodel(s, tu::scene::Filter::Ewa, o);
      SCOPED_TRACE(s.source + " K = " + std::to_string(k));
      ASSERT_EQ(f1.pixels.size(), fk.pixels.size());
      EXPECT_TRUE(f1.image.px == fk.image.px);
      for (size_t i = 0; i < f1.pixels.size(); ++i) {
        const auto &a = f1.pixels[i], &b = fk.pixels[i];
        EXPECT_TRUE(a.color == b.color && a.lod == b.lod && a.texels == b.texels && a.texels_inside == b.texels_inside &&
                    a.ewa_flags == b.ewa_flags && a.ewa_blocks == b.ewa_blocks)
            << "pixel " << a.x << "," << a.y;
      }
    }
    px += f1.pixels.size();
    for (const auto& p : f1.pixels) walked += p.ewa_blocks > 0;
  }
  std::printf("%zu scenes, %zu covered pixels (%zu walked): K = 1, 2, 4 identical\n", scenes.size(), px, walked);
  EXPECT_GT(walked, 10000u);
}
}  // namespace

#include "ewa/ewa_cycles.hpp"

namespace {
// The K = 4 engine's stream recurrence (ewa_cycles.hpp) on hand-checked streams: set-up S = 30
// clocks (one level), two set-up units, 12 clocks from the last block to the output.
TEST(EwaLanes, StreamModelLanes4) {
  tu::ewa::EngineParams p;
  p.lanes = 4;
  p.setup_units = 2;
  tu::ewa::PixelCost c;
  c.blocks = 10;
  ASSERT_EQ(tu::ewa::setup_cycles(c, p), 30);
  EXPECT_EQ(tu::ewa::stream_cycles({c}, 0, p), 30u + 10 + 12 + 1);
  // pixel 1: accepted at 1 by the second unit, handed over when the walker issues pixel 0's last block
  EXPECT_EQ(tu::ewa::stream_cycles({c, c}, 0, p), 40u + 10 + 12 + 1);
  auto per_px = [&](const tu::ewa::PixelCost& x, const tu::ewa::EngineParams& q) {
    return double(tu::ewa::stream_cycles(std::vector<tu::ewa::PixelCost>(2000, x), 0, q) -
                  tu::ewa::stream_cycles(std::vector<tu::ewa::PixelCost>(1000, x), 0, q)) / 1000.0;
  };
  EXPECT_DOUBLE_EQ(per_px(c, p), 15.5);  // set-up bound: a unit per 2 pixels, S + 1 clocks each
  c.blocks = 20;
  EXPECT_DOUBLE_EQ(per_px(c, p), 20.0);  // walk bound: the drain overlaps the next pixel
  auto one = p;
  one.setup_units = 1;
  c.blocks = 10;
  EXPECT_DOUBLE_EQ(per_px(c, one), 31.0);
  // B1-guard pixels (S = 1, one block): 8 credits per 1 + 13 clocks of latency
  tu::ewa::PixelCost g;
  g.guard = true;
  EXPECT_DOUBLE_EQ(per_px(g, p), 14.0 / 8.0);
  // border weights in the engine: every pixel 43 clocks later (mm_p1)
  auto clip = p;
  clip.lane_clip = true;
  EXPECT_EQ(tu::ewa::stream_cycles({c}, 0, clip), 30u + 10 + 12 + 43 + 1);
}
}  // namespace
