// Cosine-"power" family F_ST16 = max(0, 1 - u/16)^16: four squarings, no divide, bit-accurate.
//   B  = max(0, 1 - u/16)           u25.24 (u/16 exact: the raw code of u read with 24 frac bits)
//   S1..S4 = round_half_up(S^2)     u25.24 each
//   F  = round_half_up(S4)          u9.8
// Error bound (exhaustive, testbench/unit/brdf_fx_test.cpp; docs/blocks/brdf.md): < 0.51 LSB of
// the output against the float formula at the same c code.
#pragma once

#include "brdf_common.hpp"

namespace tu::brdf {

inline Result st16(const In& in) {
  const Front f = front(in);
  if (f.cut) return {0, f.flag};
  const W1 one = W1::from_raw(i128(1) << fmt::kBrdfWF);
  W1 s = (one - f.u.shr<4>()).as<W1, Round::Trunc, Ovf::Sat>();  // negative base -> 0
  for (int i = 0; i < 4; ++i) s = (s * s).as<W1, Round::HalfUp, Ovf::Sat>();
  return {static_cast<uint64_t>(s.as<Out, Round::HalfUp, Ovf::Sat>().raw()), f.flag};
}

}  // namespace tu::brdf
