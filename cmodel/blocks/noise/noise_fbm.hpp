// fBm of the noise unit (seed 001 §4 step 6, with the analytic normalisation instead of the
// seed's two-pass min/max, docs/blocks/noise.md §2):
//     acc = sum_{i<K} noise_fx(2^i x) 2^-i      exact, s<NoiseAccW>.<NoiseTF+K-1>
//     fbm = clamp(round_half_up(acc * C + 1/2), 0, 1)     u17.16
// with C = NoiseNorm3 or NoiseNorm2 = round(2^NoiseNormF / (2 B (2 - 2^(1-K)))), the bound B of
// |noise| (kBound3 = 1.0364 or kBound2 = 1). The clamp is a guard: |acc| <= B (2 - 2^(1-K)) up
// to rounding, so it can act only within a few ULP of 0 and 1.
// Both RTL schemes (pipelined, octave-serial) compute exactly this; the sum is exact, so the
// octave order does not matter.
//
// Error bound against fbm_ref (0.5 ULP output rounding + C * sum_i 2^-i e_noise + the constant's
// quantisation |acc| * 2^-(NoiseNormF+1)): docs/blocks/noise.md §3 (derived and measured).
#pragma once

#include <cstdint>

#include "noise/noise_core.hpp"

namespace tu::noise {

using Out = UFixed<fmt::kNoiseOutW, fmt::kNoiseTF>;

inline constexpr int kAccF = fmt::kNoiseTF + fmt::kNoiseOctaves - 1;

// Exact octave sum (raw code, kAccF fraction bits).
int64_t fbm_sum(int dims, int64_t x, int64_t y, int64_t z);
// acc C + 1/2 rounded half up to u17.16 and clamped to [0, 1] (C: u0.NoiseNormF).
uint32_t normalise_code(int64_t acc, int64_t c);
// The normalisation (sum code -> fbm code), shared by both schemes.
uint32_t fbm_normalise(int dims, int64_t acc);
// The block: input codes s32.16 (z ignored for dims 2) -> fbm code u17.16.
uint32_t fbm_fx(int dims, int64_t x, int64_t y, int64_t z);

inline double out_value(uint32_t code) { return static_cast<double>(code) * 0x1p-16; }

}  // namespace tu::noise
