// Trilinear's GL LOD rule (texture/trilinear_lod.hpp): the bit-accurate lambda (B2's lrho, then
// bias and clamps) against the float rule on the exact Jacobian, exhaustively on every lrho code,
// and the clamps / magnification switch.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "ellipse/ellipse_fx.hpp"
#include "texture/trilinear_lod.hpp"

namespace {
using namespace tu;
namespace fx = tu::ellipse::fx;

constexpr double kLsb = 1.0 / (1 << fmt::kTexLodF);

// Every lrho code (s18.10) with several (bias, min, max) sets against the float rule on the
// decoded value: the only loss is the floor to TexLodF bits.
TEST(TrilinearLod, ExhaustiveOverLrhoCodes) {
  struct P { double bias, lo, hi; };
  for (const P p : {P{0, 0, 12}, P{1.5, 0, 12}, P{-2.25, 0.5, 7}, P{16, 0, 12}, P{-16, 3, 3}}) {
    const auto c = tex::lod_params(p.bias, p.lo, p.hi);
    double worst = 0;
    for (int32_t l = -(1 << (fmt::kEllLogW - 1)); l < (1 << (fmt::kEllLogW - 1)); ++l) {
      const auto o = tex::trilinear_lod(l, c, 12);
      const double rho = std::exp2(std::ldexp(double(l), -fmt::kEllLogF));
      uint32_t rf;
      const double ref = tex::trilinear_lod_ref(rho, 0, 0, 0, p.bias, p.lo, p.hi, 12, &rf);
      const double e = ref - o.lod * kLsb;
      ASSERT_GE(e, -1e-9) << l;
      ASSERT_LT(e, kLsb) << l;
      worst = std::max(worst, e);
      // Away from every decision boundary (one LSB) the decisions agree.
      const double raw = std::ldexp(double(l), -fmt::kEllLogF) + p.bias;
      bool near = false;
      for (double b : {p.lo, p.hi, 0.0, 12.0}) near = near || std::fabs(raw - b) <= kLsb;
      if (!near) {
        ASSERT_EQ(o.flags, rf) << l;
      }
    }
    std::printf("bias %g [%g, %g]: max lambda_ref - lod = %.6f levels (bound 2^-8)\n", p.bias, p.lo, p.hi, worst);
  }
}

// B2 (analytic, on in-format numerators of random local maps) + the rule against the float rule
// on the exact Jacobian.
TEST(TrilinearLod, FixedMatchesFloatReference) {
  std::mt19937_64 rng(13);
  const auto def = tex::lod_params(0, 0, 12);
  double lo = 1e9, hi = -1e9;
  int n = 0;
  for (int t = 0; t < 200000; ++t) {
    const fx::Local l = fx::random_local(rng);
    const auto o = fx::analytic(fx::in_from_map(fx::local_map(l)));
    if (o.flags & fx::kHorizon) continue;
    const auto r = tex::trilinear_lod(o.lrho, def, 12);
    uint32_t rf;
    const double ref = tex::trilinear_lod_ref(l.ux, l.vx, l.uy, l.vy, 0, 0, 12, 12, &rf);
    if (rf != 0) {  // on a clamp both sit on it
      EXPECT_EQ(r.lod, ref == 0 ? 0u : 12u << fmt::kTexLodF);
      continue;
    }
    const double e = ref - r.lod * kLsb;
    lo = std::min(lo, e), hi = std::max(hi, e);
    ++n;
  }
  std::printf("%d unclamped pixels: lambda_ref - lod in [%.3e, %.3e] levels\n", n, lo, hi);
  EXPECT_GT(n, 100000);
  EXPECT_GE(lo, -std::ldexp(1.0, -10));
  EXPECT_LT(hi, kLsb + std::ldexp(1.0, -9));
}

TEST(TrilinearLod, ClampsAndMagnification) {
  const auto def = tex::lod_params(0, 0, 12);
  // Point footprint (B2: no axes) and magnification: level 0.
  EXPECT_EQ(tex::trilinear_lod(fx::kLogNegInf, def, 8).lod, 0u);
  EXPECT_EQ(tex::trilinear_lod(fx::kLogNegInf, def, 8).flags, tex::kTriMagnify);
  EXPECT_EQ(tex::trilinear_lod(-1, def, 8).flags, tex::kTriMagnify);
  EXPECT_EQ(tex::trilinear_lod(0, def, 8).flags, tex::kTriMagnify);  // lambda = 0: magnification
  EXPECT_EQ(tex::trilinear_lod(4, def, 8).lod, 1u);                     // one LSB above
  EXPECT_EQ(tex::trilinear_lod(4, def, 8).flags, 0u);
  // Pyramid clamp.
  const auto sat = tex::trilinear_lod(9 << fmt::kEllLogF, def, 8);
  EXPECT_EQ(sat.lod, 8u << fmt::kTexLodF);
  EXPECT_EQ(sat.flags, tex::kTriLodSat);
  // Bias then [min, max].
  const auto b = tex::trilinear_lod(2 << fmt::kEllLogF, tex::lod_params(1.5, 0, 12), 8);
  EXPECT_EQ(b.lod, 3u * 256 + 128);
  const auto m = tex::trilinear_lod(fx::kLogNegInf, tex::lod_params(0, 2.5, 6), 8);
  EXPECT_EQ(m.lod, 2u * 256 + 128);  // min_lod > 0 forces minification
  EXPECT_EQ(m.flags, tex::kTriLodClamp);
  const auto x = tex::trilinear_lod(7 << fmt::kEllLogF, tex::lod_params(0, 0, 6), 8);
  EXPECT_EQ(x.lod, 6u << fmt::kTexLodF);
  EXPECT_EQ(x.flags, tex::kTriLodClamp);
  // The extreme codes do not overflow.
  const auto big = tex::trilinear_lod((1 << (fmt::kEllLogW - 1)) - 1, tex::lod_params(16, 0, 12), 12);
  EXPECT_EQ(big.lod, 12u << fmt::kTexLodF);
  const auto neg = tex::trilinear_lod(fx::kLogNegInf, tex::lod_params(-16, 0, 12), 12);
  EXPECT_EQ(neg.lod, 0u);
}

// The GL rule is not the EWA's: a 16:1 footprint gets the major axis' level (no anisotropy clamp),
// and the rho sums are by screen axis (a rotation of the texture does not change lambda).
TEST(TrilinearLod, ScreenAxisSumsNotTheMinorAxis) {
  fx::Local l;
  l.q = 0.5, l.ux = 16, l.vx = 0, l.uy = 0, l.vy = 1;
  const auto o = fx::analytic(fx::in_from_map(fx::local_map(l)));
  const auto r = tex::trilinear_lod(o.lrho, tex::lod_params(0, 0, 12), 12);
  EXPECT_NEAR(r.lod * kLsb, 4.0, 2 * kLsb);                  // log2 16
  EXPECT_NEAR(fx::lod_value(o), 0.0, 2 * kLsb);             // B2's EWA lod: log2 of the clamped minor axis (1)
  const double c = std::cos(0.7), s = std::sin(0.7);
  l.ux = 4 * c, l.vx = 4 * s, l.uy = -s, l.vy = c;  // x step 4 texels, rotated
  const auto o2 = fx::analytic(fx::in_from_map(fx::local_map(l)));
  EXPECT_NEAR(tex::trilinear_lod(o2.lrho, tex::lod_params(0, 0, 12), 12).lod * kLsb, 2.0, 2 * kLsb);
}

// Base and max level (GL TEXTURE_BASE_LEVEL / MAX_LEVEL): every lrho code against the float rule
// on the decoded value, with the level range inside the pyramid, above it and inverted.
TEST(TrilinearLod, BaseAndMaxLevelExhaustiveOverLrhoCodes) {
  struct P { double bias, lo, hi; int base, maxlev; };
  for (const P p : {P{0, 0, 12, 2, 1000}, P{0.75, 0.5, 3, 1, 5}, P{-1, 0, 12, 3, 6}, P{16, 0, 12, 4, 4},
                    P{-16, 0, 12, 12, 1000}, P{0, 0, 12, 7, 2}, P{0, 3, 1, 1, 7}}) {
    const auto c = tex::lod_params(p.bias, p.lo, p.hi, p.base, p.maxlev);
    const auto lv = tex::level_range(c, 8);
    double worst = 0;
    for (int32_t l = -(1 << (fmt::kEllLogW - 1)); l < (1 << (fmt::kEllLogW - 1)); ++l) {
      const auto o = tex::trilinear_lod(l, c, 8);
      ASSERT_GE(o.lod, uint32_t(lv.base) << fmt::kTexLodF) << l;  // never below the base level
      ASSERT_LE(o.lod, uint32_t(lv.top) << fmt::kTexLodF) << l;   // nor above the top one
      uint32_t rf;
      const double ref = tex::lod_rule_ref(std::ldexp(double(l), -fmt::kEllLogF), p.bias, p.lo, p.hi, 8, &rf,
                                           p.base, p.maxlev);
      const double e = ref - o.lod * kLsb;
      ASSERT_GE(e, -1e-9) << l;
      ASSERT_LT(e, kLsb) << l;
      worst = std::max(worst, e);
      const double raw = std::ldexp(double(l), -fmt::kEllLogF) + p.bias - lv.base;
      bool near = false;
      for (double b : {p.lo, p.hi, 0.0, double(lv.top - lv.base)}) near = near || std::fabs(raw - b) <= kLsb;
      if (!near) ASSERT_EQ(o.flags, rf) << l;
    }
    std::printf("bias %g [%g, %g] levels %d..%d -> [%d, %d]: max lambda_ref - lod = %.6f levels\n", p.bias, p.lo,
                p.hi, p.base, p.maxlev, lv.base, lv.top, worst);
  }
}

// The stiff sampler states, each with its documented behaviour.
TEST(TrilinearLod, StiffSamplerStates) {
  // min_lod > max_lod: min_lod wins for every footprint (flag kTriLodClamp where it moved lambda).
  for (int32_t l : {fx::kLogNegInf, -5 << fmt::kEllLogF, 0, 2 << fmt::kEllLogF, (1 << (fmt::kEllLogW - 1)) - 1}) {
    const auto o = tex::trilinear_lod(l, tex::lod_params(0, 3, 1), 8);
    EXPECT_EQ(o.lod, 3u << fmt::kTexLodF) << l;
    EXPECT_EQ(o.flags, tex::kTriLodClamp) << l;
  }
  // bias +16: every footprint wider than 2^-8 texels saturates at the top; -16: magnification
  // below 2^16 texels per pixel.
  EXPECT_EQ(tex::trilinear_lod(-7 << fmt::kEllLogF, tex::lod_params(16, 0, 12), 8).lod, 8u << fmt::kTexLodF);
  EXPECT_EQ(tex::trilinear_lod(-7 << fmt::kEllLogF, tex::lod_params(16, 0, 12), 8).flags, tex::kTriLodSat);
  EXPECT_EQ(tex::trilinear_lod(15 << fmt::kEllLogF, tex::lod_params(-16, 0, 12), 8).lod, 0u);
  EXPECT_EQ(tex::trilinear_lod(15 << fmt::kEllLogF, tex::lod_params(-16, 0, 12), 8).flags, tex::kTriMagnify);
  // base_level > max_level (GL: incomplete): the base level alone.
  EXPECT_EQ(tex::level_range(5, 2, 8).base, 5);
  EXPECT_EQ(tex::level_range(5, 2, 8).top, 5);
  for (int32_t l : {fx::kLogNegInf, 0, 3 << fmt::kEllLogF, 9 << fmt::kEllLogF})
    EXPECT_EQ(tex::trilinear_lod(l, tex::lod_params(0, 0, 12, 5, 2), 8).lod, 5u << fmt::kTexLodF) << l;
  // base_level above the pyramid: its top level; max_level above it: the pyramid's top.
  EXPECT_EQ(tex::level_range(12, 1000, 8).base, 8);
  EXPECT_EQ(tex::level_range(12, 1000, 8).top, 8);
  EXPECT_EQ(tex::level_range(0, 1000, 8).top, 8);
  // Every range is inside the pyramid and ordered.
  for (int top = 0; top <= 12; ++top)
    for (int b = 0; b <= 15; ++b)
      for (int m = 0; m <= 20; ++m) {
        const auto r = tex::level_range(b, m, top);
        ASSERT_LE(0, r.base);
        ASSERT_LE(r.base, r.top);
        ASSERT_LE(r.top, top);
        ASSERT_EQ(r.base, std::min(b, top));
        ASSERT_EQ(r.top, std::max(r.base, std::min(m, top)));
      }
  // Magnification samples the base level (lod = base), not level 0.
  const auto mag = tex::trilinear_lod(fx::kLogNegInf, tex::lod_params(0, 0, 12, 3, 1000), 8);
  EXPECT_EQ(mag.lod, 3u << fmt::kTexLodF);
  EXPECT_EQ(mag.flags, tex::kTriMagnify);
  // lambda is relative to the base level: log2 rho = 5, base 2 -> level 2 + 3 = 5.
  EXPECT_EQ(tex::trilinear_lod(5 << fmt::kEllLogF, tex::lod_params(0, 0, 12, 2, 1000), 8).lod, 5u << fmt::kTexLodF);
  // ... and min_lod / max_lod clamp lambda, not the level: base 2 + max_lod 1 -> level 3.
  EXPECT_EQ(tex::trilinear_lod(7 << fmt::kEllLogF, tex::lod_params(0, 0, 1, 2, 1000), 8).lod, 3u << fmt::kTexLodF);
}

}  // namespace
