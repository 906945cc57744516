// Footprint-limited octaves (docs/blocks/noise-appendix.md §5): octave i of the fBm has lattice frequency
// 2^i; its value is 0 at every lattice point, so its energy peaks near 2^(i-1) cycles per cell.
// Sampled at the pixel spacing rho (in cells: the GL-rule major axis, B2's lrho in texels +
// log2(f / W)) it aliases once that frequency passes the Nyquist frequency 1 / (2 rho). Each
// octave is kept below that limit and faded out over the octave above it (the clamping of Norton,
// Rockwood and Skolmoski, 1982):
//     w_i = clamp(1 - log2(rho) - bias - i, 0, 1)  for i < K,  0 for i >= K
// (full while 2^(i-1) <= 1 / (2 rho), 0 from 2^(i-1) >= 1 / rho). The major axis (not the minor
// one) so that no direction aliases. lod_bias (the material's) moves the limit: < 0 keeps more
// octaves (sharper, aliases sooner), > 0 fewer; the measured sweep is in docs/blocks/noise-appendix.md §5.
//
// Fixed point: lrho s(EllLogW).EllLogF (= NoiseLodF), the host constant lfreq = log2(f / W) + bias
// rounded to NoiseLodF bits, weights u(NoiseWeightW).NoiseLodF: exact clamps of an exact integer
// sum, no rounding; kLogNegInf (no footprint) gives full weights. The weights are piecewise linear
// in log2 rho with slope -1; float weights differ from them only by the quantisation of lrho
// (B2's bound, docs/blocks/ellipse.md) and of lfreq (2^-11 octave).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "texunit/formats.hpp"

namespace tu::noise {

// Formats of the procedural path (docs/blocks/noise-appendix.md §5): the ones the RTL noise unit
// (rtl/noise/tu_noise_unit.sv) shares are in formats.hpp (water's too); named here for the C model.
namespace pfmt {
inline constexpr int kNoiseFreqF = fmt::kNoiseFreqF;  // frequency f / W, lattice cells per texel: fraction bits
inline constexpr int kNoiseFreqW = fmt::kNoiseFreqW;  // frequency code: unsigned (f / W < 256)
inline constexpr int kNoiseLodF = fmt::kEllLogF;      // footprint log2 and octave weights: fraction bits
inline constexpr int kNoiseWeightW = fmt::kNoiseWeightW;  // octave weight in [0, 1]: unsigned
static_assert(kNoiseWeightW == kNoiseLodF + 1, "a weight holds exactly 1");
inline constexpr int kNoiseGainF = fmt::kNoiseGainF;  // smoke opacity gain: fraction bits
inline constexpr int kNoiseGainW = fmt::kNoiseGainW;  // smoke opacity gain code: unsigned (gain < 256)
inline constexpr int kWaterAmpF = fmt::kWaterAmpF;  // water height amplitude a: fraction bits
inline constexpr int kWaterAmpW = fmt::kWaterAmpW;  // water amplitude code: unsigned (a < 32)
}  // namespace pfmt

using OctaveWeights = std::array<uint32_t, fmt::kNoiseOctaves>;  // u(NoiseWeightW).NoiseLodF

inline constexpr uint32_t kWeightOne = 1u << pfmt::kNoiseLodF;

// limit false: w_i = 1 for i < K (the unfiltered fBm of K octaves).
inline OctaveWeights octave_weights_fx(int32_t lrho, int32_t lfreq, int octaves, bool limit) {
  OctaveWeights w{};
  const int64_t nyquist = int64_t(kWeightOne) - int64_t(lrho) - int64_t(lfreq);  // log2(1/(2 rho)) + 2 - bias
  for (int i = 0; i < fmt::kNoiseOctaves && i < octaves; ++i) {
    const int64_t room = nyquist - int64_t(i) * kWeightOne;
    w[static_cast<size_t>(i)] = !limit ? kWeightOne
                                       : static_cast<uint32_t>(room < 0 ? 0 : room > kWeightOne ? kWeightOne : room);
  }
  return w;
}

// Float reference: lrho_cells = log2 rho in lattice cells, bias included.
inline double octave_weight_ref(double lrho_cells, int i, int octaves, bool limit) {
  if (i >= octaves) return 0;
  if (!limit) return 1;
  const double r = 1 - lrho_cells - i;
  return r < 0 ? 0 : r > 1 ? 1 : r;
}

}  // namespace tu::noise
