// Quadratic model F_QR = max(0, c (1 - 0.786 u)) (= 0.786n c^2 + (1 - 0.786n) c), bit-accurate.
//   A  = round_half_up(0.786 u)     u30.24 (0.786 = BrdfK786 / 2^24)
//   Wq = max(0, 1 - A)              u25.24
//   F  = round_half_up(c Wq)        u9.8
// Error bound (exhaustive, testbench/unit/brdf_fx_test.cpp; docs/blocks/brdf.md): < 0.51 LSB of
// the output against the float formula at the same c code.
#pragma once

#include "brdf_common.hpp"

namespace tu::brdf {

inline Result qr(const In& in) {
  const Front f = front(in);
  if (f.cut) return {0, f.flag};
  const auto k = UFixed<24, fmt::kBrdfKF>::from_raw(fmt::kBrdfK786);
  const auto a = (k * f.u).as<UFixed<34, fmt::kBrdfWF>, Round::HalfUp, Ovf::Sat>();
  const W1 one = W1::from_raw(i128(1) << fmt::kBrdfWF);
  const W1 w = (one - a).as<W1, Round::Trunc, Ovf::Sat>();
  return {static_cast<uint64_t>((f.c * w).as<Out, Round::HalfUp, Ovf::Sat>().raw()), f.flag};
}

}  // namespace tu::brdf
