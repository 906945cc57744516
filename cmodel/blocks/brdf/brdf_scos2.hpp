// Modified cosine-quadratic F_SCOS2 = max(0, (2c - 0.1u) / (u + 2c))^2, bit-accurate.
//   D  = u + 2c                              u32.22, exact (in [1, max(n, 2)])
//   T  = round_half_up(0.1 u)                u30.20 (0.1 = BrdfK01 / 2^24)
//   N  = max(0, 2c - T)                      u22.20 (the base is clamped before squaring)
//   R, p = recip(D)
//   B  = round_half_up(N R 2^(22 - p))       u25.24, <= 1
//   F  = round_half_up(B^2)                  u9.8
// Error bound (exhaustive, testbench/unit/brdf_fx_test.cpp; docs/blocks/brdf.md): < 0.52 LSB of
// the output against the float formula at the same c code.
#pragma once

#include "brdf_common.hpp"

namespace tu::brdf {

inline Result scos2(const In& in) {
  const Front f = front(in);
  if (f.cut) return {0, f.flag};
  const D d = (f.u + f.c.shl<1>()).as<D>();
  const auto k = UFixed<21, fmt::kBrdfKF>::from_raw(fmt::kBrdfK01);
  const U tenth = (k * f.u).as<U, Round::HalfUp, Ovf::Sat>();
  const auto num = (f.c.shl<1>() - tenth).as<UFixed<22, fmt::kBrdfCF>, Round::Trunc, Ovf::Sat>();
  const Recip r = recip_of(static_cast<u128>(d.raw()));
  const u128 nr = static_cast<u128>(num.raw()) * static_cast<u128>(r.r.raw());  // 44 frac
  u128 b = rnd(nr, fmt::kBrdfCF + fmt::kRecipOutF - fmt::kBrdfWF + r.p - fmt::kBrdfDF);
  if (b > u128(W1::kMaxRaw)) b = u128(W1::kMaxRaw);
  return {sat_out(rnd(b * b, 2 * fmt::kBrdfWF - fmt::kBrdfOutF)), f.flag};
}

}  // namespace tu::brdf
