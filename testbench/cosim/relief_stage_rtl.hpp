// The relief stage RTL (rtl/pom/tu_relief_stage.sv; its depth RAM and view stream modelled in C++,
// relief_stage_rtl.cpp) driven by the co-simulation harness: one row per pixel, the view word in
// the row.
#pragma once

#include <cstdint>
#include <vector>

#include "pom/pom_march.hpp"

namespace tu::cosim {

struct ReliefPixel {
  int64_t u = 0, v = 0;  // B1 codes (PerspUvW bits, signed)
  int lw = 0, lh = 0;    // log2 sides of the colour texture's level 0
  bool rel = false, guard = false, adaptive = false;
  bool iter = false;     // iterative parallax (cap = layers)
  bool dm = false;       // distance map (cap = layers, relief::dm_cap)
  int layers = 1;        // 1..63
  int dlayers = 0;       // distance map: layers, word address of voxel (0, 0, 0)
  uint32_t dbase = 0;
  uint32_t scale = 0;    // S code
  uint32_t hbase = 0;    // depth map: word address of texel (0, 0), log2 sides
  int hlw = 0, hlh = 0;
  bool ok = true;        // relief::pixel_view succeeded
  pom::View view;        // vx, vy, vz (scale unused: the material's scale)
  uint32_t vc = 0;       // complexity texel at the unshifted uv
};

struct ReliefOut {
  int64_t u = 0, v = 0;  // sign-extended
  uint32_t n = 0;
  uint32_t steps = 0;    // march steps or iterations
  uint32_t flags = 0;    // relief::ReliefFlag
  uint32_t index = 0;    // the pixel's index (carried on the side port)
};

struct ReliefRun {
  std::vector<ReliefOut> out;
  uint64_t cycles = 0, accepted = 0, extra_outputs = 0;
  bool hung = false;
};

// ram: depth words (depth in the low 8 bits), the depth RAM's contents from address 0. stall_prob:
// input bubbles and output stalls; view_bubble_prob: cycles the view word is held back.
ReliefRun run_relief_stage(const std::vector<ReliefPixel>& px, const std::vector<uint32_t>& ram,
                           double stall_prob, double view_bubble_prob, uint64_t seed);

}  // namespace tu::cosim
