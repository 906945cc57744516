// Shared with the co-simulation bindings (testbench/cosim/persp_rtl.cpp).
#pragma once

#include "block.hpp"

namespace tu::blocks {
// A persp_texel_depth row (B1's seeds, increments, n, m2) as the texel_depth row of the same pixel:
// its span record q1, q2, T1, T2, m2 (texel_depth::setup: two B1 evaluations) and the offset m.
Row texel_depth_record_row(const Row& persp_texel_depth_row);
}  // namespace tu::blocks
