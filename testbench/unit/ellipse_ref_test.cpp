// B2 float reference: the corrected closed forms and recurrences against their definitions.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "ellipse/ellipse_ref.hpp"

namespace {
using namespace tu::ellipse;

double u_of(const Coef9& k, double x, double y) {
  return (k.a * x + k.b * y + k.c) / (k.g * x + k.h * y + k.i);
}
double v_of(const Coef9& k, double x, double y) {
  return (k.d * x + k.e * y + k.f) / (k.g * x + k.h * y + k.i);
}
double rel(double a, double b) { return std::fabs(a - b) / std::max({std::fabs(a), std::fabs(b), 1e-300}); }

// Random maps with q in [0.05, 2] over a 256x256 screen, G != H (so the seed's error shows).
std::vector<Coef9> planes(int n) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> c(-3, 3), gh(-1.0 / 600, 1.0 / 600);
  std::vector<Coef9> out;
  while (static_cast<int>(out.size()) < n) {
    Coef9 k{c(rng) * 4, c(rng), c(rng) * 100, c(rng), c(rng) * 4, c(rng) * 100, gh(rng), gh(rng), 1};
    const double qmin = std::min({k.i, k.g * 256 + k.i, k.h * 256 + k.i, k.g * 256 + k.h * 256 + k.i});
    if (qmin > 0.05 && std::fabs(k.g - k.h) > 1e-4) out.push_back(k);
  }
  return out;
}

TEST(EllipseRef, AnalyticJacobianMatchesCentralDifferences) {
  for (const auto& k : planes(50)) {
    for (double x : {0.5, 100.5, 255.5}) {
      for (double y : {0.5, 77.5, 255.5}) {
        const auto j = analytic(k, x, y);
        const double h = 1e-3;
        EXPECT_LT(std::fabs(j.ux - (u_of(k, x + h, y) - u_of(k, x - h, y)) / (2 * h)), 1e-5);
        EXPECT_LT(std::fabs(j.vy - (v_of(k, x, y + h) - v_of(k, x, y - h)) / (2 * h)), 1e-5);
        EXPECT_LT(std::fabs(j.uy - (u_of(k, x, y + h) - u_of(k, x, y - h)) / (2 * h)), 1e-5);
        EXPECT_LT(std::fabs(j.vx - (v_of(k, x + h, y) - v_of(k, x - h, y)) / (2 * h)), 1e-5);
      }
    }
  }
}

TEST(EllipseRef, ForwardDifferenceIsTheNextPixelMinusThisOne) {
  // Closed forms with denominators q(q+G) (x) and the corrected q(q+H) (y).
  for (const auto& k : planes(50)) {
    for (double x : {0.0, 31.0, 255.0}) {
      for (double y : {0.0, 200.0}) {
        const auto j = forward_difference(k, x, y);
        EXPECT_LT(std::fabs(j.ux - (u_of(k, x + 1, y) - u_of(k, x, y))), 1e-9);
        EXPECT_LT(std::fabs(j.vx - (v_of(k, x + 1, y) - v_of(k, x, y))), 1e-9);
        EXPECT_LT(std::fabs(j.uy - (u_of(k, x, y + 1) - u_of(k, x, y))), 1e-9);
        EXPECT_LT(std::fabs(j.vy - (v_of(k, x, y + 1) - v_of(k, x, y))), 1e-9);
      }
    }
  }
}

TEST(EllipseRef, SeedYDenominatorIsWrongWhenGDiffersFromH) {
  // The seed's q(q+G) for du/dy misses the true difference by the factor (q+H)/(q+G).
  const Coef9 k{2, 0.5, 10, -0.3, 1.5, 20, 0.004, -0.003, 1};
  const double x = 100, y = 100;
  const auto n = numerators(k, x, y);
  const double seed = n.nuy / (n.q * (n.q + k.g));
  const double truth = u_of(k, x, y + 1) - u_of(k, x, y);
  EXPECT_GT(rel(seed, truth), 5e-3);
  EXPECT_LT(rel(forward_difference(k, x, y).uy, truth), 1e-12);
}

TEST(EllipseRef, SpanRecurrencesEqualClosedForms) {
  for (const auto& k : planes(20)) {
    const int x0 = 3, y = 17, n = 250;
    const auto span = forward_difference_span(k, x0, y, n);
    ASSERT_EQ(span.size(), static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) {
      const auto j = forward_difference(k, x0 + i, y);
      EXPECT_LT(rel(span[i].ux, j.ux), 1e-9);
      EXPECT_LT(rel(span[i].uy, j.uy), 1e-9);
      EXPECT_LT(rel(span[i].vx, j.vx), 1e-9);
      EXPECT_LT(rel(span[i].vy, j.vy), 1e-9);
    }
  }
}

TEST(EllipseRef, FeIsTheSquaredDeterminant) {
  // Points J (cos t, sin t) of the footprint lie on Ae U^2 + Be U V + Ce V^2 = Fe; the seed's
  // "+" form of Fe does not.
  for (const auto& k : planes(20)) {
    const auto j = analytic(k, 64, 64);
    const auto e = ellipse(j);
    const double fe_plus = std::pow(j.ux * j.vy + j.uy * j.vx, 2);
    bool plus_fails = false;
    for (int i = 0; i < 16; ++i) {
      const double t = i * M_PI / 8;
      const double U = j.ux * std::cos(t) + j.uy * std::sin(t);
      const double V = j.vx * std::cos(t) + j.vy * std::sin(t);
      const double lhs = e.ae * U * U + e.be * U * V + e.ce * V * V;
      EXPECT_LT(rel(lhs, e.fe), 1e-9);
      plus_fails |= rel(lhs, fe_plus) > 1e-3;
    }
    EXPECT_TRUE(plus_fails);
  }
}

TEST(EllipseRef, Q4ScaledEllipseNeedsNoDivide) {
  for (const auto& k : planes(20)) {
    const auto n = numerators(k, 50, 60);
    const auto e = ellipse(analytic(k, 50, 60));
    const auto e4 = ellipse_q4(n, det3(k), 1 / n.q);
    const double q4 = std::pow(n.q, 4);
    EXPECT_LT(rel(e4.ae, e.ae * q4), 1e-9);
    EXPECT_LT(rel(e4.be, e.be * q4), 1e-9);
    EXPECT_LT(rel(e4.ce, e.ce * q4), 1e-9);
    EXPECT_LT(rel(e4.fe, e.fe * q4), 1e-9);
    EXPECT_LT(rel(n.nux * n.nvy - n.nuy * n.nvx, det3(k) * n.q), 1e-9);
  }
}

TEST(EllipseRef, ForwardDifferenceDepartsByOnePlusGOverQ) {
  for (const auto& k : planes(20)) {
    const auto a = analytic(k, 10, 10), f = forward_difference(k, 10, 10);
    const double q = k.g * 10 + k.h * 10 + k.i;
    EXPECT_LT(rel(a.ux / f.ux, 1 + k.g / q), 1e-12);
    EXPECT_LT(rel(a.uy / f.uy, 1 + k.h / q), 1e-12);
  }
}

TEST(EllipseRef, FootprintAxesClampAndLod) {
  FootprintParams p;  // max aniso 16, max lod 12
  // Isotropic minification by 2: both semi-axes 2, LOD 1.
  auto f = footprint({2, 0, 0, 2}, p);
  EXPECT_NEAR(f.major, 2, 1e-12);
  EXPECT_NEAR(f.minor, 2, 1e-12);
  EXPECT_NEAR(f.lod, 1, 1e-12);
  EXPECT_FALSE(f.clamped_aniso);
  // Rotated 1:1000 footprint (grazing): minor grows to major/16.
  const double c = std::cos(0.3), s = std::sin(0.3);
  f = footprint({1000 * c, -s * 1, 1000 * s, c * 1}, p);
  EXPECT_NEAR(f.major, 1000, 1e-9);
  EXPECT_NEAR(f.minor, 1, 1e-9);
  EXPECT_TRUE(f.clamped_aniso);
  EXPECT_NEAR(f.aniso, 16, 1e-12);
  EXPECT_NEAR(f.lod, std::log2(1000.0 / 16), 1e-12);
  // Degenerate (a line): Fe = 0, minor 0, clamp still gives a finite LOD.
  f = footprint({3, 6, 1, 2}, p);
  EXPECT_TRUE(f.degenerate);
  EXPECT_EQ(f.minor, 0);
  EXPECT_NEAR(f.minor_clamped, f.major / 16, 1e-12);
  EXPECT_TRUE(std::isfinite(f.lod));
  // A point and magnification select level 0.
  EXPECT_EQ(footprint({0, 0, 0, 0}, p).lod, 0);
  EXPECT_EQ(footprint({0.25, 0, 0, 0.25}, p).lod, 0);
  // Larger than the texture: LOD saturates at the coarsest level and says so.
  f = footprint({1e5, 0, 0, 1e5}, p);
  EXPECT_EQ(f.lod, 12);
  EXPECT_TRUE(f.lod_saturated);
}
TEST(EllipseRef, HorizonHasNoFootprint) {
  // Ground plane seen from above the horizon: q reaches 0 at y = 100.
  const Coef9 k{1, 0, 0, 0, 1, 0, 0, -0.01, 1};
  for (auto d : {Deriv::Analytic, Deriv::ForwardDifference}) {
    EXPECT_FALSE(footprint_at(k, 5, 50, {}, d).horizon);
    const auto f = footprint_at(k, 5, 100, {}, d);
    EXPECT_TRUE(f.horizon);
    EXPECT_EQ(f.lod, 0);
    EXPECT_TRUE(footprint_at(k, 5, 150, {}, d).horizon);
  }
  // One row before the horizon the forward difference already reaches it (q + H = 0).
  EXPECT_TRUE(footprint_at(k, 5, 99.5, {}, Deriv::ForwardDifference).horizon);
  EXPECT_FALSE(footprint_at(k, 5, 99.5, {}, Deriv::Analytic).horizon);
}
}  // namespace

