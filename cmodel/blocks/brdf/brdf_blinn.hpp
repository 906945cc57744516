// Blinn F_B = c^n, the reference, by LSB-first square-and-multiply over the 10 bits of n.
//   b0 = c, r0 = 1                  u29.28
//   step i = 0..9: r = bit i of n ? round_half_up(r b) : r;  b = round_half_up(b^2)
//   F  = round_half_up(r)           u9.8
// Cost grows with log2 n (10 multiplies + 9 squarings for n <= 1023), the thesis's objection.
// Error bound (exhaustive, testbench/unit/brdf_fx_test.cpp; docs/blocks/brdf.md): < 0.51 LSB of
// the output against c^n at the same c code.
#pragma once

#include "brdf_common.hpp"

namespace tu::brdf {

using BlinnW = UFixed<fmt::kBrdfBlinnF + 1, fmt::kBrdfBlinnF>;

inline Result blinn(const In& in) {
  const Front f = front(in);
  if (f.cut) return {0, f.flag};
  BlinnW b = f.c.as<BlinnW>();
  BlinnW r = BlinnW::from_raw(i128(1) << fmt::kBrdfBlinnF);
  for (int i = 0; i < fmt::kBrdfNW; ++i) {
    if ((f.n >> i) & 1) r = (r * b).as<BlinnW, Round::HalfUp, Ovf::Sat>();
    b = (b * b).as<BlinnW, Round::HalfUp, Ovf::Sat>();
  }
  return {static_cast<uint64_t>(r.as<Out, Round::HalfUp, Ovf::Sat>().raw()), f.flag};
}

}  // namespace tu::brdf
