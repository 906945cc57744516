// Feline probe-based anisotropic filter (McCormack, Perry, Farkas, Jouppi 1999), float reference
// (docs/blocks/feline.md). The comparison the EWA is measured against: what a GPU texture unit
// does with several trilinear probes instead of a texel walk.
//
// Footprint: semi-axes s1 >= s2 (level-0 texels; s2 already grown by the anisotropy clamp) and
// the major-axis angle theta, as the EWA (ewa::axes_ref).
//   N      = min(ceil((s1 / s2) 2^-tau), Nmax) probes (1 for a point footprint; tau = 2^-7, kRatioTol);
//   lambda = log2(max(s2, s1 / Nmax)): the isotropic LOD of the minor axis, raised when N is
//            clamped so that Nmax probes still cover the major axis; then the GL rule's bias,
//            [min_lod, max_lod] clamps, magnification and pyramid clamp (tex::lod_rule_ref), as
//            the trilinear filter;
//   probe i (0 .. N-1) at t_i = (2i - (N-1)) / (N-1) (0 for N = 1) along the major axis:
//            (u, v) + t_i (s1 - m) (cos theta, sin theta), m = max(s2, s1 / Nmax) the minor axis
//            as the probes' LOD sees it, spaced over a line of length 2 (s1 - m), so that the end
//            probes' discs of radius m touch the ellipse's ends (with N clamped, 2 (s1 - s2)
//            would put Nmax discs of radius s1 / Nmax beyond the ellipse);
//   weight w_i = the EWA's Gaussian pixel model (1 - Q/2)^8 at Q = (d_i / s1)^2, d_i the probe's
//            distance from the centre (the ellipse's own weight along its major axis);
//   colour = sum w_i trilinear(lambda, probe_i) / sum w_i.
// Texels read: 8 per probe (4 when lambda reaches the top level: one level).
#pragma once

#include <cstdint>

#include "ellipse/ellipse_ref.hpp"
#include "texture/texture.hpp"

namespace tu::feline {

inline constexpr int kDefaultMaxProbes = 8;
// Probe-count tolerance in log2 codes (EllLogF fraction bits): N = ceil((s1 / s2) 2^-tau),
// tau = kRatioTol / 2^EllLogF = 2^-7 (a ratio up to 0.54 % above an integer n is n probes). B2
// floors log2 of each axis separately, so an isotropic footprint's ratio comes out a few 2^-10
// above 1: without it, it would take 2 probes.
inline constexpr int kRatioTol = 8;

struct Params {
  int max_probes = kDefaultMaxProbes;  // Nmax, 1 .. FelNMax
  double max_aniso = 16;               // the anisotropy clamp of the footprint
  double lod_bias = 0, min_lod = 0, max_lod = 12;  // the GL rule (material fields)
  int base_level = 0, max_level = 1000;             // the levels sampled (tex::level_range)
};

struct Result {
  tex::RgbaF color;
  int probes = 1;
  double lod = 0;          // the probes' lambda after the rule
  uint32_t tri_flags = 0;  // tex::TriFlag of the probes' LOD
  int texels = 0;
};

// Probe count for the ratio s1 / s2 (s2 <= 0: Nmax): ceil((s1 / s2) 2^-tau), a product within 1e-12
// of an integer n giving n.
int probe_count(double s1, double s2, int max_probes);
// Position along the major axis of probe i of n, in [-1, 1].
double probe_t(int i, int n);

// (u, v): level-0 texel coordinates of the pixel centre; j: the Jacobian there.
Result filter_ref(const tex::Texture& t, double u, double v, const ellipse::Jacobian& j, const Params& p);
// The same from the axes (s2 clamped by the caller).
Result filter_axes(const tex::Texture& t, double u, double v, double s1, double s2, double theta,
                   const Params& p);

}  // namespace tu::feline
