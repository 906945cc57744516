// Perspective divide unit (B1): float reference vs ray-plane intersection, bit-identity of every
// traversal variant, the drift study that proves the widths, guards and set-up errors.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "persp/persp.hpp"

namespace {
using namespace tu;
using namespace tu::persp;

constexpr double kTexelBound = 1.0 / 16;  // required
// Proven bound for the chosen widths (docs/blocks/persp.md, "Error bound"):
//   quantisation 2^(34-F) (1 + 2^-12) + reciprocal 2^-10 (1 + 2^-12) + output rounding 2^-9
double proven_bound(int f) {
  return std::ldexp(1.0, 34 - f) * (1 + std::ldexp(1.0, -12)) +
         std::ldexp(1.0, -10) * (1 + std::ldexp(1.0, -12)) + std::ldexp(1.0, -9);
}

Triangle tri(const char* name, std::initializer_list<double> xyzuv) {
  Triangle t;
  t.name = name;
  auto it = xyzuv.begin();
  for (auto& v : t.v) {
    for (double& p : v.p) p = *it++;
    for (double& p : v.uv) p = *it++;
  }
  return t;
}

TEST(Persp, FloatReferenceMatchesRayPlaneIntersection) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> U(-1, 1);
  int checked = 0;
  for (int scene = 0; scene < 40; ++scene) {
    Camera cam;
    cam.pos[0] = U(rng) * 3; cam.pos[1] = U(rng) * 3; cam.pos[2] = 5 + U(rng);
    cam.look_at[0] = U(rng); cam.look_at[1] = U(rng); cam.look_at[2] = U(rng);
    cam.up[0] = U(rng) * 0.3; cam.up[1] = 1; cam.up[2] = 0;
    cam.fovy_deg = 40 + 30 * (U(rng) + 1);
    cam.width = 96; cam.height = 64;
    Triangle t;
    t.name = "scene" + std::to_string(scene);
    for (auto& v : t.v) {
      for (double& p : v.p) p = U(rng) * 4;
      for (double& p : v.uv) p = (U(rng) + 1) * 512;
    }
    const Coef9 k = coefficients(cam, t);
    for (int y = 0; y < cam.height; ++y)
      for (int x = 0; x < cam.width; ++x) {
        double ur, vr;
        if (!ray_uv(cam, t, x, y, &ur, &vr)) continue;
        double u, v, q;
        eval_ref(k, x, y, &u, &v, &q);
        ASSERT_GT(q, 0) << t.name << " pixel " << x << "," << y;
        ASSERT_NEAR(u, ur, 1e-7 * (1 + std::fabs(ur))) << t.name << " pixel " << x << "," << y;
        ASSERT_NEAR(v, vr, 1e-7 * (1 + std::fabs(vr))) << t.name << " pixel " << x << "," << y;
        ++checked;
      }
  }
  EXPECT_GT(checked, 40 * 96 * 64 / 4);
}

TEST(Persp, QIsNormalisedToOneAtTheNearestVertex) {
  Camera cam;
  cam.width = 200; cam.height = 100;
  const Triangle t = tri("floor", {-1, -1, -2, 0, 0, 1, -1, -2, 64, 0, 0, -1, -20, 0, 64});
  const Coef9 k = coefficients(cam, t);
  // Vertex (-1,-1,-2) is nearest: z = 2; far vertex z = 20 -> q = 0.1 there. Check via pixels:
  // project the far vertex, q there must be ~ 2/20.
  double qmax = 0;
  for (int y = 0; y < cam.height; ++y)
    for (int x = 0; x < cam.width; ++x) {
      double u, v, q;
      eval_ref(k, x, y, &u, &v, &q);
      if (u >= 0 && v >= 0 && u + v <= 64) qmax = std::max(qmax, q);  // inside the triangle
    }
  EXPECT_LE(qmax, 1.0);
  EXPECT_GT(qmax, 0.9);
}

// Every traversal of every span gives the same bits as direct evaluation.
template <int F>
void check_variants(const typename Model<F>::Coefs& c, int y, int x0, int n, const std::string& what) {
  using M = Model<F>;
  std::vector<Pixel> d(n), inc(n), k2(n), k4(n), k8(n), two(n);
  M::span_direct(c, y, x0, n, d.data());
  M::span_incremental(c, y, x0, n, inc.data());
  M::template span_klane<2>(c, y, x0, n, k2.data());
  M::template span_klane<4>(c, y, x0, n, k4.data());
  M::template span_klane<8>(c, y, x0, n, k8.data());
  M::span_two_ended(c, y, x0, n, two.data());
  for (int i = 0; i < n; ++i) {
    ASSERT_EQ(inc[i], d[i]) << what << " incremental, pixel " << i;
    ASSERT_EQ(k2[i], d[i]) << what << " 2-lane, pixel " << i;
    ASSERT_EQ(k4[i], d[i]) << what << " 4-lane, pixel " << i;
    ASSERT_EQ(k8[i], d[i]) << what << " 8-lane, pixel " << i;
    ASSERT_EQ(two[i], d[i]) << what << " two-ended, pixel " << i;
  }
}

TEST(Persp, AllTraversalVariantsGiveIdenticalBits) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> U(0, 1);
  uint64_t pixels = 0, flagged = 0, rejected = 0;
  for (int s = 0; s < 400; ++s) {
    const int n = s < 20 ? 4096 : 1 + static_cast<int>(rng() % 700);
    const int x0 = static_cast<int>(rng() % static_cast<uint64_t>(4097 - n));
    const int y = static_cast<int>(rng() % 4096);
    // q from 1 down to 1/1000 (or crossing zero for one span in eight), u, v in [-4096, 4096].
    const double q0 = s % 8 == 7 ? 0.3 : 1.0;
    const double q1 = s % 8 == 7 ? -0.2 : std::pow(1000.0, -U(rng));
    const Coef9 k = random_span_map(rng, y, x0, x0 + n - 1, q0, q1);
    Unit::Coefs c;
    try {  // C = p_u(0, 0) extrapolated from a far-right span may not fit: set-up rejects it
      c = Unit::quantise(k, "span" + std::to_string(s));
      Unit::setup(c, y, x0, x0 + n - 1, "span");
    } catch (const SetupError& e) {
      if (rejected < 5) std::printf("rejected: %s\n", e.what());
      ++rejected;
      continue;
    }
    check_variants<fmt::kPerspF>(c, y, x0, n, "span " + std::to_string(s));
    // also at a narrow width: equivalence does not depend on precision
    check_variants<28>(Model<28>::quantise(k, "span"), y, x0, n, "F=28 span " + std::to_string(s));
    std::vector<Pixel> d(n);
    Unit::span_direct(c, y, x0, n, d.data());
    for (const auto& p : d) flagged += p.flag;
    pixels += n;
  }
  EXPECT_GT(pixels, 20u * 4096);
  EXPECT_LT(rejected, 40u);
  EXPECT_GT(flagged, 0u);  // the q-crossing spans exercised the guard
}

TEST(Persp, VariantCheckDetectsADifference) {
  // The comparison can fail: an increment off by 2^-20 changes pixels along a 4096-pixel span.
  const Coef9 k = span_map(100, 0, 4095, 1.0, 0.001, 10, 4000, -300, 2000, 0, 0.1, 0.2);
  const auto c = Unit::quantise(k, "t");
  auto bad = c;
  bad.g = Unit::Q::from_raw(c.g.raw() + (int64_t(1) << 20));
  std::vector<Pixel> d(4096), inc(4096);
  Unit::span_direct(c, 100, 0, 4096, d.data());
  Unit::span_incremental(bad, 100, 0, 4096, inc.data());
  EXPECT_NE(inc, d);
}

// ---------- drift study ----------
struct DriftCase {
  Coef9 k;
  int y;
};

std::vector<DriftCase> drift_cases() {
  // Spans of 4096 pixels (x = 0..4095), depth ratio up to 1000 (q from 1 to 1/1000 or back),
  // |u|, |v| <= 4096 texels; far ends at +-4096 texels (the worst case of the bound), random
  // rows and per-row slopes.
  std::vector<DriftCase> cs;
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> U(0, 1);
  for (int s = 0; s < 96; ++s) {
    const double ratio = s < 48 ? 1000.0 : std::pow(1000.0, U(rng));
    const bool rev = s % 2;
    const double q0 = rev ? 1 / ratio : 1.0, q1 = rev ? 1.0 : 1 / ratio;
    auto far = [&] { return (rng() % 2 ? 4096.0 : -4096.0) * (s < 24 ? 1.0 : U(rng)); };
    auto any = [&] { return (U(rng) - 0.5) * 8192; };
    const double uf = far(), vf = far(), un = any(), vn = any();
    const int y = static_cast<int>(rng() % 4096);
    cs.push_back({span_map(y, 0, 4095, q0, q1, rev ? uf : un, rev ? un : uf, rev ? vf : vn,
                           rev ? vn : vf, (U(rng) - 0.5) / 16384, (U(rng) - 0.5), (U(rng) - 0.5)),
                  y});
  }
  return cs;
}

template <int F>
double drift_max_err(const std::vector<DriftCase>& cs, uint64_t* flagged) {
  double m = 0;
  std::vector<Pixel> out(4096);
  for (const auto& dc : cs) {
    Model<F>::span_incremental(Model<F>::quantise(dc.k, "drift"), dc.y, 0, 4096, out.data());
    for (int x = 0; x < 4096; ++x) {
      if (out[x].flag) {
        ++*flagged;
        continue;
      }
      double u, v, q;
      eval_ref(dc.k, x, dc.y, &u, &v, &q);
      m = std::max({m, std::fabs(std::ldexp(static_cast<double>(out[x].u), -fmt::kPerspUvF) - u),
                    std::fabs(std::ldexp(static_cast<double>(out[x].v), -fmt::kPerspUvF) - v)});
    }
  }
  return m;
}

TEST(Persp, DriftStudyProvesTheChosenWidths) {
  const auto cs = drift_cases();
  uint64_t flagged = 0;
  const double e40 = drift_max_err<fmt::kPerspF>(cs, &flagged);
  const double e38 = drift_max_err<fmt::kPerspF - 2>(cs, &flagged);
  const double e36 = drift_max_err<fmt::kPerspF - 4>(cs, &flagged);
  const double e32 = drift_max_err<fmt::kPerspF - 8>(cs, &flagged);
  const double e28 = drift_max_err<fmt::kPerspF - 12>(cs, &flagged);
  std::printf("drift: %zu spans x 4096 px, z_far/z_near <= 1000, |u|,|v| <= 4096 texels\n", cs.size());
  std::printf("| F (fraction bits) | p width | q width | max error (texels) | proven bound |\n");
  const double es[] = {e40, e38, e36, e32, e28};
  const int fs[] = {fmt::kPerspF, fmt::kPerspF - 2, fmt::kPerspF - 4, fmt::kPerspF - 8,
                    fmt::kPerspF - 12};
  for (int i = 0; i < 5; ++i)
    std::printf("| %d | s%d.%d | s%d.%d | %.6g | %.6g |\n", fs[i],
                fs[i] + fmt::kPerspPW - fmt::kPerspF, fs[i], fs[i] + fmt::kPerspQW - fmt::kPerspF,
                fs[i], es[i], proven_bound(fs[i]));
  EXPECT_EQ(flagged, 0u);  // q >= 1/1000 > 2^-10: nothing guarded
  // Chosen widths: below the proven bound, which is below 1/16 texel.
  EXPECT_LT(proven_bound(fmt::kPerspF), kTexelBound);
  EXPECT_LT(e40, proven_bound(fmt::kPerspF));
  EXPECT_LT(e40, kTexelBound);
  for (int i = 1; i < 5; ++i) EXPECT_LT(es[i], proven_bound(fs[i])) << "F=" << fs[i];
  // The study resolves width: the narrowest is clearly worse than the chosen one and misses 1/16.
  EXPECT_GT(e28, kTexelBound);
  EXPECT_GT(e32, e40);
}

// ---------- guards and set-up errors ----------
TEST(Persp, GuardFlagsAndSaturates) {
  using Q = Unit::Q;
  const int64_t guard = int64_t(1) << (fmt::kPerspF - fmt::kPerspGuardLog2);
  const Unit::P p = Unit::P::from_double(1.5);
  for (int64_t qr : {int64_t(0), int64_t(-1), -guard, guard - 1, static_cast<int64_t>(Q::kMinRaw)}) {
    const Pixel px = Unit::pixel({p, p, Q::from_raw(qr)});
    EXPECT_TRUE(px.flag) << qr;
    EXPECT_EQ(px.u, static_cast<int64_t>(Uv::kMaxRaw));
    EXPECT_EQ(px.v, static_cast<int64_t>(Uv::kMaxRaw));
  }
  const Pixel ok = Unit::pixel({p, p, Q::from_raw(guard)});  // q = 2^-10: u = 1536
  EXPECT_FALSE(ok.flag);
  EXPECT_EQ(ok.u, int64_t(1536) << fmt::kPerspUvF);
  // Largest |u|: p near -2^13, q at the guard -> -2^23 saturates cleanly (no wrap).
  const Pixel big = Unit::pixel({Unit::P::from_raw(Unit::P::kMinRaw), p, Q::from_raw(guard)});
  EXPECT_EQ(big.u, static_cast<int64_t>(Uv::kMinRaw));
}

TEST(Persp, SetupOverflowNamesTheTriangle) {
  Coef9 k = span_map(0, 0, 100, 1, 0.5, 0, 10, 0, 10, 0, 0, 0);
  k.g = 9.0;  // |G| >= 8 does not fit s44.40
  try {
    Unit::quantise(k, "tri#17");
    FAIL() << "no SetupError";
  } catch (const SetupError& e) {
    EXPECT_NE(std::string(e.what()).find("tri#17"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("coefficient G"), std::string::npos) << e.what();
  }
  // Coefficients fit, but p_u at the far end of the span does not (|p| >= 2^13).
  const Coef9 k2 = span_map(0, 0, 4095, 1, 1, 0, 8191.9, 0, 0, 0, 0, 0);
  const auto c2 = Unit::quantise(k2, "wide");
  EXPECT_NO_THROW(Unit::setup(c2, 0, 0, 4095, "wide"));
  const auto c3 = Unit::quantise(span_map(0, 0, 4095, 1, 1.5, 0, 8000, 0, 0, 0, 0, 0), "tri#3");
  try {
    Unit::setup(c3, 0, 0, 4095, "tri#3");
    FAIL() << "no SetupError";
  } catch (const SetupError& e) {
    EXPECT_NE(std::string(e.what()).find("tri#3"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("p_u at pixel (4095, 0)"), std::string::npos) << e.what();
  }
  // A triangle whose plane contains the eye.
  Camera cam;
  EXPECT_THROW(coefficients(cam, tri("edge-on", {0, 0, -1, 0, 0, 0, 0, -2, 1, 0, 0, 1, -3, 0, 1})),
               SetupError);
}

// The hardware set-up's flag (setup_span, vectors of block persp_setup) is the software path's
// SetupError: same condition, same accumulators, and it names the same failure.
TEST(Persp, SetupSpanFlagMatchesSetupError) {
  const auto c3 = Unit::quantise(span_map(0, 0, 4095, 1, 1.5, 0, 8000, 0, 0, 0, 0, 0), "tri#3");
  const auto s3 = Unit::setup_span(c3, 0, 0, 4095);
  EXPECT_TRUE(s3.ovf);
  EXPECT_STREQ(s3.what, "p_u");
  EXPECT_EQ(s3.at, 4095);
  std::mt19937_64 rng(5);
  int flagged = 0, clean = 0;
  for (int t = 0; t < 2000; ++t) {
    const int y = static_cast<int>(rng() % 4096), x0 = static_cast<int>(rng() % 4096),
              x1 = static_cast<int>(rng() % 4096);
    // defined on [0, 2047]; extrapolated to x = 4095, |p_u| often passes 2^13
    Coef9 k = span_map(y, 0, 2047, 0.001 + (rng() % 1000) / 1000.0, 0.001 + (rng() % 1000) / 1000.0,
                       -8000.0 + (rng() % 16000), -8000.0 + (rng() % 16000), 1, 2, 0, 0, 0);
    Unit::Coefs c;
    try {
      c = Unit::quantise(k, "r");
    } catch (const SetupError&) {
      continue;
    }
    const auto s = Unit::setup_span(c, y, x0, x1);
    if (s.ovf) {
      ++flagged;
      EXPECT_THROW(Unit::setup(c, y, x0, x1, "r"), SetupError);
    } else {
      ++clean;
      const auto a = Unit::setup(c, y, x0, x1, "r");
      EXPECT_EQ(a.pu.raw(), s.acc.pu.raw());
      EXPECT_EQ(a.pv.raw(), s.acc.pv.raw());
      EXPECT_EQ(a.q.raw(), s.acc.q.raw());
      EXPECT_EQ(s.acc.pu.raw(), Unit::direct(c, x0, y).pu.raw());
    }
  }
  EXPECT_GT(flagged, 100);
  EXPECT_GT(clean, 100);
}

TEST(Persp, TriangleReachingTheEyePlaneIsFlagged) {
  // A floor triangle that passes behind the camera: pixels looking at q <= 0 are flagged.
  Camera cam;
  cam.width = 320; cam.height = 240;
  cam.pos[1] = 1;
  cam.look_at[1] = 1;  // horizontal: the horizon is the middle row; above it q < 0
  const Triangle t = tri("behind", {-5, 0, 3, 0, 0, 5, 0, 3, 64, 0, 0, 0, -30, 0, 64});
  const auto c = Unit::quantise(coefficients(cam, t), t.name);
  uint64_t flagged = 0, ok = 0;
  std::vector<Pixel> out(320);
  for (int y = 0; y < 240; ++y) {
    Unit::span_incremental(c, y, 0, 320, out.data(), t.name);
    for (int x = 0; x < 320; ++x) {
      double u, v, q;
      eval_ref(coefficients(cam, t), x, y, &u, &v, &q);
      const bool expect_flag = q < std::ldexp(1.0, -fmt::kPerspGuardLog2) - 1e-7;
      if (std::fabs(q - std::ldexp(1.0, -fmt::kPerspGuardLog2)) > 1e-7) {
        ASSERT_EQ(out[x].flag, expect_flag) << x << "," << y << " q=" << q;
      }
      (out[x].flag ? flagged : ok) += 1;
    }
  }
  EXPECT_GT(flagged, 1000u);
  EXPECT_GT(ok, 1000u);
}

}  // namespace
