// Reciprocal unit: 1/q for a signed fixed-point code q (RecipInW bits), pipelined, II = 1.
//
// Structure (docs/blocks/reciprocal.md): leading-zero normalise q to M in [1,2) and exponent p,
// then a piecewise-quadratic approximation of 1/M on 2^RecipIdxW segments, Horner form
//     R = round_half_up( c0 + trunc( trunc(c1 + trunc(c2*dx)) * dx ) )
// with c0, c1, c2 from a ROM indexed by the top RecipIdxW fraction bits of M.
//
// Result: 1/q = R * 2^(F - p), where F is the caller's fraction-bit count of q.
// Error bound (proved exhaustively over all 2^24 input codes by testbench/unit/reciprocal_test):
//     |R - 1/M| < 1 ULP = 2^-RecipOutF (faithful); R is monotonic non-increasing in q.
// Guard: q <= 0 sets `flag` and saturates: R = all ones (largest mantissa), p = 0.
#pragma once

#include <array>
#include <cstdint>

#include "texunit/fixed.hpp"
#include "texunit/formats.hpp"

namespace tu::recip {

using Mant = UFixed<fmt::kRecipMantW, fmt::kRecipMantW - 1>;  // M in [1,2)
using Dx = UFixed<fmt::kRecipDxW, fmt::kRecipMantW - 1>;      // offset inside a segment
using C2 = UFixed<fmt::kRecipC2W, fmt::kRecipC2F>;
using T1 = UFixed<fmt::kRecipT1W, fmt::kRecipT1F>;
using C1 = SFixed<fmt::kRecipC1W, fmt::kRecipC1F>;
using S = SFixed<fmt::kRecipSW, fmt::kRecipC1F>;
using T2 = SFixed<fmt::kRecipT2W, fmt::kRecipT2F>;
using C0 = UFixed<fmt::kRecipC0W, fmt::kRecipC0F>;
using Out = UFixed<fmt::kRecipOutW, fmt::kRecipOutF>;  // R in (0.5, 1]

inline constexpr int kSegments = 1 << fmt::kRecipIdxW;

struct Coef {
  C0 c0;
  C1 c1;
  C2 c2;
};

// ROM contents: Chebyshev-node quadratic interpolation of 1/M per segment, rounded to nearest in
// each coefficient format. Deterministic (IEEE double, correctly rounded ops only).
const std::array<Coef, kSegments>& table();

// Core: mantissa code m (u24.23, top bit set) -> R code. Inline: B1 and B2 call it per pixel.
inline Out core(Mant m) {
  static const Coef* const rom = table().data();  // one guarded load instead of a call
  const auto idx = m.slice(fmt::kRecipDxW, fmt::kRecipIdxW);
  const Dx dx = Dx::from_raw(m.slice(0, fmt::kRecipDxW));
  const Coef& c = rom[idx];
  const T1 t1 = (c.c2 * dx).as<T1>();           // truncate
  const S s = (c.c1 + t1).as<S>();              // exact (same fraction bits)
  const T2 t2 = (s * dx).as<T2>();              // truncate (floor)
  const auto y = c.c0 + t2;                     // exact
  return y.as<Out, Round::HalfUp, Ovf::Sat>();  // round half up
}

struct Result {
  uint32_t mant;   // R code, RecipOutW bits
  uint32_t shift;  // p, RecipShiftW bits
  bool flag;       // q <= 0: saturated
};

// Full unit on a RecipInW-bit two's-complement code (sign-extended into int32).
Result eval(int32_t q);

// Value of a result for input fraction bits f (1/q in real units); saturated results give +inf.
double value(const Result& r, int f);

}  // namespace tu::recip
