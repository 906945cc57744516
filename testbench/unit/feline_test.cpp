// Feline probe filter (feline/feline_ref.hpp, feline/feline_fx.hpp): the probe count exhaustively
// over every ratio code, the C model against the float reference on the same B2 outputs (seeded
// random footprints + curated extremes), the declared widths on the extremes, the reference's
// geometry, and the render engines on the default scene.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "feline/feline_fx.hpp"
#include "texunit/render.hpp"

namespace {
using namespace tu;
namespace ffx = tu::feline::fx;

const tex::Texture& bricks() {
  static const tex::Texture t = tex::Texture::build("bricks", tex::bricks(256).color, tex::Wrap::Repeat);
  return t;
}

// Step 1 on every ratio code e (log2 s1/s2, EllLogF fraction bits) up to 2^15 (log2 32 = 5 above
// the largest B2 anisotropy clamp) and every cap: N = min(Nmax, ceil(2^(e - tau))) exactly, and
// equal to the float reference's count on the decoded ratio.
TEST(FelineFx, ProbeCountExhaustiveOverRatioCodes) {
  for (int nmax = 1; nmax <= fmt::kFelNMax; ++nmax) {
    for (int64_t e = 0; e < (int64_t(1) << 15); ++e) {
      const double ratio = std::exp2(std::ldexp(double(e), -fmt::kEllLogF));
      const double tol = std::exp2(std::ldexp(double(e - feline::kRatioTol), -fmt::kEllLogF));
      const int want = static_cast<int>(std::min<double>(nmax, std::max(1.0, std::ceil(tol))));
      ASSERT_EQ(ffx::probe_count(e, nmax), want) << "e " << e << " nmax " << nmax;
      ASSERT_EQ(ffx::probe_count(e, nmax), feline::probe_count(ratio, 1, nmax)) << e;
    }
  }
  // The tables: Lg[n] = floor(log2(n) 2^10), R[m] = round(2^16 / m).
  EXPECT_EQ(ffx::log2_int_table()[16], 4 << fmt::kEllLogF);
  EXPECT_EQ(ffx::log2_int_table()[3], 1623);  // 1623.0.. = log2(3) 1024
  EXPECT_EQ(ffx::recip_table()[1], 1u << fmt::kFelRecipF);
  EXPECT_EQ(ffx::recip_table()[3], 21845u);
}

// The reference's geometry: a circle is one probe (= trilinear); a 4:1 ellipse four probes over
// +-(s1 - s2) along the major axis with symmetric weights; a 64:1 ellipse with Nmax 8 eight
// probes at log2(s1 / 8).
TEST(FelineRef, ProbesAlongTheMajorAxis) {
  const auto& t = bricks();
  feline::Params p;
  p.max_probes = 8;
  const auto one = feline::filter_axes(t, 100.3, 50.7, 3, 3, 0.4, p);
  EXPECT_EQ(one.probes, 1);
  const auto tri = tex::trilinear_ref(t, std::log2(3.0), 100.3, 50.7);
  EXPECT_NEAR(one.color.r, tri.r, 1e-9);
  EXPECT_EQ(one.texels, 8);
  EXPECT_EQ(feline::filter_axes(t, 100, 50, 8, 2, 0.4, p).probes, 4);
  EXPECT_EQ(feline::filter_axes(t, 100, 50, 8.02, 2, 0.4, p).probes, 4);  // within the tolerance
  EXPECT_EQ(feline::filter_axes(t, 100, 50, 8.05, 2, 0.4, p).probes, 5);
  EXPECT_EQ(feline::filter_axes(t, 100, 50, 3.01, 3, 0.4, p).probes, 1);
  const auto clamped = feline::filter_axes(t, 100, 50, 64, 1, 0.4, p);
  EXPECT_EQ(clamped.probes, 8);
  EXPECT_DOUBLE_EQ(clamped.lod, 3);  // log2(64 / 8)
  EXPECT_DOUBLE_EQ(feline::probe_t(0, 4), -1);
  EXPECT_DOUBLE_EQ(feline::probe_t(3, 4), 1);
  EXPECT_DOUBLE_EQ(feline::probe_t(0, 1), 0);
  // A texture constant along the major axis: every probe sees the same colour as the centre.
  img::Rgba8Image stripes(64, 64);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) stripes.at(x, y) = (y / 4) % 2 ? img::Rgba8{255, 0, 0, 255} : img::Rgba8{0, 0, 255, 255};
  const auto st = tex::Texture::build("stripes", stripes, tex::Wrap::Repeat);
  const auto along = feline::filter_axes(st, 30, 30.5, 16, 1, 0, p);
  const auto centre = tex::trilinear_ref(st, along.lod, 30, 30.5);
  EXPECT_NEAR(along.color.r, centre.r, 1e-9);
}

struct ErrStats {
  double max_abs = 0, se = 0;
  size_t n = 0, lod_diff = 0, probe_diff = 0;
};

// C model vs the float reference on the same B2 outputs: the probe count is exact, the LOD
// within its 8-bit floor, the colour within the bound of the probes' trilinear (2.99 LSB): the
// positions (s1 from the 8-bit log, the CORDIC direction), weights and normalisation add less
// than the trilinear's own rounding takes.
TEST(FelineFx, MatchesFloatReferenceOnB2Outputs) {
  const auto& t = bricks();
  std::mt19937_64 rng(23);
  for (int nmax : {2, 4, 8, 16}) {
    ErrStats st;
    for (int i = 0; i < 20000; ++i) {
      const ewa::fx::In in = ewa::fx::random_in(rng);
      ffx::Config cfg;
      cfg.max_probes = nmax;
      feline::Params p;
      p.max_probes = nmax;
      const auto fx = ffx::filter(in, t, cfg);
      const auto ref = ffx::filter_ref_b2(in, t, p);
      st.probe_diff += fx.probes != ref.probes;
      const double lod = std::ldexp(double(fx.lod), -fmt::kTexLodF);
      ASSERT_GE(ref.lod - lod, -1e-9) << i;
      ASSERT_LT(ref.lod - lod, 1.0 / (1 << fmt::kTexLodF)) << i;
      st.lod_diff += std::floor(lod) != std::floor(ref.lod);
      for (double e : {fx.color.r - ref.color.r, fx.color.g - ref.color.g, fx.color.b - ref.color.b}) {
        st.max_abs = std::max(st.max_abs, std::fabs(e));
        st.se += e * e;
        ++st.n;
      }
    }
    std::printf("Nmax %2d: 20000 random pixels, probe count differs on %zu, level differs on %zu; colour vs "
                "float max |err| %.3f LSB, RMS %.4f LSB\n",
                nmax, st.probe_diff, st.lod_diff, st.max_abs, std::sqrt(st.se / double(st.n)));
    EXPECT_EQ(st.probe_diff, 0u);
    // Within the probes' trilinear bound (texture.md: 2.99 LSB); measured 1.24 .. 1.37.
    EXPECT_LT(st.max_abs, 2.99);
    EXPECT_LT(std::sqrt(st.se / double(st.n)), 0.5);
  }
}

// Declared widths on the extremes: the largest major axis (clamped to 2^FelAxisMaxLog2), the
// thinnest ellipse (anisotropy 2^10 before B2's clamp), magnification, every direction; the
// weights of the inner probes are never 0.
TEST(FelineFx, WidthsOnExtremes) {
  const auto& t = bricks();
  uint64_t max_sig = 0, max_delta = 0;
  int64_t max_h = 0;
  uint32_t max_t = 0;
  for (double major : {1e-3, 0.5, 1.0, 7.9, 1000.0, 8191.0, 1e5}) {
    for (double aniso : {1.0, 1.5, 4.0, 16.0, 1024.0}) {
      for (double th : {0.0, 0.3, M_PI / 4, M_PI / 2 - 1e-3, -1.2}) {
        const auto in = ewa::fx::in_from_local(ewa::fx::footprint_local(major, aniso, th, 1000.25, -3000.5),
                                               10 << fmt::kEllLogF);
        for (int nmax : {1, 2, 16}) {
          ffx::Config cfg;
          cfg.max_probes = nmax;
          const auto su = ffx::setup(in, t, cfg);
          max_sig = std::max(max_sig, su.sig1);
          max_delta = std::max(max_delta, su.delta);
          max_h = std::max({max_h, std::abs(su.hu), std::abs(su.hv)});
          uint64_t wsum = 0;
          for (int i = 0; i < su.n; ++i) {
            const auto pr = ffx::probe(su, in, i);
            wsum += pr.w;
            max_t = std::max(max_t, pr.q);
            if (std::abs(2 * i - (su.n - 1)) <= 1) {
              EXPECT_GT(pr.w, 0u) << major << " " << aniso;
            }
          }
          EXPECT_LT(wsum, uint64_t(1) << fmt::kFelWsumW);
          EXPECT_LT(wsum * 255, uint64_t(1) << fmt::kFelAccW);
          EXPECT_LE(su.n, nmax);
        }
      }
    }
  }
  std::printf("extremes: s1 %llu (< 2^%d), D %llu, |h| %lld (< 2^%d), Q code max %u\n", (unsigned long long)max_sig,
              fmt::kFelSigW, (unsigned long long)max_delta, (long long)max_h, fmt::kFelStepW - 1, max_t);
  EXPECT_LT(max_sig, uint64_t(1) << fmt::kFelSigW);
  EXPECT_LE(max_delta, max_sig);
  EXPECT_LT(max_h, int64_t(1) << (fmt::kFelStepW - 1));
  EXPECT_GE(max_sig, uint64_t(1) << (fmt::kFelSigW - 2));  // the clamp is reached: the width is tight
}

// The render engines on the default scene at half resolution (texture path): the C model close to
// the float Feline, and Feline between trilinear and EWA against the box truth.
TEST(FelineRender, DefaultSceneBetweenTrilinearAndEwa) {
  auto s = scene::without_relief(scene::default_scene());
  s.camera.width /= 2;
  s.camera.height /= 2;
  const auto ref = render::render_ref(s, scene::Filter::Feline);
  const auto fx = render::render_cmodel(s, scene::Filter::Feline, render::texture_path_only());
  ASSERT_EQ(fx.pixels.size(), ref.pixels.size());
  render::TruthOptions to;
  to.ss = 8;
  to.relief = false;
  const auto truth = render::render_truth(s, to);
  const auto tri = render::render_cmodel(s, scene::Filter::Trilinear, render::texture_path_only());
  const auto ewa = render::render_cmodel(s, scene::Filter::Ewa, render::texture_path_only());
  const double p_ref = render::psnr_covered(fx, ref), p_truth = render::psnr_covered(fx, truth);
  const double p_tri = render::psnr_covered(tri, truth), p_ewa = render::psnr_covered(ewa, truth);
  double probes = 0;
  for (const auto& p : fx.pixels) probes += p.probes;
  std::printf("128x96: C-model Feline vs float Feline %.2f dB; vs truth (8x8 box): Feline %.2f dB, trilinear "
              "%.2f dB, EWA %.2f dB; %.2f probes per pixel\n",
              p_ref, p_truth, p_tri, p_ewa, probes / double(fx.pixels.size()));
  EXPECT_GT(p_ref, 40);
  EXPECT_GT(p_truth, p_tri);
  EXPECT_LT(p_truth, p_ewa);
}

}  // namespace
