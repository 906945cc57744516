// Reciprocal unit: exhaustive error and monotonicity over every input code, guards, and the
// normaliser's exponent handling.
#include <gtest/gtest.h>

#include <cmath>

#include "reciprocal/reciprocal.hpp"

namespace {
using namespace tu;

constexpr int kW = fmt::kRecipInW;
const double kUlp = std::ldexp(1.0, -fmt::kRecipOutF);

TEST(Reciprocal, CoreExhaustiveFaithfulAndMonotonic) {
  // Every mantissa code M in [1,2): |R - 1/M| < 1 ULP, R non-increasing.
  const uint32_t lo = 1u << (fmt::kRecipMantW - 1), hi = 1u << fmt::kRecipMantW;
  double max_err = 0, sum_sq = 0, max_poly = 0;
  int64_t prev = INT64_MAX;
  uint64_t non_monotonic = 0;
  for (uint32_t m = lo; m < hi; ++m) {
    const auto r = recip::core(recip::Mant::from_raw(m)).raw();
    const double exact = static_cast<double>(lo) / m;
    const double err = std::fabs(std::ldexp(static_cast<double>(r), -fmt::kRecipOutF) - exact);
    // Approximation error alone: the ROM polynomial evaluated exactly (long double).
    const auto& c = recip::table()[(m >> fmt::kRecipDxW) & ((1u << fmt::kRecipIdxW) - 1)];
    const long double dx = std::ldexp(static_cast<long double>(m & ((1u << fmt::kRecipDxW) - 1)),
                                      1 - fmt::kRecipMantW);
    const long double poly = c.c0.to_ldouble() + dx * (c.c1.to_ldouble() + dx * c.c2.to_ldouble());
    max_poly = std::max(max_poly, static_cast<double>(std::fabs(poly - 1.0L * lo / m)));
    max_err = std::max(max_err, err);
    sum_sq += err * err;
    if (r > prev) ++non_monotonic;
    prev = r;
  }
  const double rms = std::sqrt(sum_sq / (hi - lo));
  RecordProperty("max_ulp", std::to_string(max_err / kUlp));
  RecordProperty("rms_ulp", std::to_string(rms / kUlp));
  std::printf("reciprocal core: max %.4f ULP, rms %.4f ULP over %u codes; polynomial with ROM "
              "coefficients alone: max %.4f ULP\n", max_err / kUlp, rms / kUlp, hi - lo,
              max_poly / kUlp);
  EXPECT_LT(max_poly, kUlp / 8) << "approximation leaves too little room for rounding";
  EXPECT_LT(max_err, kUlp) << "not faithful";
  EXPECT_EQ(non_monotonic, 0u);
}

TEST(Reciprocal, CoreRoundingIsCarryBit) {
  // tu_ewa_norm_tail takes the core's unrounded y (tu_recip_core_y) and folds the rounding into
  // its product: R = sat(round_half_up(y / 2^6)) = floor(y / 2^6) + y[5] needs y >= 0 and no
  // saturation, and its overflow flag needs R >= 2^(RecipOutF-1). Every mantissa code.
  constexpr int kRnd = fmt::kRecipC0F - fmt::kRecipOutF;
  const uint32_t lo = 1u << (fmt::kRecipMantW - 1), hi = 1u << fmt::kRecipMantW;
  int64_t min_r = INT64_MAX, max_r = 0;
  uint64_t bad = 0;
  for (uint32_t m = lo; m < hi; ++m) {
    const auto mm = recip::Mant::from_raw(m);
    const auto& c = recip::table()[mm.slice(fmt::kRecipDxW, fmt::kRecipIdxW)];
    const recip::Dx dx = recip::Dx::from_raw(mm.slice(0, fmt::kRecipDxW));
    const recip::T1 t1 = (c.c2 * dx).as<recip::T1>();
    const recip::S s = (c.c1 + t1).as<recip::S>();
    const recip::T2 t2 = (s * dx).as<recip::T2>();
    const int64_t y = static_cast<int64_t>((c.c0 + t2).raw());
    const int64_t r = static_cast<int64_t>(recip::core(mm).raw());
    if (y < 0 || (y >> kRnd) + ((y >> (kRnd - 1)) & 1) != r) ++bad;
    min_r = std::min(min_r, r);
    max_r = std::max(max_r, r);
  }
  EXPECT_EQ(bad, 0u);
  EXPECT_GE(min_r, int64_t(1) << (fmt::kRecipOutF - 1));
  EXPECT_LE(max_r, int64_t(1) << fmt::kRecipOutF);
}

TEST(Reciprocal, EveryInputCodeIsFaithfulOrFlagged) {
  // All 2^RecipInW codes of the full unit (normaliser + core + guards).
  const int64_t n = int64_t(1) << kW;
  double max_ulp = 0;
  uint64_t flagged = 0;
  double prev_val = INFINITY;
  for (int64_t c = 0; c < n; ++c) {
    const auto q = static_cast<int32_t>(c);  // eval() sign-extends the low RecipInW bits
    const auto r = recip::eval(q);
    const int64_t qs = c >= n / 2 ? c - n : c;
    if (qs <= 0) {
      ASSERT_TRUE(r.flag) << qs;
      ASSERT_EQ(r.mant, static_cast<uint32_t>(recip::Out::kMaxRaw));
      ASSERT_EQ(r.shift, 0u);
      ++flagged;
      continue;
    }
    ASSERT_FALSE(r.flag) << qs;
    const double val = recip::value(r, 0);  // 1/q for q an integer
    const double ulp = std::ldexp(kUlp, -static_cast<int>(r.shift));
    max_ulp = std::max(max_ulp, std::fabs(val - 1.0 / static_cast<double>(qs)) / ulp);
    if (qs > 1) {
      ASSERT_LE(val, prev_val) << "not monotonic at q = " << qs;
    }
    prev_val = val;
  }
  std::printf("reciprocal unit: max %.4f ULP over %lld codes, %llu flagged (q <= 0)\n", max_ulp,
              static_cast<long long>(n), static_cast<unsigned long long>(flagged));
  EXPECT_EQ(flagged, static_cast<uint64_t>(n / 2 + 1));
  EXPECT_LT(max_ulp, 1.0);
}

TEST(Reciprocal, ExactPowersOfTwo) {
  for (int p = 0; p < kW - 1; ++p) {
    const auto r = recip::eval(1 << p);
    EXPECT_EQ(r.shift, static_cast<uint32_t>(p));
    EXPECT_EQ(r.mant, 1u << fmt::kRecipOutF) << "1/2^" << p << " must be exact";
  }
}

TEST(Reciprocal, TableCoefficientsFitTheirFormats) {
  // Rounding to the coefficient formats must never saturate (it would bias a whole segment).
  for (const auto& c : recip::table()) {
    EXPECT_LT(c.c0.raw(), recip::C0::kMaxRaw);
    EXPECT_GT(c.c1.raw(), recip::C1::kMinRaw);
    EXPECT_LT(c.c2.raw(), recip::C2::kMaxRaw);
  }
}
}  // namespace
