#include "noise/noise_proc.hpp"

#include <algorithm>
#include <cmath>

#include "noise/noise_core.hpp"
#include "noise/noise_fbm.hpp"
#include "noise/noise_ref.hpp"
#include "texunit/convert.hpp"

namespace tu::noise {

namespace {
constexpr int kCoordDrop = fmt::kTexUvF + pfmt::kNoiseFreqF - fmt::kNoiseTF;
static_assert(pfmt::kNoiseLodF == fmt::kEllLogF, "octave weights take B2's lrho as it is");
static_assert(kCoordDrop > 0, "the frequency product drops bits (round half up)");

int64_t wrap32(int64_t code) { return static_cast<int32_t>(static_cast<uint32_t>(code)); }

double bound(int dims) { return dims == 2 ? kBound2 : kBound3; }

constexpr int64_t kOne = int64_t(1) << fmt::kNoiseTF;

uint32_t clamp_unit(int64_t q) { return static_cast<uint32_t>(std::clamp<int64_t>(q, 0, int64_t(1) << fmt::kNoiseTF)); }
}  // namespace

uint32_t norm_code(int dims, int octaves) {
  const int64_t b = dims == 2 ? fmt::kNoiseBound2E4 : fmt::kNoiseBound3E4;
  return static_cast<uint32_t>(((int64_t(1) << (fmt::kNoiseNormF + octaves - 1)) * 10000 /
                                    (b * ((int64_t(1) << octaves) - 1)) + 1) / 2);
}

int64_t coord_code(int64_t uv_code, uint32_t freq, int64_t shift) {
  // Modulo 2^64 (unsigned, defined): the bits kept are far below 2^64.
  const uint64_t p = static_cast<uint64_t>(uv_code) * freq + (uint64_t(1) << (kCoordDrop - 1));
  return wrap32(static_cast<int64_t>(p >> kCoordDrop) + shift);
}

ProcCodes quantise(const ProcParams& p) {
  ProcCodes c;
  c.smoke = p.smoke;
  c.dims = p.dims;
  c.octaves = std::clamp(p.octaves, 1, fmt::kNoiseOctaves);
  c.freq = static_cast<uint32_t>(std::clamp<int64_t>(round_i64(std::ldexp(p.freq, pfmt::kNoiseFreqF)), 1,
                                                     int64_t(UINT32_MAX)));
  // Saturated to B2's lrho format (s(EllLogW).EllLogF, the RTL's field): a bias beyond +-128
  // octaves keeps every octave or none either way.
  constexpr int64_t kLogMax = (int64_t(1) << (fmt::kEllLogW - 1)) - 1;
  c.lfreq = static_cast<int32_t>(std::clamp<int64_t>(
      round_i64(std::ldexp(std::log2(std::ldexp(double(c.freq), -pfmt::kNoiseFreqF)) + std::clamp(p.lod_bias, -256.0, 256.0),
                           pfmt::kNoiseLodF)),
      -kLogMax - 1, kLogMax));
  c.sx = round_i64(std::ldexp(p.sx, fmt::kNoiseTF));
  c.sy = round_i64(std::ldexp(p.sy, fmt::kNoiseTF));
  c.z = p.dims == 2 ? 0 : wrap32(round_i64(std::ldexp(std::fmod(p.z, 256.0), fmt::kNoiseTF)));
  c.limit = p.limit;
  c.norm = norm_code(p.dims, c.octaves);
  c.mean_abs = round_i64(std::ldexp(p.dims == 2 ? kMeanAbs2 : kMeanAbs3, fmt::kNoiseTF));
  c.thr = static_cast<uint32_t>(round_i64(std::ldexp(std::clamp(p.threshold, 0.0, 1.0), fmt::kNoiseTF)));
  c.gain = static_cast<uint32_t>(std::clamp<int64_t>(round_i64(std::ldexp(p.gain, pfmt::kNoiseGainF)), 0,
                                                     (int64_t(1) << pfmt::kNoiseGainW) - 1));
  c.water = p.water;
  c.amp = static_cast<uint32_t>(std::clamp<int64_t>(round_i64(std::ldexp(p.amplitude, pfmt::kWaterAmpF)), 0,
                                                    (int64_t(1) << pfmt::kWaterAmpW) - 1));
  const double ln = std::hypot(p.light[0], p.light[1], p.light[2]);
  for (size_t i = 0; i < 3; ++i)
    c.light[i] = ln > 0 ? round_i64(std::ldexp(p.light[i] / ln, fmt::kNoiseTF)) : (i == 2 ? kOne : 0);
  for (size_t i = 0; i < 3; ++i) {
    c.c0[i] = static_cast<uint8_t>(std::clamp<int64_t>(round_i64(p.c0[i]), 0, 255));
    c.c1[i] = static_cast<uint8_t>(std::clamp<int64_t>(round_i64(p.c1[i]), 0, 255));
  }
  return c;
}

namespace {
// The weighted octave sum at noise point (x, y, c.z), s(NoiseAccW).kAccF, exact.
int64_t weighted_sum(const ProcCodes& c, int64_t x, int64_t y, const OctaveWeights& w) {
  int64_t acc = 0;
  for (int i = 0; i < c.octaves; ++i) {
    const uint32_t wi = w[static_cast<size_t>(i)];
    int64_t n = 0;  // a faded-out octave's core output is multiplied by 0 (the RTL gates nothing)
    if (wi != 0) {
      const Axis a[3] = {split(x, i), split(y, i), split(c.z, i)};
      n = noise_fx(c.dims, a).raw();
    }
    // w n (+ (1 - w) m for smoke's |n|) rounded half up to NoiseTF bits (exact at w = 1 and 0).
    const int64_t rest = c.smoke ? c.mean_abs * (int64_t(kWeightOne) - wi) : 0;
    const int64_t wn = ((c.smoke ? std::abs(n) : n) * wi + rest + (int64_t(1) << (pfmt::kNoiseLodF - 1))) >>
                       pfmt::kNoiseLodF;
    acc += wn * (int64_t(1) << (fmt::kNoiseOctaves - 1 - i));
  }
  return acc;
}

// floor(sqrt(n)) exactly, n < 2^62 (the RTL: tu_isqrt_pipe).
int64_t isqrt(int64_t n) {
  auto r = static_cast<int64_t>(std::sqrt(static_cast<double>(n)));
  while (r > 0 && r * r > n) --r;
  while ((r + 1) * (r + 1) <= n) ++r;
  return r;
}

// Water's slopes -a dP/dx, -a dP/dy (kWaterF fraction bits, before the saturation), dP by forward
// differences over 2^-8 cells (codes: 2^kWaterStepCode ULP of s32.16).
std::array<int64_t, 2> water_slopes(const ProcCodes& c, int64_t x, int64_t y, const OctaveWeights& w) {
  const int64_t p0 = weighted_sum(c, x, y, w);
  const int64_t dx = weighted_sum(c, wrap32(x + (int64_t(1) << kWaterStepCode)), y, w) - p0;
  const int64_t dy = weighted_sum(c, x, wrap32(y + (int64_t(1) << kWaterStepCode)), w) - p0;
  // Slopes dP/dx = d 2^(kWaterStepLog2 - kAccF); g = -a slope with kWaterF fraction bits.
  constexpr int kShift = fmt::kNoiseTF - kWaterStepCode;  // 2^-8 cells: the step in the slope
  static_assert(kAccF - kShift + pfmt::kWaterAmpF == kWaterF, "g carries kWaterF fraction bits");
  return {-int64_t(c.amp) * dx, -int64_t(c.amp) * dy};
}

// Water: Lambert of the normal (-a dP/dx, -a dP/dy, 1).
uint32_t water_shade(const ProcCodes& c, int64_t x, int64_t y, const OctaveWeights& w) {
  const auto g = water_slopes(c, x, y, w);
  auto slope = [](int64_t v) { return std::clamp(v, -kWaterSlopeMax, kWaterSlopeMax); };
  const int64_t gx = slope(g[0]), gy = slope(g[1]);
  const int64_t one = int64_t(1) << kWaterF;
  const int64_t len = isqrt(gx * gx + gy * gy + one * one);  // kWaterF fraction bits, floor
  const int64_t dot = gx * c.light[0] + gy * c.light[1] + one * c.light[2];  // kWaterF + NoiseTF bits
  if (dot <= 0) return 0;
  return clamp_unit((dot + len / 2) / len);  // NoiseTF bits, round half up
}
}  // namespace

std::array<int64_t, 2> water_slopes_fx(const ProcCodes& c, int64_t u, int64_t v, int32_t lrho) {
  return water_slopes(c, coord_code(u, c.freq, c.sx), coord_code(v, c.freq, c.sy),
                      octave_weights_fx(lrho, c.lfreq, c.octaves, c.limit));
}

uint32_t proc_value_fx(const ProcCodes& c, int64_t u, int64_t v, int32_t lrho) {
  const int64_t x = coord_code(u, c.freq, c.sx), y = coord_code(v, c.freq, c.sy);
  const OctaveWeights w = octave_weights_fx(lrho, c.lfreq, c.octaves, c.limit);
  if (c.water) return water_shade(c, x, y, w);
  const int64_t acc = weighted_sum(c, x, y, w);
  if (!c.smoke) return normalise_code(acc, c.norm);
  constexpr int kDrop = kAccF + fmt::kNoiseNormF - 1 - fmt::kNoiseTF;  // 2 acc C: one bit less dropped
  const int64_t turb = clamp_unit((acc * c.norm + (int64_t(1) << (kDrop - 1))) >> kDrop);
  const int64_t d = (turb - int64_t(c.thr)) * c.gain + (int64_t(1) << (pfmt::kNoiseGainF - 1));
  return clamp_unit(d >> pfmt::kNoiseGainF);
}

img::Rgba8 proc_color_fx(const ProcCodes& c, uint32_t value) {
  auto mix = [&](int a, int b) {
    return static_cast<uint8_t>((int64_t(a) * (int64_t(1) << fmt::kNoiseTF) + int64_t(value) * (b - a) +
                                 (int64_t(1) << (fmt::kNoiseTF - 1))) >> fmt::kNoiseTF);
  };
  const uint8_t alpha = c.smoke ? mix(0, 255) : 255;
  return {mix(c.c0[0], c.c1[0]), mix(c.c0[1], c.c1[1]), mix(c.c0[2], c.c1[2]), alpha};
}

namespace {
double weighted_sum_ref(const ProcParams& p, double x, double y, double lcells) {
  double acc = 0;
  for (int i = 0; i < p.octaves; ++i) {
    const double w = octave_weight_ref(lcells, i, p.octaves, p.limit);
    const double s = std::ldexp(1.0, i);
    const double n = w == 0 ? 0 : p.dims == 2 ? noise2_ref(s * x, s * y) : noise3_ref(s * x, s * y, s * p.z);
    acc += (p.smoke ? w * std::fabs(n) + (1 - w) * (p.dims == 2 ? kMeanAbs2 : kMeanAbs3) : w * n) / s;
  }
  return acc;
}
}  // namespace

double proc_value_ref(const ProcParams& p, double u, double v, double lrho) {
  const double x = u * p.freq + p.sx, y = v * p.freq + p.sy;
  const double lcells = lrho + std::log2(p.freq) + p.lod_bias;
  if (p.water) {
    const double step = std::ldexp(1.0, kWaterStepCode - fmt::kNoiseTF);  // 2^-8 cells, as the C model
    const double p0 = weighted_sum_ref(p, x, y, lcells);
    const double gx = -p.amplitude * (weighted_sum_ref(p, x + step, y, lcells) - p0) / step;
    const double gy = -p.amplitude * (weighted_sum_ref(p, x, y + step, lcells) - p0) / step;
    const double ln = std::hypot(p.light[0], p.light[1], p.light[2]);
    const double dot = (gx * p.light[0] + gy * p.light[1] + p.light[2]) / (ln * std::sqrt(gx * gx + gy * gy + 1));
    return std::clamp(dot, 0.0, 1.0);
  }
  const double acc = weighted_sum_ref(p, x, y, lcells);
  const double scale = bound(p.dims) * octave_amplitude_sum(p.octaves);
  if (!p.smoke) return std::clamp(acc / (2 * scale) + 0.5, 0.0, 1.0);
  const double turb = std::clamp(acc / scale, 0.0, 1.0);
  return std::clamp((turb - p.threshold) * p.gain, 0.0, 1.0);
}

std::array<double, 4> proc_color_ref(const ProcParams& p, double value) {
  std::array<double, 4> c{};
  for (size_t i = 0; i < 3; ++i) c[i] = p.c0[i] + value * (p.c1[i] - p.c0[i]);
  c[3] = p.smoke ? 255 * value : 255;
  return c;
}

}  // namespace tu::noise
