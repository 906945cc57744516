// EWA texture filter (B5), float reference: Heckbert's elliptical weighted average with the
// seed-003 Gaussian pixel-model weight w = (1 - Q/2)^8 (Q <= 1), on a mip pyramid.
//
// Footprint: the image of the unit pixel disc under the Jacobian J (texels per pixel), i.e. an
// ellipse with semi-axes sigma1 >= sigma2 (singular values of J) along J's left singular vectors.
// The minor axis is grown to sigma1 / max_aniso (anisotropy clamp). Level L = floor(log2(minor)),
// clamped to the pyramid, so the minor semi-axis at level L is in [1, 2) texels; both semi-axes are
// at least 1 texel (magnification keeps a reconstruction support, and a disc of radius 1 always
// holds a texel centre, so the weight sum is never 0). Texel walk over the ellipse's bounding box;
// when the box exceeds max_texels the level is raised until it fits (documented fallback: blur
// instead of an unbounded walk).
#pragma once

#include <functional>
#include <vector>

#include "ellipse/ellipse_ref.hpp"
#include "texture/texture.hpp"

namespace tu::ewa {

// Texel cap of the renderers and the RTL top's span input (bounding-box texels per pixel).
inline constexpr int kDefaultMaxTexels = 1024;

struct Params {
  double max_aniso = 16;
  int max_texels = kDefaultMaxTexels;  // bounding-box texels per pixel before falling back to a coarser level
  // Sub-texel border weights (seed 003 §2, docs/blocks/ewa.md "Border weights"): the box grows by
  // 1/2 texel per side, texels with |d| <= 1/2 get w' Phi(d / 0.2) (exact), d = border_distance().
  bool clip = false;
  // The sampler's level choice (tex::lod_rule_ref on log2 of the clamped minor axis): material
  // lod_bias, min_lod, max_lod, base_level, max_level. The texel cap may still raise the level.
  double lod_bias = 0, min_lod = 0, max_lod = 12;
  int base_level = 0, max_level = 1000;
  // Optional visibility per walk row (afvis, docs/blocks/afvis.md): given the level, the row y and
  // the x of its texels with weight > 0 (walk order), clears keep[k] for the texels left out of the
  // sums. None kept at all: the level's texel nearest the centre (Result::no_weight).
  std::function<void(int level, int64_t y, const std::vector<int64_t>& xs, std::vector<char>* keep)> row_mask = {};
};

struct Result {
  tex::RgbaF color;
  int level = 0;
  int texels_visited = 0;  // bounding-box texels walked
  int texels_inside = 0;   // texels with Q < 1 (weighted)
  bool capped = false;     // the texel cap raised the level
  bool no_weight = false;  // row_mask left no texel: the nearest texel at the level
};

// The footprint's semi-axes s1 >= s2 (singular values of J; s2 grown to s1 / max_aniso) and the
// major-axis angle theta (radians, in (u, v)), from the eigen-decomposition of J J^T.
struct Axes {
  double s1 = 0, s2 = 0, theta = 0;
};
Axes axes_ref(const ellipse::Jacobian& j, double max_aniso);

// (u, v): level-0 texel coordinates of the pixel centre; j: the Jacobian there.
Result filter_ref(const tex::Texture& t, double u, double v, const ellipse::Jacobian& j,
                  const Params& p);

// The same filter from the footprint's semi-axes s1 >= s2 (level-0 texels, s2 already grown by
// the anisotropy clamp) and the major-axis angle theta (radians, in (u, v)). filter_ref calls it;
// the bit-accurate model's vectors use it on B2's axes (ewa_fx.hpp).
Result filter_axes(const tex::Texture& t, double u, double v, double s1, double s2, double theta,
                   const Params& p);

// Gaussian pixel-model weight, Q in [0, 1); 0 outside.
inline double gpm_weight(double q) {
  if (q < 0 || q >= 1) return 0;
  const double t = 1 - q / 2;
  const double t2 = t * t, t4 = t2 * t2;
  return t4 * t4;
}

// Signed distance (texels, > 0 inside) from a texel centre to the ellipse's tangent at the radial
// projection of its frame offset (pu, pv) (Q = pu^2 + pv^2): d = (1 - r) r / |g|, r = sqrt(Q),
// g = K^T (pu, pv) = grad Q / 2 in texel offsets, K the frame (rows (c, s) / a, (-s, c) / b).
// Exact for a circle; zones as the C model: Q < 1/4 -> +inf (inside), Q > 9/4 -> -inf (outside).
double border_distance(double pu, double pv, double a, double b, double c, double s);
// Border weight of a texel (Params::clip): w(Q) inside (d > 1/2), w' Phi(d / 0.2) for |d| <= 1/2
// with w' = w(Q) for Q < 1 and the boundary weight 2^-8 beyond, 0 for d < -1/2.
double border_weight(double pu, double pv, double a, double b, double c, double s);

}  // namespace tu::ewa
