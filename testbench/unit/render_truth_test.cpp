// Ground truth (render::render_truth) and the exact relief intersection (relief::exact_hit): the
// intersection against a dense search, the truth's convergence in the sample count, and PSNR over
// covered / relief pixels.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>

#include "pom/relief_exact.hpp"
#include "texunit/render.hpp"

namespace {
using namespace tu;

double bilinear_depth(const img::Gray8& d, double u, double v) {
  const double x = u * d.width - 0.5, y = v * d.height - 0.5;
  const double fx = std::floor(x), fy = std::floor(y);
  auto at = [&](double i, double j) {
    return d.at(static_cast<int>(static_cast<int64_t>(i) & (d.width - 1)),
                static_cast<int>(static_cast<int64_t>(j) & (d.height - 1))) / 255.0;
  };
  const double a = x - fx, b = y - fy;
  return (at(fx, fy) * (1 - a) + at(fx + 1, fy) * a) * (1 - b) + (at(fx, fy + 1) * (1 - a) + at(fx + 1, fy + 1) * a) * b;
}

TEST(ReliefExact, FlatAndVerticalViews) {
  img::Gray8 flat(16, 16);
  for (auto& p : flat.px) p = 102;  // depth 0.4
  const auto h = relief::exact_hit(flat, 0.3, 0.7, 0.6, 0.0, 0.8, 0.05);
  EXPECT_NEAR(h.depth, 0.4, 1e-12);
  EXPECT_NEAR(h.u, 0.3 - 0.4 * 0.6 / 0.8 * 0.05, 1e-12);
  std::mt19937_64 rng(5);
  img::Gray8 m(32, 32);
  for (auto& p : m.px) p = static_cast<uint8_t>(rng() & 255);
  for (int t = 0; t < 100; ++t) {  // straight down: the hit is the field under the point
    const double u = (rng() % 100000) / 1e5, v = (rng() % 100000) / 1e5;
    EXPECT_NEAR(relief::exact_hit(m, u, v, 0, 0, 1, 0.1).depth, bilinear_depth(m, u, v), 1e-12);
  }
}

// The first D with D >= depth(T - D P), found by a 2^20-step scan and bisection, on random maps
// and views (grazing ones included: the walk crosses many cells).
TEST(ReliefExact, MatchesDenseSearch) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> U(0, 1);
  double worst = 0;
  uint32_t max_cells = 0;
  for (int t = 0; t < 200; ++t) {
    img::Gray8 m(16, 16);
    for (auto& p : m.px) p = static_cast<uint8_t>(rng() & 255);
    const double th = 2 * M_PI * U(rng), vz = 0.02 + 0.98 * U(rng), r = std::sqrt(1 - vz * vz);
    const double vx = r * std::cos(th), vy = r * std::sin(th), u = U(rng), v = U(rng), sc = 0.1;
    const auto h = relief::exact_hit(m, u, v, vx, vy, vz, sc);
    const double a = std::max(vz, 512.0 / 16384), pu = vx / a * sc, pv = vy / a * sc;
    auto g = [&](double d) { return d - bilinear_depth(m, u - d * pu, v - d * pv); };
    const int steps = 1 << 20;
    double lo = 0, hi = 1;
    if (g(0) < 0) {
      for (int i = 1; i <= steps; ++i) {
        const double d = double(i) / steps;
        if (g(d) >= 0) {
          lo = double(i - 1) / steps, hi = d;
          break;
        }
      }
      for (int k = 0; k < 40; ++k) (g(0.5 * (lo + hi)) >= 0 ? hi : lo) = 0.5 * (lo + hi);
    } else {
      hi = 0;
    }
    worst = std::max(worst, std::fabs(h.depth - hi));
    max_cells = std::max(max_cells, h.cells);
  }
  std::printf("exact_hit vs dense search: max |D - D_dense| = %.3e, up to %u cells\n", worst, max_cells);
  EXPECT_LT(worst, 1e-9);
}

// The scene at a quarter of the pixels (same view): the test stays a few seconds.
scene::Scene small_default() {
  auto s = scene::default_scene();
  s.camera.width /= 2;
  s.camera.height /= 2;
  return s;
}

TEST(RenderTruth, SixteenAndThirtyTwoSamplesAgree) {
  const auto s = small_default();
  render::TruthOptions o;
  const auto t0 = std::chrono::steady_clock::now();
  const auto a = render::render_truth(s, o);
  o.ss = 32;
  const auto b = render::render_truth(s, o);
  const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double all = render::psnr_covered(a, b), rel = render::psnr_covered(a, b, render::relief_pixels(s));
  std::printf("%dx%d, %zu covered pixels: truth 16 vs 32 samples %.2f dB (relief pixels %.2f dB), %.1f s\n",
              s.camera.width, s.camera.height, a.pixels.size(), all, rel, sec);
  EXPECT_EQ(a.pixels.size(), b.pixels.size());
  EXPECT_GE(all, 45);
}

TEST(RenderTruth, ConstantTextureAndKernels) {
  auto s = scene::default_scene();
  s.camera.width = 64, s.camera.height = 48;
  s.textures.at("checker").cells = 1;  // one cell: a constant texture
  s.objects.pop_back();                // the ground only
  for (auto k : {render::TruthKernel::Box, render::TruthKernel::Gaussian}) {
    render::TruthOptions o;
    o.ss = 4;
    o.kernel = k;
    const auto f = render::render_truth(s, o);
    ASSERT_FALSE(f.pixels.empty());
    for (const auto& p : f.pixels) ASSERT_EQ(p.color, (img::Rgba8{230, 230, 230, 255}));
  }
}

TEST(RenderTruth, PsnrIsOverCoveredPixels) {
  auto s = scene::default_scene();
  s.camera.width = 64, s.camera.height = 48;
  const auto a = render::render_ref(s, scene::Filter::Bilinear);
  auto b = a;
  for (auto& p : b.image.px) p = {1, 2, 3, 255};  // background (and covered pixels) changed
  for (const auto& p : a.pixels) b.image.at(p.x, p.y) = p.color;
  EXPECT_TRUE(std::isinf(render::psnr_covered(a, b)));
  EXPECT_LT(tex::psnr(a.image, b.image), 30);  // whole-image PSNR sees the background
  b.image.at(a.pixels[0].x, a.pixels[0].y).r ^= 0x40;
  EXPECT_FALSE(std::isinf(render::psnr_covered(a, b)));
  EXPECT_TRUE(std::isinf(render::psnr_covered(a, b, [&](const render::PixelRecord& p) { return &p != &a.pixels[0]; })));
}

}  // namespace
