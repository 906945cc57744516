// The C-model render engine: the bit-accurate pipeline B1 -> B2 -> filter per covered pixel.
#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>

#include "afvis/afvis.hpp"
#include "ellipse/ellipse_fx.hpp"
#include "ewa/ewa_cycles.hpp"
#include "ewa/ewa_fx.hpp"
#include "ewa/ewa_lanes.hpp"
#include "feline/feline_fx.hpp"
#include "pom/relief.hpp"
#include "texture/trilinear_lod.hpp"
#include "texunit/parallel.hpp"
#include "texunit/render.hpp"
#include "texunit/shading.hpp"

namespace tu::render {

namespace {
constexpr img::Rgba8 kBackground{0, 0, 80, 255};  // as render_ref

ewa::fx::Weights weights_of(scene::WeightSource w) {
  switch (w) {
    case scene::WeightSource::Formula: return ewa::fx::Weights::Formula;
    case scene::WeightSource::Table1d: return ewa::fx::Weights::Table1d;
    case scene::WeightSource::Table2d: return ewa::fx::Weights::Table2d;
  }
  return ewa::fx::Weights::Formula;
}

// Relief (docs/blocks/relief-appendix.md §9): B1's u, v codes are shifted by the material's method
// (relief::shift_texel_uv_fx, the step the RTL tu_relief_stage implements). The tangent-space
// view is the shader's float input, quantised to the unit's s16.14 (as render_ref).
// Returns the pixel's quantised view (nullopt: no view, no shift).
std::optional<pom::View> shift_relief_fx(const scene::Scene& s, const persp::RayCaster& rays, const scene::Relief& rel,
                                         const Cover& c, const relief::Maps& maps, const tex::Texture& tx, int x, int y,
                                         int64_t* u, int64_t* v, PixelRecord* rec) {
  relief::TangentView tv;
  if (!relief::pixel_view(rays, s, c.object, c.triangle, x, y, &tv)) return std::nullopt;  // no shift (as render_ref)
  const int lw = std::countr_zero(static_cast<unsigned>(tx.levels[0].width));
  const int lh = std::countr_zero(static_cast<unsigned>(tx.levels[0].height));
  const pom::View view = relief::quantise(tv, rel.scale);
  const auto r = relief::shift_texel_uv_fx(maps, *u, *v, lw, lh, view, rel.method, rel.layers);
  *u = r.u;
  *v = r.v;
  rec->relief_n = static_cast<int>(r.n);
  rec->relief_steps = static_cast<int>(r.steps);
  rec->relief_flags = r.flags;
  return view;
}

// AF with parallax visibility (docs/blocks/afvis.md): the EWA walk over the texels the eye sees.
afvis::Relief afvis_relief(const relief::Maps& maps, const img::Gray8* trace_map, const tex::Texture& tx,
                           const pom::View& view, int bias) {
  const pom::Parallax p = pom::parallax(view);
  const img::Gray8& cells = trace_map ? *trace_map : maps.depth;
  return {&maps.depth, trace_map, afvis::min_depth(cells), p.pu, p.pv,
          std::countr_zero(static_cast<unsigned>(tx.levels[0].width)),
          std::countr_zero(static_cast<unsigned>(tx.levels[0].height)), bias};
}
}  // namespace

namespace {
// A built-in texture (checkerboard, bricks: a pure function of its spec) is built once per process
// and copied for each render (a copy is ~50x cheaper than the build and its mip pyramid); PNG
// textures are read each time. The key holds every field the build reads, the source included
// (the texture's name names it).
tex::Texture texture_of(const scene::Scene& s, const std::string& name) {
  const auto it = s.textures.find(name);
  if (it == s.textures.end() || it->second.builtin.empty()) return scene::build_texture(s, name);
  const scene::TextureSpec& t = it->second;
  const auto& a = t.addressing;
  const std::string key = s.source + '\n' + name + '\n' + t.builtin + ' ' + std::to_string(t.size) + ' ' +
                          std::to_string(t.cells) + ' ' + std::to_string(int(a.u)) + ' ' + std::to_string(int(a.v)) + ' ' +
                          std::to_string(a.border.r) + ' ' + std::to_string(a.border.g) + ' ' + std::to_string(a.border.b) +
                          ' ' + std::to_string(a.border.a) + ' ' + std::to_string(t.format) + ' ' + std::to_string(t.srgb) + ' ' +
                          std::to_string(t.mip_filter);
  static std::mutex mu;
  static std::map<std::string, std::shared_ptr<const tex::Texture>> cache;
  {
    const std::lock_guard<std::mutex> lock(mu);
    if (const auto c = cache.find(key); c != cache.end()) return *c->second;
  }
  auto built = std::make_shared<const tex::Texture>(scene::build_texture(s, name));
  const std::lock_guard<std::mutex> lock(mu);
  return *cache.emplace(key, std::move(built)).first->second;
}
}  // namespace

ewa::Engine engine_of(scene::Filter f) {
  switch (f) {
    case scene::Filter::Nearest: return ewa::Engine::Nearest;
    case scene::Filter::Bilinear: return ewa::Engine::Bilinear;
    case scene::Filter::Trilinear: return ewa::Engine::Trilinear;
    case scene::Filter::Ewa: return ewa::Engine::Ewa;
    case scene::Filter::Feline: return ewa::Engine::Feline;
  }
  return ewa::Engine::Ewa;
}

namespace {
// Rebase periods of an object's uv along u and v (persp::rebase_offset), level-0 texels: along a
// repeat axis the pyramid's longest side 2^max(lw, lh) (a whole number of repeats at every mip
// level, so the address of every texel of every level is unchanged), along a mirror axis twice that
// (mirror repeats every other repeat); none (0) along clamp, border and mirror_once axes (their
// address rule is not periodic), nor for a procedural material (its noise lattice has its own
// period in cells) or a relief one (the march discards uv outside [0, 1]). `why` says which.
std::array<double, 2> uv_periods(const scene::Scene& s, size_t object, int tex_w, int tex_h, std::string why[2]) {
  const scene::Material& m = s.materials.at(s.objects.at(object).material);
  const tex::Addressing& a = s.textures.at(m.texture).addressing;
  const double side = std::max(std::bit_ceil(unsigned(std::max(tex_w, 1))), std::bit_ceil(unsigned(std::max(tex_h, 1))));
  std::array<double, 2> p{0, 0};
  for (int k = 0; k < 2; ++k) {
    const tex::Wrap w = k ? a.v : a.u;
    if (m.procedural) why[k] = "a procedural material keeps its uv (the noise lattice has its own period)";
    else if (m.relief) why[k] = "a relief material keeps its uv (the march discards uv outside [0, 1])";
    else if (w == tex::Wrap::Repeat) p[k] = side;
    else if (w == tex::Wrap::Mirror) p[k] = 2 * side;
    else why[k] = std::string("wrap mode '") + scene::kWrapNames[int(w)] + "' is not periodic";
  }
  return p;
}

// Why a rebased triangle `t` (texels) with float coefficients `k` does not fit B1's formats: the
// reason appended to the SetupError (docs/scene-format.md "B1 set-up limits").
std::string setup_reason(const persp::Triangle& t, const persp::Coef9& k, const std::array<double, 2>& period,
                         const std::string why[2]) {
  const double lim = persp::kRebaseFrom;
  for (int a = 0; a < 2; ++a) {
    double lo = INFINITY, hi = -INFINITY, big = 0;
    for (const auto& v : t.v) lo = std::min(lo, v.uv[a]), hi = std::max(hi, v.uv[a]), big = std::max(big, std::fabs(v.uv[a]));
    if (big < lim) continue;
    const std::string axis = a ? "v" : "u";
    char buf[96];
    std::snprintf(buf, sizeof buf, "%.0f texels", big);
    if (!(period[a] > 0))
      return "; its |" + axis + "| reaches " + buf + ", B1 holds |" + axis + " q| < 8192 texels (q = 1 at the nearest vertex) and " +
             why[a] + ": keep |" + axis + "| x the texture's size below 8192 texels";
    std::snprintf(buf, sizeof buf, "%.0f texels", hi - lo);
    return "; its " + axis + " spans " + buf + ", more than B1's |" + axis +
           " q| < 8192 texels hold even after rebasing by whole repeats: split the triangle";
  }
  const double grad = std::max({std::fabs(k.a), std::fabs(k.b), std::fabs(k.d), std::fabs(k.e)});
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.0f", grad);
  if (!(std::fabs(k.g) < 8 && std::fabs(k.h) < 8 && std::fabs(k.i) < 8))
    return "; q = z_near / z extrapolated to pixel (0, 0) of the screen leaves B1's range (|q| < 8): the plane is seen "
           "too obliquely away from the screen origin";
  if (!(grad < lim))
    return std::string("; its uv changes by ") + buf + " texels per pixel, beyond B1's 8192: use a smaller texture";
  if (!(std::fabs(k.c) < lim && std::fabs(k.f) < lim))
    return std::string("; B1 evaluates the map from pixel (0, 0) of the screen and its uv changes by up to ") + buf +
           " texels per pixel (a far or strongly minified triangle on a large texture), too fast for the map extrapolated "
           "to the screen origin to stay within 8192 texels: use a smaller texture or bring the triangle nearer";
  return "; p = uv q and q at the corners of the triangle's screen rectangle must stay within 8192 texels and 8 "
         "(q = 1 at the nearest vertex; more where the triangle comes nearer than camera.z_near)";
}

// B1's set-up of one (rebased) triangle: the quantised coefficients, after checking the
// accumulators at every pixel the triangle can cover (its screen rectangle, or the whole screen
// when a vertex is not in front of the eye): p and q are affine in x, y, so the rectangle's
// corners bound every span end the unit's per-scanline set-up checks. SetupError with the reason.
persp::Unit::Coefs setup_one(const persp::Camera& cam, const persp::RayCaster& rays, const persp::Triangle& r,
                             const std::array<double, 2>& period, const std::string why[2]) {
  const persp::Coef9 k = persp::coefficients(cam, r);
  try {
    const persp::Unit::Coefs c = persp::Unit::quantise(k, r.name);
    int x0 = 0, x1 = cam.width - 1, y0 = 0, y1 = cam.height - 1;
    if (!rays.bounds(r, &x0, &x1, &y0, &y1)) x0 = 0, x1 = cam.width - 1, y0 = 0, y1 = cam.height - 1;
    if (x0 <= x1 && y0 <= y1)
      for (int y : {y0, y1}) (void)persp::Unit::setup(c, y, x0, x1, r.name);
    return c;
  } catch (const persp::SetupError& e) {
    throw persp::SetupError(e.what() + setup_reason(r, k, period, why));
  }
}
}  // namespace

std::vector<persp::Unit::Coefs> setup_fx(const scene::Scene& s, size_t object, int tex_w, int tex_h) {
  std::string why[2];
  const auto period = uv_periods(s, object, tex_w, tex_h, why);
  const persp::RayCaster rays(s.camera);
  std::vector<persp::Unit::Coefs> out;
  for (const auto& t : scene::in_texels(s.objects.at(object), tex_w, tex_h)) {
    try {
      const persp::Triangle r = persp::rebased(t, period);
      try {
        out.push_back(setup_one(s.camera, rays, r, period, why));
      } catch (const persp::SetupError&) {
        // A triangle whose map leaves B1's range as given (extrapolated to pixel (0, 0) or to its
        // rectangle's corners) although its uv stays below kRebaseFrom: rebased if that changes it.
        const persp::Triangle f = persp::rebased(t, period, true);
        if (persp::rebase_offset(r, period, true) == std::array<double, 2>{0, 0}) throw;
        out.push_back(setup_one(s.camera, rays, f, period, why));
      }
    } catch (const persp::SetupError& e) {
      throw persp::SetupError(scene::object_where(s, object) + ": " + e.what());
    }
  }
  return out;
}

uint32_t laniso_code(double max_aniso) {
  const double l = std::round(std::ldexp(std::log2(std::max(1.0, max_aniso)), fmt::kEllLogF));
  return static_cast<uint32_t>(std::min(l, std::ldexp(1.0, fmt::kEllAnisoW) - 1));
}

tex::LodParams lod_params(const scene::Material& m) {
  return tex::lod_params(m.lod_bias, m.min_lod, m.max_lod, m.base_level, m.max_level);
}

Frame render_cmodel(const scene::Scene& s, std::optional<scene::Filter> filter, const CmodelOptions& opt) {
  const int w = s.camera.width, h = s.camera.height;
  Frame f;
  f.image = img::Rgba8Image(w, h, kBackground);
  const auto cov = visibility(s, opt.uv_shift ? 1 : opt.threads);
  std::vector<tex::Texture> texs;
  std::vector<std::vector<persp::Unit::Coefs>> coefs;
  for (size_t o = 0; o < s.objects.size(); ++o) {
    texs.push_back(texture_of(s, s.materials.at(s.objects[o].material).texture));
    coefs.push_back(setup_fx(s, o, texs.back().levels[0].width, texs.back().levels[0].height));
  }
  std::vector<std::optional<relief::Maps>> reliefs;  // per object with relief and opt.relief
  for (const auto& o : s.objects)
    reliefs.push_back(opt.relief && s.materials.at(o.material).relief
                          ? std::optional(relief::make_maps(s, o.material))
                          : std::nullopt);
  // Per object with af_visibility: the trace's cells (the depth map, or its min-depth pyramid level).
  std::vector<std::optional<img::Gray8>> afv_cells(s.objects.size());
  for (size_t o = 0; o < s.objects.size(); ++o)
    if (reliefs[o] && opt.afvis != AfvisMode::Off && (opt.afvis == AfvisMode::On || s.materials.at(s.objects[o].material).relief->af_visibility))
      afv_cells[o] = afvis::min_depth_pyramid(reliefs[o]->depth, opt.afvis_pyramid);
  const auto mats = object_materials(s);
  // Per object and triangle, what every pixel of it shares: B2's laniso, the sampler state, det3.
  struct ObjConst {
    uint32_t laniso;
    tex::LodParams lp;
    std::vector<ellipse::fx::Det3> det;
  };
  std::vector<ObjConst> oc;
  for (size_t o = 0; o < s.objects.size(); ++o) {
    oc.push_back({laniso_code(mats[o]->max_aniso), lod_params(*mats[o]), {}});
    for (const auto& k : coefs[o]) oc.back().det.push_back(ellipse::fx::det3(k));
  }
  std::vector<uint64_t> tex_base;  // per object: its texture's trace base (texel-cache model)
  for (const auto& o : s.objects)
    tex_base.push_back(uint64_t(std::distance(s.textures.begin(), s.textures.find(s.materials.at(o.material).texture))) << 32);
  std::vector<std::optional<noise::ProcCodes>> procs;  // per procedural object: the unit's constants
  for (const auto& p : procedural_objects(s, texs))
    procs.push_back(opt.procedural && p ? std::optional(noise::quantise(*p)) : std::nullopt);
  const persp::RayCaster rays(s.camera);
  const shading::Setup shade(s, opt.shade_model.value_or(shading::kUnitModel));
  // The shading stage after the filter (brdf::shade::eval): every covered pixel of a lit scene.
  auto shaded = [&](const Cover& c, int x, int y, img::Rgba8 t) {
    if (!shade.active()) return t;
    return brdf::shade::eval(shade.model(c.object), shade.fx_in(rays, c.object, c.triangle, x, y), t).rgba;
  };
  // Rows on opt.threads threads, each into its own list, joined in row order. The uv_shift hook
  // may keep state (its call order is part of its contract): one thread then.
  std::vector<std::vector<PixelRecord>> rows(static_cast<size_t>(h));
  std::atomic<int> rows_done{0};
  par::for_each_index(h, opt.uv_shift ? 1 : opt.threads, [&](int y) {
    auto& pixels = rows[static_cast<size_t>(y)];
    size_t n_row = 0;
    for (int x = 0; x < w; ++x) n_row += cov[static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x)].object >= 0;
    pixels.reserve(n_row);
    for (int x = 0; x < w; ++x) {
      const Cover c = cov[static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x)];
      if (c.object < 0) continue;
      const auto& m = *mats[static_cast<size_t>(c.object)];
      const auto& tx = texs[static_cast<size_t>(c.object)];
      const auto& k = coefs[static_cast<size_t>(c.object)][static_cast<size_t>(c.triangle)];
      const ObjConst& ok = oc[static_cast<size_t>(c.object)];
      const int top = tx.num_levels() - 1;
      // B1: u, v codes; B2: footprint on the same quantised coefficients (and accumulators).
      const persp::Unit::Acc acc = persp::Unit::direct(k, x, y);
      const persp::Pixel px = persp::Unit::pixel(acc);
      ewa::fx::In in;
      in.u = px.u;
      in.v = px.v;
      PixelRecord rec;
      std::optional<pom::View> view;
      if (const auto& maps = reliefs[static_cast<size_t>(c.object)]; maps && !px.flag)
        view = shift_relief_fx(s, rays, *m.relief, c, *maps, tx, x, y, &in.u, &in.v, &rec);
      if (opt.uv_shift) opt.uv_shift(x, y, c.object, &in.u, &in.v);
      in.b2 = ellipse::fx::pixel(k, acc, ok.det[static_cast<size_t>(c.triangle)], ok.laniso, static_cast<uint32_t>(top),
                                 s.footprint == scene::Footprint::Recurrence);
      rec.x = x, rec.y = y, rec.object = c.object;
      // u, v in texels: times 2^-TexUvF, exact (as std::ldexp, without its call per pixel).
      constexpr double kUvLsb = 1.0 / double(int64_t(1) << fmt::kTexUvF);
      rec.u = double(in.u) * kUvLsb;
      rec.v = double(in.v) * kUvLsb;
      rec.b2_flags = in.b2.flags;
      if (const auto& pc = procs[static_cast<size_t>(c.object)]) {
        // The noise unit at B1's (u, v) with B2's lrho; beyond the B1 guard the footprint spans
        // every octave: all weights 0, the field's mean.
        rec.color = shaded(c, x, y, noise::proc_color_fx(*pc, noise::proc_value_fx(*pc, in.u, in.v, px.flag ? noise::kNoFootprint : in.b2.lrho)));
        rec.texels = 0;
        f.image.at(x, y) = rec.color;
        pixels.push_back(rec);
        continue;
      }
      if (px.flag) {
        // B1 guard (q < 2^-PerspGuardLog2, beyond 1024x the unit distance): no texture
        // coordinates. The footprint there spans the texture: its mean, the 1x1 top level.
        rec.color = tx.levels.back().at(0, 0);
        rec.lod = top;
        rec.texels = 1;
        rec.color = shaded(c, x, y, rec.color);
        f.image.at(x, y) = rec.color;
        pixels.push_back(rec);
        continue;
      }
      std::optional<tex::TexelTrace> trace;
      if (opt.trace_texels) trace.emplace(&rec.texel_addrs, tex_base[static_cast<size_t>(c.object)]);
      const tex::LodParams& lp = ok.lp;
      switch (filter.value_or(m.filter)) {
        case scene::Filter::Nearest:  // GL NEAREST / LINEAR: the base level
          rec.color = tex::nearest(tx, tex::level_range(lp, top).base, in.u, in.v);
          rec.texels = 1;
          break;
        case scene::Filter::Bilinear:
          rec.color = tex::bilinear(tx, tex::level_range(lp, top).base, in.u, in.v);
          rec.texels = 4;
          break;
        case scene::Filter::Trilinear: {
          // The GL rule on B2's log2 rho: the blend position between levels floor(lod) and + 1.
          const auto tl = tex::trilinear_lod(in.b2.lrho, lp, top);
          rec.lod = std::ldexp(double(tl.lod), -fmt::kTexLodF);
          rec.tri_flags = tl.flags;
          rec.color = tex::trilinear(tx, tl.lod, in.u, in.v);
          rec.texels = 8;
          break;
        }
        case scene::Filter::Feline: {
          const auto r = feline::fx::filter(in, tx, {m.feline_max_probes, lp});
          rec.color = r.color;
          rec.lod = std::ldexp(double(r.lod), -fmt::kTexLodF);
          rec.tri_flags = r.tri_flags;
          rec.texels = r.texels;
          rec.probes = r.probes;
          break;
        }
        case scene::Filter::Ewa: {
          // The EWA's level: the sampler's rule on B2's clamped minor axis (tu_ellipse elod_o).
          in.b2.lod = tex::trilinear_lod(in.b2.lmin, lp, top).lod;
          const ewa::fx::Config ecfg{weights_of(opt.weights.value_or(m.weights)), ewa::kDefaultMaxTexels,
                                     m.clip.empty() ? nullptr : &clip::variant(m.clip)};
          ewa::fx::Out r;
          if (const auto& cells = afv_cells[static_cast<size_t>(c.object)]; cells && view) {
            const auto& maps = *reliefs[static_cast<size_t>(c.object)];
            const auto a = afvis::filter(in, tx, {ecfg, opt.afvis_rule},
                                         afvis_relief(maps, opt.afvis_pyramid > 0 ? &*cells : nullptr, tx, *view, opt.afvis_bias));
            r = a.ewa;
            rec.afv_traced = static_cast<int>(a.traced);
            rec.afv_steps = static_cast<int>(a.steps);
            rec.afv_visible = static_cast<int>(a.visible);
            rec.afv_clocks = a.clocks;
          } else {
            r = ewa::fx::filter_lanes(in, tx, ecfg, opt.ewa_lanes);
          }
          rec.color = r.color;
          rec.lod = r.level;
          rec.texels = static_cast<int>(r.texels_visited);
          rec.texels_inside = static_cast<int>(r.texels_inside);
          rec.ewa_flags = r.flags;
          rec.levels = ewa::pixel_cost(in, r.level, r.flags, r.texels_visited, top).levels;
          rec.ewa_blocks = static_cast<int>(r.lane_blocks);
          break;
        }
      }
      trace.reset();
      rec.color = shaded(c, x, y, rec.color);
      f.image.at(x, y) = rec.color;
      pixels.push_back(std::move(rec));
    }
    if (const int done = ++rows_done; opt.progress && (done % 8 == 0 || done == h))
      std::fprintf(stderr, "\rC-model render %3d%%", done * 100 / h);
  });
  f.pixels = par::concat(std::move(rows));
  if (opt.progress) std::fprintf(stderr, "\n");
  return f;
}

}  // namespace tu::render
