// Two-generating-function BRDF F_dsh = max(0, (F_SH + G) / 2), the clamped average (note §3.3),
//   G = 2 (c + 0.1)^8 / E - 0.25,  E = 1.25 (1.25 (u + c^8))^2 + 1.5 = 1.953125 w^2 + 1.5, bit-accurate.
//   S   = round_half_up(c / D_SH)          u25.24, D_SH and its reciprocal as in brdf_schlick.hpp
//   c^8 = three squarings of c             u25.24 each, half up
//   q^8 = three squarings of q = c + 0.1   u26.24 .. u28.24 (q^8 <= 2.144), half up
//   w   = u + c^8                          u34.24, exact
//   w2  = round_half_up(w^2)               u44.24
//   E   = 125 w2 / 64 + 1.5                BrdfEF (30) fraction bits, exact, in [1.5, 2^21)
//   R, p = recip(E)                        1/E = R 2^(30 - p)
//   G1  = round_half_up(2 q^8 R 2^(30 - p))  24 fraction bits
//   F   = round_half_up(max(0, S + G1 - 0.25) / 2)  u9.8
// Error bound (exhaustive, testbench/unit/brdf_fx_test.cpp; docs/blocks/brdf.md): < 0.52 LSB of
// the output against the float formula at the same c code.
#pragma once

#include "brdf_common.hpp"

namespace tu::brdf {

inline Result dsh(const In& in) {
  const Front f = front(in);
  if (f.cut) return {0, f.flag};
  constexpr int kF = fmt::kBrdfWF;
  using Q = UFixed<kF + 2, kF>;  // (c + 0.1)^k <= 2.144
  const D d = (f.u + f.c).as<D>();
  const Recip rs = recip_of(static_cast<u128>(d.raw()));
  const u128 s = rnd(static_cast<u128>(f.c.raw()) * static_cast<u128>(rs.r.raw()),
                     fmt::kBrdfCF + fmt::kRecipOutF - kF + rs.p - fmt::kBrdfDF);
  W1 c8 = (f.c * f.c).as<W1, Round::HalfUp, Ovf::Sat>();
  c8 = (c8 * c8).as<W1, Round::HalfUp, Ovf::Sat>();
  c8 = (c8 * c8).as<W1, Round::HalfUp, Ovf::Sat>();
  Q q = (f.c + UFixed<21, fmt::kBrdfKF>::from_raw(fmt::kBrdfK01)).as<Q>();
  for (int i = 0; i < 3; ++i) q = (q * q).as<Q, Round::HalfUp, Ovf::Sat>();
  const auto w = (f.u + c8).as<UFixed<34, kF>>();
  const auto w2 = (w * w).as<UFixed<44, kF>, Round::HalfUp, Ovf::Sat>();
  const u128 e = static_cast<u128>(w2.raw()) * 125 + (u128(3) << (fmt::kBrdfEF - 1));
  const Recip re = recip_of(e);
  const u128 g1 = rnd(static_cast<u128>(q.raw()) * static_cast<u128>(re.r.raw()),
                      kF + fmt::kRecipOutF - kF - 1 + re.p - fmt::kBrdfEF);
  const u128 quarter = u128(1) << (kF - 2);
  const u128 sum = s + g1;
  return {sat_out(sum > quarter ? rnd(sum - quarter, kF - fmt::kBrdfOutF + 1) : 0), f.flag};
}

}  // namespace tu::brdf
