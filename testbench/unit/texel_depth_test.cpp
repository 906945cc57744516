// Texel-depth texturing (seed 001 §3, persp/texel_depth.hpp): the seed's w(s) from the span ends'
// depths is the perspective-correct interpolation (float); in fixed point, from the same quantised
// data as B1 (its seeds and increments), it is NOT bit-identical to B1's incremental divide: the
// pixels that differ, by how much, and both methods' error against the exact rational are
// measured here (docs/blocks/persp.md "Texel-depth variant"); the structural scheme's latency.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "persp/schemes.hpp"
#include "persp/texel_depth.hpp"

namespace {
using namespace tu;
using persp::Unit;

TEST(TexelDepth, SeedFormulaIsThePerspectiveCorrectInterpolation) {
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> U(0, 1);
  double worst = 0;
  for (int k = 0; k < 2000; ++k) {
    const int len = 2 + static_cast<int>(rng() % 1000), x0 = static_cast<int>(rng() % 3000), y = static_cast<int>(rng() % 4096);
    const auto map = persp::random_span_map(rng, y, x0, x0 + len - 1, std::pow(1000.0, -U(rng)), std::pow(1000.0, -U(rng)));
    for (int x = x0; x < x0 + len; x += 1 + len / 16) {
      double u, v, q, tu_, tv_;
      persp::eval_ref(map, x, y, &u, &v, &q);
      persp::texel_depth::pixel_ref(map, y, x0, x0 + len - 1, x, &tu_, &tv_);
      worst = std::max({worst, std::fabs(tu_ - u), std::fabs(tv_ - v)});
    }
  }
  std::printf("seed's w(s) vs the exact perspective map: max |dT| %.3g texels\n", worst);
  EXPECT_LT(worst, 1e-6);  // double rounding of |T| <= 4096 only
}

TEST(TexelDepth, FixedPointAgainstTheIncrementalDivideFromTheSameData) {
  std::mt19937_64 rng(32);
  std::uniform_real_distribution<double> U(0, 1);
  uint64_t pixels = 0, identical = 0, spans = 0, end_diffs = 0;
  int64_t max_code_diff = 0;
  double err_b1 = 0, err_td = 0;
  for (int k = 0; k < 4000; ++k) {
    const int len = 2 + static_cast<int>(rng() % 2000), x0 = static_cast<int>(rng() % (4096 - len)),
              y = static_cast<int>(rng() % 4096);
    const auto map = persp::random_span_map(rng, y, x0, x0 + len - 1, std::pow(1000.0, -U(rng)), std::pow(1000.0, -U(rng)));
    Unit::Coefs c;
    Unit::Acc s0;
    try {
      c = Unit::quantise(map, "span");
      s0 = Unit::setup(c, y, x0, x0 + len - 1, "span");
    } catch (const persp::SetupError&) {
      continue;
    }
    const auto span = persp::texel_depth::setup(s0, c.a, c.d, c.g, len - 1);
    if (span.guard) continue;
    ++spans;
    std::vector<persp::Pixel> b1(static_cast<size_t>(len));
    Unit::span_incremental(c, y, x0, len, b1.data());
    for (int m = 0; m < len; ++m) {
      const persp::Pixel td = persp::texel_depth::pixel(span, m), &ib = b1[static_cast<size_t>(m)];
      ++pixels;
      identical += td == ib;
      if ((m == 0 || m == len - 1) && !(td == ib)) ++end_diffs;
      max_code_diff = std::max({max_code_diff, std::abs(td.u - ib.u), std::abs(td.v - ib.v)});
      // Both against the exact rational of the quantised map (long double).
      const auto acc = Unit::direct(c, x0 + m, y);
      const long double q = static_cast<long double>(acc.q.raw());
      const long double u = static_cast<long double>(acc.pu.raw()) / q, v = static_cast<long double>(acc.pv.raw()) / q;
      if (std::fabs(static_cast<double>(u)) > 4096 || std::fabs(static_cast<double>(v)) > 4096) continue;
      auto err = [&](const persp::Pixel& p) {
        return static_cast<double>(std::max(std::fabs(std::ldexp(static_cast<long double>(p.u), -fmt::kPerspUvF) - u),
                                            std::fabs(std::ldexp(static_cast<long double>(p.v), -fmt::kPerspUvF) - v)));
      };
      err_b1 = std::max(err_b1, err(ib));
      err_td = std::max(err_td, err(td));
    }
  }
  std::printf("texel depth vs B1 incremental (same quantised seeds): %llu spans, %llu pixels, %.2f %% bit-identical, "
              "max |du| %lld LSB (2^-8 texel); max error vs exact: B1 %.5f, texel depth %.5f texels\n",
              (unsigned long long)spans, (unsigned long long)pixels, 100.0 * double(identical) / double(pixels),
              (long long)max_code_diff, err_b1, err_td);
  ASSERT_GT(spans, 3000u);
  EXPECT_EQ(end_diffs, 0u);          // the ends are B1's own outputs
  EXPECT_LT(identical, pixels);      // not bit-identical: w is rounded before the multiply
  EXPECT_GT(identical, pixels / 2);  // ... but most pixels agree
  EXPECT_LE(max_code_diff, 1);       // at most 1 LSB apart (measured on these 4 M pixels)
  EXPECT_LT(err_b1, 1.0 / 256);
  EXPECT_LT(err_td, 2.0 / 256);
}

TEST(TexelDepth, WeightEndsClampAndGuard) {
  persp::texel_depth::Span s;
  s.m2 = 10, s.q1 = int64_t(1) << 40, s.q2 = int64_t(1) << 38;
  EXPECT_EQ(persp::texel_depth::w_code(s, 0), 0u);
  EXPECT_EQ(persp::texel_depth::w_code(s, 10), uint64_t(1) << persp::texel_depth::kWF);
  EXPECT_EQ(persp::texel_depth::w_code(s, 99), uint64_t(1) << persp::texel_depth::kWF);  // past the end: clamped
  // m = 5 of a span whose depth quadruples: w = 5 q2 / (10 q1 + 5 (q2 - q1)) = 0.2 (exact 1/5).
  EXPECT_NEAR(std::ldexp(double(persp::texel_depth::w_code(s, 5)), -persp::texel_depth::kWF), 0.2, 1e-6);
  s.guard = true;
  EXPECT_TRUE(persp::texel_depth::pixel(s, 3).flag);
}

TEST(TexelDepth, SchemeCostsTwoMoreStagesAndTwoMoreMultipliersThanB1) {
  const auto td = sched::schedule(persp::texel_depth_scheme()), b1 = sched::schedule(persp::scheme("persp"));
  std::printf("texel depth: latency %d, II %d, %d multipliers; B1 incremental: latency %d, II %d, %d multipliers\n",
              td.latency, td.ii, td.units_used.at("mul"), b1.latency, b1.ii, b1.units_used.at("mul"));
  EXPECT_EQ(td.ii, 1);
  EXPECT_EQ(td.latency, b1.latency + 2);  // w = N R rounded, then (T2 - T1) w
  // + N R and the span load m2 q1 of D (tu_texel_depth; used once per span, still a multiplier).
  EXPECT_EQ(td.units_used.at("mul"), b1.units_used.at("mul") + 2);
}
// The declared formats hold every unguarded span (tu_texel_depth's widths): N = m q2 and
// D = (m2 - m) q1 + m q2 below 2^TexelDepthAccW for the largest offsets and q codes; the
// leading-one position of D fits the RTL's 6-bit exponent; dT w fits its product width.
TEST(TexelDepth, DeclaredWidthsHoldTheWorstCase) {
  const i128 q_max = (i128(1) << (fmt::kPerspQW - 1)) - 1, m_max = (i128(1) << fmt::kPerspXyW) - 1;
  const i128 acc_max = m_max * q_max;  // N at m = m2, D at any m (a convex combination times m2)
  EXPECT_LT(acc_max, i128(1) << fmt::kTexelDepthAccW);
  EXPECT_GE(acc_max, i128(1) << (fmt::kTexelDepthAccW - 1));  // and no bit to spare
  EXPECT_LE(fmt::kTexelDepthAccW - 1, 63);                    // msb position: 6 bits
  // dT * w: |T2 - T1| <= 2^PerspUvW - 1 times w <= 2^WF fits the RTL's signed
  // (PerspUvW + 1) + (WF + 1)-bit product.
  const int wf = persp::texel_depth::kWF;
  EXPECT_LT(((i128(1) << fmt::kPerspUvW) - 1) << wf, i128(1) << (fmt::kPerspUvW + 1 + wf + 1 - 1));
  // A span at those limits: the widest D (m2 q, 55 bits) gives w = m / m2 within the reciprocal's
  // faithful bound (2^-22 relative: at most 4 codes at w = 1/2).
  persp::texel_depth::Span s;
  s.q1 = s.q2 = static_cast<int64_t>(q_max);
  s.m2 = static_cast<int>(m_max);
  EXPECT_NEAR(static_cast<double>(persp::texel_depth::w_code(s, 2047)), std::ldexp(2047.0 / 4095.0, wf), 4.0);
}
}  // namespace
