// Gradient dot product of improved noise, Perlin's grad(hash & 15, x, y, z): the 12 cube-edge
// vectors (+-1, +-1, 0), (+-1, 0, +-1), (0, +-1, +-1) (and 4 repeats) dotted with the corner
// offset: +-u +-v, u = h < 8 ? x : y, v = h < 4 ? y : (h == 12 || h == 14) ? x : z.
// Formats: offsets s<DW>.<TF> in [-1,1); result s<DW+2>.<TF> in [-2,2] (2 at a lattice corner
// with both offsets -1 and negated). Exact (no rounding).
#pragma once

#include <cstdint>

#include "texunit/fixed.hpp"

namespace tu::noise {

template <int DW, int TF>
SFixed<DW + 2, TF> grad(uint32_t hash, SFixed<DW, TF> x, SFixed<DW, TF> y, SFixed<DW, TF> z) {
  const uint32_t h = hash & 15;
  const auto u = h < 8 ? x : y;
  const auto v = h < 4 ? y : (h == 12 || h == 14) ? x : z;
  const auto su = (h & 1) ? -u : u.template cast<DW + 1, TF, true>();
  const auto sv = (h & 2) ? -v : v.template cast<DW + 1, TF, true>();
  return (su + sv).template cast<DW + 2, TF, true>();
}

}  // namespace tu::noise
