// The exact ray / height-field intersection: the ideal that every relief method approximates and
// the ground-truth renderer (render::render_truth) shifts its samples with. Defined once here.
//
// Height field: the depth map (POM convention: code / 255, 0 = top surface, 1 = deepest) as a
// bilinear function of (u, v) in texture repeats, texel centres at ((i + 1/2) / W, (j + 1/2) / H),
// REPEAT wrap. Ray: from the surface point T = (u, v) at depth 0 along the tangent-space view
// V (towards the eye, so the ray goes -V): position T - D P at depth D in [0, 1], with
// P = Vxy / a * scale and a = max(|Vz|, PomVzMin) (the fixed-point unit's |Vz| guard, so that a
// grazing view stays finite; Vz < 0 is mirrored as in pom::march). The hit is the smallest D with
// D >= depth(T - D P): it exists (depth <= 1 at D = 1). Cell walk: the bilinear cells the ray's
// projection crosses, in order (2-D DDA); inside a cell D - depth(T - D P) is a quadratic in D,
// whose smallest root in the cell's D interval is taken (closed form, double precision).
// Error: double rounding only (|D - D_exact| ~ 1e-15 relative on a non-grazing root; a root where
// the quadratic touches zero is taken as a hit).
#pragma once

#include <cstdint>

#include "texunit/image.hpp"

namespace tu::relief {

struct ExactHit {
  double u = 0, v = 0;  // hit position in texture repeats (not wrapped: T - D P)
  double depth = 0;     // D in [0, 1]
  uint32_t cells = 0;   // bilinear cells visited (cost of the walk)
};
// vx, vy, vz: tangent-space view (unit vector towards the eye); scale: relief depth in texture
// repeats (the material's `scale`).
ExactHit exact_hit(const img::Gray8& depth, double u, double v, double vx, double vy, double vz,
                   double scale);

}  // namespace tu::relief
