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

}  // namespace
