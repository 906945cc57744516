// The 2 x 2 (K = 4) EWA walk (cmodel/blocks/ewa/ewa_lanes.hpp, docs/blocks/ewa.md "Multi-texel
// walk"): bit-identical to the sequential walk on every pixel tried (random footprints with each
// weight source, border weights on and off; curated extremes with repeat and clamp; the largest
// boxes), the texel set independent of K, the widths of the K-input sum.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "ewa/ewa_fx.hpp"
#include "ewa_walk_checks.hpp"
#include "ewa/ewa_lanes.hpp"
#include "gauss/clip.hpp"

namespace {
using namespace tu;
namespace efx = ewa::fx;

const tex::Texture& bricks() { return test::bricks_texture(); }

void expect_same(const efx::Out& a, const efx::Out& b) { test::expect_same_walk(a, b); }

TEST(EwaLanes, RandomPixelsEqualTheSequentialWalk) {
  std::mt19937_64 rng(23);
  uint64_t box = 0, blocks = 0, n = 0;
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
        box += su.box, blocks += st.blocks, ++n;
      }
  }
  std::printf("%llu pixel walks: %.2f texels, %.2f 2x2 blocks per pixel (%.2f texels per clock)\n",
              (unsigned long long)n, double(box) / double(n), double(blocks) / double(n), double(box) / double(blocks));
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
          expect_same(efx::walk(su, *t, cfg), efx::walk_lanes(su, *t, cfg));
          ++n;
        }
  EXPECT_EQ(n, 2 * px.size() * 6);
}

}  // namespace
