// Linear interpolation of the noise lerp tree: L = a + round_half_up(s (b - a)).
// Formats: s u<TF+1>.<TF> in [0,1]; a, b s<VW>.<TF>; b - a exact (VW+1 bits); the product is
// rounded half up to TF fraction bits. The rounded product lies between 0 and b - a (both
// representable), so L lies between a and b: no overflow in VW bits, L = a at s = 0, b at s = 1.
// Error bound: |L - (a + s (b - a))| <= 2^-(TF+1) (0.5 ULP, rounding only).
#pragma once

#include "texunit/fixed.hpp"

namespace tu::noise {

template <int VW, int TF>
SFixed<VW, TF> lerp(UFixed<TF + 1, TF> s, SFixed<VW, TF> a, SFixed<VW, TF> b) {
  const auto step = (s * (b - a)).template cast<VW + 1, TF, true, Round::HalfUp>();
  return (a + step).template cast<VW, TF, true>();
}

}  // namespace tu::noise
