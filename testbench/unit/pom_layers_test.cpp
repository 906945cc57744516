// Adaptive POM layer counter (seed-000 note §1.4.3 golden table, §5 edge cases), exhaustive
// checks of the declared formats against the float formula.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "pom/pom_layers.hpp"

namespace {
using namespace tu;

const int kCodes[24] = {0,   11,  22,  33,  44,  55,  66,  77,  88,  99,  110, 121,
                        133, 144, 155, 166, 177, 188, 199, 210, 221, 232, 243, 255};

int32_t vz_of_angle(int deg) {
  return static_cast<int32_t>(std::llround(std::cos(deg * M_PI / 180.0) * (1 << fmt::kPomVzF)));
}

TEST(PomLayers, GoldenTableOfTheNoteIsExact) {
  // Note §1.4.3 (float32 emulation of the shader, MinLayers 4, MaxLayers 32). Our unit matches
  // every one of the 14 x 24 entries exactly (no +-1 entries needed), including the closest
  // calls: 70 deg level 21 (exact 22.9997 -> 22), 20 deg level 10 (5.99896 -> 5),
  // 10 deg level 23 (4.98278 -> 4), 90 deg level 23 (exactly 32).
  const std::vector<std::pair<int, std::vector<int>>> table = {
      {0, std::vector<int>(24, 4)},
      {10, std::vector<int>(24, 4)},
      {20, {5, 5, 5, 5, 5, 5, 5, 5, 5, 5, 5, 6, 6, 6, 6, 6, 6, 6, 6, 6, 6, 6, 6, 6}},
      {30, {6, 6, 6, 6, 6, 7, 7, 7, 7, 7, 7, 7, 8, 8, 8, 8, 8, 8, 8, 9, 9, 9, 9, 9}},
      {40, {7, 7, 8, 8, 8, 8, 9, 9, 9, 9, 9, 10, 10, 10, 10, 11, 11, 11, 11, 11, 12, 12, 12, 12}},
      {45, {8, 8, 9, 9, 9, 9, 10, 10, 10, 10, 11, 11, 11, 11, 12, 12, 12, 12, 13, 13, 13, 13, 14, 14}},
      {50, {9, 9, 9, 10, 10, 10, 11, 11, 11, 11, 12, 12, 12, 13, 13, 13, 14, 14, 14, 15, 15, 15, 15, 16}},
      {60, {10, 11, 11, 12, 12, 12, 13, 13, 14, 14, 14, 15, 15, 16, 16, 16, 17, 17, 18, 18, 18, 19, 19, 20}},
      {70, {12, 13, 13, 14, 14, 15, 15, 16, 16, 17, 17, 18, 18, 19, 19, 20, 20, 21, 21, 22, 22, 22, 23, 24}},
      {75, {13, 13, 14, 15, 15, 16, 16, 17, 17, 18, 18, 19, 20, 20, 21, 21, 22, 22, 23, 23, 24, 24, 25, 26}},
      {80, {14, 14, 15, 16, 16, 17, 17, 18, 19, 19, 20, 20, 21, 22, 22, 23, 23, 24, 25, 25, 26, 26, 27, 28}},
      {85, {15, 15, 16, 17, 17, 18, 19, 19, 20, 20, 21, 22, 22, 23, 24, 24, 25, 26, 26, 27, 28, 28, 29, 30}},
      {89, {15, 16, 17, 17, 18, 19, 19, 20, 21, 21, 22, 23, 24, 24, 25, 26, 26, 27, 28, 28, 29, 30, 30, 31}},
      {90, {16, 16, 17, 18, 18, 19, 20, 20, 21, 22, 22, 23, 24, 25, 25, 26, 27, 27, 28, 29, 29, 30, 31, 32}},
  };
  for (const auto& [ang, row] : table)
    for (int l = 0; l < 24; ++l) {
      const auto r = pom::layers(vz_of_angle(ang), static_cast<uint32_t>(kCodes[l]));
      EXPECT_EQ(r.n, static_cast<uint32_t>(row[static_cast<size_t>(l)])) << ang << " deg, level " << l;
      EXPECT_FALSE(r.neg);
      // The same view from behind gives the same N and raises neg.
      const auto b = pom::layers(-vz_of_angle(ang), static_cast<uint32_t>(kCodes[l]));
      EXPECT_EQ(b.n, r.n);
      EXPECT_EQ(b.neg, ang != 90);  // vz = 0 is not negative
    }
}

TEST(PomLayers, DivideBy255IsExactOverItsRange) {
  for (uint32_t y = 0; y < (1u << fmt::kPomQW); ++y) ASSERT_EQ(pom::div255(y), y / 255) << y;
}

TEST(PomLayers, RomIsMonotonicWithExactEnds) {
  const auto& t = pom::f_table();
  ASSERT_EQ(t.size(), static_cast<size_t>(pom::kRomSize));
  EXPECT_EQ(t.front(), 1u << fmt::kPomFF);  // F(|Vz| = 0) = 1: N = 32 at C = 1 is reachable
  EXPECT_EQ(t.back(), 0u);                  // F(|Vz| = 1) = 0: head-on gives Nmin
  for (size_t i = 1; i < t.size(); ++i) EXPECT_LT(t[i], t[i - 1]) << i;
  for (size_t i = 0; i < t.size(); ++i) {
    const double exact = std::ldexp(std::pow(1.0 - std::ldexp(double(i), -fmt::kPomIdxF), 0.8), fmt::kPomFF);
    EXPECT_LE(std::fabs(double(t[i]) - exact), 0.5) << i;
    EXPECT_LT(t[i], 1u << fmt::kPomFW);
  }
}

TEST(PomLayers, ExhaustiveOverIndexAndCodeAgainstFloatFormula) {
  // Domain: every ROM index x every complexity code (2049 x 256), default 4/32. The float
  // formula at |Vz| = idx/2^11 differs from the unit only through F's rounding (|dF| <= 2^-17,
  // so |dN| <= 28 * 2^-17 = 2.1e-4): any difference must sit that close to an integer.
  int diffs = 0, maxerr = 0;
  const double tol = 28.0 * std::ldexp(1.0, -fmt::kPomFF - 1);
  for (uint32_t idx = 0; idx < static_cast<uint32_t>(pom::kRomSize); ++idx)
    for (uint32_t c = 0; c < 256; ++c) {
      double exact = 0;
      const uint32_t ref = pom::layers_ref(std::ldexp(double(idx), -fmt::kPomIdxF), c / 255.0,
                                           4, 32, &exact);
      const uint32_t got = pom::layers_idx(idx, c);
      const int e = std::abs(int(got) - int(ref));
      maxerr = std::max(maxerr, e);
      if (e) {
        ++diffs;
        EXPECT_LT(std::fabs(exact - std::round(exact)), tol) << idx << "," << c;
      }
    }
  EXPECT_LE(maxerr, 1);
  std::printf("pom_layers exhaustive (idx, code): %d of %d differ from the float formula, max %d layer\n",
              diffs, pom::kRomSize * 256, maxerr);
}

TEST(PomLayers, ExhaustiveOverVzCodeAndCodeAgainstFloatFormula) {
  // Domain: all 2^16 Vz codes x 256 codes (16.8M pairs), default 4/32, against the float formula
  // at the real |Vz|. Differences (max 1 layer) come from quantising |Vz| to 11 bits; each one
  // must be explained: the formula at the index's own |Vz| gives the unit's N.
  int64_t diffs = 0;
  int maxerr = 0;
  int64_t unexplained = 0;
  for (int32_t v = -(1 << 15); v < (1 << 15); ++v) {
    const double a = std::ldexp(double(v), -fmt::kPomVzF);
    const uint32_t idx = pom::vz_index(v);
    const double aq = std::ldexp(double(idx), -fmt::kPomIdxF);
    for (uint32_t c = 0; c < 256; ++c) {
      const uint32_t got = pom::layers(v, c).n;
      const uint32_t ref = pom::layers_ref(a, c / 255.0);
      if (got != ref) {
        ++diffs;
        maxerr = std::max(maxerr, std::abs(int(got) - int(ref)));
        if (pom::layers_ref(aq, c / 255.0) != got && pom::layers_idx(idx, c) == got) {
          // allowed only through the F rounding already bounded in the (idx, code) test
          double ex = 0;
          pom::layers_ref(aq, c / 255.0, 4, 32, &ex);
          if (std::fabs(ex - std::round(ex)) >= 28.0 * std::ldexp(1.0, -fmt::kPomFF - 1)) ++unexplained;
        }
      }
    }
  }
  EXPECT_LE(maxerr, 1);
  EXPECT_EQ(unexplained, 0);
  std::printf("pom_layers exhaustive (vz, code): %lld of %d differ, max %d layer\n",
              static_cast<long long>(diffs), (1 << 16) * 256, maxerr);
}

TEST(PomLayers, EdgeCases) {
  const int32_t one = 1 << fmt::kPomVzF;
  // Vz -> 0 (grazing): F = 1, N spans Nmin..Nmax/2 + ... = 16..32 by complexity.
  EXPECT_EQ(pom::layers(0, 0).n, 16u);
  EXPECT_EQ(pom::layers(0, 255).n, 32u);
  EXPECT_EQ(pom::layers(3, 255).n, 32u);  // |Vz| = 3*2^-14 rounds to index 0: F = 1
  EXPECT_EQ(pom::layers(4, 255).n, 31u);  // 4*2^-14 rounds (half up) to index 1: N = 31.989
  // Head-on: N = Nmin whatever the complexity; |Vz| > 1 (unnormalised input) saturates to 1.
  for (int32_t v : {one, one - 1, one + 1, 2 * one - 1, -one, -2 * one})
    for (uint32_t c : {0u, 255u}) EXPECT_EQ(pom::layers(v, c).n, 4u) << v;
  // Vz < 0: |Vz| is used and neg is raised, including the most negative code.
  EXPECT_TRUE(pom::layers(-1, 0).neg);
  EXPECT_TRUE(pom::layers(-(1 << 15), 0).neg);
  EXPECT_EQ(pom::layers(-(1 << 15), 255).n, 4u);
  // C = 0 and C = 255 are the N_T,min and N_T,max ends (note Table 2.2 at 45 and 80 degrees).
  EXPECT_EQ(pom::layers(vz_of_angle(45), 0).n, 8u);
  EXPECT_EQ(pom::layers(vz_of_angle(45), 255).n, 14u);
  EXPECT_EQ(pom::layers(vz_of_angle(80), 0).n, 14u);
  EXPECT_EQ(pom::layers(vz_of_angle(80), 255).n, 28u);
  // Clamp and degenerate configurations: N always in [max(Nmin,1), max(Nmax, lo)].
  EXPECT_EQ(pom::layers(0, 255, 0, 0).n, 1u);
  EXPECT_EQ(pom::layers(0, 0, 63, 63).n, 63u);
  EXPECT_EQ(pom::layers(0, 255, 63, 0).n, 63u);
  EXPECT_EQ(pom::layers(0, 0, 16, 8).n, 16u);  // Nmin > Nmax/2: formula falls, clamp holds it
  EXPECT_EQ(pom::layers(one, 0, 1, 50).n, 1u);
  EXPECT_EQ(pom::layers(0, 255, 1, 50).n, 50u);
}

TEST(PomLayers, RandomConfigurationsMatchTheExactRational) {
  // For any Nmin, Nmax the unit equals the exact floor of Nmin + f*T/(510*2^16), clamped.
  std::mt19937_64 rng(7);
  for (int i = 0; i < 200000; ++i) {
    const uint64_t r = rng();
    const auto v = static_cast<int32_t>(static_cast<int16_t>(r & 0xffff));
    const auto c = static_cast<uint32_t>((r >> 16) & 0xff);
    const auto nmin = static_cast<uint32_t>((r >> 24) & 63), nmax = static_cast<uint32_t>((r >> 30) & 63);
    const int64_t f = pom::f_table()[pom::vz_index(v)];
    const int64_t num = int64_t(nmin) * 510 * 65536 + f * (255 * (int64_t(nmax) - 2 * nmin) + int64_t(nmax) * c);
    const int64_t den = 510 * 65536;
    int64_t n = num >= 0 ? num / den : -((-num + den - 1) / den);
    const int64_t lo = std::max<int64_t>(nmin, 1), hi = std::max<int64_t>(nmax, lo);
    n = std::clamp(n, lo, hi);
    ASSERT_EQ(pom::layers(v, c, nmin, nmax).n, static_cast<uint32_t>(n)) << v << " " << c << " " << nmin << " " << nmax;
  }
}

}  // namespace
