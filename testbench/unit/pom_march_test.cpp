// POM march + refinement and iterative parallax (seed-000 note §1.3, §5; seed-002 note).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "pom/pom_march.hpp"
#include "pom/relief_quality.hpp"
#include "reciprocal/reciprocal.hpp"

namespace {
using namespace tu;
using namespace tu::pom;

constexpr int kF = fmt::kPomVzF;
View view_deg(double th_deg, double ph_deg = 30, double s = 0.05) {
  const double th = th_deg * M_PI / 180, ph = ph_deg * M_PI / 180;
  View v;
  v.vx = static_cast<int32_t>(std::lround(std::sin(th) * std::cos(ph) * (1 << kF)));
  v.vy = static_cast<int32_t>(std::lround(std::sin(th) * std::sin(ph) * (1 << kF)));
  v.vz = static_cast<int32_t>(std::lround(std::cos(th) * (1 << kF)));
  v.scale = static_cast<uint32_t>(std::lround(s * 65536));
  return v;
}
img::Gray8 flat(uint8_t c) { return img::Gray8(16, 16, c); }

TEST(PomMarch, DepthZeroEverywhereNoShift) {
  const auto d = flat(0);
  for (uint32_t n : {1u, 4u, 32u, 63u}) {
    const auto r = march(d, 12345, 54321, view_deg(80), n, false);
    EXPECT_EQ(r.steps, 0u);
    EXPECT_EQ(r.w, 0u);
    EXPECT_EQ(r.u, 12345);
    EXPECT_EQ(r.v, 54321);
    EXPECT_FALSE(r.discard);
  }
}

TEST(PomMarch, DepthOneEverywhereMarchesNStepsToTMinusP) {
  const auto d = flat(255);
  const View vw = view_deg(60);
  const auto p = parallax(vw);
  for (uint32_t n = 1; n <= 63; ++n) {
    const auto r = march(d, 30000, 30000, vw, n, false);
    EXPECT_EQ(r.steps, n);
    EXPECT_EQ(r.w, 0u);  // exact hit on the last layer: a = 255N - 255N = 0
    // T'' = T - N*dT; dT = round(P/N): |N*dT - P| <= N/2 + faithful-reciprocal slack
    EXPECT_LE(std::llabs(30000 - r.u - p.pu), int64_t(n)) << n;
    EXPECT_LE(std::llabs(30000 - r.v - p.pv), int64_t(n)) << n;
  }
}

TEST(PomMarch, FlatMapHitsExactDepthAnyCode) {
  // Constant depth c: exit at k = ceil(c*N/255) (the exact integer rule, no float N+1 quirk),
  // and the refinement lands on T - (c/255)*P within a few LSB.
  const View vw = view_deg(70);
  const auto p = parallax(vw);
  for (int c : {1, 51, 85, 102, 128, 153, 170, 204, 254})
    for (uint32_t n : {4u, 12u, 19u, 23u, 24u, 25u, 27u, 28u, 31u, 32u}) {
      const auto r = march(flat(static_cast<uint8_t>(c)), 40000, 20000, vw, n, false);
      EXPECT_EQ(r.steps, static_cast<uint32_t>((c * int(n) + 254) / 255)) << c << " " << n;
      const double eu = 40000 - c / 255.0 * p.pu, ev = 20000 - c / 255.0 * p.pv;
      EXPECT_NEAR(double(r.u), eu, 1.0 + n / 2.0) << c << " " << n;
      EXPECT_NEAR(double(r.v), ev, 1.0 + n / 2.0) << c << " " << n;
    }
}

TEST(PomMarch, VzToZeroIsGuardedAndVzNegativeMirrors) {
  const auto d = flat(255);
  View v0;
  v0.vx = 1 << kF;
  v0.vy = 0;
  v0.scale = 3277;
  for (int32_t vz : {0, 1, -1, fmt::kPomVzMin - 1}) {
    v0.vz = vz;
    const auto p = parallax(v0);
    EXPECT_TRUE(p.clamped) << vz;
    EXPECT_EQ(p.back, vz < 0);
    // |P| = S / 2^-5 = 32 S
    EXPECT_NEAR(double(p.pu), 32.0 * 3277, 2.0);
    const auto r = march(d, 0, 0, v0, 32, true);
    EXPECT_EQ(r.steps, 32u);
    EXPECT_GE(r.u, 0);
    EXPECT_LT(r.u, kUvOne);
  }
  v0.vz = fmt::kPomVzMin;
  EXPECT_FALSE(parallax(v0).clamped);
  // Vz < 0 gives the same march as +|Vz| (mirrored), with `back` raised.
  const auto hm = map_bricks(64);
  for (double ang : {30.0, 60.0, 85.0}) {
    View a = view_deg(ang), b = a;
    b.vz = -a.vz;
    for (int64_t u : {1000, 33000, 60000}) {
      const auto ra = march(hm, u, 777, a, 16, true), rb = march(hm, u, 777, b, 16, true);
      EXPECT_EQ(ra.u, rb.u);
      EXPECT_EQ(ra.v, rb.v);
      EXPECT_EQ(ra.steps, rb.steps);
      EXPECT_FALSE(ra.back);
      EXPECT_TRUE(rb.back);
    }
  }
}

TEST(PomMarch, DegenerateViewVectorNoShift) {
  View v;
  v.vx = v.vy = v.vz = 0;  // camera at the surface point
  v.scale = 60000;
  const auto hm = map_noisy(32);
  for (int64_t u : {0, 5000, 65535}) {
    const auto r = march(hm, u, 100, v, 8, false);
    EXPECT_EQ(r.u, u);
    EXPECT_EQ(r.v, 100);
    EXPECT_LE(r.steps, 8u);
  }
}

TEST(PomMarch, DiscardOutsideUnitSquareWrapOtherwise) {
  const auto d = flat(255);
  const View vw = view_deg(80, 0, 0.2);  // P ~ +1.13 in u: T - P leaves [0,1]
  const auto r = march(d, 1000, 30000, vw, 8, false);
  EXPECT_TRUE(r.discard);
  EXPECT_LT(r.u, 0);
  const auto w = march(d, 1000, 30000, vw, 8, true);
  EXPECT_FALSE(w.discard);
  EXPECT_EQ(w.u, r.u & (kUvOne - 1));
  EXPECT_FALSE(march(d, 65000, 30000, view_deg(5, 0, 0.01), 8, false).discard);
}

TEST(PomMarch, AgreesWithFloatReferenceSameN) {
  // Same N: the fixed-point march and the double reference take the same number of steps except
  // where dT's rounding moves a sample across a texel edge (< 1%). When the steps agree both
  // results lie on the same segment [T_k, T_k + dT], so |error| <= |dT| + N + 2 LSB (dT's
  // rounding accumulates over k <= N steps); most are within a few LSB.
  const auto hm = map_smooth(64);
  std::mt19937 rng(5);
  int same = 0, total = 0, close = 0;
  for (int t = 0; t < 3000; ++t) {
    const View vw = view_deg(std::uniform_real_distribution<double>(0, 80)(rng),
                             std::uniform_real_distribution<double>(0, 360)(rng), 0.05);
    const int64_t u = rng() & 0xffff, v = rng() & 0xffff;
    const uint32_t n = 1 + rng() % 63;
    const auto r = march(hm, u, v, vw, n, true);
    const auto f = march_ref(hm, u / 65536.0, v / 65536.0, vw.vx / 16384.0, vw.vy / 16384.0,
                             vw.vz / 16384.0, vw.scale / 65536.0, n);
    ++total;
    if (r.steps != f.steps) continue;
    ++same;
    const auto p = parallax(vw);
    const double bound = std::max(std::fabs(double(p.pu)), std::fabs(double(p.pv))) / n + n + 2;
    auto wrapd = [](double x) { return std::min(std::fabs(x), 65536 - std::fabs(x)); };
    const double e = std::max(wrapd(r.u - f.u * 65536), wrapd(r.v - f.v * 65536));
    EXPECT_LE(e, bound) << t;
    close += e <= n + 2;
  }
  EXPECT_GE(same, total * 99 / 100);
  EXPECT_GE(close, same * 95 / 100);
  std::printf("march vs ref: %d/%d same steps, %d within N+2 LSB\n", same, total, close);
}

TEST(IterParallax, FlatMapConvergesAndDepthZeroIsNoShift) {
  const View vw = view_deg(45);
  // depth 0: d_0 = 0 -> converged, no update
  auto r = iter_parallax(flat(0), 1234, 4321, ipx_dir_seed(vw));
  EXPECT_EQ(r.iters, 0u);
  EXPECT_FALSE(r.nonconv);
  EXPECT_EQ(r.u, 1234);
  // flat c: the normalised direction lands in one step; the seed direction contracts by (1-Vz)
  const auto pn = ipx_dir_normalised(vw);
  r = iter_parallax(flat(128), 30000, 30000, pn);
  EXPECT_EQ(r.iters, 1u);
  EXPECT_NEAR(double(r.u), 30000 - 128 * 257 / 65536.0 * pn.su, 1.0);
  r = iter_parallax(flat(128), 30000, 30000, ipx_dir_seed(vw));
  EXPECT_FALSE(r.nonconv);
  EXPECT_GT(r.iters, 1u);
  EXPECT_LE(r.iters, 16u);
  // depth 1 at grazing with the seed direction: too slow for the cap -> flagged
  r = iter_parallax(flat(255), 30000, 30000, ipx_dir_seed(view_deg(85)));
  EXPECT_TRUE(r.nonconv);
  EXPECT_EQ(r.iters, static_cast<uint32_t>(fmt::kIpxCap));
}

TEST(IterParallax, SteepReliefOscillatesAndIsFlagged) {
  // A step: the ray enters over depth 0.05 next to a wall of depth 1; with the normalised
  // direction the fixed-point iteration jumps across the step and back.
  img::Gray8 st(64, 64);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) st.at(x, y) = (x / 8) % 2 ? 255 : 13;
  const auto dir = ipx_dir_normalised(view_deg(80, 0, 0.1));
  int flagged = 0;
  for (int x = 0; x < 64; ++x) {
    const auto r = iter_parallax(st, (int64_t(2 * x + 1) << 16) / 128, 100, dir);
    flagged += r.nonconv;
    if (!r.nonconv) {
      // converged: |d| < eps at the returned point
      EXPECT_LT(r.iters, static_cast<uint32_t>(fmt::kIpxCap));
    }
  }
  EXPECT_GT(flagged, 0);
  EXPECT_LT(flagged, 64);
}

}  // namespace

namespace {
TEST(ReliefQuality, TableInvariants) {
  // Small scene (32x32): head-on every method is exact; at 80 deg 32 layers beat 4 layers;
  // adaptive uses N = Nmin = 4 head-on (the same steps as N = 4); steps grow with N.
  tu::pom::QualityParams p;
  p.side = 32;
  p.angles = {0, 80};
  const auto rows = tu::pom::quality(p);
  ASSERT_EQ(rows.size(), 3u * 2u * 8u);
  auto get = [&](const std::string& m, double a, const std::string& meth) {
    for (const auto& r : rows)
      if (r.map == m && r.angle == a && r.method == meth) return r;
    ADD_FAILURE() << m << " " << a << " " << meth;
    return tu::pom::QualityRow{};
  };
  for (const char* m : {"smooth", "bricks", "noisy"}) {
    for (const char* meth : {"N=4", "N=32", "adaptive", "iter-seed", "iter-norm"})
      EXPECT_TRUE(std::isinf(get(m, 0, meth).psnr)) << m << " " << meth;
    EXPECT_EQ(get(m, 0, "adaptive").steps, get(m, 0, "N=4").steps) << m;
    EXPECT_GT(get(m, 80, "N=32").psnr, get(m, 80, "N=4").psnr) << m;
    EXPECT_GT(get(m, 80, "N=32").steps, get(m, 80, "N=8").steps) << m;
    EXPECT_GT(get(m, 80, "N=8").steps, get(m, 80, "N=4").steps) << m;
    EXPECT_NEAR(get(m, 80, "N=4").fetches, get(m, 80, "N=4").steps + 1, 1e-12);
  }
}
}  // namespace

// tu_pom_refine's stage 5 (rtl/pom/tu_pom_refine.sv) computes w without a shifter and without a
// compare after the product: a' = a << (DW - 1 - p) (p = msb of den), w = (a' R + 2^22) >> 23, and
// min(., 2^WF) replaced by the flag a >= den (a != 0). This checks, for every den of the 16-bit
// port, that the C model's unclamped w is >= 2^WF at a = den and <= 2^WF at a = den - 1 (w grows
// with a, so the clamp acts exactly when a >= den), and that the RTL's form equals refine()'s w at
// a = 0, 1, den / 2, den - 1, den, den + 1 and 8 random a per den.
TEST(PomMarch, RefineClampIsTheCompareAGeDen) {
  constexpr int kDW = fmt::kPomDenW, kWF = fmt::kPomWF;
  constexpr int64_t kOne = int64_t(1) << kWF;
  auto unclamped = [](int64_t a, int64_t den) {
    const auto r = recip::eval(static_cast<int32_t>(den));
    const int sh = static_cast<int>(r.shift) + fmt::kRecipOutF;
    return ((a << kWF) * int64_t(r.mant) + (int64_t(1) << (sh - 1))) >> sh;
  };
  auto rtl_w = [&](int64_t a, int64_t den) -> int64_t {
    if (a >= den && a != 0) return kOne;
    const auto r = recip::eval(static_cast<int32_t>(den));
    const int64_t as = (a << (kDW - 1 - static_cast<int>(r.shift))) & ((int64_t(1) << kDW) - 1);
    constexpr int xsh = kDW - 1 + fmt::kRecipOutF - kWF;
    return ((as * int64_t(r.mant) + (int64_t(1) << (xsh - 1))) >> xsh) & ((int64_t(1) << (kWF + 1)) - 1);
  };
  std::mt19937_64 rng(14);
  uint64_t checked = 0;
  for (int64_t den = 1; den < (int64_t(1) << kDW); ++den) {
    ASSERT_GE(unclamped(den, den), kOne) << den;
    ASSERT_LE(unclamped(den - 1, den), kOne) << den;
    std::vector<int64_t> as = {0, 1, den / 2, den - 1, den, den + 1};
    for (int i = 0; i < 8; ++i) as.push_back(static_cast<int64_t>(rng() % (uint64_t(1) << kDW)));
    for (int64_t a : as) {
      a &= (int64_t(1) << kDW) - 1;
      MarchCore c;
      c.steps = 1;
      c.a = static_cast<uint32_t>(a);
      c.den = static_cast<uint32_t>(den);
      ASSERT_EQ(rtl_w(a, den), int64_t(refine(c, 0, 0, true).w)) << "a " << a << " den " << den;
      ++checked;
    }
  }
  // den = 0 (outside the march's range): the C model's reciprocal saturates, w = 2^WF for a > 0.
  for (int64_t a : {int64_t(0), int64_t(1), int64_t(65535)}) {
    MarchCore c;
    c.steps = 1;
    c.a = static_cast<uint32_t>(a);
    EXPECT_EQ(rtl_w(a, 0), int64_t(refine(c, 0, 0, true).w)) << a;
  }
  EXPECT_EQ(checked, uint64_t((int64_t(1) << kDW) - 1) * 14);
}
