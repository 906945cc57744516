#include "ewa_lanes.hpp"

#include <algorithm>

namespace tu::ewa::fx {

namespace {
constexpr int64_t kStep = int64_t(1) << fmt::kEwaPosF;  // one texel in offset codes
}

uint64_t lane_blocks(int64_t x0, int64_t x1, int64_t y0, int64_t y1) {
  // >> 1 is floor(x / 2) for negative coordinates too: the block's even-aligned column
  return static_cast<uint64_t>(((x1 >> 1) - (x0 >> 1) + 1) * ((y1 >> 1) - (y0 >> 1) + 1));
}

Out walk_lanes(const PixelSetup& su, const tex::Texture& t, const Config& cfg, LaneStats* st) {
  Out out = walk_out(su);
  const QuadForm qf = quad_form(su);
  const int64_t A = qf.a, B = qf.b, ddq = qf.ddq;
  Sums sums;
  struct Lane {
    int64_t x, y, xi, eta, q, d;  // d = Q(x + 2) - Q(x)
  };
  for (int64_t by = su.y0 >> 1; by <= su.y1 >> 1; ++by) {
    Lane ln[4];
    for (int l = 0; l < 4; ++l) {  // block row start: direct, as the sequential walk's rows
      Lane& a = ln[l];
      a.x = 2 * (su.x0 >> 1) + (l & 1);
      a.y = 2 * by + (l >> 1);
      const int64_t du = a.x * kStep - su.cu, dv = a.y * kStep - su.cv;
      a.xi = int64_t(su.kxu) * du + int64_t(su.kxv) * dv;
      a.eta = int64_t(su.kyu) * du + int64_t(su.kyv) * dv;
      a.q = a.xi * a.xi + a.eta * a.eta;
      a.d = A * (4 * du * kStep + 4 * kStep * kStep) + 2 * B * dv * kStep;
    }
    for (int64_t bx = su.x0 >> 1; bx <= su.x1 >> 1; ++bx) {
      uint64_t clock_sum[4] = {0, 0, 0, 0};
      for (Lane& a : ln) {
        if (a.x >= su.x0 && a.x <= su.x1 && a.y >= su.y0 && a.y <= su.y1) {  // else masked
          ++out.texels_visited;
          const uint32_t w = texel_weight(su, cfg, a.q, a.xi, a.eta);
          if (w > 0) {
            ++out.texels_inside;
            const img::Rgba8 px = t.fetch(su.level, a.x, a.y);
            const uint8_t c[4] = {px.r, px.g, px.b, px.a};
            for (int k = 0; k < 4; ++k) clock_sum[k] += uint64_t(w) * c[k];
            sums.wsum += w;
          }
        }
        a.q += a.d;  // two texels along x
        a.d += 4 * ddq;
        a.xi += 2 * int64_t(su.kxu) * kStep;
        a.eta += 2 * int64_t(su.kyu) * kStep;
        a.x += 2;
      }
      for (int k = 0; k < 4; ++k) sums.acc[k] += clock_sum[k];  // the K-input adder's sum
      if (st) {
        ++st->blocks;
        st->max_clock_sum = std::max({st->max_clock_sum, clock_sum[0], clock_sum[1], clock_sum[2], clock_sum[3]});
      }
    }
  }
  finish(su, t, sums, &out);
  return out;
}

}  // namespace tu::ewa::fx
