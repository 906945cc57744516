// Shading stage (cmodel/blocks/brdf/brdf_shade.hpp): N.H to the BRDF's c format, the guards (off,
// light behind, saturation, back-facing c), the error against the float formula on seeded random
// unit vectors and colours plus the stiff points, and the shade port word's layout.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "brdf/brdf_shade.hpp"
#include "texunit/render.hpp"
#include "texunit/scene.hpp"

namespace {
using namespace tu;
using tu::brdf::Model;
using tu::brdf::kModels;
using tu::brdf::cut_code;
using tu::brdf::name;
using namespace tu::brdf::shade;

constexpr int64_t kOneV = int64_t(1) << fmt::kShadeVecF;

TEST(BrdfShade, DotRoundsHalfUpAndSaturates) {
  const Vec x{kOneV, 0, 0};
  EXPECT_EQ(dot(x, x), int64_t(1) << fmt::kBrdfCF);
  // One LSB of each: 2^-40 rounds to 0; 2^-21 (half a c LSB) rounds up, -2^-21 up to 0.
  EXPECT_EQ(dot(Vec{1, 0, 0}, Vec{1, 0, 0}), 0);
  EXPECT_EQ(dot(Vec{kOneV / 2, 0, 0}, Vec{1, 0, 0}), 1);   // 2^-21 exactly: half up
  EXPECT_EQ(dot(Vec{-kOneV / 2, 0, 0}, Vec{1, 0, 0}), 0);  // -2^-21: half up is 0
  // The largest codes: 3 (2 - 2^-20)^2 ~ 12 saturates to s(BrdfCW) (c clamps to 1 and flags).
  const int64_t big = (int64_t(1) << (fmt::kShadeVecW - 1)) - 1;
  EXPECT_EQ(dot(Vec{big, big, big}, Vec{big, big, big}), (int64_t(1) << (fmt::kBrdfCW - 1)) - 1);
  EXPECT_EQ(dot(Vec{big, big, big}, Vec{-big - 1, -big - 1, -big - 1}), -(int64_t(1) << (fmt::kBrdfCW - 1)));
}

TEST(BrdfShade, Guards) {
  const img::Rgba8 t{200, 100, 50, 77};
  In in;
  in.on = false;
  EXPECT_EQ(eval(Model::Msh, in, t).rgba, t);  // off: the filtered colour unchanged
  in.on = true;
  in.n = {0, 0, kOneV};
  in.h = {0, 0, kOneV};
  in.nexp = 10;
  in.ccut = cut_code(Model::St16, 10);
  for (int ch = 0; ch < 3; ++ch) in.ks[ch] = 256, in.lc[ch] = 256;
  in.amb = 0;
  // Light behind (N.L < 0, and N.L = 0): no diffuse, no highlight although N.H = 1.
  for (int64_t lz : {-kOneV, int64_t(0)}) {
    in.l = {kOneV, 0, lz};
    const Result r = eval(Model::St16, in, t);
    EXPECT_EQ(r.f, 0u);
    EXPECT_EQ(r.d, 0u);
    EXPECT_EQ(r.rgba, (img::Rgba8{0, 0, 0, 77}));
  }
  // Light along N: d = 1, F(1) = 1: 200 + 255 saturates, alpha kept.
  in.l = {0, 0, kOneV};
  const Result r = eval(Model::St16, in, t);
  EXPECT_EQ(r.d, 256u);
  EXPECT_EQ(r.f, 256u);
  EXPECT_EQ(r.rgba, (img::Rgba8{255, 255, 255, 77}));
  // The largest colours (511/256) and ambient: still 255, no wrap.
  for (int ch = 0; ch < 3; ++ch) in.ks[ch] = 511, in.lc[ch] = 511;
  in.amb = 511;
  EXPECT_EQ(eval(Model::Msh, in, {255, 255, 255, 255}).rgba, (img::Rgba8{255, 255, 255, 255}));
  // Black texel: the highlight alone, 255 ks F = 255 at F = 1 (exact).
  for (int ch = 0; ch < 3; ++ch) in.ks[ch] = 256, in.lc[ch] = 256;
  in.amb = 0;
  EXPECT_EQ(eval(Model::Blinn, in, {0, 0, 0, 0}).rgba, (img::Rgba8{255, 255, 255, 0}));
  // N.H < 0 (H behind N while L is in front): F(0), 0 for F_MSH.
  in.h = {0, 0, -kOneV};
  EXPECT_EQ(eval(Model::Msh, in, {0, 0, 0, 0}).f, 0u);
}

// Random unit vectors (N, L, H on the hemisphere of N half the time), colours and texels; the
// stiff points: grazing light, L = N, H = N, colours 0 and 511/256.
TEST(BrdfShade, ErrorAgainstTheFloatFormula) {
  std::mt19937_64 rng(17);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> u01(0, 1);
  auto unit = [&](double* v) {
    double l = 0;
    while (l < 1e-6) {
      for (int k = 0; k < 3; ++k) v[k] = g(rng);
      l = std::hypot(v[0], v[1], v[2]);
    }
    for (int k = 0; k < 3; ++k) v[k] /= l;
  };
  for (Model m : kModels) {
    double worst = 0, worst_lc1 = 0;
    for (int i = 0; i < 40000; ++i) {
      RefIn r;
      unit(r.n);
      unit(r.l);
      if (i % 4 == 0) for (int k = 0; k < 3; ++k) r.l[k] = r.n[k];  // L = N
      double hv[3];
      unit(hv);
      // H near N (the highlight) most of the time.
      const double a = i % 2 ? u01(rng) * 0.2 : u01(rng);
      double len = 0;
      for (int k = 0; k < 3; ++k) r.h[k] = r.n[k] + a * hv[k], len += r.h[k] * r.h[k];
      for (int k = 0; k < 3; ++k) r.h[k] /= std::sqrt(len);
      if (i % 7 == 0) for (int k = 0; k < 3; ++k) r.h[k] = r.n[k];  // H = N
      r.nexp = i % 5 == 0 ? (i % 3 == 0 ? 1 : 1000) : 1 + static_cast<int>(u01(rng) * 999);
      const bool unit_light = i % 2 == 0;
      for (int k = 0; k < 3; ++k) {
        r.lc[k] = unit_light ? u01(rng) : 2 * u01(rng);
        r.ks[k] = unit_light ? u01(rng) : 2 * u01(rng);
        if (i % 11 == 0) r.lc[k] = k == 0 ? 0 : 2, r.ks[k] = k == 1 ? 0 : 2;
      }
      r.amb = i % 13 == 0 ? 0 : u01(rng) * 0.5;
      const img::Rgba8 t{static_cast<uint8_t>(rng()), static_cast<uint8_t>(rng()), static_cast<uint8_t>(rng()), 255};
      // Compare with the formula on the quantised colours (their rounding is the set-up's, not the
      // stage's): the stage's own error.
      const In q = quantise(r, cut_code(m, r.nexp));
      RefIn rq = r;
      const double v1 = std::ldexp(1.0, -fmt::kShadeVecF);
      rq.n[0] = q.n.x * v1, rq.n[1] = q.n.y * v1, rq.n[2] = q.n.z * v1;
      rq.l[0] = q.l.x * v1, rq.l[1] = q.l.y * v1, rq.l[2] = q.l.z * v1;
      rq.h[0] = q.h.x * v1, rq.h[1] = q.h.y * v1, rq.h[2] = q.h.z * v1;
      for (int k = 0; k < 3; ++k) rq.lc[k] = q.lc[k] / 256.0, rq.ks[k] = q.ks[k] / 256.0;
      rq.amb = q.amb / 256.0;
      const auto want = ref_channels(m, rq, t);
      const img::Rgba8 got = eval(m, q, t).rgba;
      const int gv[3] = {got.r, got.g, got.b};
      for (int k = 0; k < 3; ++k) {
        const double e = std::fabs(gv[k] - std::min(255.0, want[static_cast<size_t>(k)]));
        // The bound of the header: 0.5 + 255 (2^-9 + lc 2^-9) + 255 ks (2^-9 + 2n 2^-21): the
        // output, d, lc d and F roundings, and c rounded to BrdfCF bits (slope of F <= 2n).
        const double bound = 0.5 + 255 * (1 + rq.lc[k]) / 512 + 255 * rq.ks[k] * (1.0 / 512 + 2.0 * q.nexp / (1 << 21)) + 1e-3;
        EXPECT_LE(e, bound) << name(m) << " i " << i << " ch " << k;
        worst = std::max(worst, e);
        if (unit_light) worst_lc1 = std::max(worst_lc1, e);
      }
    }
    std::printf("%-8s max |out - formula| %.3f LSB (colours <= 1: %.3f)\n", name(m).c_str(), worst, worst_lc1);
  }
}

TEST(BrdfShade, PortWordLayout) {
  In in;
  in.on = true;
  in.amb = 0x1ab;
  in.lc[2] = 0x155;  // b of lc: right above amb
  in.n.x = -1;       // all ShadeVecW bits set, right below `on`
  const auto w = pack(in);
  EXPECT_EQ(w[0] & 0x1ff, 0x1abu);
  EXPECT_EQ((w[0] >> 9) & 0x1ff, 0x155u);
  const int on_bit = 9 * fmt::kShadeVecW + fmt::kBrdfNW + fmt::kBrdfClW + 7 * fmt::kShadeColW;
  EXPECT_EQ((w[static_cast<size_t>(on_bit / 32)] >> (on_bit % 32)) & 1, 1u);
  for (int b = on_bit - fmt::kShadeVecW; b < on_bit; ++b)
    EXPECT_EQ((w[static_cast<size_t>(b / 32)] >> (b % 32)) & 1, 1u) << b;
  EXPECT_EQ((w[static_cast<size_t>((on_bit - fmt::kShadeVecW - 1) / 32)] >> ((on_bit - fmt::kShadeVecW - 1) % 32)) & 1, 0u);
}

// The docs' shaded sphere: the bit-accurate render (fixed-point filter and shading) against the
// float reference (float filter and shading), and the same two renders without the light: the
// shading stage's own share of the difference.
TEST(BrdfShade, ShadedSphereCModelAgainstTheFloatReference) {
  const auto s = tu::scene::load(std::string(TU_SOURCE_DIR) + "/docs/scenes/shaded_sphere.json");
  const double lit = tu::render::psnr_covered(tu::render::render_cmodel(s), tu::render::render_ref(s));
  auto dark = s;
  dark.lights.clear();
  const double flat = tu::render::psnr_covered(tu::render::render_cmodel(dark), tu::render::render_ref(dark));
  std::printf("shaded sphere: C model vs float reference %.2f dB (unshaded %.2f dB)\n", lit, flat);
  EXPECT_GT(lit, 40.0);
}

}  // namespace
