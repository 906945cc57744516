#include "feline/feline_ref.hpp"

#include <algorithm>
#include <cmath>

#include "ewa/ewa_ref.hpp"
#include "texunit/formats.hpp"
#include "texture/trilinear_lod.hpp"

namespace tu::feline {

int probe_count(double s1, double s2, int max_probes) {
  if (!(s1 > 0)) return 1;
  if (!(s2 > 0)) return max_probes;
  // A ratio within 1e-12 of an integer n is n probes (s1 / s2 of an exact ratio rounds either way).
  const double r = s1 / s2 * std::exp2(-std::ldexp(double(kRatioTol), -fmt::kEllLogF));
  return static_cast<int>(std::clamp(std::ceil(r * (1 - 1e-12)), 1.0, double(max_probes)));
}

double probe_t(int i, int n) { return n <= 1 ? 0.0 : double(2 * i - (n - 1)) / (n - 1); }

Result filter_ref(const tex::Texture& t, double u, double v, const ellipse::Jacobian& j, const Params& p) {
  const auto ax = ewa::axes_ref(j, p.max_aniso);
  return filter_axes(t, u, v, ax.s1, ax.s2, ax.theta, p);
}

Result filter_axes(const tex::Texture& t, double u, double v, double s1, double s2, double theta,
                   const Params& p) {
  Result r;
  const int top = t.num_levels() - 1;
  r.probes = probe_count(s1, s2, p.max_probes);
  const double minor = std::max(s2, s1 / p.max_probes);
  r.lod = tex::lod_rule_ref(minor > 0 ? std::log2(minor) : -INFINITY, p.lod_bias, p.min_lod, p.max_lod,
                            top, &r.tri_flags, p.base_level, p.max_level);
  // The line of the clamped minor axis: the end probes' discs (radius minor) touch the ellipse's ends.
  const double c = std::cos(theta), s = std::sin(theta), half = std::max(0.0, s1 - minor);
  double wsum = 0;
  for (int i = 0; i < r.probes; ++i) {
    const double d = probe_t(i, r.probes) * half;
    const double w = ewa::gpm_weight(s1 > 0 ? (d / s1) * (d / s1) : 0);
    const tex::RgbaF px = tex::trilinear_ref(t, r.lod, u + d * c, v + d * s);
    r.color.r += w * px.r, r.color.g += w * px.g, r.color.b += w * px.b, r.color.a += w * px.a;
    wsum += w;
  }
  if (!(wsum > 0)) wsum = 1, r.color = tex::trilinear_ref(t, r.lod, u, v);  // s2 = 0: end probes at Q = 1
  r.color = {r.color.r / wsum, r.color.g / wsum, r.color.b / wsum, r.color.a / wsum};
  r.texels = r.probes * (r.lod >= top ? 4 : 8);
  return r;
}

}  // namespace tu::feline
