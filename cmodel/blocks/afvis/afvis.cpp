#include "afvis/afvis.hpp"

#include <algorithm>
#include <bit>
#include <cstdlib>

#include "ewa/ewa_lanes.hpp"
#include "texunit/formats.hpp"

namespace tu::afvis {

namespace {
constexpr int64_t kStep = int64_t(1) << fmt::kEwaPosF;  // one walk texel in offset codes

int log2_of(int side) { return std::countr_zero(static_cast<unsigned>(side)); }
}  // namespace

uint8_t min_depth(const img::Gray8& depth) {
  return depth.px.empty() ? 0 : *std::min_element(depth.px.begin(), depth.px.end());
}

img::Gray8 min_depth_pyramid(const img::Gray8& depth, int k) {
  const int w = std::max(1, depth.width >> k), h = std::max(1, depth.height >> k);
  const int bw = depth.width / w, bh = depth.height / h;
  img::Gray8 out(w, h, 255);
  for (int y = 0; y < depth.height; ++y)
    for (int x = 0; x < depth.width; ++x) {
      uint8_t& m = out.at(x / bw, y / bh);
      m = std::min(m, depth.at(x, y));
    }
  return out;
}

int64_t centre_code(int64_t x, int level, int lw) {
  // (x + 1/2) 2^level level-0 texels = (2x + 1) 2^(level - 1); / 2^lw repeats; PomUvF bits.
  const int by = level - 1 + fmt::kPomUvF - lw;
  return by >= 0 ? (2 * x + 1) * (int64_t(1) << by) : (2 * x + 1) >> -by;
}

Trace trace(const img::Gray8& cells, uint8_t dmin, uint8_t d0, int64_t u, int64_t v, int64_t pu,
            int64_t pv, int bias, TraceStats* st) {
  Trace t;
  t.steps = 1;  // the read of d0
  if (int(d0) <= int(dmin) + bias || (pu == 0 && pv == 0)) return t;
  const int cu_log = fmt::kPomUvF - log2_of(cells.width), cv_log = fmt::kPomUvF - log2_of(cells.height);
  const int64_t cw = int64_t(1) << cu_log, ch = int64_t(1) << cv_log;  // cell sides in uv codes
  const int64_t au = std::abs(pu), av = std::abs(pv);
  const int su = pu > 0 ? 1 : -1, sv = pv > 0 ? 1 : -1;
  int64_t i = u >> cu_log, j = v >> cv_log;  // the cell of the surface point (floor, as tex_nearest)
  // Length (uv codes along the axis) to the next boundary in the ray's direction.
  int64_t nu = su > 0 ? (i + 1) * cw - u : u - i * cw;
  int64_t nv = sv > 0 ? (j + 1) * ch - v : v - j * ch;
  const int64_t reach = int64_t(d0) - dmin - bias;  // depth the ray climbs before nothing can occlude it
  const int64_t top = int64_t(d0) - bias;            // d0 - bias - h: the depth test's left operand
  for (uint32_t entered = 0;; ++entered) {
    // Crossing order n_u / |Pu| vs n_v / |Pv| (an axis with P = 0 never crosses).
    const bool along_u = av == 0 || (au != 0 && nu * av <= nv * au);
    const int64_t n = along_u ? nu : nv, a = along_u ? au : av;
    if (st) {
      st->max_n = std::max({st->max_n, nu, nv});
      st->max_cross = std::max({st->max_cross, nu * av, nv * au});
      st->max_abs_test = std::max({st->max_abs_test, 255 * n, reach * a});
    }
    if (reach * a <= 255 * n) return t;  // above the map's highest point at this crossing
    if (entered == static_cast<uint32_t>(fmt::kAfvStepMax)) {
      t.capped = true;
      return t;
    }
    if (along_u) {
      i += su;
      nu += cw;
    } else {
      j += sv;
      nv += ch;
    }
    const int64_t h = cells.at(static_cast<int>(i & (cells.width - 1)), static_cast<int>(j & (cells.height - 1)));
    ++t.steps;
    if (st) st->max_abs_test = std::max(st->max_abs_test, std::abs((top - h) * a));
    if ((top - h) * a > 255 * n) {  // entered the cell more than bias below its surface
      t.visible = false;
      return t;
    }
  }
}

Out filter(const ewa::fx::In& in, const tex::Texture& t, const Config& cfg, const Relief& r) {
  return walk(ewa::fx::setup(in, t, cfg.ewa), t, cfg, r);
}

Out walk(const ewa::fx::PixelSetup& su, const tex::Texture& t, const Config& cfg, const Relief& r,
         TraceStats* st) {
  Out out;
  out.ewa = ewa::fx::walk_out(su);
  const img::Gray8& cells = r.trace_map ? *r.trace_map : *r.depth;
  ewa::fx::Sums sums;
  struct RowTexel {
    int64_t x;
    uint32_t w;
  };
  std::vector<RowTexel> row;
  std::vector<char> keep;
  for (int64_t y = su.y0; y <= su.y1; ++y) {
    // Q direct at each texel (bit-identical to the walk's incremental Q: EwaFx.IncrementalEqualsDirect).
    const int64_t dv = y * kStep - su.cv;
    row.clear();
    for (int64_t x = su.x0; x <= su.x1; ++x) {
      const int64_t du = x * kStep - su.cu;
      const int64_t xi = int64_t(su.kxu) * du + int64_t(su.kxv) * dv;
      const int64_t eta = int64_t(su.kyu) * du + int64_t(su.kyv) * dv;
      ++out.ewa.texels_visited;
      if (const uint32_t w = ewa::fx::texel_weight(su, cfg.ewa, xi * xi + eta * eta, xi, eta); w > 0)
        row.push_back({x, w});
    }
    out.ewa.texels_inside += static_cast<uint32_t>(row.size());
    out.max_row = std::max(out.max_row, static_cast<uint32_t>(row.size()));
    out.clocks += static_cast<uint64_t>(su.x1 - su.x0 + 1) + fmt::kAfvRowCycles;  // scan, drain, row start
    const int64_t cv = centre_code(y, su.level, r.lh);
    apply_rule(cfg.rule, row.size(), [&](size_t k) {
      const int64_t cu = centre_code(row[k].x, su.level, r.lw);
      const Trace tr = trace(cells, r.dmin, pom::tex_nearest(*r.depth, cu, cv), cu, cv, r.pu, r.pv, r.bias, st);
      out.clocks += trace_clocks(tr);
      ++out.traced;
      out.steps += tr.steps;
      out.capped += tr.capped ? 1 : 0;
      return tr.visible;
    }, &keep);
    for (size_t k = 0; k < row.size(); ++k) {
      if (!keep[k]) continue;
      ++out.visible;
      const img::Rgba8 px = t.fetch(su.level, row[k].x, y);
      const uint64_t w = row[k].w;
      sums.acc[0] += w * px.r, sums.acc[1] += w * px.g, sums.acc[2] += w * px.b, sums.acc[3] += w * px.a;
      sums.wsum += w;
    }
  }
  out.no_visible = sums.wsum == 0;
  out.clocks += 1 + 1 + (out.no_visible ? 3 : fmt::kEwaNormCycles);  // hand-over, last accumulate, finish
  ewa::fx::finish(su, t, sums, &out.ewa);
  return out;
}

}  // namespace tu::afvis
