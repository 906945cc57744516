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

TEST(TexelDepth, SchemeCostsOneMoreMultiplyStageThanB1) {
  const auto td = sched::schedule(persp::texel_depth_scheme()), b1 = sched::schedule(persp::scheme("persp"));
  std::printf("texel depth: latency %d, II %d, %d multipliers; B1 incremental: latency %d, II %d, %d multipliers\n",
              td.latency, td.ii, td.units_used.at("mul"), b1.latency, b1.ii, b1.units_used.at("mul"));
  EXPECT_EQ(td.ii, 1);
  EXPECT_EQ(td.latency, b1.latency + 2);  // w = N R rounded, then (T2 - T1) w
  EXPECT_EQ(td.units_used.at("mul"), b1.units_used.at("mul") + 1);
}
}  // namespace
