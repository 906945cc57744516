// Float reference of the Perlin noise unit (seed 001 §4, docs/blocks/noise.md): Ken Perlin's
// improved noise (SIGGRAPH 2002, "Improving Noise"), exactly his published reference algorithm:
// the 256-entry permutation table (doubled), fade 6t^5 - 15t^4 + 10t^3, grad(hash & 15, x, y, z)
// from the 12 edge vectors of the cube (length sqrt(2), 4 repeated), trilinear lerps.
// 2-D noise is DEFINED as the z = 0 slice of the 3-D noise: noise2(x, y) = noise3(x, y, 0)
// (the z lerp then takes the z0 face, the gradients' z terms vanish; 4 corners, 3 lerps).
// Both are periodic with period 256 in every axis (the lattice index is floor(x) & 255).
//
// Bounds (derived in docs/blocks/noise.md §2, checked by testbench/unit/noise_test):
//   |noise3| <= kBound3 = 1.0364: the maximum over the unit cube of
//     B(t) = sum_c w_c(t) * (|d_c|_1 - min_i |d_c,i|),  w_c = product of fade weights,
//   i.e. every corner picking the gradient worst for it (the sup over every hash table);
//   B peaks at 1.0363538 (t = (0.35526, 0.48149, 0.5) and its symmetric images).
//   |noise2| <= kBound2 = 1: per axis sum_c w_c |d_c,i| = t + fade(t)(1 - 2t) <= 1/2.
// fBm (seed step 6): P_K = sum_{i<K} noise(2^i x) 2^-i; normalised with the analytic bound
// instead of the seed's two-pass min/max: fbm = (P_K / (B * (2 - 2^(1-K))) + 1) / 2 in [0, 1].
#pragma once

#include <array>
#include <cstdint>

#include "texunit/formats.hpp"

namespace tu::noise {

inline constexpr double kBound3 = fmt::kNoiseBound3E4 * 1e-4;  // 1.0364 >= sup |noise3| = 1.0363538
inline constexpr double kBound2 = fmt::kNoiseBound2E4 * 1e-4;  // 1 = sup of the worst case in 2-D

// Perlin's permutation of 0..255 (the reference's p[], used modulo 256 = the doubled table).
const std::array<uint8_t, 256>& permutation();

double fade_ref(double t);                            // 6t^5 - 15t^4 + 10t^3
double grad_ref(int hash, double x, double y, double z);  // Perlin's grad(hash & 15, x, y, z)
double noise3_ref(double x, double y, double z);
double noise2_ref(double x, double y);  // noise3_ref(x, y, 0)

// Sum of the first `octaves` octave amplitudes: 2 - 2^(1 - octaves).
double octave_amplitude_sum(int octaves);
// Normalised fBm in [0, 1] (dims 2: z ignored).
double fbm_ref(int dims, int octaves, double x, double y, double z);
// The worst-case-gradient function B(t) above (dims 2 or 3), for the bound's tests.
double worst_case_ref(int dims, double tx, double ty, double tz);

}  // namespace tu::noise
