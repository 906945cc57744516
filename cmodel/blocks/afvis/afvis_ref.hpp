// AF with parallax visibility, float reference (docs/blocks/afvis.md): the same box-field DDA as
// afvis::trace in double (no step cap), the exact visibility on the bilinear height field of the
// truth renderer (relief::exact_hit), and the float EWA with the visibility row rule.
#pragma once

#include <cstdint>

#include "afvis/afvis.hpp"
#include "ewa/ewa_ref.hpp"
#include "texunit/image.hpp"

namespace tu::afvis {

// P of a tangent-space view (towards the eye) in repeats per unit of relief depth: Vxy S / a,
// a = max(|Vz|, PomVzMin 2^-PomVzF) (pom::parallax in double; Vz < 0 mirrored).
struct ParallaxRef {
  double pu = 0, pv = 0;
};
ParallaxRef parallax_ref(double vx, double vy, double vz, double scale);

// The box-field trace of afvis::trace in double: the point (u, v) (repeats) at depth code d0,
// towards the eye along P; cells of `cells`, dmin its smallest code. No cap.
Trace trace_ref(const img::Gray8& cells, uint8_t dmin, double d0, double u, double v, double pu,
                double pv, int bias = 0);
// The same test with its slack: the smallest (h - D_entry) over the cells entered, in depth codes
// (< 0: occluded; near 0: a tie that rounding may flip); +inf when no cell is entered.
double trace_margin_ref(const img::Gray8& cells, uint8_t dmin, double d0, double u, double v,
                        double pu, double pv, int bias = 0);

// The exact visibility of the surface point above (u, v) on the BILINEAR field (texel centres at
// (i + 1/2) / side): the eye's ray through it first meets the relief there (relief::exact_hit from
// the point where the ray enters the top, at depth 0), within tol (relief depth units).
bool visible_bilinear(const img::Gray8& depth, double u, double v, double vx, double vy, double vz,
                      double scale, double tol = 1e-9);
// The bilinear depth (0..1) at (u, v) repeats (REPEAT).
double depth_bilinear(const img::Gray8& depth, double u, double v);

// The float EWA (ewa::filter_axes) with visibility: a row mask applying `rule` with trace_ref at
// the level-L texel centres of a colour texture of lw x lh (log2) level-0 texels.
struct RefRelief {
  const img::Gray8* depth = nullptr;
  const img::Gray8* trace_map = nullptr;
  uint8_t dmin = 0;
  double pu = 0, pv = 0;
  int lw = 0, lh = 0;
  Rule rule = Rule::Row;
  uint32_t* traced = nullptr;  // optional: traces run (added to)
  uint32_t* steps = nullptr;   // optional: depth reads (added to)
  int bias = kDefaultBias;     // depth codes (trace)
};
ewa::Params with_visibility(ewa::Params p, const RefRelief& r);

}  // namespace tu::afvis
