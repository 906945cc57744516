// Schlick's rational approximation F_SH = c / (u + c), u = n (1 - c), bit-accurate.
//   D = u + c                 u32.22, exact (D = n - (n-1) c in [1, n])
//   R, p = recip(D)           1/D = R 2^(22 - p), |R - 1/M| < 2^-24 (M: D's top 24 bits)
//   F = round_half_up(c R 2^(22 - p))  u9.8
// Error bound (exhaustive over every c code and n in testbench/unit/brdf_fx_test.cpp, figures in
// docs/blocks/brdf.md): < 0.52 LSB of the output against the float formula at the same c code.
#pragma once

#include "brdf_common.hpp"

namespace tu::brdf {

inline Result schlick(const In& in) {
  const Front f = front(in);
  if (f.cut) return {0, f.flag};
  const D d = (f.u + f.c).as<D>();
  const Recip r = recip_of(static_cast<u128>(d.raw()));
  const u128 prod = static_cast<u128>(f.c.raw()) * static_cast<u128>(r.r.raw());  // 44 frac
  return {sat_out(rnd(prod, fmt::kBrdfCF + fmt::kRecipOutF - fmt::kBrdfOutF + r.p - fmt::kBrdfDF)),
          f.flag};
}

}  // namespace tu::brdf
