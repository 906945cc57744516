#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <ostream>
#include <limits>
#include <stdexcept>

#include "afvis/afvis_ref.hpp"
#include "ellipse/ellipse_fx.hpp"
#include "ewa/ewa_fx.hpp"
#include "ewa/ewa_ref.hpp"
#include "feline/feline_ref.hpp"
#include "pom/pom_layers.hpp"
#include "pom/relief.hpp"
#include "texture/trilinear_lod.hpp"
#include "texunit/parallel.hpp"
#include "texunit/render.hpp"
#include "texunit/shading.hpp"
#include "texunit/convert.hpp"
#include "texunit/output.hpp"

namespace tu::render {

namespace {
constexpr img::Rgba8 kBackground{0, 0, 80, 255};

uint8_t to8(double x) { return static_cast<uint8_t>(std::clamp<int64_t>(round_i64(x), 0, 255)); }
img::Rgba8 to8(const tex::RgbaF& c) { return {to8(c.r), to8(c.g), to8(c.b), to8(c.a)}; }

// Relief: (u, v) (level-0 texels) shifted by the 256-layer exact march in the tangent frame of
// the covered triangle; the footprint (ellipse) stays that of the unshifted surface. Records N of
// the material's method (the layer-count debug image).
// Returns the pixel's tangent-space view (nullopt: none, no shift).
std::optional<relief::TangentView> shift_relief(const scene::Scene& s, const persp::RayCaster& rays, const scene::Relief& rel,
                                                const Cover& c, const relief::Maps& maps, const tex::Texture& tx, int x, int y,
                                                double* u, double* v, PixelRecord* rec) {
  relief::TangentView tv;
  if (!relief::pixel_view(rays, s, c.object, c.triangle, x, y, &tv)) return std::nullopt;
  const double W = tx.levels[0].width, H = tx.levels[0].height, one = std::ldexp(1.0, fmt::kPomUvF);
  rec->relief_n = static_cast<int>(relief::layers_at(maps, round_i64(*u / W * one), round_i64(*v / H * one),
                                                     relief::quantise(tv, rel.scale), rel.method, rel.layers));
  const auto r = relief::shift_uv_ref(maps, *u / W, *v / H, tv, rel.scale);
  *u = r.u * W;
  *v = r.v * H;
  return tv;
}
}  // namespace

std::vector<persp::Coef9> setup_ref(const scene::Scene& s, size_t object, int tex_w, int tex_h) {
  std::vector<persp::Coef9> k;
  try {
    for (const auto& t : scene::in_texels(s.objects.at(object), tex_w, tex_h))
      k.push_back(persp::coefficients(s.camera, t));
  } catch (const persp::SetupError& e) {
    throw persp::SetupError(scene::object_where(s, object) + ": " + e.what());
  }
  return k;
}

std::vector<Cover> visibility(const scene::Scene& s, int threads) {
  const int w = s.camera.width, h = s.camera.height;
  std::vector<Cover> cov(static_cast<size_t>(w) * static_cast<size_t>(h));
  std::vector<double> depth(cov.size(), std::numeric_limits<double>::infinity());
  const persp::RayCaster rays(s.camera);
  struct Box {
    int object, triangle, x0, x1, y0, y1;  // only the pixels the triangle can cover
  };
  std::vector<Box> boxes;
  for (size_t o = 0; o < s.objects.size(); ++o)
    for (size_t t = 0; t < s.objects[o].triangles.size(); ++t) {
      Box b{static_cast<int>(o), static_cast<int>(t), 0, w - 1, 0, h - 1};
      if (!rays.bounds(s.objects[o].triangles[t], &b.x0, &b.x1, &b.y0, &b.y1))
        b = {b.object, b.triangle, 0, w - 1, 0, h - 1};
      boxes.push_back(b);
    }
  // Rows are independent; within a pixel the triangles keep the scene's order (ties: first).
  par::for_each_index(h, threads, [&](int y) {
    // The row's rays once (RayCaster::dir), shared by every triangle (hit_dir: hit's bits).
    std::vector<double> dirs;
    for (const Box& b : boxes) {
      if (y < b.y0 || y > b.y1) continue;
      if (dirs.empty()) {
        dirs.resize(3 * static_cast<size_t>(w));
        for (int x = 0; x < w; ++x) rays.dir(x, y, &dirs[3 * static_cast<size_t>(x)]);
      }
      const auto& tri = s.objects[static_cast<size_t>(b.object)].triangles[static_cast<size_t>(b.triangle)];
      for (int x = b.x0; x <= b.x1; ++x) {
        persp::Hit hit;
        if (!rays.hit_dir(tri, &dirs[3 * static_cast<size_t>(x)], &hit)) continue;
        if (hit.s < 0 || hit.r < 0 || hit.s + hit.r > 1) continue;
        const size_t i = static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x);
        if (hit.dist < depth[i]) {
          depth[i] = hit.dist;
          cov[i] = {b.object, b.triangle};
        }
      }
    }
  });
  return cov;
}

std::vector<CoverRun> cover_runs(const std::vector<Cover>& cov, int width) {
  std::vector<CoverRun> runs;
  const auto w = static_cast<size_t>(width);
  for (size_t row = 0; w > 0 && row < cov.size() / w; ++row) {
    const Cover* line = cov.data() + row * w;
    for (size_t x = 0; x < w;) {
      const Cover c = line[x];
      size_t x1 = x;
      while (x1 + 1 < w && line[x1 + 1].object == c.object && line[x1 + 1].triangle == c.triangle) ++x1;
      if (c.object >= 0)
        runs.push_back({static_cast<int>(row), static_cast<int>(x), static_cast<int>(x1), c});
      x = x1 + 1;
    }
  }
  return runs;
}

size_t covered(const std::vector<Cover>& cov) {
  return static_cast<size_t>(std::count_if(cov.begin(), cov.end(), [](const Cover& c) { return c.object >= 0; }));
}

std::vector<const scene::Material*> object_materials(const scene::Scene& s) {
  std::vector<const scene::Material*> m;
  for (const auto& o : s.objects) m.push_back(&s.materials.at(o.material));
  return m;
}

Frame render_ref(const scene::Scene& s, std::optional<scene::Filter> filter, std::optional<brdf::Model> shade_model) {
  const int w = s.camera.width, h = s.camera.height;
  Frame f;
  f.image = img::Rgba8Image(w, h, kBackground);
  const auto cov = visibility(s);
  // Per object: texture and per-triangle coefficients.
  std::vector<tex::Texture> texs;
  std::vector<std::vector<persp::Coef9>> coefs;
  for (size_t o = 0; o < s.objects.size(); ++o) {
    texs.push_back(scene::build_texture(s, s.materials.at(s.objects[o].material).texture));
    coefs.push_back(setup_ref(s, o, texs.back().levels[0].width, texs.back().levels[0].height));
    // What B1 cannot set up is refused here too: every engine renders the same scenes.
    (void)setup_fx(s, o, texs.back().levels[0].width, texs.back().levels[0].height);
  }
  // Per object with relief: depth / complexity maps (docs/blocks/relief-appendix.md §9).
  std::vector<std::optional<relief::Maps>> reliefs;
  for (const auto& o : s.objects)
    reliefs.push_back(s.materials.at(o.material).relief ? std::optional(relief::make_maps(s, o.material))
                                                        : std::nullopt);
  const auto mats = object_materials(s);
  const auto procs = procedural_objects(s, texs);
  const persp::RayCaster rays(s.camera);
  const shading::Setup shade(s, shade_model.value_or(shading::kUnitModel));
  f.pixels.reserve(covered(cov));
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const Cover c = cov[static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x)];
      if (c.object < 0) continue;
      const auto& m = *mats[static_cast<size_t>(c.object)];
      const auto& tx = texs[static_cast<size_t>(c.object)];
      const persp::Coef9& k = coefs[static_cast<size_t>(c.object)][static_cast<size_t>(c.triangle)];
      double u, v, q;
      persp::eval_ref(k, x, y, &u, &v, &q);
      PixelRecord rec;
      std::optional<relief::TangentView> tv;
      if (const auto& maps = reliefs[static_cast<size_t>(c.object)]) tv = shift_relief(s, rays, *m.relief, c, *maps, tx, x, y, &u, &v, &rec);
      rec.x = x, rec.y = y, rec.object = c.object, rec.u = u, rec.v = v;
      const auto j = ellipse::analytic(k, x, y);
      const ellipse::FootprintParams fp{m.max_aniso, static_cast<double>(tx.num_levels() - 1)};
      const auto foot = ellipse::footprint(j, fp);
      rec.aniso = foot.aniso;
      rec.footprint_lod = foot.lod;
      if (const auto& pp = procs[static_cast<size_t>(c.object)]) {
        rec.color = procedural_ref(*pp, u, v, j);  // the noise instead of a texture fetch, then the shading
        if (brdf::shade::RefIn si; shade.ref_in(rays, c.object, c.triangle, x, y, &si))
          rec.color = brdf::shade::ref(shade.model(c.object), si, rec.color);
        f.image.at(x, y) = rec.color;
        f.pixels.push_back(rec);
        continue;
      }
      const tex::LevelRange lv = tex::level_range(m.base_level, m.max_level, tx.num_levels() - 1);
      switch (filter.value_or(m.filter)) {
        case scene::Filter::Nearest:  // GL NEAREST / LINEAR: the base level
          rec.color = tx.fetch(lv.base, floor_i64(std::ldexp(u, -lv.base)), floor_i64(std::ldexp(v, -lv.base)));
          rec.texels = 1;
          break;
        case scene::Filter::Bilinear:
          rec.color = to8(tex::bilinear_ref(tx, lv.base, u, v));
          rec.texels = 4;
          break;
        case scene::Filter::Trilinear:
          rec.lod = tex::trilinear_lod_ref(j.ux, j.vx, j.uy, j.vy, m.lod_bias, m.min_lod, m.max_lod,
                                           tx.num_levels() - 1, &rec.tri_flags, m.base_level, m.max_level);
          rec.color = to8(tex::trilinear_ref(tx, rec.lod, u, v));
          rec.texels = 8;
          break;
        case scene::Filter::Feline: {
          const auto r = feline::filter_ref(tx, u, v, j, {m.feline_max_probes, m.max_aniso, m.lod_bias, m.min_lod, m.max_lod,
                                                           m.base_level, m.max_level});
          rec.color = to8(r.color);
          rec.lod = r.lod;
          rec.tri_flags = r.tri_flags;
          rec.texels = r.texels;
          rec.probes = r.probes;
          break;
        }
        case scene::Filter::Ewa: {
          ewa::Params ep{m.max_aniso, ewa::kDefaultMaxTexels, !m.clip.empty(), m.lod_bias, m.min_lod, m.max_lod,
                          m.base_level, m.max_level};
          if (tv && m.relief->af_visibility) {  // the visible texels only (docs/blocks/afvis.md)
            const auto& maps = *reliefs[static_cast<size_t>(c.object)];
            const auto p = afvis::parallax_ref(tv->x, tv->y, tv->z, m.relief->scale);
            ep = afvis::with_visibility(ep, {&maps.depth, nullptr, afvis::min_depth(maps.depth), p.pu, p.pv,
                                             std::countr_zero(static_cast<unsigned>(tx.levels[0].width)),
                                             std::countr_zero(static_cast<unsigned>(tx.levels[0].height))});
          }
          const auto r = ewa::filter_ref(tx, u, v, j, ep);
          rec.color = to8(r.color);
          rec.lod = r.level;
          rec.texels = r.texels_visited;
          break;
        }
      }
      if (brdf::shade::RefIn si; shade.ref_in(rays, c.object, c.triangle, x, y, &si))
        rec.color = brdf::shade::ref(shade.model(c.object), si, rec.color);
      f.image.at(x, y) = rec.color;
      f.pixels.push_back(rec);
    }
  }
  return f;
}

std::optional<img::Gray8> layers_image(const scene::Scene& s, const Frame& f) {
  std::vector<int> nmax;  // per object: Nmax of adaptive relief, 0 otherwise
  for (const auto& o : s.objects) {
    const auto& rel = s.materials.at(o.material).relief;
    nmax.push_back(rel && rel->method == scene::ReliefMethod::PomAdaptive ? std::clamp(rel->layers, 1, 63) : 0);
  }
  if (std::all_of(nmax.begin(), nmax.end(), [](int n) { return n == 0; })) return std::nullopt;
  img::Gray8 g(f.image.width, f.image.height);
  for (const auto& p : f.pixels) {
    const int n = nmax[static_cast<size_t>(p.object)], lo = static_cast<int>(pom::kDefaultNmin);
    if (n > 0 && p.relief_n > 0) g.at(p.x, p.y) = to8(n > lo ? 255.0 * (p.relief_n - lo) / (n - lo) : 255.0);
  }
  return g;
}

img::Rgba8Image error_heatmap(const img::Rgba8Image& a, const img::Rgba8Image& b, int full_scale) {
  if (a.width != b.width || a.height != b.height)
    throw std::invalid_argument("error_heatmap: images differ in size");
  img::Rgba8Image out(a.width, a.height);
  for (size_t i = 0; i < a.px.size(); ++i) {
    const int d = std::max({std::abs(a.px[i].r - b.px[i].r), std::abs(a.px[i].g - b.px[i].g),
                            std::abs(a.px[i].b - b.px[i].b)});
    const double t = std::min(1.0, static_cast<double>(d) / std::max(1, full_scale));
    out.px[i] = d == 0 ? img::Rgba8{0, 0, 0, 255}
                       : img::Rgba8{to8(255 * t), to8(64 * (1 - t)), to8(255 * (1 - t)), 255};
  }
  return out;
}

const std::vector<PixelFlag>& pixel_flags() {
  using R = PixelRecord;
  static const std::vector<PixelFlag> flags = {
      {"b1_guard", &R::b2_flags, ellipse::fx::kHorizon},
      {"b2_degenerate", &R::b2_flags, ellipse::fx::kDegenerate},
      {"b2_aniso_clamp", &R::b2_flags, ellipse::fx::kAnisoClamp},
      {"b2_lod_sat", &R::b2_flags, ellipse::fx::kLodSat},
      {"b2_magnify", &R::b2_flags, ellipse::fx::kMagnify},
      {"tri_magnify", &R::tri_flags, tex::kTriMagnify},
      {"tri_lod_clamp", &R::tri_flags, tex::kTriLodClamp},
      {"tri_lod_sat", &R::tri_flags, tex::kTriLodSat},
      {"ewa_unit_disc", &R::ewa_flags, ewa::fx::kUnitDisc},
      {"ewa_axis_clamp", &R::ewa_flags, ewa::fx::kAxisClamp},
      {"ewa_lod_sat", &R::ewa_flags, ewa::fx::kLodSat},
      {"ewa_texel_cap", &R::ewa_flags, ewa::fx::kCapped},
      {"ewa_no_weight", &R::ewa_flags, ewa::fx::kNoWeight},
      {"relief_vz_guard", &R::relief_flags, relief::kReliefVzGuard},
      {"relief_nonconv", &R::relief_flags, relief::kReliefNonConv},
      {"relief_back", &R::relief_flags, relief::kReliefBack},
  };
  return flags;
}

std::vector<size_t> flag_counts(const Frame& f) {
  const auto& flags = pixel_flags();
  std::vector<size_t> n(flags.size(), 0);
  for (const auto& p : f.pixels)
    for (size_t i = 0; i < flags.size(); ++i) n[i] += flags[i].on(p);
  return n;
}

void write_dump_csv(std::ostream& out, const Frame& f) {
  const auto& flags = pixel_flags();
  out << "x,y,u,v,lod,texels,r,g,b,a,relief_n,relief_steps";
  for (const auto& fl : flags) out << ',' << fl.name;
  out << '\n';
  char buf[160];
  for (const auto& p : f.pixels) {
    std::snprintf(buf, sizeof buf, "%d,%d,%.6f,%.6f,%.4f,%d,%d,%d,%d,%d,%d,%d", p.x, p.y, p.u, p.v,
                  p.lod, p.texels, p.color.r, p.color.g, p.color.b, p.color.a, p.relief_n, p.relief_steps);
    out << buf;
    for (const auto& fl : flags) out << (fl.on(p) ? ",1" : ",0");
    out << '\n';
  }
}

void write_dump_csv(const std::string& path, const Frame& f) {
  out::write_atomic(path, [&](std::ostream& os) { write_dump_csv(os, f); });
}

}  // namespace tu::render
