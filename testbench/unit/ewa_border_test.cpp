// EWA sub-texel border weights (seed 003 §2, docs/blocks/ewa.md "Border weights"): the border
// distance d's fixed-point error and widths, its construction against the true Euclidean distance,
// zones, the walk with every clip variant against the float reference.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "ewa/ewa_fx.hpp"
#include "ewa/ewa_ref.hpp"
#include "gauss/weight.hpp"

namespace tu::ewa::fx {
namespace {

const tex::Texture& bricks() {
  static const tex::Texture t = tex::Texture::build("bricks", tex::bricks(256).color, tex::Wrap::Repeat);
  return t;
}

constexpr int kQF = 2 * (fmt::kEwaKF + fmt::kEwaPosF);
constexpr int64_t kStep = int64_t(1) << fmt::kEwaPosF;

// Every walked texel of a set-up: its exact Q, xi, eta (as ewa::fx::walk, direct form).
template <class F>
void for_each_texel(const PixelSetup& su, F&& f) {
  for (int64_t y = su.y0; y <= su.y1; ++y)
    for (int64_t x = su.x0; x <= su.x1; ++x) {
      const int64_t du = x * kStep - su.cu, dv = y * kStep - su.cv;
      const int64_t xi = int64_t(su.kxu) * du + int64_t(su.kxv) * dv;
      const int64_t eta = int64_t(su.kyu) * du + int64_t(su.kyv) * dv;
      f(xi * xi + eta * eta, xi, eta);
    }
}

// d in double from the same exact integers (the frame k, xi, eta, Q of the walk).
double d_double(const PixelSetup& su, int64_t q, int64_t xi, int64_t eta) {
  const double k = std::ldexp(1.0, -fmt::kEwaKF), x = std::ldexp(double(xi), -(fmt::kEwaKF + fmt::kEwaPosF)),
               e = std::ldexp(double(eta), -(fmt::kEwaKF + fmt::kEwaPosF));
  const double gu = (su.kxu * x + su.kyu * e) * k, gv = (su.kxv * x + su.kyv * e) * k;
  const double r = std::sqrt(std::ldexp(double(q), -kQF));
  return (1 - r) * r / std::hypot(gu, gv);
}

std::vector<In> random_pixels(uint64_t seed, int n) {
  std::mt19937_64 rng(seed);
  std::vector<In> v;
  for (int i = 0; i < n; ++i) v.push_back(random_in(rng));
  return v;
}

Config clip_cfg(const std::string& variant) {
  Config c;
  c.clip = &clip::variant(variant);
  return c;
}

// The fixed-point d is within 1 LSB (2^-ClipInF) of d in double on the same integers, on every
// band texel; zones agree except within 1 LSB of |d| = 1/2; the widths of g, r, |g| hold.
TEST(EwaBorder, DistanceWithinOneLsbOfDouble) {
  const Config cfg = clip_cfg("mm_p3");
  double worst = 0;
  int64_t band = 0, max_g = 0;
  uint64_t max_root = 0;
  for (const In& in : random_pixels(5, 3000)) {
    const PixelSetup su = setup(in, bricks(), cfg);
    for_each_texel(su, [&](int64_t q, int64_t xi, int64_t eta) {
      const Border b = border(su, q, xi, eta);
      const double qd = std::ldexp(double(q), -kQF);
      if (qd < 0.25 || qd > 2.25) {
        EXPECT_EQ(b.zone, qd < 0.25 ? Zone::Inside : Zone::Outside);
        return;
      }
      max_g = std::max({max_g, int64_t(std::abs(b.gu)), int64_t(std::abs(b.gv))});
      max_root = std::max({max_root, uint64_t(b.r), uint64_t(b.g)});
      const double d = d_double(su, q, xi, eta), lsb = std::ldexp(1.0, -fmt::kClipInF);
      if (std::fabs(std::fabs(d) - 0.5) < lsb) return;  // either zone is within 1 LSB
      const Zone want = d > 0.5 ? Zone::Inside : d < -0.5 ? Zone::Outside : Zone::Band;
      EXPECT_EQ(b.zone, want) << d;
      if (want != Zone::Band || b.zone != Zone::Band) return;
      ++band;
      worst = std::max(worst, std::fabs(std::ldexp(double(b.d), -fmt::kClipInF) - d) / lsb);
    });
  }
  std::printf("band texels %lld, max |d - d_double| = %.3f LSB; max |gu|, |gv| = %lld (< 2^%d), max r, |g| = %llu (< 2^%d)\n",
              (long long)band, worst, (long long)max_g, fmt::kEwaGradW - 1, (unsigned long long)max_root, fmt::kEwaRootW);
  EXPECT_GT(band, 40000);
  EXPECT_LT(worst, 1.0);
  EXPECT_LT(max_g, int64_t(1) << (fmt::kEwaGradW - 1));
  EXPECT_LT(max_root, uint64_t(1) << fmt::kEwaRootW);
}

// Construction: d is the distance to the tangent at the radial projection, exact for a circle;
// against the true Euclidean signed distance to the ellipse (a in [1, 16], b in [1, 2), the walk
// levels' range) on points where either is in the band (both clamped to [-1/2, 1/2], as v sees
// them), and against the first-order (Taubin) distance (1 - Q) / |grad Q| on the same points.
TEST(EwaBorder, DistanceAgainstEuclidean) {
  // True signed distance from (x, y) (frame axes, texels) to the ellipse x^2/a^2 + y^2/b^2 = 1:
  // the nearest point by a parameter sweep, refined by golden-section search.
  auto true_d = [](double x, double y, double a, double b) {
    auto dist2 = [&](double t) { return std::pow(a * std::cos(t) - x, 2) + std::pow(b * std::sin(t) - y, 2); };
    double best = 0, bt = 0;
    for (int i = 0; i < 720; ++i) {
      const double t = i * M_PI / 360, d = dist2(t);
      if (i == 0 || d < best) best = d, bt = t;
    }
    double lo = bt - M_PI / 360, hi = bt + M_PI / 360;
    for (int i = 0; i < 60; ++i) {
      const double m1 = lo + (hi - lo) * 0.382, m2 = lo + (hi - lo) * 0.618;
      if (dist2(m1) < dist2(m2)) hi = m2;
      else lo = m1;
    }
    const double dd = std::sqrt(dist2((lo + hi) / 2));
    return x * x / (a * a) + y * y / (b * b) < 1 ? dd : -dd;
  };
  auto clamp_half = [](double d) { return std::clamp(d, -0.5, 0.5); };
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> ua(0, 4), ub(0, 1), ut(0, 2 * M_PI), uo(-3, 3);
  double worst_circle = 0, worst = 0, worst_v = 0, se = 0, se_taubin = 0;
  int n = 0;
  for (int i = 0; i < 4000; ++i) {
    const double a = std::exp2(ua(rng)), b = std::min(a, std::exp2(ub(rng))), th = ut(rng);
    const double c = std::cos(th), s = std::sin(th);
    for (int k = 0; k < 40; ++k) {
      const double du = uo(rng) * a, dv = uo(rng) * a;
      const double pu = (du * c + dv * s) / a, pv = (-du * s + dv * c) / b, q = pu * pu + pv * pv;
      // r < 0.3 or r > 1.75: both distances exceed 1/2 (b >= 1), no search needed.
      if (q < 0.09 || q > 3.0625) continue;
      const double d = border_distance(pu, pv, a, b, c, s);
      const double t = true_d(pu * a, pv * b, a, b);
      if (std::fabs(d) > 0.5 && std::fabs(t) > 0.5) continue;
      ++n;
      const double e = std::fabs(clamp_half(d) - clamp_half(t));
      worst = std::max(worst, e);
      se += e * e;
      const double taubin = (1 - q) / (2 * std::hypot(pu / a, pv / b));  // |grad Q| = 2 |K^T p|
      se_taubin += std::pow(clamp_half(taubin) - clamp_half(t), 2);
      // The error that matters: of the weight v(d) = Phi(d / 0.2) against v(true distance).
      auto phi = [](double x) { return 0.5 * std::erfc(-x / (0.2 * std::sqrt(2.0))); };
      worst_v = std::max(worst_v, std::fabs(phi(clamp_half(d)) - phi(clamp_half(t))));
      if (std::isfinite(d)) {  // the same radius on a circle of radius a: a - |p| a
        const double dc = border_distance(std::sqrt(q), 0, a, a, 1, 0);
        worst_circle = std::max(worst_circle, std::fabs(dc - (a - std::sqrt(q) * a)));
      }
    }
  }
  const double rms = std::sqrt(se / n), rms_taubin = std::sqrt(se_taubin / n);
  std::printf("%d points: |d - euclidean| max %.4f, rms %.4f texel (Taubin rms %.4f); max |v(d) - v(euclidean)| "
              "%.4f; circle: %.2e\n", n, worst, rms, rms_taubin, worst_v, worst_circle);
  EXPECT_GT(n, 5000);
  EXPECT_LT(worst_circle, 1e-12);
  EXPECT_LT(rms, 0.6 * rms_taubin);
  EXPECT_LT(worst, 0.2);  // at the tips of thin ellipses (nearest point sideways)
}

// The walk with every clip variant against the float border walk (exact Phi) on the same B2
// outputs; a constant texture is reproduced exactly; off = the plain walk.
TEST(EwaBorder, ClipVariantsMatchFloat) {
  const auto pixels = random_pixels(3, 1000);
  const img::Rgba8 flat_c{201, 13, 77, 255};
  const auto flat = tex::Texture::build("flat", img::Rgba8Image(64, 64, flat_c), tex::Wrap::Repeat);
  for (const auto& v : clip::variants()) {
    const Config cfg = clip_cfg(v.name);
    int worst = 0;
    double mean = 0;
    for (const In& in : pixels) {
      const Result r = filter_ref_b2(in, bricks(), 1024, true);
      const Out o = filter(in, bricks(), cfg);
      EXPECT_EQ(o.level, r.level);
      const int e = std::max({std::abs(o.color.r - int(std::lround(r.color.r))), std::abs(o.color.g - int(std::lround(r.color.g))),
                              std::abs(o.color.b - int(std::lround(r.color.b)))});
      worst = std::max(worst, e);
      mean += e;
      EXPECT_EQ(filter(in, flat, cfg).color, flat_c);
    }
    std::printf("%-13s max %d, mean %.3f levels from the float border walk\n", v.name.c_str(), worst, mean / double(pixels.size()));
    EXPECT_LE(worst, 4) << v.name;
  }
}

// Zones: Q < 1/4 is the plain weight, Q > 9/4 is 0; the incremental walk equals the direct one
// with the border weights on; the box grows by 1/2 texel per side.
TEST(EwaBorder, ZonesIncrementalAndBox) {
  const Config on = clip_cfg("tab16"), off;
  for (const In& in : random_pixels(7, 500)) {
    const PixelSetup su = setup(in, bricks(), on), su0 = setup(in, bricks(), off);
    if (su.level == su0.level) {
      EXPECT_EQ(su.hu, su0.hu + kBorderGrow);
      EXPECT_EQ(su.hv, su0.hv + kBorderGrow);
    }
    for_each_texel(su, [&](int64_t q, int64_t xi, int64_t eta) {
      const double qd = std::ldexp(double(q), -kQF);
      const uint32_t w = border_weight(su, on, q, xi, eta);
      if (qd > 2.25) EXPECT_EQ(w, 0u);
      if (qd < 0.25) EXPECT_EQ(w, gauss::weight(static_cast<uint32_t>(q >> (kQF - fmt::kGaussQF))));
    });
    const Out a = filter(in, bricks(), on), b = filter(in, bricks(), on, /*direct=*/true);
    EXPECT_EQ(a.color, b.color);
    EXPECT_EQ(a.texels_inside, b.texels_inside);
  }
}

}  // namespace
}  // namespace tu::ewa::fx
