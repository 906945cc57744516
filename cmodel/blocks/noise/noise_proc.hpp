// Procedural materials (docs/blocks/noise-appendix.md §5, seed 001 §4.2 / §4.3): the unit's colour from
// Perlin noise at the pixel's (u, v[, t]) instead of a texture fetch.
//
//   noise point    x = u f/W + sx, y = v f/W + sy, z = speed t   (cells; u, v level-0 texels)
//   octave weights w_i from the footprint (noise_octave_weights.hpp)
//   fbm            value = (sum_i w_i n(2^i p) 2^-i) / (2 B S_K) + 1/2            in [0, 1]
//   smoke          turb = (sum_i (w_i |n_i| + (1 - w_i) m) 2^-i) / (B S_K)  (turbulence) in [0, 1]
//                  with m = E|noise| (kMeanAbs2/3): a faded octave of |n| tends to its mean, not 0
//                  value = clamp((turb - threshold) gain, 0, 1)   (opacity mapping)
//   water          P = sum_i w_i n_i 2^-i, normal (-a dP/dx, -a dP/dy, 1) by forward differences over
//                  2^-8 cells (the same in the reference), value = max(0, n.L) / |n| (Lambert, the
//                  tangent-space light L; the scene has no lights and the BRDF stage is not in the unit)
//   colour         color0 + value (color1 - color0); alpha 255 (fbm, water), value (smoke)
// with S_K = 2 - 2^(1-K), B = kBound2 (2-D, z = 0) or kBound3. Faded octaves lower the contrast
// toward the mean (1/2; smoke: clear), the band-limited expectation of the field.
// Time as the third dimension is the note's reconstruction of the seed's `animate` (§4.3).
//
// Fixed point (formats NoiseFreq*, NoiseLodF, NoiseGain*; the noise core and its bound as
// noise_core.hpp):
//   x code s32.16 = wrap32(round_half_up(u_code * freq >> (TexUvF + NoiseFreqF - NoiseTF)) + sx):
//     the product is taken modulo 2^64 and the code modulo 2^32, both multiples of the period
//     256 cells, so the wrap is exact for every u (no overflow case); freq = round(f/W 2^24).
//   w_i n_i  s19.16, round half up (exact when w_i = 1); sum s23.19 exact as fbm_sum;
//   value    u17.16: acc C_K + 1/2 (fbm) or 2 acc C_K (smoke), round half up, clamp (guard);
//            C_K = norm_code(dims, K), u0.18, = NoiseNorm2/3 at K = NoiseOctaves;
//   opacity  (turb - thr) gain: thr u17.16, gain u16.8, round half up, clamp to [0, 1];
//   water    slopes from exact sums: g = -a dP s(WaterSlopeW).kWaterF (a u5.8), saturated to
//            +-kWaterSlopeMax (guard), |n|^2 exact (< 2^62), |n| = floor(isqrt) kWaterF bits, n.L
//            with L s.16 (normalised by the host), value = floor((n.L + floor(|n|/2)) / |n|) (round
//            half up), clamp to 1 (0 when n.L <= 0)
//   colour   (c0 2^16 + value (c1 - c0) + 2^15) >> 16 per channel (8 bits, exact floor).
// With every weight 1 the fbm value equals fbm_fx's sum normalised with C_K (bit for bit).
// Error against proc_ref: the noise core's bound per octave (docs/blocks/noise.md §3) plus the
// frequency quantisation |u| 2^-25 cells and the octave-weight quantisation; measured in
// NoiseProc.* (testbench/unit/noise_proc_test.cpp) and docs/blocks/noise-appendix.md §5.
#pragma once

#include <array>
#include <cstdint>

#include "noise/noise_octave_weights.hpp"
#include "texunit/image.hpp"

namespace tu::noise {

// E|noise| over the plane (2-D) and over space (3-D): sampled means of Perlin's table over 2^22
// random points in [0, 256)^n (NoiseProc.MeanAbsoluteNoise checks them to 2e-3 on 2^18 points).
inline constexpr double kMeanAbs2 = 0.2074, kMeanAbs3 = 0.2206;

// Water's finite-difference step 2^-8 cells = 2^kWaterStepCode codes of s32.16, and the slope
// format: g = -a dP carries kAccF - (NoiseTF - kWaterStepCode) + WaterAmpF fraction bits
// (formats.hpp WaterStepCode, WaterSlopeF: shared with the RTL noise unit).
inline constexpr int kWaterStepCode = fmt::kWaterStepCode;
inline constexpr int kWaterF = fmt::kWaterSlopeF;
// The slope's saturation (guard): |g| <= kWaterSlopeMax, i.e. |a dP/dx| < 2^11, far above what the
// noise reaches (|dP/dx| <= K max|grad noise|, a < 32); it keeps |n|^2 < 2^62 (the RTL's root width).
inline constexpr int64_t kWaterSlopeMax = (int64_t(1) << (fmt::kWaterSlopeW - 1)) - 1;

struct ProcParams {  // the float description (the scene's material, in noise units)
  bool smoke = false;
  int dims = 2;              // 2: z = 0 (fbm without time), 3: z = speed t
  int octaves = fmt::kNoiseOctaves;
  double freq = 1.0 / 32;    // lattice cells per level-0 texel (f / W)
  double sx = 0, sy = 0;     // seed shift, whole cells
  double z = 0;              // speed t, cells
  bool limit = true;         // footprint-limited octaves
  double lod_bias = 0;       // octaves
  double threshold = 0.2, gain = 2;
  bool water = false;        // water instead of fbm (smoke false)
  double amplitude = 0.5;    // water: height a P in cells
  std::array<double, 3> light{0.4, 0.3, 0.866};  // water: tangent-space light (x along u, z the normal)
  std::array<double, 3> c0{0, 0, 0}, c1{255, 255, 255};
};

struct ProcCodes {  // the quantised per-material constants the unit holds
  bool smoke = false;
  int dims = 2, octaves = fmt::kNoiseOctaves;
  uint32_t freq = 0;        // u32.24
  int32_t lfreq = 0;        // log2(freq) + lod_bias, s.10
  int64_t sx = 0, sy = 0;   // s32.16 (whole cells)
  int64_t z = 0;            // s32.16 (wrapped)
  bool limit = true;
  uint32_t norm = 0;        // C_K u0.18
  int64_t mean_abs = 0;     // smoke: m = E|noise|, s19.16
  uint32_t thr = 0, gain = 0;  // u17.16, u16.8
  bool water = false;
  uint32_t amp = 0;            // water: a u8.8
  std::array<int64_t, 3> light{};  // water: unit light s.16
  std::array<uint8_t, 3> c0{}, c1{};
};

ProcCodes quantise(const ProcParams& p);
// C_K = round_half_up(2^NoiseNormF / (2 B (2 - 2^(1-K)))) as the formats' NoiseNorm2/3.
uint32_t norm_code(int dims, int octaves);
// The noise coordinate of a B1 texel code (s(PerspUvW).TexUvF) as s32.16.
int64_t coord_code(int64_t uv_code, uint32_t freq, int64_t shift);

// lrho of a footprint wider than every octave (beyond the B1 guard): every weight 0.
inline constexpr int32_t kNoFootprint = int32_t(1) << 24;

// The value u17.16 in [0, 1] at B1's (u, v) codes with B2's lrho (s18.10).
uint32_t proc_value_fx(const ProcCodes& c, int64_t u, int64_t v, int32_t lrho);
img::Rgba8 proc_color_fx(const ProcCodes& c, uint32_t value);
// Water's slopes (-a dP/dx, -a dP/dy) at B1's (u, v) with lrho, kWaterF fraction bits, before
// the saturation to +-kWaterSlopeMax (NoiseProc.WaterSlopesStayFarBelowTheSaturation).
std::array<int64_t, 2> water_slopes_fx(const ProcCodes& c, int64_t u, int64_t v, int32_t lrho);

// Float reference: u, v in level-0 texels, lrho = log2 rho in texels (GL rule).
double proc_value_ref(const ProcParams& p, double u, double v, double lrho);
// The colour of a value (RGBA, not rounded).
std::array<double, 4> proc_color_ref(const ProcParams& p, double value);

}  // namespace tu::noise
