#include "ewa_ref.hpp"

#include <algorithm>
#include <cmath>
#include "texture/trilinear_lod.hpp"
#include "texunit/convert.hpp"

namespace tu::ewa {

Result filter_ref(const tex::Texture& t, double u, double v, const ellipse::Jacobian& j,
                  const Params& p) {
  const Axes ax = axes_ref(j, p.max_aniso);
  return filter_axes(t, u, v, ax.s1, ax.s2, ax.theta, p);
}

Axes axes_ref(const ellipse::Jacobian& j, double max_aniso) {
  // Singular values and the major direction of J (eigen-decomposition of J J^T).
  const double a11 = j.ux * j.ux + j.uy * j.uy, a12 = j.ux * j.vx + j.uy * j.vy,
               a22 = j.vx * j.vx + j.vy * j.vy;
  const double tr = a11 + a22, det = std::fabs(j.ux * j.vy - j.uy * j.vx);
  const double disc = std::sqrt(std::max(0.0, tr * tr / 4 - det * det));
  const double s1 = std::sqrt(tr / 2 + disc);
  double s2 = s1 > 0 ? det / s1 : 0;
  const double theta = 0.5 * std::atan2(2 * a12, a11 - a22);  // major axis angle in (u, v)
  s2 = std::max(s2, s1 / max_aniso);
  return {s1, s2, theta};
}

Result filter_axes(const tex::Texture& t, double u, double v, double s1, double s2, double theta,
                   const Params& p) {
  const int max_level = t.num_levels() - 1;
  int level = static_cast<int>(std::floor(tex::lod_rule_ref(s2 > 0 ? std::log2(s2) : -INFINITY, p.lod_bias, p.min_lod,
                                                            p.max_lod, max_level, nullptr, p.base_level, p.max_level)));
  const double c = std::cos(theta), s = std::sin(theta);
  Result r;
  for (;; ++level) {
    const double scale = std::ldexp(1.0, -level);
    // At least 1 texel (reconstruction support); at most the level's size (a footprint larger
    // than the texture averages all of it anyway).
    const double lim = std::max(t.levels[static_cast<size_t>(level)].width,
                                t.levels[static_cast<size_t>(level)].height);
    const double a = std::clamp(s1 * scale, 1.0, lim), b = std::clamp(s2 * scale, 1.0, lim);
    const double grow = p.clip ? 0.5 : 0;  // border texels up to 1/2 texel outside
    const double hu = std::sqrt(a * a * c * c + b * b * s * s) + grow;
    const double hv = std::sqrt(a * a * s * s + b * b * c * c) + grow;
    // Texel i has its centre at i. Centres beyond 2^62 texels (never in a validated scene) are
    // clamped so that the walk's int64 indices below cannot overflow.
    const double cu = std::clamp(u * scale - 0.5, -0x1p62, 0x1p62);
    const double cv = std::clamp(v * scale - 0.5, -0x1p62, 0x1p62);
    // Saturating conversions: u, v beyond int64 (or NaN) give a box the cap below rejects.
    const int64_t x0 = ceil_i64(cu - hu), x1 = floor_i64(cu + hu);
    const int64_t y0 = ceil_i64(cv - hv), y1 = floor_i64(cv + hv);
    // hu, hv <= the level's side (a, b clamped to it): box fits in double without overflow.
    const double box = (double(x1) - double(x0) + 1) * (double(y1) - double(y0) + 1);
    if (box > p.max_texels && level < max_level) {
      r.capped = true;
      continue;
    }
    double acc[4] = {0, 0, 0, 0}, wsum = 0;
    std::vector<int64_t> xs;
    std::vector<double> ws;
    std::vector<char> keep;
    for (int64_t y = y0; y <= y1; ++y) {
      xs.clear(), ws.clear();
      for (int64_t x = x0; x <= x1; ++x) {
        const double du = x - cu, dv = y - cv;
        const double pu = (du * c + dv * s) / a, pv = (-du * s + dv * c) / b;
        const double w = p.clip ? border_weight(pu, pv, a, b, c, s) : gpm_weight(pu * pu + pv * pv);
        ++r.texels_visited;
        if (w == 0) continue;
        ++r.texels_inside;
        xs.push_back(x), ws.push_back(w);
      }
      keep.assign(xs.size(), 1);
      if (p.row_mask) p.row_mask(level, y, xs, &keep);
      for (size_t k = 0; k < xs.size(); ++k) {
        if (!keep[k]) continue;
        const tex::Rgba8 px = t.fetch(level, xs[k], y);
        const double w = ws[k];
        acc[0] += w * px.r, acc[1] += w * px.g, acc[2] += w * px.b, acc[3] += w * px.a;
        wsum += w;
      }
    }
    r.level = level;
    if (wsum == 0) {  // only with row_mask (a, b >= 1: the nearest texel is inside)
      r.no_weight = true;
      const tex::Rgba8 px = t.fetch(level, floor_i64(cu + 0.5), floor_i64(cv + 0.5));
      r.color = {double(px.r), double(px.g), double(px.b), double(px.a)};
      return r;
    }
    r.color = {acc[0] / wsum, acc[1] / wsum, acc[2] / wsum, acc[3] / wsum};
    return r;
  }
}

double border_distance(double pu, double pv, double a, double b, double c, double s) {
  const double q = pu * pu + pv * pv;
  if (q < 0.25) return HUGE_VAL;
  if (q > 2.25) return -HUGE_VAL;
  const double gu = pu * c / a - pv * s / b, gv = pu * s / a + pv * c / b;
  const double g = std::hypot(gu, gv), r = std::sqrt(q);
  return g > 0 ? (1 - r) * r / g : HUGE_VAL;
}

double border_weight(double pu, double pv, double a, double b, double c, double s) {
  const double d = border_distance(pu, pv, a, b, c, s), q = pu * pu + pv * pv;
  if (d > 0.5) return gpm_weight(q);
  if (d < -0.5) return 0;
  const double w = q < 1 ? gpm_weight(q) : std::ldexp(1.0, -8);
  return w * 0.5 * std::erfc(-d / (0.2 * std::sqrt(2.0)));
}

}  // namespace tu::ewa
