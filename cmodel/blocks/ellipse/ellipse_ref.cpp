#include "ellipse_ref.hpp"

#include <algorithm>
#include <cmath>

namespace tu::ellipse {

Numerators numerators(const Coef9& k, double x, double y) {
  const double pu = k.a * x + k.b * y + k.c;
  const double pv = k.d * x + k.e * y + k.f;
  const double q = k.g * x + k.h * y + k.i;
  return {k.a * q - k.g * pu, k.d * q - k.g * pv, k.b * q - k.h * pu, k.e * q - k.h * pv, q};
}

Jacobian analytic(const Coef9& k, double x, double y) {
  const auto n = numerators(k, x, y);
  const double q2 = n.q * n.q;
  return {n.nux / q2, n.nvx / q2, n.nuy / q2, n.nvy / q2};
}

Jacobian forward_difference(const Coef9& k, double x, double y) {
  const auto n = numerators(k, x, y);
  const double dx = n.q * (n.q + k.g);
  const double dy = n.q * (n.q + k.h);
  return {n.nux / dx, n.nvx / dx, n.nuy / dy, n.nvy / dy};
}

std::vector<Jacobian> forward_difference_span(const Coef9& k, int x0, int y, int n) {
  const double m = k.a * k.h - k.b * k.g;
  const double nn = k.d * k.h - k.e * k.g;
  // Per scanline (the x-numerators do not depend on x).
  const double nux = k.a * k.i - k.c * k.g + m * y;
  const double nvx = k.d * k.i - k.f * k.g + nn * y;
  double nuy = k.b * k.i - k.c * k.h - m * x0;
  double nvy = k.e * k.i - k.f * k.h - nn * x0;
  double q = k.g * x0 + k.h * y + k.i;
  std::vector<Jacobian> out;
  out.reserve(static_cast<size_t>(std::max(n, 0)));
  for (int i = 0; i < n; ++i) {
    const double dx = q * (q + k.g), dy = q * (q + k.h);
    out.push_back({nux / dx, nvx / dx, nuy / dy, nvy / dy});
    q += k.g;
    nuy -= m;
    nvy -= nn;
  }
  return out;
}

Ellipse ellipse(const Jacobian& j) {
  const double det = j.ux * j.vy - j.uy * j.vx;
  return {j.vx * j.vx + j.vy * j.vy, -2 * (j.ux * j.vx + j.uy * j.vy), j.ux * j.ux + j.uy * j.uy,
          det * det};
}

double det3(const Coef9& k) {
  return k.a * (k.e * k.i - k.f * k.h) - k.b * (k.d * k.i - k.f * k.g) +
         k.c * (k.d * k.h - k.e * k.g);
}

Ellipse ellipse_q4(const Numerators& n, double det, double inv_q) {
  const double f = det * inv_q;
  return {n.nvx * n.nvx + n.nvy * n.nvy, -2 * (n.nux * n.nvx + n.nuy * n.nvy),
          n.nux * n.nux + n.nuy * n.nuy, f * f};
}

Footprint footprint(const Jacobian& j, const FootprintParams& p) {
  Footprint f;
  // Singular values of J = [[ux, uy], [vx, vy]]: the semi-axes of the image of the unit circle.
  const double s = j.ux * j.ux + j.uy * j.uy + j.vx * j.vx + j.vy * j.vy;  // sigma1^2 + sigma2^2
  const double det = std::fabs(j.ux * j.vy - j.uy * j.vx);                 // sigma1 * sigma2
  const double disc = std::sqrt(std::max(0.0, s * s / 4 - det * det));
  f.major = std::sqrt(s / 2 + disc);
  f.minor = f.major > 0 ? det / f.major : 0;  // stable for thin ellipses
  f.degenerate = det == 0;
  f.minor_clamped = std::max(f.minor, f.major / p.max_aniso);
  f.clamped_aniso = f.minor_clamped > f.minor;
  f.aniso = f.minor_clamped > 0 ? f.major / f.minor_clamped : 1;
  // Magnification (footprint below one texel) and the point footprint select level 0.
  const double l = f.minor_clamped > 0 ? std::log2(f.minor_clamped) : 0;
  f.lod = std::clamp(l, 0.0, p.max_lod);
  f.lod_saturated = l > p.max_lod;
  return f;
}

Footprint footprint_at(const Coef9& k, double x, double y, const FootprintParams& p, Deriv d) {
  const double q = k.g * x + k.h * y + k.i;
  const bool fd = d == Deriv::ForwardDifference;
  if (q <= 0 || (fd && (q + k.g <= 0 || q + k.h <= 0))) {
    Footprint f;
    f.horizon = true;
    return f;
  }
  return footprint(fd ? forward_difference(k, x, y) : analytic(k, x, y), p);
}

}  // namespace tu::ellipse
