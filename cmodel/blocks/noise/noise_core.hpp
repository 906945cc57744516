// One octave of improved noise in fixed point (the noise core, rtl/noise/tu_noise_core.sv):
// lattice cell from the input code, corner hashes through the permutation ROM, gradient dots,
// fade, lerps (x, then y, then z). 2-D (dims = 2) is the z = 0 slice: 4 corners, x and y lerps;
// bit-identical to dims = 3 with z = 0 (the z lerp at s = 0 returns its z0 input exactly).
//
// Formats: input code s<NoiseCoordW>.<NoiseTF>; cell index floor(x) & 255 (NoiseLatW bits: the
// period-256 wrap, exact for every code, negative ones included: floor of two's complement);
// t = frac(x) u16.16; offsets t, t - 1 s17.16; dots, lerps and the result s19.16.
// Octave i evaluates the code shifted left by i (exactly 2^i x; the bits above the lattice index
// drop out, which is the period-256 wrap again).
//
// Error bound against noise3_ref / noise2_ref at the decoded point (approximation: none, the
// algorithm is evaluated exactly except for rounding):
//   analytic: each lerp adds <= e_s * |b - a| + 0.5 ULP with |b - a| <= 4 and e_s the fade bound
//   (0.541 ULP), so |noise_fx - noise_ref| <= 3 * (4 * 0.541 + 0.5) = 8.0 ULP of 2^-16 (3-D),
//   5.3 ULP (2-D); measured (noise_test, 2^20 random points + stiff set, and the report):
//   see docs/blocks/noise.md §3. Lattice points give exactly 0.
#pragma once

#include <cstdint>

#include "texunit/fixed.hpp"
#include "texunit/formats.hpp"

namespace tu::noise {

using T = UFixed<fmt::kNoiseTF, fmt::kNoiseTF>;        // local coordinate in [0,1)
using S = UFixed<fmt::kNoiseSW, fmt::kNoiseTF>;        // fade weight in [0,1]
using D = SFixed<fmt::kNoiseDW, fmt::kNoiseTF>;        // corner offset in [-1,1)
using Val = SFixed<fmt::kNoiseValW, fmt::kNoiseTF>;    // dots, lerps, noise in [-2,2]

// The lattice cell and local coordinate of a code at octave i (code * 2^i).
struct Axis {
  uint32_t cell;  // NoiseLatW bits
  T t;
};
Axis split(int64_t code, int octave);

// One octave: dims 2 or 3 (a[2] ignored for 2).
Val noise_fx(int dims, const Axis a[3]);

// Decoded value of an input code (the point the float reference is evaluated at).
inline double coord_value(int64_t code) { return static_cast<double>(code) * 0x1p-16; }

}  // namespace tu::noise
