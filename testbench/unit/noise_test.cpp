// Perlin noise unit (docs/blocks/noise.md): the float reference against Perlin's published
// algorithm, the analytic bounds, the fixed-point fade (exhaustive), lerp, noise core and fBm
// error bounds, lattice points, cell-border continuity and the period-256 wrap.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <set>

#include "noise/noise_fade.hpp"
#include "noise/noise_fbm.hpp"
#include "noise/noise_lerp.hpp"
#include "noise/noise_ref.hpp"

namespace {
using namespace tu;
using namespace tu::noise;

const double kUlp = std::ldexp(1.0, -fmt::kNoiseTF);
// The sanitizer build (Debug, ASan + UBSan) checks the same code paths on 1/16 of the points.
#if defined(__SANITIZE_ADDRESS__)
constexpr int kLog2Thin = 4;
#else
constexpr int kLog2Thin = 0;
#endif
constexpr int64_t kOne = int64_t(1) << fmt::kNoiseTF;

// Literal transcription of Perlin's Java reference (mrl.nyu.edu/~perlin/noise/, 2002): the
// explicit 512-entry doubled table and his fade/lerp/grad, as an independent check of noise3_ref.
struct JavaReference {
  int p[512];
  JavaReference() {
    for (int i = 0; i < 256; i++) p[256 + i] = p[i] = permutation()[static_cast<size_t>(i)];
  }
  static double fade(double t) { return t * t * t * (t * (t * 6 - 15) + 10); }
  static double lerp(double t, double a, double b) { return a + t * (b - a); }
  static double grad(int hash, double x, double y, double z) {
    int h = hash & 15;
    double u = h < 8 ? x : y, v = h < 4 ? y : h == 12 || h == 14 ? x : z;
    return ((h & 1) == 0 ? u : -u) + ((h & 2) == 0 ? v : -v);
  }
  double noise(double x, double y, double z) const {
    int X = static_cast<int>(std::floor(x)) & 255, Y = static_cast<int>(std::floor(y)) & 255,
        Z = static_cast<int>(std::floor(z)) & 255;
    x -= std::floor(x);
    y -= std::floor(y);
    z -= std::floor(z);
    double u = fade(x), v = fade(y), w = fade(z);
    int A = p[X] + Y, AA = p[A] + Z, AB = p[A + 1] + Z, B = p[X + 1] + Y, BA = p[B] + Z, BB = p[B + 1] + Z;
    return lerp(w, lerp(v, lerp(u, grad(p[AA], x, y, z), grad(p[BA], x - 1, y, z)),
                        lerp(u, grad(p[AB], x, y - 1, z), grad(p[BB], x - 1, y - 1, z))),
                lerp(v, lerp(u, grad(p[AA + 1], x, y, z - 1), grad(p[BA + 1], x - 1, y, z - 1)),
                     lerp(u, grad(p[AB + 1], x, y - 1, z - 1), grad(p[BB + 1], x - 1, y - 1, z - 1))));
  }
};

TEST(NoiseRef, PermutationIsAPermutationOf0To255) {
  const auto& p = permutation();
  EXPECT_EQ(std::set<int>(p.begin(), p.end()).size(), 256u);
  EXPECT_EQ(p[0], 151);
  EXPECT_EQ(p[255], 180);
}

TEST(NoiseRef, MatchesThePublishedAlgorithm) {
  // The value quoted for Perlin's reference implementation.
  EXPECT_NEAR(noise3_ref(3.14, 42, 7), 0.136919958784, 1e-12);
  // Fractional and negative coordinates in every axis (values of the Java transcription above,
  // 12 digits; the last is a period-256 image of the first).
  const struct {
    double x, y, z, v;
  } pts[] = {{-3.14, 42, 7, -0.117999705600},  {3.14, -42.5, 7, 0.498459979392},
             {3.14, 42, -7.25, -0.099482627437}, {-0.5, -0.5, -0.5, -0.875},
             {-1.75, -2.6, -3.1, 0.334353956460}, {259.14, 298, 263, 0.136919958784}};
  const JavaReference java;
  for (const auto& q : pts) {
    EXPECT_DOUBLE_EQ(noise3_ref(q.x, q.y, q.z), java.noise(q.x, q.y, q.z)) << q.x << " " << q.y << " " << q.z;
    EXPECT_NEAR(noise3_ref(q.x, q.y, q.z), q.v, 1e-12) << q.x << " " << q.y << " " << q.z;
  }
  // Everywhere on a random set with every axis negative or fractional.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-600, 600);
  for (int i = 0; i < 100000; ++i) {
    const double x = u(rng), y = u(rng), z = u(rng);
    ASSERT_DOUBLE_EQ(noise3_ref(x, y, z), java.noise(x, y, z)) << x << " " << y << " " << z;
  }
}

TEST(NoiseRef, LatticeZerosPeriodAndTwoDSlice) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-300, 300);
  for (int i = 0; i < 10000; ++i) {
    const double x = u(rng), y = u(rng), z = u(rng);
    EXPECT_EQ(noise3_ref(std::floor(x), std::floor(y), std::floor(z)), 0.0);
    EXPECT_NEAR(noise3_ref(x + 256, y - 512, z + 256), noise3_ref(x, y, z), 1e-9);
    EXPECT_EQ(noise2_ref(x, y), noise3_ref(x, y, 0));
  }
}

// The bound B(t) (worst-case gradient per corner) is the sup over every hash table: it must
// dominate the noise everywhere, peak at 1.0363538 (3-D) and 1 (2-D), and stay below kBound.
TEST(NoiseRef, AnalyticBoundHoldsAndItsTightness) {
  double peak3 = 0, peak2 = 0;
  const int n = 100;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      peak2 = std::max(peak2, worst_case_ref(2, i / double(n), j / double(n), 0));
      for (int k = 0; k <= n; ++k) peak3 = std::max(peak3, worst_case_ref(3, i / double(n), j / double(n), k / double(n)));
    }
  const double at_peak = worst_case_ref(3, 0.355256691, 0.481492218, 0.5);
  EXPECT_NEAR(at_peak, 1.0363538, 1e-7);
  EXPECT_LE(peak3, at_peak);
  EXPECT_LT(at_peak, kBound3);
  EXPECT_NEAR(peak2, 1.0, 1e-12);  // at the cell centre
  EXPECT_LE(peak2, kBound2);
  // Sampled maxima of the real noise (Perlin's table) against the bounds.
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(0, 256);
  double max3 = 0, max2 = 0;
  for (int i = 0; i < (1 << (20 - kLog2Thin)); ++i) {
    const double x = u(rng), y = u(rng), z = u(rng);
    const double v3 = std::fabs(noise3_ref(x, y, z)), v2 = std::fabs(noise2_ref(x, y));
    ASSERT_LE(v3, worst_case_ref(3, x - std::floor(x), y - std::floor(y), z - std::floor(z)) + 1e-12);
    ASSERT_LE(v2, worst_case_ref(2, x - std::floor(x), y - std::floor(y), 0) + 1e-12);
    max3 = std::max(max3, v3);
    max2 = std::max(max2, v2);
  }
  // The 6 permutations and 8 reflections of the peak point in every cell of a 64^3 block.
  double peak_cells = 0;
  const double t[3] = {0.355256691, 0.481492218, 0.5};
  const int perm[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  const int cells = 64 >> (kLog2Thin / 2);
  for (int cx = 0; cx < cells; ++cx)
    for (int cy = 0; cy < cells; ++cy)
      for (int cz = 0; cz < cells; ++cz)
        for (const auto& pm : perm)
          for (int r = 0; r < 8; ++r) {
            double q[3];
            for (int a = 0; a < 3; ++a) q[a] = (r >> a & 1) ? 1 - t[pm[a]] : t[pm[a]];
            peak_cells = std::max(peak_cells, std::fabs(noise3_ref(cx + q[0], cy + q[1], cz + q[2])));
          }
  EXPECT_LE(max3, kBound3);
  EXPECT_LE(peak_cells, kBound3);
  EXPECT_LE(max2, kBound2);
  std::printf("bound3 %.7f (peak of B), sampled max |noise3| %.6f (%d points), %.6f (peak images in %d^3 cells); "
              "bound2 %.3f, sampled max |noise2| %.6f\n", at_peak, max3, 1 << (20 - kLog2Thin), peak_cells, cells, peak2, max2);
  // fBm normalised by the bound stays in [0,1].
  for (int i = 0; i < 100000; ++i) {
    const double x = u(rng), y = u(rng), z = u(rng);
    for (int dims : {2, 3}) {
      const double f = fbm_ref(dims, fmt::kNoiseOctaves, x, y, z);
      ASSERT_GE(f, 0.0);
      ASSERT_LE(f, 1.0);
    }
  }
}

TEST(NoiseFade, ExhaustiveErrorMonotonicAndEnds) {
  double max_err = 0;
  int64_t prev = -1;
  uint64_t decreasing = 0;
  for (uint32_t c = 0; c < (1u << fmt::kNoiseTF); ++c) {
    const auto s = fade(T::from_raw(c));
    max_err = std::max(max_err, std::fabs(s.to_double() - fade_ref(c * kUlp)));
    decreasing += s.raw() < prev;
    prev = s.raw();
    ASSERT_LE(s.raw(), kOne) << c;  // s <= 1: no clamp needed
  }
  const double analytic = 10 * std::ldexp(1.0, -fmt::kNoiseFadeIF) + std::ldexp(1.0, -fmt::kNoiseFadeIF - 1) + kUlp / 2;
  EXPECT_EQ(fade(T::from_raw(0)).raw(), 0);
  EXPECT_EQ(decreasing, 0u);
  EXPECT_LE(max_err, analytic);
  EXPECT_NEAR(max_err / kUlp, 0.516, 0.001);  // the figure in noise_fade.hpp and noise.md
  std::printf("fade: max %.4f ULP (analytic bound %.4f)\n", max_err / kUlp, analytic / kUlp);
}

TEST(NoiseLerp, EndsExactAndHalfUlp) {
  std::mt19937_64 rng(5);
  using V = Val;
  for (int i = 0; i < 200000; ++i) {
    const V a = V::from_raw(static_cast<int64_t>(rng() % (4 * kOne + 1)) - 2 * kOne);
    const V b = V::from_raw(static_cast<int64_t>(rng() % (4 * kOne + 1)) - 2 * kOne);
    const S s = S::from_raw(static_cast<int64_t>(rng() % (kOne + 1)));
    const auto l = lerp(s, a, b);
    const double exact = a.to_double() + s.to_double() * (b.to_double() - a.to_double());
    ASSERT_LE(std::fabs(l.to_double() - exact), kUlp / 2);
    ASSERT_GE(l.raw(), std::min(a.raw(), b.raw()));
    ASSERT_LE(l.raw(), std::max(a.raw(), b.raw()));
    ASSERT_EQ(lerp(S::from_raw(0), a, b).raw(), a.raw());
    ASSERT_EQ(lerp(S::from_raw(kOne), a, b).raw(), b.raw());
  }
}

double ref_noise(int dims, int64_t x, int64_t y, int64_t z) {
  return dims == 3 ? noise3_ref(coord_value(x), coord_value(y), coord_value(z)) : noise2_ref(coord_value(x), coord_value(y));
}
double fx_noise(int dims, int64_t x, int64_t y, int64_t z, int octave = 0) {
  const Axis a[3] = {split(x, octave), split(y, octave), split(z, octave)};
  return noise_fx(dims, a).to_double();
}
int64_t rand_code(std::mt19937_64& rng) { return static_cast<int64_t>(rng() % (1200 * uint64_t(kOne))) - 600 * kOne; }

// The core's derived bound (noise_core.hpp): 3 (resp. 2) lerp levels of 4 e_s + 0.5 ULP.
double core_bound(int dims) {
  const double es = 10 * std::ldexp(1.0, -fmt::kNoiseFadeIF) + std::ldexp(1.0, -fmt::kNoiseFadeIF - 1) + kUlp / 2;
  return dims * (4 * es + kUlp / 2);
}

TEST(NoiseFx, CoreErrorBoundOnAMillionPoints) {
  for (int dims : {2, 3}) {
    std::mt19937_64 rng(dims);
    double max_err = 0, sum_sq = 0;
    const int n = 1 << (20 - kLog2Thin);
    for (int i = 0; i < n; ++i) {
      const int64_t x = rand_code(rng), y = rand_code(rng), z = rand_code(rng);
      const double e = fx_noise(dims, x, y, z) - ref_noise(dims, x, y, z);
      max_err = std::max(max_err, std::fabs(e));
      sum_sq += e * e;
    }
    EXPECT_LE(max_err, core_bound(dims));
    std::printf("noise%dd core: max %.3f ULP, rms %.3f ULP over %d points (bound %.2f ULP)\n", dims,
                max_err / kUlp, std::sqrt(sum_sq / n) / kUlp, n, core_bound(dims) / kUlp);
  }
}

TEST(NoiseFx, LatticePointsTwoDSliceAndPeriodWrapAreExact) {
  std::mt19937_64 rng(9);
  for (int i = 0; i < 20000; ++i) {
    const int64_t x = rand_code(rng), y = rand_code(rng), z = rand_code(rng);
    const int64_t lx = x & ~(kOne - 1), ly = y & ~(kOne - 1), lz = z & ~(kOne - 1);
    for (int dims : {2, 3}) EXPECT_EQ(fx_noise(dims, lx, ly, lz), 0.0);
    EXPECT_EQ(fx_noise(2, x, y, z), fx_noise(3, x, y, 0));
    EXPECT_EQ(fx_noise(3, x + 256 * kOne, y - 512 * kOne, z + 256 * kOne), fx_noise(3, x, y, z));
    // Octave i is the code scaled by 2^i: equal to octave 0 of the scaled code.
    EXPECT_EQ(fx_noise(3, x, y, z, 3), fx_noise(3, x * 8, y * 8, z * 8));
    // The largest and smallest codes wrap like the float reference.
    for (int64_t c : {(int64_t(1) << 31) - 1, -(int64_t(1) << 31)})
      EXPECT_LE(std::fabs(fx_noise(3, c, y, z) - ref_noise(3, c, y, z)), core_bound(3));
  }
}

TEST(NoiseFx, ContinuousAcrossCellBorders) {
  // Stepping one LSB across a lattice line: the fixed-point step differs from the float step by
  // at most twice the core bound (no jump at the border).
  std::mt19937_64 rng(21);
  double worst = 0;
  for (int i = 0; i < (100000 >> kLog2Thin); ++i)
    for (int axis = 0; axis < 3; ++axis) {
      int64_t c[3] = {rand_code(rng), rand_code(rng), rand_code(rng)};
      c[axis] &= ~(kOne - 1);  // on the border
      int64_t b[3] = {c[0], c[1], c[2]};
      b[axis] -= 1;  // last code of the previous cell
      const double dfx = fx_noise(3, c[0], c[1], c[2]) - fx_noise(3, b[0], b[1], b[2]);
      const double dref = ref_noise(3, c[0], c[1], c[2]) - ref_noise(3, b[0], b[1], b[2]);
      worst = std::max(worst, std::fabs(dfx - dref));
      ASSERT_LE(std::fabs(dfx), std::fabs(dref) + 2 * core_bound(3));
    }
  EXPECT_LE(worst, 2 * core_bound(3));
  std::printf("cell-border step: fixed vs float differ by at most %.3f ULP\n", worst / kUlp);
}

// fBm bound (noise_fbm.hpp): 0.5 ULP + C' sum 2^-i e_core + |acc|max * |C - C'|.
double fbm_bound(int dims) {
  const double b = dims == 3 ? kBound3 : kBound2;
  const double amp = octave_amplitude_sum(fmt::kNoiseOctaves);
  const double c_exact = 1.0 / (2 * b * amp);
  const double c_code = std::ldexp(dims == 3 ? fmt::kNoiseNorm3 : fmt::kNoiseNorm2, -fmt::kNoiseNormF);
  return kUlp / 2 + c_exact * amp * core_bound(dims) + b * amp * std::fabs(c_code - c_exact);
}

TEST(NoiseFbm, ErrorBoundAndRange) {
  for (int dims : {2, 3}) {
    std::mt19937_64 rng(100 + dims);
    double max_err = 0, sum_sq = 0;
    const int n = 1 << (18 - kLog2Thin);  // 1,000,000 points: the co-simulation runs (docs/blocks/noise-appendix.md §4)
    for (int i = 0; i < n; ++i) {
      const int64_t x = rand_code(rng), y = rand_code(rng), z = rand_code(rng);
      const uint32_t o = fbm_fx(dims, x, y, z);
      ASSERT_LE(o, static_cast<uint32_t>(kOne));
      const double e = out_value(o) - fbm_ref(dims, fmt::kNoiseOctaves, coord_value(x), coord_value(y), coord_value(z));
      max_err = std::max(max_err, std::fabs(e));
      sum_sq += e * e;
    }
    EXPECT_LE(max_err, fbm_bound(dims));
    std::printf("fbm %dd: max %.3f ULP, rms %.3f ULP over %d points (bound %.2f ULP)\n", dims, max_err / kUlp,
                std::sqrt(sum_sq / n) / kUlp, n, fbm_bound(dims) / kUlp);
  }
  EXPECT_EQ(fbm_fx(3, 5 * kOne, -7 * kOne, 300 * kOne), static_cast<uint32_t>(kOne / 2));  // lattice: 1/2
  // The normalisation clamps instead of wrapping far outside the reachable sum.
  EXPECT_EQ(fbm_normalise(3, int64_t(1) << 40), static_cast<uint32_t>(kOne));
  EXPECT_EQ(fbm_normalise(3, -(int64_t(1) << 40)), 0u);
}

}  // namespace
