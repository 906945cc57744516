// Pixel footprint (B2), float reference: Jacobian of the screen->texture map, Heckbert's EWA
// ellipse, its axes, the anisotropy clamp and the mip LOD. Corrected algebra from
// shared/spec/notes/seed-001-heckbert-ellipse-perlin.md §2.3-2.7.
//
// Map (B1): u = pu/q, v = pv/q with pu = A x + B y + C, pv = D x + E y + F, q = G x + H y + I.
// Numerators of the derivatives (the same for the analytic and the forward-difference forms):
//   nUx = A q - G pu = A I - C G + M y        M = A H - B G
//   nVx = D q - G pv = D I - F G + N y        N = D H - E G
//   nUy = B q - H pu = B I - C H - M x
//   nVy = E q - H pv = E I - F H - N x
// Analytic:          Ux = nUx / q^2,          Uy = nUy / q^2            (all four share q^2)
// Forward difference: Ux = nUx / (q (q + G)), Uy = nUy / (q (q + H))   ([FIX] seed prints q(q+G))
// Ellipse: Ae = Vx^2 + Vy^2, Be = -2 (Ux Vx + Uy Vy), Ce = Ux^2 + Uy^2, Fe = (Ux Vy - Uy Vx)^2
// ([FIX] minus: the squared Jacobian determinant).
#pragma once

#include "persp/persp.hpp"

namespace tu::ellipse {

using persp::Coef9;

struct Jacobian {
  double ux, vx, uy, vy;  // du/dx, dv/dx, du/dy, dv/dy (texels per pixel)
};

struct Ellipse {
  double ae, be, ce, fe;
};

struct Footprint {
  double major = 0, minor = 0;   // semi-axes of the pixel footprint, texels (singular values of J)
  double minor_clamped = 0;      // minor grown so that major / minor <= max_aniso
  double aniso = 1;              // major / minor_clamped
  double lod = 0;                // log2(minor_clamped), clamped to [0, max_lod]
  bool degenerate = false;       // Fe == 0: the footprint is a line or a point
  bool clamped_aniso = false;    // the anisotropy clamp changed the minor axis
  bool lod_saturated = false;    // footprint larger than the coarsest mip level
  bool horizon = false;          // q <= 0: no footprint (flagged, all zero)
};

struct Numerators {
  double nux, nvx, nuy, nvy, q;
};

Numerators numerators(const Coef9& k, double x, double y);
Jacobian analytic(const Coef9& k, double x, double y);
Jacobian forward_difference(const Coef9& k, double x, double y);
// The recurrences of seed-001 §2.7 (corrected), walked in double along a span from (x0, y):
// x-numerators per scanline (+M, +N per row), y-numerators per pixel (-M, -N), denominators
// q(q+G) and q(q+H). Returns one Jacobian per pixel; equals forward_difference up to rounding.
std::vector<Jacobian> forward_difference_span(const Coef9& k, int x0, int y, int n);

Ellipse ellipse(const Jacobian& j);
// det of the 3x3 map [[A,B,C],[D,E,F],[G,H,I]]; nUx nVy - nUy nVx = det3 * q.
double det3(const Coef9& k);
// Ellipse scaled by q^4 (the implicit equation is homogeneous): Ae' = nVx^2 + nVy^2,
// Be' = -2 (nUx nVx + nUy nVy), Ce' = nUx^2 + nUy^2, Fe' = (det3 * (1/q))^2: no division beyond
// the 1/q that B1 already computes.
Ellipse ellipse_q4(const Numerators& n, double det3, double inv_q);

struct FootprintParams {
  double max_aniso = 16;  // major / minor at most this
  double max_lod = 12;    // coarsest mip level (log2 of the texture size)
};
Footprint footprint(const Jacobian& j, const FootprintParams& p);

enum class Deriv { Analytic, ForwardDifference };
// Footprint at pixel (x, y). At or beyond the horizon (q <= 0, or q + G / q + H <= 0 for the
// forward difference) there is no footprint: `horizon` is set and every measure is 0.
Footprint footprint_at(const Coef9& k, double x, double y, const FootprintParams& p, Deriv d);

}  // namespace tu::ellipse
