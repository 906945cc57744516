// Texel-depth texturing (seed 001 §3, thesis §2.3; docs/blocks/persp.md "Texel-depth variant"):
// a B1 variant that interpolates along a scanline from the span ends' depths,
//   w(s) = z1 s / (z2 - s (z2 - z1)),  s = m / m2,   T(m) = T1 + (T2 - T1) w    (eq. 2.32-2.33)
// with T1, T2 the texture coordinates at the span ends x0, x1 = x0 + m2 and z1, z2 their depths
// (the listing's loop with the note's corrections: started at an end, stepped away from it, one
// divide per pixel; the note shows it is the perspective-correct interpolation).
//
// Float reference: that formula in double, z = 1/q of B1's exact map at the ends.
// C model (bit-accurate), from the same quantised data as B1 (persp::Unit::Coefs):
//   per scanline : T1, T2 = B1's own outputs at x0 and x1 (two B1 pixel evaluations, s32.8 texels);
//                  q1, q2 = B1's exact accumulators q at x0, x1 (s44.40); a guarded end (q < 2^-10)
//                  flags the whole span (q is linear along the span: its minimum is at an end).
//   per pixel    : with z = 1/q the seed's w is w = m q2 / (m2 q1 + m (q2 - q1)) (numerator and
//                  denominator times q1 q2: no per-scanline reciprocal), N = m q2 and
//                  D = m2 q1 + m (q2 - q1) exact integers (two accumulators, D = m2 q(m) exactly);
//                  w = N * R(D) rounded half up to u1.kWF (R: B1's reciprocal core on D's top
//                  RecipMantW bits), clamped to [0, 1]; T = T1 + round_half_up((T2 - T1) w) to
//                  s32.8, saturating.
// Error: the two end roundings of B1 (2^-9 each) carried by (1 - w), w, plus the w rounding times
// |T2 - T1| and the final rounding: measured against the exact rational in testbench/unit/
// texel_depth_test.cpp and the report row persp/texel_depth (vectors: block persp_texel_depth).
// RTL: rtl/persp/tu_texel_depth.sv, the per-pixel datapath from the span record (block
// texel_depth; formats TexelDepth* in formats.hpp: N, D are TexelDepthAccW-bit unsigned
// accumulators, exact when unguarded; w is u1.TexelDepthWF).
#pragma once

#include <cstdint>

#include "persp/persp.hpp"

namespace tu::persp::texel_depth {

inline constexpr int kWF = fmt::kTexelDepthWF;  // w: unsigned, kWF fraction bits, 0..1

struct Span {
  int64_t t1[2] = {}, t2[2] = {};  // u, v at x0 and x1: B1's Uv codes
  int64_t q1 = 0, q2 = 0;          // B1's q raw codes at x0, x1
  int m2 = 0;                      // x1 - x0
  bool guard = false;              // an end guarded: every pixel flagged
};
// From B1's span seeds (q, p_u, p_v at x0) and increments (A, D, G) and the span's last offset m2.
Span setup(const Unit::Acc& at_x0, Unit::P a, Unit::P d, Unit::Q g, int m2);
// The span record as the RTL receives it (q1, q2 raw codes, T1, T2 Uv codes, m2); the guard is
// derived from q1, q2 (B1's rule: an end with q < 2^-PerspGuardLog2, incl. q <= 0).
Span record(int64_t q1, int64_t q2, const int64_t t1[2], const int64_t t2[2], int m2);
// Pixel at offset m in [0, m2] from x0.
Pixel pixel(const Span& s, int m);
// w code of pixel m (u1.kWF), exposed for the test of the clamp and the ends.
uint64_t w_code(const Span& s, int m);

// Float reference: the seed's formula with z = 1/q at the span ends of the exact map k on row y.
void pixel_ref(const Coef9& k, int y, int x0, int x1, int x, double* u, double* v);

}  // namespace tu::persp::texel_depth
