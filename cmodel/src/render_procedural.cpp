// Procedural materials in the render engines (docs/blocks/noise-appendix.md §5): the scene's description
// in noise units, and the per-pixel colour of the float reference, the C model and the truth.
#include <algorithm>
#include <cmath>

#include "noise/noise_proc.hpp"
#include "texunit/convert.hpp"
#include "texunit/render.hpp"

namespace tu::render {

noise::ProcParams procedural_params(const scene::Material& m, int tex_w) {
  const scene::Procedural& pr = m.procedural.value();
  noise::ProcParams p;
  p.smoke = pr.kind == scene::ProceduralKind::Smoke;
  p.water = pr.kind == scene::ProceduralKind::Water;
  p.amplitude = pr.amplitude;
  p.light = pr.light;
  p.z = pr.speed * pr.time;
  p.dims = pr.speed != 0 ? 3 : 2;  // z = 0 for every frame: the 2-D core (bit-identical slice)
  p.octaves = pr.octaves;
  p.freq = pr.frequency / tex_w;  // cells per level-0 texel, on both axes (square cells)
  p.sx = (37 * pr.seed) % 256;
  p.sy = (91 * pr.seed) % 256;
  p.limit = pr.footprint_limit;
  p.lod_bias = m.lod_bias;
  p.threshold = pr.threshold;
  p.gain = pr.gain;
  for (size_t i = 0; i < 3; ++i) p.c0[i] = pr.color0[i], p.c1[i] = pr.color1[i];
  return p;
}

std::vector<std::optional<noise::ProcParams>> procedural_objects(const scene::Scene& s,
                                                                 const std::vector<tex::Texture>& texs) {
  std::vector<std::optional<noise::ProcParams>> out;
  for (size_t o = 0; o < s.objects.size(); ++o) {
    const auto& m = s.materials.at(s.objects[o].material);
    out.push_back(m.procedural ? std::optional(procedural_params(m, texs.at(o).levels[0].width)) : std::nullopt);
  }
  return out;
}

img::Rgba8 procedural_ref(const noise::ProcParams& p, double u, double v, const ellipse::Jacobian& j) {
  // The GL rule's rho: the longer of the two pixel-step vectors (texels).
  const double rho2 = std::max(j.ux * j.ux + j.vx * j.vx, j.uy * j.uy + j.vy * j.vy);
  const double lrho = rho2 > 0 ? 0.5 * std::log2(rho2) : -INFINITY;
  const auto c = noise::proc_color_ref(p, noise::proc_value_ref(p, u, v, lrho));
  auto to8 = [](double x) { return static_cast<uint8_t>(std::clamp<int64_t>(round_i64(x), 0, 255)); };
  return {to8(c[0]), to8(c[1]), to8(c[2]), to8(c[3])};
}

}  // namespace tu::render
