// B2 fixed-point model: recurrences == direct (bit-exact), log2/isqrt units, analytic and
// forward-difference variants against the float reference, and the curated stiff cases.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "ellipse/ellipse_fx.hpp"
#include "reciprocal/reciprocal.hpp"

namespace {
using namespace tu;
using namespace tu::ellipse;
namespace fx = tu::ellipse::fx;


TEST(EllipseFx, RecurrencesEqualDirectBitExact) {
  std::mt19937_64 rng(7);
  for (int t = 0; t < 40; ++t) {
    const int y = static_cast<int>(rng() % 4096), x0 = static_cast<int>(rng() % 3000), n = 1000;
    const auto k = persp::random_span_map(rng, y, x0, x0 + n - 1, 1.0, 0.01);
    const auto c = persp::Unit::quantise(k, "t");
    const auto span = fx::numerators_span(c, x0, y, n);
    for (int i = 0; i < n; i += 37) {
      const auto d = fx::numerators_direct(c, x0 + i, y);
      ASSERT_TRUE(d.nux == span[i].nux && d.nvx == span[i].nvx && d.nuy == span[i].nuy &&
                  d.nvy == span[i].nvy);
    }
    ASSERT_TRUE(fx::numerators_direct(c, x0 + n - 1, y).nuy == span[n - 1].nuy);
  }
}

TEST(EllipseFx, Log2AndIsqrtUnits) {
  std::mt19937_64 rng(3);
  for (int t = 0; t < 20000; ++t) {
    const u128 x = (u128(rng()) << 30 | (rng() >> 34)) >> (rng() % 90);
    if (x == 0) continue;
    const double l = std::ldexp(double(fx::log2_fx(x)), -(fmt::kEllLogF + 1));
    const double err = l - std::log2(static_cast<double>(x));
    ASSERT_LE(err, 1e-9);                                 // truncating: never above
    ASSERT_GT(err, -std::ldexp(1.0, -fmt::kEllLogF));  // less than two internal LSBs below
    const u128 s = x >> (rng() % 40);
    const u128 r = fx::isqrt(s);
    ASSERT_TRUE(r * r <= s && (r + 1) * (r + 1) > s);
  }
  for (uint64_t v = 1; v < 5000; ++v) ASSERT_EQ(fx::log2_fx(u128(1) << 40) - 40 * 2048, 0) << v;
}

// The table-driven log2 equals the hardware's squaring chain on every mantissa, so log2_fx and
// log2_fx_serial agree on every input (x only enters through msb and its top mantissa bits).
TEST(EllipseFx, Log2TableExhaustive) {
  const uint64_t lo = uint64_t(1) << (fmt::kEllLogMantW - 1), hi = uint64_t(1) << fmt::kEllLogMantW;
  for (uint64_t m = lo; m < hi; ++m) ASSERT_EQ(fx::log2_frac(m), fx::log2_frac_serial(m)) << m;
  std::mt19937_64 rng(11);
  for (int t = 0; t < 200000; ++t) {
    const u128 x = (u128(rng()) << 64 | rng()) >> (rng() % 128);
    if (x != 0) ASSERT_EQ(fx::log2_fx(x), fx::log2_fx_serial(x));
  }
  for (int b = 0; b < 128; ++b)
    for (const u128 x : {u128(1) << b, (u128(1) << b) + 1, (u128(1) << b) - 1, ~u128(0) >> b})
      if (x != 0) {
        ASSERT_EQ(fx::log2_fx(x), fx::log2_fx_serial(x)) << b;
      }
}

// Floating-point estimate + correction equals the bit-serial square root: random inputs of every
// length, perfect squares and their neighbours, the 2^52 / 2^104 switches and the extremes.
TEST(EllipseFx, IsqrtFastEqualsSerial) {
  std::vector<u128> xs = {0, 1, 2, 3, 4, ~u128(0), ~u128(0) - 1, u128(1) << 52,
                          (u128(1) << 52) - 1, (u128(1) << 52) + 1, u128(1) << 104,
                          (u128(1) << 104) - 1, (u128(1) << 104) + 1};
  std::mt19937_64 rng(12);
  for (int b = 1; b <= 64; ++b)
    for (int t = 0; t < 200; ++t) {
      const uint64_t k = b == 64 ? rng() : rng() >> (64 - b);
      const u128 sq = u128(k) * k;
      xs.push_back(sq);
      xs.push_back(sq + 1);
      if (sq) xs.push_back(sq - 1);
      if (k) xs.push_back(sq + 2 * u128(k));  // (k+1)^2 - 1
    }
  for (int t = 0; t < 200000; ++t) xs.push_back((u128(rng()) << 64 | rng()) >> (rng() % 128));
  for (const u128 x : xs) ASSERT_EQ(fx::isqrt(x), fx::isqrt_serial(x));
}

struct Stat {
  double lod = 0, lmaj = 0, lmin = 0, rel_a = 0, rel_f = 0;
  int n = 0;
};

// Random local maps (the block's random set): fixed analytic vs float analytic on the same codes.
Stat analytic_study(int count, uint64_t seed) {
  std::mt19937_64 rng(seed);
  Stat st;
  FootprintParams fp;
  while (st.n < count) {
    const auto in = fx::in_from_map(fx::local_map(fx::random_local(rng)));
    const auto o = fx::analytic(in);
    const double q = std::ldexp(double(in.q), -fmt::kPerspF);
    auto nf = [&](int64_t c) { return std::ldexp(double(c), -fmt::kEllNumF); };
    const Numerators n{nf(in.nux), nf(in.nvx), nf(in.nuy), nf(in.nvy), q};
    const double q2 = q * q;
    const auto f = footprint({n.nux / q2, n.nvx / q2, n.nuy / q2, n.nvy / q2}, fp);
    EXPECT_EQ(o.flags & fx::kHorizon, 0u);
    st.lod = std::max(st.lod, std::fabs(fx::lod_value(o) - f.lod));
    st.lmaj = std::max(st.lmaj, std::fabs(fx::log_value(o.lmaj) - std::log2(f.major)));
    if (!(o.flags & (fx::kDegenerate | fx::kMagnify)))  // magnified: tiny numerators, lod 0
      st.lmin = std::max(st.lmin, std::fabs(fx::log_value(o.lmin) - std::log2(f.minor_clamped)));
    const auto e4 = ellipse_q4(n, fx::det3_value(in), 1 / q);
    const double ae = fx::coef_value(double(o.ae), o);
    st.rel_a = std::max(st.rel_a, std::fabs(ae - e4.ae) / e4.ae);
    st.rel_f = std::max(st.rel_f, std::fabs(fx::fe_value(o) - e4.fe) / e4.fe);
    ++st.n;
  }
  return st;
}

TEST(EllipseFx, AnalyticMatchesFloatReference) {
  const Stat s = analytic_study(4000, 11);
  std::printf("analytic fixed vs float: max |lod err| %.5f levels, |log2 major err| %.5f, "
              "|log2 minor_c err| (lod > 0) %.5f, rel Ae' %.3g, rel Fe' %.3g (%d px)\n",
              s.lod, s.lmaj, s.lmin, s.rel_a, s.rel_f, s.n);
  EXPECT_LT(s.lod, 0.006);
  EXPECT_LT(s.lmaj, 0.003);
  EXPECT_LT(s.lmin, 0.003);
}

}  // namespace

namespace {
fx::Local local(double q, double major, double aniso, double theta) {
  fx::Local l;
  l.q = q;
  const double c = std::cos(theta), s = std::sin(theta), minor = aniso > 0 ? major / aniso : 0;
  l.ux = c * major;
  l.vx = s * major;
  l.uy = -s * minor;
  l.vy = c * minor;
  l.u = 100;
  l.v = -200;
  return l;
}
fx::Out run(const fx::Local& l, uint32_t laniso = 4 << fmt::kEllLogF, uint32_t max_lod = 12) {
  return fx::analytic(fx::in_from_map(fx::local_map(l), laniso, max_lod));
}

// Stiff case 1: grazing planes, anisotropy 1:1000 before the clamp -> minor grown to major/16,
// lod = log2(major) - 4, flag kAnisoClamp, every orientation.
TEST(EllipseFxStiff, GrazingAnisotropyClamped) {
  for (double an : {100.0, 1000.0})
    for (int t = 0; t < 16; ++t) {
      const auto o = run(local(0.05, 64, an, t * M_PI / 16));
      EXPECT_EQ(o.flags, fx::kAnisoClamp);
      EXPECT_NEAR(fx::log_value(o.lmaj), 6.0, 0.003);
      EXPECT_EQ(o.lmin, o.lmaj - (4 << fmt::kEllLogF));
      EXPECT_NEAR(fx::lod_value(o), 2.0, 0.005);
    }
  // Below the limit the clamp does not act: 1:10 -> lod = log2(6.4).
  const auto o = run(local(0.05, 64, 10, 0.3));
  EXPECT_EQ(o.flags, 0u);
  EXPECT_NEAR(fx::lod_value(o), std::log2(6.4), 0.005);
  // Clamp ratio 1:1: the LOD follows the major axis.
  EXPECT_NEAR(fx::lod_value(run(local(0.3, 50, 40, 1.3), 0)), std::log2(50.0), 0.005);
}

// Stiff case 2: footprint larger than the texture: lod saturates at max_lod, flag kLodSat.
TEST(EllipseFxStiff, HugeFootprintSaturates) {
  for (uint32_t ml : {12u, 8u, 0u}) {
    const auto o = run(local(0.01, 8192, 1, 0.3), 4 << fmt::kEllLogF, ml);
    EXPECT_EQ(o.flags, fx::kLodSat);
    EXPECT_EQ(o.lod, ml << fmt::kEllLodF);
    EXPECT_NEAR(fx::log_value(o.lmin), 13.0, 0.003);
  }
}

// Stiff case 3: degenerate footprints. A line (det3 = 0): kDegenerate | kAnisoClamp, minor =
// major / 16. A point (J = 0): kDegenerate | kMagnify, lod 0, axes -inf.
TEST(EllipseFxStiff, DegenerateLineAndPoint) {
  const auto line = run(local(0.5, 32, 0, 0.7));
  EXPECT_EQ(line.flags, fx::kDegenerate | fx::kAnisoClamp);
  EXPECT_EQ(line.fm, 0u);
  EXPECT_NEAR(fx::lod_value(line), 1.0, 0.005);
  fx::Local p = local(0.5, 1, 1, 0);
  p.ux = p.vx = p.uy = p.vy = 0;
  const auto pt = run(p);
  EXPECT_EQ(pt.flags, fx::kDegenerate | fx::kMagnify);
  EXPECT_EQ(pt.lod, 0u);
  EXPECT_EQ(pt.lmaj, fx::kLogNegInf);
  EXPECT_EQ(pt.ae | pt.ce, 0u);
}

// Stiff case 4: horizon. q below the guard 2^-10 (incl. 0 and negative): kHorizon, all else 0.
// Just above the guard the unit works normally (no saturation of the formats).
TEST(EllipseFxStiff, Horizon) {
  auto in = fx::in_from_map(fx::local_map(local(0.001, 900, 3, 0.2)));
  for (int64_t q : {(int64_t(1) << 30) - 1, int64_t(0), int64_t(-5), -(int64_t(1) << 43)}) {
    in.q = q;
    const auto o = fx::analytic(in);
    EXPECT_EQ(o.flags, fx::kHorizon);
    EXPECT_EQ(o, fx::Out{.flags = fx::kHorizon});
    EXPECT_EQ(fx::forward_difference(in, 0, 0).flags, fx::kHorizon);
  }
  const auto o = run(local(std::ldexp(1.0, -10) * 1.01, 1000, 4, 0.9));
  EXPECT_EQ(o.flags & fx::kHorizon, 0u);
  EXPECT_NEAR(fx::log_value(o.lmaj), std::log2(1000.0), 0.003);
  EXPECT_NEAR(fx::lod_value(o), std::log2(250.0), 0.005);
}

// Stiff case 5: magnification (footprint below one texel): lod 0, kMagnify.
TEST(EllipseFxStiff, Magnification) {
  for (double s : {0.5, 0.1, 1.0 / 1024}) {
    const auto o = run(local(0.7, s, 1.5, 0.4));
    EXPECT_EQ(o.flags, fx::kMagnify);
    EXPECT_EQ(o.lod, 0u);
    EXPECT_NEAR(fx::log_value(o.lmaj), std::log2(s), 0.003);
  }
}

// Format extremes never reach UB (the sanitizer build runs this) and stay deterministic.
TEST(EllipseFxStiff, FormatExtremes) {
  const int64_t big = -(int64_t(1) << 47), top = (int64_t(1) << 47) - 1;
  for (int dexp : {-128, 0, 127})
    for (int64_t q : {(int64_t(1) << 43) - 1, int64_t(1) << 30}) {
      for (fx::In in : {fx::In{big, big, big, big, q, (int64_t(1) << 39) - 1, dexp, 4096, 15},
                        fx::In{top, big, big, top, q, -(int64_t(1) << 39) + 1, dexp, 4096, 15},
                        fx::In{1, 0, 0, 1, q, int64_t(1) << 38, dexp, 16383, 15}}) {
        const auto o = fx::analytic(in);
        EXPECT_EQ(o, fx::analytic(in));
        EXPECT_LE(o.lod, 15u << fmt::kEllLodF);
        fx::forward_difference(in, -(int64_t(1) << 43), (int64_t(1) << 43) - 1);
      }
    }
}

// Forward difference (corrected seed recurrences) vs analytic: the x column differs by
// q/(q+G), the y column by q/(q+H). With G = H = 0 the two agree to the fixed-point error; with
// G/q = 1/4 the major axis (along x) shrinks by log2(1.25).
TEST(EllipseFx, ForwardDifferenceDepartsByOnePlusGOverQ) {
  fx::Local l = local(0.2, 40, 4, 0);  // major along x
  auto in = fx::in_from_map(fx::local_map(l));
  const auto a = fx::analytic(in);
  const auto f0 = fx::forward_difference(in, 0, 0);
  EXPECT_NEAR(fx::log_value(f0.lmaj), fx::log_value(a.lmaj), 0.003);
  EXPECT_NEAR(fx::lod_value(f0), fx::lod_value(a), 0.005);
  l.g = 0.05;  // G/q = 1/4
  in = fx::in_from_map(fx::local_map(l));
  const auto f1 = fx::forward_difference(in, fx::q_code(0.05), 0);
  EXPECT_NEAR(fx::log_value(f1.lmaj), std::log2(40 / 1.25), 0.003);
  // Against the float forward difference of the same map.
  const auto k = fx::local_map(l);
  const auto fr = footprint(forward_difference(k, 0, 0), FootprintParams{});
  EXPECT_NEAR(fx::log_value(f1.lmaj), std::log2(fr.major), 0.003);
  EXPECT_NEAR(fx::lod_value(f1), fr.lod, 0.006);
}

// The recurrence variant (fx::recurrence, rtl/ellipse/tu_ellipse_rec.sv) runs the analytic back
// end on J with q := 1: exact only if 1/q's mantissa R(1.0) is exactly 1 (then log2 q = 0 and
// f = det J); and on the horizon of any of q, q + G, q + H it must flag and zero like analytic().
TEST(EllipseFx, RecurrenceBackEndSeesQOne) {
  EXPECT_EQ(recip::core(recip::Mant::from_raw(i128(1) << (fmt::kRecipMantW - 1))).raw(),
            i128(1) << fmt::kRecipOutF);
  std::mt19937_64 rng(11);
  for (int i = 0; i < 2000; ++i) {
    const auto l = fx::random_local(rng);
    const auto in = fx::in_from_map(fx::local_map(l));
    const int64_t qg = in.q + fx::q_code(l.g), qh = in.q + fx::q_code(l.h);
    const auto f = fx::rec_front(in, qg, qh);
    EXPECT_EQ(f.q, int64_t(1) << fmt::kPerspF);
    const auto o = fx::recurrence(in, qg, qh);
    // Fe' = (det J)^2: |f| = |det J| truncated to EllFmW bits
    const double dj = std::ldexp(double(f.nux), -fmt::kEllNumF) * std::ldexp(double(f.nvy), -fmt::kEllNumF) -
                      std::ldexp(double(f.nuy), -fmt::kEllNumF) * std::ldexp(double(f.nvx), -fmt::kEllNumF);
    if (dj != 0) {
      EXPECT_NEAR(std::sqrt(fx::fe_value(o)) / std::fabs(dj), 1.0, 1e-8);
    }
  }
  const int64_t guard = int64_t(1) << (fmt::kPerspF - fmt::kPerspGuardLog2);
  const auto in = fx::in_from_map(fx::local_map(local(0.01, 300, 6, 0.4)));
  for (auto [qg, qh] : {std::pair{guard - 1, in.q}, std::pair{in.q, guard - 1}, std::pair{int64_t(0), in.q},
                        std::pair{in.q, -(int64_t(1) << 44)}}) {
    EXPECT_EQ(fx::recurrence(in, qg, qh), fx::Out{.flags = fx::kHorizon});
  }
  EXPECT_EQ(fx::recurrence(in, guard, guard).flags & fx::kHorizon, 0u);  // at the guard: not flagged
}

// Error / cost study for docs/blocks/ellipse.md (printed; bounds asserted): random local maps,
// each variant against the float analytic reference.
TEST(EllipseFx, VariantStudy) {
  std::mt19937_64 rng(2026);
  FootprintParams fp;
  double fd_float_lod = 0, fd_float_maj = 0, fd_fx_lod = 0, fd_fx_vs_float = 0, an_lod = 0, an_rel = 0;
  double gq_max = 0, fd_rel_a = 0;
  int n = 0;
  for (; n < 20000; ++n) {
    const auto l = fx::random_local(rng);
    const auto k = fx::local_map(l);
    const auto in = fx::in_from_map(k);
    const auto ref = footprint(analytic(k, 0, 0), fp);
    const auto fdf = footprint(forward_difference(k, 0, 0), fp);
    const auto a = fx::analytic(in);
    const auto f = fx::forward_difference(in, fx::q_code(l.g), fx::q_code(l.h));
    gq_max = std::max({gq_max, std::fabs(l.g / l.q), std::fabs(l.h / l.q)});
    fd_float_lod = std::max(fd_float_lod, std::fabs(fdf.lod - ref.lod));
    fd_float_maj = std::max(fd_float_maj, std::fabs(std::log2(fdf.major / ref.major)));
    fd_fx_lod = std::max(fd_fx_lod, std::fabs(fx::lod_value(f) - ref.lod));
    fd_fx_vs_float = std::max(fd_fx_vs_float, std::fabs(fx::lod_value(f) - fdf.lod));
    an_lod = std::max(an_lod, std::fabs(fx::lod_value(a) - ref.lod));
    const auto e = tu::ellipse::ellipse(analytic(k, 0, 0));
    const double q4 = std::pow(l.q, 4);
    an_rel = std::max(an_rel, std::fabs(fx::coef_value(double(a.ae), a) / q4 - e.ae) / e.ae);
    const auto ef = tu::ellipse::ellipse(forward_difference(k, 0, 0));
    fd_rel_a = std::max(fd_rel_a, std::fabs(fx::coef_value(double(f.ae), f) - ef.ae) / ef.ae);
  }
  std::printf("variant study, %d random local maps (|G|/q, |H|/q <= %.4f):\n", n, gq_max);
  std::printf("  float forward difference vs float analytic: max |lod err| %.5f, max |log2 major ratio| %.5f\n",
              fd_float_lod, fd_float_maj);
  std::printf("  fixed forward difference vs float analytic: max |lod err| %.5f; vs float FD %.5f; rel Ae %.3g\n",
              fd_fx_lod, fd_fx_vs_float, fd_rel_a);
  std::printf("  fixed analytic vs float analytic: max |lod err| %.5f; rel Ae' %.3g\n", an_lod, an_rel);
  EXPECT_LT(an_lod, 0.006);
  EXPECT_LT(fd_fx_vs_float, 0.006);
  EXPECT_GT(fd_float_maj, 0.01);  // the 1 + G/q departure is visible
}

}  // namespace
