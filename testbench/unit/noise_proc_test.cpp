// Procedural materials (docs/blocks/noise-appendix.md §5): the footprint-limited octave weights
// (exhaustive over B2's lrho codes), the procedural value against its float reference, the
// documented corner cases (full weights = the block's fBm, no footprint = the mean, the period
// wrap at extreme codes), and in a render: C model against the float reference, and the footprint
// limit against the supersampled truth.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>

#include "ellipse/ellipse_fx.hpp"
#include "noise/noise_fbm.hpp"
#include "noise/noise_proc.hpp"
#include "noise/noise_ref.hpp"
#include "texunit/render.hpp"
#include "texunit/scene.hpp"

namespace {
using namespace tu;
using namespace tu::noise;

constexpr int64_t kOne = int64_t(1) << fmt::kNoiseTF;
constexpr double kUlp = 1.0 / double(kOne);

ProcParams params(bool smoke, int dims, int octaves) {
  ProcParams p;
  p.smoke = smoke;
  p.dims = dims;
  p.octaves = octaves;
  p.freq = 1.0 / 32;  // 8 cells per 256-texel repeat: exact in u32.24, log2 exact
  p.sx = 111, p.sy = 17;
  p.z = dims == 3 ? 3.375 : 0;
  return p;
}

// Max and rms error (ULP of 2^-16) of proc_value_fx against proc_value_ref on `count` random
// B1 codes in +-2^22 texels with lrho over the fading range.
struct ErrStats {
  double max = 0, rms = 0;
};
ErrStats error_vs_ref(const ProcParams& p, int count, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int64_t> uv(-(int64_t(1) << 30), int64_t(1) << 30);
  std::uniform_int_distribution<int32_t> lr(-9 << pfmt::kNoiseLodF, 6 << pfmt::kNoiseLodF);
  const auto c = quantise(p);
  ErrStats st;
  double se = 0;
  for (int n = 0; n < count; ++n) {
    const int64_t u = uv(rng), v = uv(rng);
    const int32_t l = lr(rng);
    const double fx = proc_value_fx(c, u, v, l) * kUlp;
    const double ref = proc_value_ref(p, std::ldexp(double(u), -fmt::kTexUvF), std::ldexp(double(v), -fmt::kTexUvF),
                                      std::ldexp(double(l), -pfmt::kNoiseLodF));
    const double e = std::fabs(fx - ref) / kUlp;
    st.max = std::max(st.max, e);
    se += e * e;
  }
  st.rms = std::sqrt(se / count);
  return st;
}

TEST(NoiseProc, NormalisationConstantsMatchTheFormats) {
  EXPECT_EQ(norm_code(3, fmt::kNoiseOctaves), uint32_t(fmt::kNoiseNorm3));
  EXPECT_EQ(norm_code(2, fmt::kNoiseOctaves), uint32_t(fmt::kNoiseNorm2));
  for (int k = 1; k <= fmt::kNoiseOctaves; ++k)
    for (int d : {2, 3}) {
      const double c = 1 / (2 * (d == 2 ? kBound2 : kBound3) * octave_amplitude_sum(k));
      EXPECT_NEAR(norm_code(d, k) * std::ldexp(1.0, -fmt::kNoiseNormF), c, std::ldexp(1.0, -fmt::kNoiseNormF - 1) + 1e-12);
      EXPECT_LT(norm_code(d, k), 1u << fmt::kNoiseNormW);  // fits NoiseNormW
    }
}

// Every lrho code of B2's s18.10 range (and kLogNegInf), every octave, both switch positions:
// the fixed weights equal the float rule at the decoded lrho exactly, lie in [0, 1] and do not
// rise with the footprint.
TEST(NoiseProc, OctaveWeightsExhaustiveOverLrho) {
  const int32_t lfreq = -5 << pfmt::kNoiseLodF;  // f / W = 1/32
  OctaveWeights prev{};
  for (int64_t l = ellipse::fx::kLogNegInf; l < -ellipse::fx::kLogNegInf; ++l) {
    const auto w = octave_weights_fx(static_cast<int32_t>(l), lfreq, fmt::kNoiseOctaves, true);
    const double lcells = std::ldexp(double(l), -pfmt::kNoiseLodF) - 5;
    for (int i = 0; i < fmt::kNoiseOctaves; ++i) {
      const uint32_t wi = w[static_cast<size_t>(i)];
      ASSERT_LE(wi, kWeightOne);
      ASSERT_EQ(std::ldexp(double(wi), -pfmt::kNoiseLodF), octave_weight_ref(lcells, i, fmt::kNoiseOctaves, true)) << l;
      if (l > ellipse::fx::kLogNegInf) {
        ASSERT_LE(wi, prev[static_cast<size_t>(i)]) << l;
      }
      if (i > 0) {
        ASSERT_LE(wi, w[static_cast<size_t>(i - 1)]);  // higher octaves go first
      }
    }
    prev = w;
  }
  const auto off = octave_weights_fx(1 << 16, lfreq, 2, false);
  EXPECT_EQ(off[0], kWeightOne);
  EXPECT_EQ(off[1], kWeightOne);
  EXPECT_EQ(off[2], 0u);  // octaves >= K
  for (uint32_t wi : octave_weights_fx(ellipse::fx::kLogNegInf, lfreq, fmt::kNoiseOctaves, true)) EXPECT_EQ(wi, kWeightOne);
  for (uint32_t wi : octave_weights_fx(kNoFootprint, lfreq, fmt::kNoiseOctaves, true)) EXPECT_EQ(wi, 0u);
}

// With every weight 1 the procedural fBm is the block's fBm (fbm_fx) of the mapped coordinates,
// bit for bit; with no footprint it is exactly the mean (1/2; smoke: the mean turbulence's value).
TEST(NoiseProc, FullWeightsAreTheBlocksFbmAndNoFootprintIsTheMean) {
  std::mt19937_64 rng(18);
  std::uniform_int_distribution<int64_t> uv(-(int64_t(1) << 30), int64_t(1) << 30);
  for (int dims : {2, 3}) {
    const auto c = quantise(params(false, dims, fmt::kNoiseOctaves));
    const auto cs = quantise(params(true, dims, fmt::kNoiseOctaves));
    for (int n = 0; n < 20000; ++n) {
      const int64_t u = uv(rng), v = uv(rng);
      const uint32_t block = fbm_fx(dims, coord_code(u, c.freq, c.sx), coord_code(v, c.freq, c.sy), c.z);
      ASSERT_EQ(proc_value_fx(c, u, v, ellipse::fx::kLogNegInf), block);
      ASSERT_EQ(proc_value_fx(c, u, v, kNoFootprint), uint32_t(kOne / 2));
      ASSERT_EQ(proc_value_fx(cs, u, v, kNoFootprint), proc_value_fx(cs, 0, 0, kNoFootprint));  // the mean's
    }
  }
}

// The value against the float reference at the decoded point and lrho: random u, v over +-2^22
// texels and lrho over the fading range. Derived bound: the block's fBm bound (3.20 / 4.41 ULP,
// docs/blocks/noise.md §3) + the weighted octaves' rounding (0.5 ULP each, times C 2^-i: < 0.3
// ULP) + the coordinate rounding (2^-17 cells per octave, times the slope of the noise, < 2.6,
// times C S_K: < 0.4 ULP); smoke doubles the noise terms (2 C) before its gain. Both switch
// positions, K = 1..4.
TEST(NoiseProc, ValueErrorAgainstTheFloatReference) {
  uint64_t seed = 7;
  for (bool smoke : {false, true})
    for (int dims : {2, 3})
      for (int k = 1; k <= fmt::kNoiseOctaves; ++k) {
        auto p = params(smoke, dims, k);
        p.gain = 1;  // smoke: the turbulence itself (threshold 0.2)
        const auto e = error_vs_ref(p, 1 << 14, seed++);
        const double bound = (dims == 2 ? 3.20 : 4.41) + 0.3 + 0.4;
        std::printf("%s dims %d K %d: max %.3f ULP, rms %.3f ULP (bound %.2f)\n", smoke ? "smoke" : "fbm  ", dims, k,
                    e.max, e.rms, smoke ? 2 * bound : bound);
        EXPECT_LE(e.max, smoke ? 2 * bound : bound);
      }
}

TEST(NoiseProc, MeanAbsoluteNoise) {
  std::mt19937_64 rng(22);
  std::uniform_real_distribution<double> d(0, 256);
  double s2 = 0, s3 = 0;
  const int n = 1 << 18;  // the constants: 2^22 points
  for (int i = 0; i < n; ++i) {
    s2 += std::fabs(noise2_ref(d(rng), d(rng)));
    s3 += std::fabs(noise3_ref(d(rng), d(rng), d(rng)));
  }
  EXPECT_NEAR(s2 / n, kMeanAbs2, 2e-3);
  EXPECT_NEAR(s3 / n, kMeanAbs3, 2e-3);
}

// Water's Lambert shade against the float reference (the same forward difference over 2^-8
// cells). Derived bound: the shade is 1-Lipschitz in the slope g, and each slope differences two
// octave sums, each within e_P = S_K (7.99 + 0.5) ULP of its reference (the core bound of §3 per
// octave, plus the weight's rounding), over a step of 2^-8 cells: |error| <= a 2 e_P 2^8 + 2 ULP
// (the square root and the division).
TEST(NoiseProc, WaterShadeAgainstTheFloatReference) {
  for (int dims : {2, 3}) {
    auto p = params(false, dims, fmt::kNoiseOctaves);
    p.water = true;
    p.amplitude = 0.5;
    const auto e = error_vs_ref(p, 1 << 13, 5 + uint64_t(dims));
    const double bound = p.amplitude * 2 * octave_amplitude_sum(fmt::kNoiseOctaves) * 8.49 * 256 + 2;
    std::printf("water dims %d: max %.1f ULP, rms %.1f ULP (bound %.0f ULP of 2^-16)\n", dims, e.max, e.rms, bound);
    EXPECT_LE(e.max, bound);
    // A flat field (no footprint: every weight 0) faces the normal: the shade is L.z.
    EXPECT_NEAR(proc_value_fx(quantise(p), 123, 456, kNoFootprint) * kUlp, 0.866 / std::hypot(0.4, 0.3, 0.866), 2 * kUlp);
  }
}

// The slope's saturation (|a dP/dx| < 2^11, kWaterSlopeMax) is a guard: at the largest amplitude
// code (a = 31.996) and every octave at full weight, the steepest slope found on 2^16 random points
// per dimension stays far below it (the measured margin is printed), so it never acts on a scene.
TEST(NoiseProc, WaterSlopesStayFarBelowTheSaturation) {
  for (int dims : {2, 3}) {
    auto p = params(false, dims, fmt::kNoiseOctaves);
    p.water = true;
    p.amplitude = 32;  // clamped to the largest code
    p.limit = false;
    const auto c = quantise(p);
    ASSERT_EQ(c.amp, (1u << pfmt::kWaterAmpW) - 1);
    std::mt19937_64 rng(77 + uint64_t(dims));
    std::uniform_int_distribution<int64_t> uv(-(int64_t(1) << 30), int64_t(1) << 30);
    int64_t gmax = 0;
    for (int n = 0; n < 1 << 16; ++n) {
      const auto g = water_slopes_fx(c, uv(rng), uv(rng), 0);
      gmax = std::max({gmax, std::abs(g[0]), std::abs(g[1])});
    }
    const double slope = std::ldexp(double(gmax), -kWaterF), limit = std::ldexp(double(kWaterSlopeMax), -kWaterF);
    std::printf("water dims %d, a = %.3f: max |a dP/dx| = %.1f, saturation at %.0f (%.0fx margin)\n", dims,
                std::ldexp(double(c.amp), -pfmt::kWaterAmpF), slope, limit, limit / slope);
    EXPECT_GT(gmax, 0);
    EXPECT_LT(gmax, kWaterSlopeMax / 4);
  }
}

// The period-256 wrap of the coordinate mapping: u and u + 256 cells (8192 texels at f/W = 1/32)
// give the same code and value, also at the extreme B1 codes (UBSan: no overflow anywhere).
TEST(NoiseProc, PeriodWrapAndExtremeCodes) {
  const auto c = quantise(params(false, 3, 4));
  const int64_t period = int64_t(8192) << fmt::kTexUvF;
  const int64_t lo = -(int64_t(1) << 31), hi = (int64_t(1) << 31) - 1;
  for (int64_t u : {lo, lo + 1, int64_t(-1), int64_t(0), int64_t(12345), hi - period, hi}) {
    EXPECT_EQ(coord_code(u, c.freq, c.sx) & 0xFFFFFF, coord_code(u + period, c.freq, c.sx) & 0xFFFFFF);
    EXPECT_EQ(proc_value_fx(c, u, 77, -3000), proc_value_fx(c, u + period, 77, -3000));
    EXPECT_LE(proc_value_fx(c, u, hi, -7000), uint32_t(kOne));
  }
}

TEST(NoiseProc, ColourMappingEndsAndMonotonic) {
  auto p = params(true, 2, 4);
  p.c0 = {10, 200, 0};
  p.c1 = {250, 20, 0};
  const auto c = quantise(p);
  const auto a = proc_color_fx(c, 0), b = proc_color_fx(c, uint32_t(kOne));
  EXPECT_EQ(a, (img::Rgba8{10, 200, 0, 0}));
  EXPECT_EQ(b, (img::Rgba8{250, 20, 0, 255}));
  img::Rgba8 prev = a;
  for (uint32_t v = 0; v <= uint32_t(kOne); v += 7) {
    const auto m = proc_color_fx(c, v);
    ASSERT_GE(m.r, prev.r);
    ASSERT_LE(m.g, prev.g);
    ASSERT_GE(m.a, prev.a);
    prev = m;
  }
}

// A small version of docs/scenes/procedural.json (64 x 48): the C model within 1 grey level of
// the float reference on most pixels, and the footprint limit brings the render closer to the
// supersampled truth than the unlimited octaves (the aliasing the limit removes).
TEST(NoiseProc, RenderMatchesTheReferenceAndTheLimitReducesAliasing) {
  auto s = scene::procedural_scene();
  s.camera.width = 64, s.camera.height = 48;
  const auto ref = render::render_ref(s);
  const auto cm = render::render_cmodel(s);
  EXPECT_GT(render::psnr_covered(cm, ref), 45);
  render::TruthOptions to;
  to.ss = 8;
  const auto truth = render::render_truth(s, to);
  auto unlimited = s;
  for (auto& [n, m] : unlimited.materials) m.procedural->footprint_limit = false;
  const double with = render::psnr_covered(render::render_cmodel(s), truth);
  const double without = render::psnr_covered(render::render_cmodel(unlimited), truth);
  std::printf("PSNR vs truth: footprint limit %.2f dB, all octaves %.2f dB\n", with, without);
  EXPECT_GT(with, without + 1);
}

TEST(NoiseProc, DocsSceneIsTheEmbeddedOne) {
  std::ifstream in(std::string(TU_SOURCE_DIR) + "/docs/scenes/procedural.json", std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), scene::procedural_scene_json());
}

TEST(NoiseProc, SceneFieldsAreValidated) {
  const std::string head = R"({"texunit_scene": 1, "camera": {"position": [0,1,0], "look_at": [0,0,-1],
    "width": 8, "height": 8}, "textures": {"t": {"builtin": "checkerboard"}}, "materials": {"m": {"texture": "t",
    "procedural": )";
  const std::string tail = R"(}}, "objects": [{"type": "triangle", "material": "m",
    "vertices": [[0,0,-1],[1,0,-1],[0,1,-1]], "uv": [[0,0],[1,0],[0,1]]}]})";
  auto err = [&](const std::string& proc) {
    try {
      scene::parse(head + proc + tail, "p.json", ".");
    } catch (const scene::SceneError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(err(R"({"kind": "fbm"})"), "");
  EXPECT_NE(err(R"({"kind": "marble"})").find("p.json: /materials/m/procedural/kind: 'marble' is not one of"), std::string::npos);
  EXPECT_NE(err(R"({"kind": "fbm", "octaves": 5})").find("/materials/m/procedural/octaves: value 5 is out of range [1, 4]"), std::string::npos);
  EXPECT_NE(err(R"({"kind": "fbm", "frequency": 200})").find("/procedural/frequency"), std::string::npos);
  EXPECT_NE(err(R"({"kind": "fbm", "footprint_limit": 1})").find("/procedural/footprint_limit: expected true or false"), std::string::npos);
  EXPECT_NE(err(R"({"kind": "fbm", "color1": [0, -1, 0]})").find("/procedural/color1/1"), std::string::npos);
  EXPECT_NE(err(R"({"kind": "fbm", "threshold": 0.5})").find("/procedural/threshold: unknown field"), std::string::npos);
  EXPECT_NE(err(R"({"kind": "water", "light": [0, 0, 0]})").find("/procedural/light: is the zero vector"), std::string::npos);
  EXPECT_NE(err(R"({"kind": "water", "amplitude": 20})").find("/procedural/amplitude"), std::string::npos);
  const auto s = scene::parse(head + R"({"kind": "smoke", "octaves": 2, "time": 1.5})" + tail, "p.json", ".");
  const auto& p = *s.materials.at("m").procedural;
  EXPECT_EQ(p.kind, scene::ProceduralKind::Smoke);
  EXPECT_EQ(p.octaves, 2);
  EXPECT_EQ(p.speed, 1.0);  // smoke: time is a dimension by default
  EXPECT_EQ(scene::at_time(s, 0.5).materials.at("m").procedural->time, 2.0);
}

}  // namespace
