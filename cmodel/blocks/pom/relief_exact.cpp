#include "pom/relief_exact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "texunit/formats.hpp"

namespace tu::relief {

namespace {
double depth_at(const img::Gray8& d, int64_t i, int64_t j) {
  const auto wi = static_cast<int>(i & (d.width - 1)), wj = static_cast<int>(j & (d.height - 1));
  return d.at(wi, wj) / 255.0;
}

// Smallest root of c0 + c1 t + c2 t^2 in [0, len], or -1.
double first_root(double c0, double c1, double c2, double len) {
  auto in = [&](double t) { return t >= 0 && t <= len; };
  if (std::fabs(c2) < 1e-300) {
    if (c1 == 0) return -1;
    const double t = -c0 / c1;
    return in(t) ? t : -1;
  }
  const double disc = c1 * c1 - 4 * c2 * c0;
  if (disc < 0) return -1;
  // Stable pair: q = -(c1 + sign(c1) sqrt(disc)) / 2, roots q / c2 and c0 / q.
  const double sq = std::sqrt(disc), q = -0.5 * (c1 + std::copysign(sq, c1));
  double r1 = q / c2, r2 = q != 0 ? c0 / q : r1;
  if (r1 > r2) std::swap(r1, r2);
  if (in(r1)) return r1;
  if (in(r2)) return r2;
  return -1;
}
}  // namespace

ExactHit exact_hit(const img::Gray8& depth, double u, double v, double vx, double vy, double vz,
                   double scale) {
  const double a = std::max(std::fabs(vz), std::ldexp(double(fmt::kPomVzMin), -fmt::kPomVzF));
  const double pu = vx / a * scale, pv = vy / a * scale;
  // Depth-map texel coordinates (centres at integers) along the ray: X(D) = x0 + dx D.
  const double x0 = u * depth.width - 0.5, y0 = v * depth.height - 0.5;
  const double dx = -pu * depth.width, dy = -pv * depth.height;
  int64_t ci = static_cast<int64_t>(std::floor(x0)), cj = static_cast<int64_t>(std::floor(y0));
  const int sx = dx > 0 ? 1 : -1, sy = dy > 0 ? 1 : -1;
  const double inf = std::numeric_limits<double>::infinity();
  // D at which the ray leaves the current cell along x / y.
  auto exit_d = [&](double p0, double dp, int64_t c, int s) {
    if (dp == 0) return inf;
    return ((s > 0 ? double(c + 1) : double(c)) - p0) / dp;
  };
  double d0 = 0;
  ExactHit h;
  for (;;) {
    ++h.cells;
    const double tx = exit_d(x0, dx, ci, sx), ty = exit_d(y0, dy, cj, sy);
    const double d1 = std::min({tx, ty, 1.0});
    const double h00 = depth_at(depth, ci, cj), h10 = depth_at(depth, ci + 1, cj);
    const double h01 = depth_at(depth, ci, cj + 1), h11 = depth_at(depth, ci + 1, cj + 1);
    const double e = h10 - h00, f = h01 - h00, k = h00 - h10 - h01 + h11;
    // Local parameter t = D - d0: fx = ax + dx t, fy = ay + dy t.
    const double ax = x0 + dx * d0 - double(ci), ay = y0 + dy * d0 - double(cj);
    const double b0 = h00 + e * ax + f * ay + k * ax * ay;
    const double b1 = e * dx + f * dy + k * (ax * dy + dx * ay);
    const double b2 = k * dx * dy;
    // g(t) = (d0 + t) - (b0 + b1 t + b2 t^2)
    const double c0 = d0 - b0, c1 = 1 - b1, c2 = -b2, len = d1 - d0;
    double t = c0 >= 0 ? 0 : first_root(c0, c1, c2, len);
    if (t < 0 && d1 >= 1) t = len;  // D = 1 is always at or below the field (rounding guard)
    if (t >= 0) {
      h.depth = std::clamp(d0 + t, 0.0, 1.0);
      h.u = u - h.depth * pu;
      h.v = v - h.depth * pv;
      return h;
    }
    if (tx <= ty) ci += sx; else cj += sy;
    d0 = d1;
  }
}

}  // namespace tu::relief
