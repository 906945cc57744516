// Ground-truth render (docs/blocks/texture.md "Ground truth"): N x N stratified, jittered point
// samples of level-0 texels per pixel at the exact perspective (u, v), with the exact
// ray / height-field intersection on relief materials, box- or Gaussian-weighted.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "pom/relief.hpp"
#include "pom/relief_exact.hpp"
#include "texunit/render.hpp"
#include "texunit/shading.hpp"

namespace tu::render {

namespace {
constexpr img::Rgba8 kBackground{0, 0, 80, 255};  // as render_ref

// Deterministic jitter in [0, 1): splitmix64 of the pixel and the sample index.
double jitter(uint64_t key) {
  key += 0x9E3779B97F4A7C15ull;
  key = (key ^ (key >> 30)) * 0xBF58476D1CE4E5B9ull;
  key = (key ^ (key >> 27)) * 0x94D049BB133111EBull;
  key ^= key >> 31;
  return static_cast<double>(key >> 11) * 0x1.0p-53;
}

// The triangle's barycentric (s, r) of a level-0 texel position (the uv map is affine).
bool barycentric(const persp::Triangle& t, double u, double v, double* s, double* r) {
  const double a = t.v[1].uv[0] - t.v[0].uv[0], b = t.v[2].uv[0] - t.v[0].uv[0];
  const double c = t.v[1].uv[1] - t.v[0].uv[1], d = t.v[2].uv[1] - t.v[0].uv[1];
  const double det = a * d - b * c;
  if (std::fabs(det) < 1e-300) return false;
  const double du = u - t.v[0].uv[0], dv = v - t.v[0].uv[1];
  *s = (d * du - b * dv) / det;
  *r = (a * dv - c * du) / det;
  return true;
}

struct ReliefCtx {
  relief::Maps maps;
  double scale = 0;
};
}  // namespace

Frame render_truth(const scene::Scene& s, const TruthOptions& opt) {
  const int w = s.camera.width, h = s.camera.height;
  const int n = std::max(1, opt.ss);
  Frame f;
  f.image = img::Rgba8Image(w, h, kBackground);
  const auto cov = visibility(s);
  std::vector<tex::Texture> texs;
  std::vector<std::vector<persp::Triangle>> tris;  // uv in level-0 texels
  std::vector<std::vector<persp::Coef9>> coefs;
  std::vector<std::optional<ReliefCtx>> reliefs;
  for (const auto& o : s.objects) {
    const auto& m = s.materials.at(o.material);
    texs.push_back(scene::build_texture(s, m.texture));
    const auto& base = texs.back().levels[0];
    tris.push_back(scene::in_texels(o, base.width, base.height));
    std::vector<persp::Coef9> k;
    for (const auto& t : tris.back()) k.push_back(persp::coefficients(s.camera, t));
    (void)setup_fx(s, coefs.size(), base.width, base.height);  // what B1 cannot set up is refused in every engine
    coefs.push_back(std::move(k));
    reliefs.push_back(opt.relief && m.relief ? std::optional(ReliefCtx{relief::make_maps(s, o.material), m.relief->scale})
                                             : std::nullopt);
  }
  // Procedural materials: the unfiltered field (all K octaves) at every sample.
  auto procs = procedural_objects(s, texs);
  for (auto& p : procs)
    if (p) p->limit = false;
  // Sample offsets from the pixel centre: box = the pixel square, Gaussian = the EWA's pixel
  // model over the unit disc, w = (1 - r^2 / 2)^8 for r < 1 (ewa_ref.hpp).
  const bool gauss = opt.kernel == TruthKernel::Gaussian;
  const shading::Setup shade(s);  // lit scenes: the float shading of the centre's surface point
  const persp::RayCaster rays(s.camera);
  const double span = gauss ? 2.0 : 1.0;
  for (int y = 0; y < h; ++y) {
    if (opt.progress && (y % 8 == 0 || y == h - 1))
      std::fprintf(stderr, "\rtruth render %3d%%", (y + 1) * 100 / h);
    for (int x = 0; x < w; ++x) {
      const Cover c = cov[static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x)];
      if (c.object < 0) continue;
      const size_t oi = static_cast<size_t>(c.object), ti = static_cast<size_t>(c.triangle);
      const auto& tx = texs[oi];
      const auto& k = coefs[oi][ti];
      const auto& rel = reliefs[oi];
      const double W = tx.levels[0].width, H = tx.levels[0].height;
      double acc[4] = {0, 0, 0, 0}, wsum = 0;
      for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
          const uint64_t key = ((uint64_t(y) * uint64_t(w) + uint64_t(x)) * uint64_t(n) + uint64_t(j)) * uint64_t(n) + uint64_t(i);
          const double ox = ((i + jitter(2 * key)) / n - 0.5) * span;
          const double oy = ((j + jitter(2 * key + 1)) / n - 0.5) * span;
          double wt = 1;
          if (gauss) {
            const double r2 = ox * ox + oy * oy;
            if (r2 >= 1) continue;
            wt = std::pow(1 - r2 / 2, 8);
          }
          // The surface seen at the pixel centre, extended past its triangle's edges: the
          // footprint every filter of the unit integrates (no geometric anti-aliasing).
          const long double X = x + ox, Y = y + oy;
          const long double q = k.g * X + k.h * Y + k.i;
          if (!(q > 0)) continue;  // beyond the horizon
          double u = static_cast<double>((k.a * X + k.b * Y + k.c) / q);
          double v = static_cast<double>((k.d * X + k.e * Y + k.f) / q);
          if (!std::isfinite(u) || !std::isfinite(v)) continue;
          if (rel) {
            double bs, br;
            relief::TangentView tv;
            const auto& tri = s.objects[oi].triangles[ti];
            if (barycentric(tris[oi][ti], u, v, &bs, &br) && relief::tangent_view(tri, s.camera.pos, bs, br, &tv)) {
              const auto hit = relief::exact_hit(rel->maps.depth, u / W, v / H, tv.x, tv.y, tv.z, rel->scale);
              u = hit.u * W;
              v = hit.v * H;
            }
          }
          if (const auto& pp = procs[oi]) {
            const auto pc = noise::proc_color_ref(*pp, noise::proc_value_ref(*pp, u, v, 0));
            for (size_t ch = 0; ch < 4; ++ch) acc[ch] += wt * pc[ch];
            wsum += wt;
            continue;
          }
          if (std::fabs(u) > 0x1p52 || std::fabs(v) > 0x1p52) continue;  // no integer texel
          const img::Rgba8 t = tx.fetch(0, static_cast<int64_t>(std::floor(u)), static_cast<int64_t>(std::floor(v)));
          acc[0] += wt * t.r, acc[1] += wt * t.g, acc[2] += wt * t.b, acc[3] += wt * t.a;
          wsum += wt;
        }
      }
      PixelRecord rec;
      rec.x = x, rec.y = y, rec.object = c.object;
      persp::eval_ref(k, x, y, &rec.u, &rec.v, &rec.lod);
      rec.lod = 0;
      rec.texels = n * n;
      auto to8 = [&](double a) { return static_cast<uint8_t>(std::clamp(std::lround(a / wsum), 0L, 255L)); };
      if (wsum > 0) {
        rec.color = {to8(acc[0]), to8(acc[1]), to8(acc[2]), to8(acc[3])};
      } else if (auto pp = procs[oi]) {  // every sample beyond the horizon: the field's mean
        pp->limit = true;
        const auto pc = noise::proc_color_ref(*pp, noise::proc_value_ref(*pp, 0, 0, INFINITY));
        wsum = 1;
        rec.color = {to8(pc[0]), to8(pc[1]), to8(pc[2]), to8(pc[3])};
      } else {
        rec.color = tx.levels.back().at(0, 0);  // every sample beyond the horizon: the texture mean
      }
      if (brdf::shade::RefIn si; shade.ref_in(rays, c.object, c.triangle, x, y, &si))
        rec.color = brdf::shade::ref(shade.model(c.object), si, rec.color);
      f.image.at(x, y) = rec.color;
      f.pixels.push_back(rec);
    }
  }
  if (opt.progress) std::fprintf(stderr, "\n");
  return f;
}

double psnr_covered(const Frame& a, const Frame& b, const std::function<bool(const PixelRecord&)>& keep) {
  double se = 0;
  size_t cnt = 0;
  for (const auto& p : a.pixels) {
    if (keep && !keep(p)) continue;
    const auto& c = a.image.at(p.x, p.y);
    const auto& d = b.image.at(p.x, p.y);
    const double e[3] = {double(c.r) - d.r, double(c.g) - d.g, double(c.b) - d.b};
    se += e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
    cnt += 3;
  }
  if (cnt == 0) return NAN;
  return se == 0 ? INFINITY : 10 * std::log10(255.0 * 255.0 * static_cast<double>(cnt) / se);
}

std::function<bool(const PixelRecord&)> relief_pixels(const scene::Scene& s) {
  std::vector<bool> rel;
  for (const auto& o : s.objects) rel.push_back(s.materials.at(o.material).relief.has_value());
  return [rel](const PixelRecord& p) { return p.object >= 0 && rel[static_cast<size_t>(p.object)]; };
}

}  // namespace tu::render
