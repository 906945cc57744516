// EWA multi-texel walk (issue 23): K texels per clock, K = 4 as a 2 x 2 block, K = 2 as a 2 x 1
// block (K = 1: the sequential walk's visit), bit-identical to the sequential walk (ewa::fx::walk)
// on every pixel (docs/blocks/ewa.md "Multi-texel walk"). The RTL (tu_ewa_walk_lanes) is K = 4.
//
// The texel set is the set-up's bounding box [x0, x1] x [y0, y1] (cap and fallback, border growth:
// ewa::fx::setup), independent of K. The walk covers it with BW x BH blocks aligned to multiples
// of BW, BH (K = 4: block (bx, by) = texels 2 bx + {0, 1} x 2 by + {0, 1}), row-major; a lane
// outside the box is masked (not visited, weight 0). Per lane the incremental Q steps BW texels:
//     Q(x + BW) = Q(x) + D, D(x + BW) = D(x) + BW^2 ddQ, D = Q(x + BW) - Q(x)   (exact integers),
// xi, eta += BW k 2^PosF; each block row starts directly (as the sequential walk's rows).
// Texel memory: four banks by texel parity (x & 1, y & 1) of the wrapped coordinate; the four
// lanes of a block hit four different banks, except where wrap folds two lanes onto one texel
// (clamp at an edge, a level one texel wide or high): then they read the same address of the same
// bank (broadcast). (The banked memory and its broadcast are the RTL step; not modelled here.)
// Accumulation: the K products w texel_c of a clock are summed (exact: K w texel < K 2^16 255
// < 2^26) and added to the same exact sums as the sequential walk, so the result is bit-identical
// (acc u41.16, wsum u33.16: EwaFx.WidthsOnLargestBox holds for any visit order).
#pragma once

#include <cstdint>

#include "ewa/ewa_fx.hpp"

namespace tu::ewa::fx {

inline constexpr int kLaneBlock = 2;  // the block is kLaneBlock x kLaneBlock texels (K = 4)

// The block of a K-lane walk: K = 1 (1 x 1), 2 (2 x 1), 4 (2 x 2); other K: std::invalid_argument.
struct LaneShape {
  int bw = 1, bh = 1;
};
LaneShape lane_shape(int k);

// Shared by the sequential walk (ewa_fx.cpp) and the 2 x 2 walk (defined in ewa_fx.cpp):
// the weight of a walked texel: border_weight with border weights on (cfg.clip), else the weight
// source's w(Q) for Q < 1 and 0 outside;
uint32_t texel_weight(const PixelSetup& su, const Config& cfg, int64_t q, int64_t xi, int64_t eta);
// the exact sums of a walk (any visit order gives the same) and the pixel's colour from them:
// normalised (wsum > 0) or the nearest texel at L with kNoWeight (wsum = 0).
struct Sums {
  uint64_t acc[4] = {0, 0, 0, 0};
  uint64_t wsum = 0;
};
void finish(const PixelSetup& su, const tex::Texture& t, const Sums& s, Out* out);
// A walk's Out before its texels (level, set-up flags, capped), and Q(du, dv) = A du^2 + B du dv +
// C dv^2 in the frame coefficients (exact) with ddq = 2 A 2^(2 EwaPosF), Q's second difference along x.
Out walk_out(const PixelSetup& su);
struct QuadForm {
  int64_t a = 0, b = 0, ddq = 0;
};
QuadForm quad_form(const PixelSetup& su);

// Blocks (walk clocks) of a box at K lanes: aligned blocks covering [x0, x1] x [y0, y1] (K = 4:
// 2 x 2 blocks on even coordinates; K = 1: the box).
uint64_t lane_blocks(int64_t x0, int64_t x1, int64_t y0, int64_t y1, int k = 4);

struct LaneStats {
  uint64_t blocks = 0;      // clocks of the walk
  uint64_t max_clock_sum = 0;  // largest sum of the K products of one clock and one channel
};

// The K-lane walk on an explicit set-up: the same Out as walk(su, t, cfg) (tests assert it).
Out walk_lanes(const PixelSetup& su, const tex::Texture& t, const Config& cfg, LaneStats* st = nullptr, int k = 4);
// setup + the K-lane walk (K = 1: ewa::fx::filter's sequential walk): the render engine's
// CmodelOptions::ewa_lanes.
Out filter_lanes(const In& in, const tex::Texture& t, const Config& cfg, int k);

}  // namespace tu::ewa::fx
