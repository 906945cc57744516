// Modified Schlick F_MSH = 1.6 c / (u + 1.25 c)^2 (= 2c / (1.25 (n - nc + 1.25c)^2)), bit-accurate.
//   D  = u + c + c/4                  u32.22, exact (in [1, n]; [1, 1.25] at n = 1)
//   R, p = recip(D)                   1/D = R 2^(22 - p)
//   R2 = round_half_up(R^2)           u25.24
//   KC = round_half_up(1.6 c)         u25.24 (1.6 = BrdfK16 / 2^24)
//   F  = round_half_up(KC R2 2^(2(22 - p)))  u9.8 (F(1) = 1.024: code 262)
// Error bound (exhaustive, testbench/unit/brdf_fx_test.cpp; docs/blocks/brdf.md): < 0.55 LSB of
// the output against the float formula at the same c code.
#pragma once

#include "brdf_common.hpp"

namespace tu::brdf {

struct MshParts {  // the intermediates the shared-multiplier RTL computes one after another
  D d;
  W1 kc;
};
inline MshParts msh_parts(const Front& f) {
  const D d = (f.u + f.c + f.c.shr<2>()).as<D>();
  const auto k = UFixed<26, fmt::kBrdfKF>::from_raw(fmt::kBrdfK16);
  return {d, (k * f.c).as<W1, Round::HalfUp, Ovf::Sat>()};
}

inline Result msh(const In& in) {
  const Front f = front(in);
  if (f.cut) return {0, f.flag};
  const MshParts m = msh_parts(f);
  const Recip r = recip_of(static_cast<u128>(m.d.raw()));
  const W1 r2 = (r.r * r.r).as<W1, Round::HalfUp, Ovf::Sat>();
  const u128 prod = static_cast<u128>(m.kc.raw()) * static_cast<u128>(r2.raw());  // 48 frac
  return {sat_out(rnd(prod, 2 * fmt::kBrdfWF - fmt::kBrdfOutF + 2 * (r.p - fmt::kBrdfDF))),
          f.flag};
}

}  // namespace tu::brdf
