#include "afvis/afvis_ref.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "pom/pom_march.hpp"
#include "pom/relief_exact.hpp"
#include "texunit/convert.hpp"
#include "texunit/formats.hpp"

namespace tu::afvis {

namespace {
struct RefTrace {
  Trace t;
  double margin = std::numeric_limits<double>::infinity();
};
// The DDA of afvis::trace in cell units (the cell of the point: floor), s in relief depth units.
RefTrace run_ref(const img::Gray8& cells, uint8_t dmin, double d0, double u, double v, double pu,
                 double pv, int bias) {
  RefTrace r;
  r.t.steps = 1;
  d0 -= bias;  // the ray bias codes lower: the same tests as afvis::trace
  if (d0 <= dmin || (pu == 0 && pv == 0)) return r;
  const double x = u * cells.width, y = v * cells.height;
  const double au = std::fabs(pu) * cells.width, av = std::fabs(pv) * cells.height;
  const int su = pu > 0 ? 1 : -1, sv = pv > 0 ? 1 : -1;
  int64_t i = floor_i64(x), j = floor_i64(y);
  const double inf = std::numeric_limits<double>::infinity();
  double su_next = au > 0 ? (su > 0 ? double(i + 1) - x : x - double(i)) / au : inf;  // s at the next crossing
  double sv_next = av > 0 ? (sv > 0 ? double(j + 1) - y : y - double(j)) / av : inf;
  for (;;) {
    const bool along_u = su_next <= sv_next;
    const double s = along_u ? su_next : sv_next;
    const double d_entry = d0 - 255 * s;
    if (d_entry <= dmin) return r;
    if (along_u) {
      i += su;
      su_next += 1 / au;
    } else {
      j += sv;
      sv_next += 1 / av;
    }
    const double h = cells.at(static_cast<int>(i & (cells.width - 1)), static_cast<int>(j & (cells.height - 1)));
    ++r.t.steps;
    r.margin = std::min(r.margin, h - d_entry);
    if (d_entry > h) {
      r.t.visible = false;
      return r;
    }
  }
}
}  // namespace

ParallaxRef parallax_ref(double vx, double vy, double vz, double scale) {
  const double a = std::max(std::fabs(vz), std::ldexp(double(fmt::kPomVzMin), -fmt::kPomVzF));
  return {vx / a * scale, vy / a * scale};
}

Trace trace_ref(const img::Gray8& cells, uint8_t dmin, double d0, double u, double v, double pu,
                double pv, int bias) {
  return run_ref(cells, dmin, d0, u, v, pu, pv, bias).t;
}

double trace_margin_ref(const img::Gray8& cells, uint8_t dmin, double d0, double u, double v,
                        double pu, double pv, int bias) {
  return run_ref(cells, dmin, d0, u, v, pu, pv, bias).margin;
}

double depth_bilinear(const img::Gray8& depth, double u, double v) {
  const double x = u * depth.width - 0.5, y = v * depth.height - 0.5;
  const int64_t i = floor_i64(x), j = floor_i64(y);
  const double fx = x - double(i), fy = y - double(j);
  auto at = [&](int64_t a, int64_t b) {
    return depth.at(static_cast<int>(a & (depth.width - 1)), static_cast<int>(b & (depth.height - 1))) / 255.0;
  };
  return (at(i, j) * (1 - fx) + at(i + 1, j) * fx) * (1 - fy) + (at(i, j + 1) * (1 - fx) + at(i + 1, j + 1) * fx) * fy;
}

bool visible_bilinear(const img::Gray8& depth, double u, double v, double vx, double vy, double vz,
                      double scale, double tol) {
  const double d = depth_bilinear(depth, u, v);
  const ParallaxRef p = parallax_ref(vx, vy, vz, scale);
  const relief::ExactHit h = relief::exact_hit(depth, u + d * p.pu, v + d * p.pv, vx, vy, vz, scale);
  return h.depth >= d - tol;
}

ewa::Params with_visibility(ewa::Params p, const RefRelief& r) {
  p.row_mask = [r](int level, int64_t y, const std::vector<int64_t>& xs, std::vector<char>* keep) {
    const double tw = std::ldexp(1.0, r.lw), th = std::ldexp(1.0, r.lh), l = std::ldexp(1.0, level);
    const double cv = (double(y) + 0.5) * l / th;
    const img::Gray8& cells = r.trace_map ? *r.trace_map : *r.depth;
    apply_rule(r.rule, xs.size(), [&](size_t k) {
      const double cu = (double(xs[k]) + 0.5) * l / tw;
      const Trace t = trace_ref(cells, r.dmin, pom::tex_nearest_f(*r.depth, cu, cv), cu, cv, r.pu, r.pv, r.bias);
      if (r.traced) ++*r.traced;
      if (r.steps) *r.steps += t.steps;
      return t.visible;
    }, keep);
  };
  return p;
}

}  // namespace tu::afvis
