#include "ewa_lanes.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace tu::ewa::fx {

namespace {
constexpr int64_t kStep = int64_t(1) << fmt::kEwaPosF;  // one texel in offset codes
// floor(x / b) for b = 1, 2 (>> 1 floors negative coordinates too)
int64_t block_of(int64_t x, int b) { return b == 2 ? x >> 1 : x; }
}  // namespace

LaneShape lane_shape(int k) {
  switch (k) {
    case 1: return {1, 1};
    case 2: return {2, 1};
    case 4: return {2, 2};
    default: throw std::invalid_argument("ewa lanes: K = " + std::to_string(k) + " (1, 2 or 4)");
  }
}

uint64_t lane_blocks(int64_t x0, int64_t x1, int64_t y0, int64_t y1, int k) {
  const LaneShape sh = lane_shape(k);
  return static_cast<uint64_t>((block_of(x1, sh.bw) - block_of(x0, sh.bw) + 1) *
                               (block_of(y1, sh.bh) - block_of(y0, sh.bh) + 1));
}

Out walk_lanes(const PixelSetup& su, const tex::Texture& t, const Config& cfg, LaneStats* st, int k) {
  const LaneShape sh = lane_shape(k);
  Out out = walk_out(su);
  const QuadForm qf = quad_form(su);
  const int64_t A = qf.a, B = qf.b, ddq = qf.ddq;
  const int64_t step = sh.bw * kStep;  // one block along x, offset codes
  Sums sums;
  struct Lane {
    int64_t x, y, xi, eta, q, d;  // d = Q(x + BW) - Q(x)
  };
  const int64_t bx0 = block_of(su.x0, sh.bw), bx1 = block_of(su.x1, sh.bw);
  for (int64_t by = block_of(su.y0, sh.bh); by <= block_of(su.y1, sh.bh); ++by) {
    Lane ln[4];
    for (int l = 0; l < k; ++l) {  // block row start: direct, as the sequential walk's rows
      Lane& a = ln[l];
      a.x = sh.bw * bx0 + l % sh.bw;
      a.y = sh.bh * by + l / sh.bw;
      const int64_t du = a.x * kStep - su.cu, dv = a.y * kStep - su.cv;
      a.xi = int64_t(su.kxu) * du + int64_t(su.kxv) * dv;
      a.eta = int64_t(su.kyu) * du + int64_t(su.kyv) * dv;
      a.q = a.xi * a.xi + a.eta * a.eta;
      a.d = A * (2 * du * step + step * step) + B * dv * step;
    }
    for (int64_t bx = bx0; bx <= bx1; ++bx) {
      uint64_t clock_sum[4] = {0, 0, 0, 0};
      for (int l = 0; l < k; ++l) {
        Lane& a = ln[l];
        if (a.x >= su.x0 && a.x <= su.x1 && a.y >= su.y0 && a.y <= su.y1) {  // else masked
          ++out.texels_visited;
          const uint32_t w = texel_weight(su, cfg, a.q, a.xi, a.eta);
          if (w > 0) {
            ++out.texels_inside;
            const img::Rgba8 px = t.fetch(su.level, a.x, a.y);
            const uint8_t c[4] = {px.r, px.g, px.b, px.a};
            for (int ch = 0; ch < 4; ++ch) clock_sum[ch] += uint64_t(w) * c[ch];
            sums.wsum += w;
          }
        }
        a.q += a.d;  // BW texels along x
        a.d += sh.bw * sh.bw * ddq;
        a.xi += int64_t(su.kxu) * step;
        a.eta += int64_t(su.kyu) * step;
        a.x += sh.bw;
      }
      for (int ch = 0; ch < 4; ++ch) sums.acc[ch] += clock_sum[ch];  // the K-input adder's sum
      if (st) {
        ++st->blocks;
        st->max_clock_sum = std::max({st->max_clock_sum, clock_sum[0], clock_sum[1], clock_sum[2], clock_sum[3]});
      }
    }
  }
  finish(su, t, sums, &out);
  return out;
}

Out filter_lanes(const In& in, const tex::Texture& t, const Config& cfg, int k) {
  if (k == 1) return filter(in, t, cfg);
  return walk_lanes(setup(in, t, cfg), t, cfg, nullptr, k);
}

}  // namespace tu::ewa::fx
