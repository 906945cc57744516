// Fade polynomial of improved noise in fixed point: s = 6t^5 - 15t^4 + 10t^3 = t^3 b,
// b = t (6t - 15) + 10 (Horner; 6t - 15 is exact, 6t = 4t + 2t).
// Formats (templated; defaults from formats.hpp): t u<TF>.<TF> in [0,1);
//   t2 = round_half_up(t*t), t3 = round_half_up(t2*t): u<IF>.<IF>;
//   b = round_half_up(t*(6t-15)) + 10: u<BW>.<IF> in (1,10];
//   s = round_half_up(t3*b): u<TF+1>.<TF> in [0,1].
// Error bound: analytic |s - fade(t)| <= 10 * 2^-IF + 2^-(IF+1) + 2^-(TF+1) = 0.541 ULP (2^-TF) at
// TF = 16, IF = 24; measured exhaustively over all 2^16 codes (noise_test NoiseFade.Exhaustive):
// 0.516 ULP, s(0) = 0, s <= 1 and s non-decreasing in t (no clamp needed). IF = 24 is the
// narrowest that keeps s monotonic (IF = 22: 5 decreasing steps near t = 0.07, 0.575 ULP;
// IF = 20: 47 steps, 0.773 ULP), where fade rises by less than 1 ULP per input code.
#pragma once

#include "texunit/fixed.hpp"
#include "texunit/formats.hpp"

namespace tu::noise {

template <int TF = fmt::kNoiseTF, int IF = fmt::kNoiseFadeIF, int BW = fmt::kNoiseFadeBW>
UFixed<TF + 1, TF> fade(UFixed<TF, TF> t) {
  using I = UFixed<IF, IF>;
  const auto six_t_m15 = (t.template shl<2>() + t.template shl<1>()) - UFixed<4, 0>::from_raw(15);
  const auto b = ((t * six_t_m15).template cast<IF + 5, IF, true, Round::HalfUp>() + UFixed<4, 0>::from_raw(10))
                     .template cast<BW, IF, false>();
  const I t2 = (t * t).template as<I, Round::HalfUp>();
  const I t3 = (t2 * t).template as<I, Round::HalfUp>();
  return (t3 * b).template cast<TF + 1, TF, false, Round::HalfUp>();
}

}  // namespace tu::noise
