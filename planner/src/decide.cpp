// decide(): the plan's decisions and measurements (plan.hpp); moved from tools/texunit/plan.cpp.
#include "planner/plan.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>

#include "brdf/brdf_error.hpp"
#include "brdf/brdf_shade.hpp"
#include "ewa/ewa_cycles.hpp"
#include "planner/formats.hpp"
#include "planner/pipeline.hpp"
#include "pom/relief.hpp"
#include "texture/texel_format.hpp"
#include "texunit/render.hpp"
#include "texunit/shading.hpp"
#include "texunit/texture_unit_model.hpp"
#include "texunit/scene.hpp"

namespace tu::plan {

void pick_relief(ReliefChoice& c, double min_psnr_db) {
  const ReliefCandidate* best = nullptr;
  for (const auto& k : c.cands)
    if (k.psnr_db >= min_psnr_db && (!best || k.cycles_per_px < best->cycles_per_px)) best = &k;
  c.meets = best != nullptr;
  if (!best)
    for (const auto& k : c.cands)
      if (!best || k.psnr_db > best->psnr_db) best = &k;
  if (best) c.chosen = best->method;
}

TextureNeeds texture_needs(const scene::Scene& s) {
  TextureNeeds n;
  // Wrap modes (tu_texel_addr): repeat always, another mode when a texture an object samples uses it.
  for (const auto& o : s.objects) {
    const auto& a = s.textures.at(s.materials.at(o.material).texture).addressing;
    n.wrap_modes |= 1 << static_cast<int>(a.u) | 1 << static_cast<int>(a.v);
  }
  for (int k = 0; k < 5; ++k)
    if (n.wrap_modes >> k & 1) n.wrap_names.push_back(scene::kWrapNames[k]);
  // Texel formats (tu_texel_decode): the formats and sRGB of the textures objects sample (rgba8,
  // the decode's default path, always); the port as wide as the widest of them.
  n.texel_w = 0;
  for (const auto& o : s.objects) {
    const auto& t = s.textures.at(s.materials.at(o.material).texture);
    if (t.format == static_cast<int>(tex::TexelFormat::Bc1)) {  // the block fetch (64-bit RAM words)
      n.bc1 = true;
      n.srgb = n.srgb || t.srgb;
      continue;
    }
    n.tex_formats |= 1 << t.format;
    n.srgb = n.srgb || t.srgb;
    n.texel_w = std::max(n.texel_w, tex::bits_per_texel(static_cast<tex::TexelFormat>(t.format)));
  }
  if (n.texel_w == 0) n.texel_w = 32;
  for (int k = 0; k < static_cast<int>(std::size(tex::kTexelFormatNames)); ++k)
    if (n.tex_formats >> k & 1) n.format_names.push_back(tex::kTexelFormatNames[k]);
  if (n.bc1) n.format_names.push_back(tex::format_name(tex::TexelFormat::Bc1));
  return n;
}

std::map<std::string, int> lod_histogram(const std::vector<double>& lod) {
  std::map<std::string, int> h;
  for (double l : lod) ++h[std::to_string(static_cast<int>(std::floor(l)))];
  return h;
}

std::map<std::string, int> aniso_histogram(const std::vector<double>& aniso) {
  std::map<std::string, int> h;
  for (double a : aniso) ++h[a < 2 ? "1-2" : a < 4 ? "2-4" : a < 8 ? "4-8" : a < 16 ? "8-16" : "16+"];
  return h;
}

Footprints footprints(const scene::Scene& s, const render::Frame& f) {
  Footprints fp;
  for (const auto& p : f.pixels) {
    fp.aniso.push_back(p.aniso);
    fp.lod.push_back(p.footprint_lod);
    const auto& m = s.materials.at(s.objects[static_cast<size_t>(p.object)].material);
    ++fp.material_pixels[m.name];
    if (m.relief) {
      fp.relief = true;
      fp.max_layers = std::max(fp.max_layers, m.relief->layers);
      const auto meth = m.relief->method;
      (meth == scene::ReliefMethod::Iterative                                                          ? fp.iterative
       : meth == scene::ReliefMethod::DistanceMap || meth == scene::ReliefMethod::DistanceMapRefined ? fp.distance_map
                                                                                                      : fp.pom) = true;
    }
  }
  return fp;
}

NoiseScheme choose_noise_scheme(double max_cycles, uint64_t pipelined, uint64_t serial, int cores) {
  NoiseScheme ns;
  ns.octave_serial = max_cycles > 0 && double(serial) <= max_cycles && cores > 1;
  ns.max_cycles = max_cycles > 0 ? max_cycles : 0;
  ns.pipelined_cycles = pipelined;
  ns.octave_serial_cycles = serial;
  ns.why = max_cycles <= 0                     ? "no cycle budget: the fastest"
           : ns.octave_serial                  ? "the octave-serial unit meets max_cycles with one core"
           : double(pipelined) <= max_cycles   ? "only the pipelined unit meets max_cycles"
                                               : "no scheme meets max_cycles: the fastest";
  return ns;
}

namespace {
// PSNR over a's covered pixels of the objects `keep` accepts (render::psnr_covered).
double psnr_objects(const render::Frame& a, const render::Frame& b, const std::function<bool(int object)>& keep) {
  return render::psnr_covered(a, b, [&](const render::PixelRecord& p) { return keep(p.object); });
}

double texels_per_pixel(const render::Frame& f) {
  double t = 0;
  for (const auto& p : f.pixels) t += p.texels;
  return f.pixels.empty() ? 0 : t / static_cast<double>(f.pixels.size());
}

// Relief method per material: each candidate method at the material's layers through the
// bit-accurate C-model render (bilinear, so the relief method is the only difference), its PSNR
// on the material's pixels against the float reference (the 256-layer exact march), its cost the
// relief stage's cycles per pixel of the material (relief::stage_cycles over its pixels in raster
// order: exact, = the RTL, ReliefStageCosim); the cheapest meeting min_psnr_db, else the best.
// distance_map_refined is a candidate only where the material authors it (its map takes tens of
// seconds to build on a 256-texel height; on the maps of docs/blocks/relief-appendix.md §13.6 it equals
// the classic one).
ReliefChoice choose_relief(const scene::Scene& s, const std::string& material, const render::Frame& ref) {
  const auto authored = s.materials.at(material).relief->method;
  ReliefChoice c{authored, authored, false, s.materials.at(material).relief->layers, {}};
  using M = scene::ReliefMethod;
  std::vector<M> methods = {M::PomFixed, M::PomAdaptive, M::Iterative, M::DistanceMap};
  if (authored == M::DistanceMapRefined) methods.push_back(M::DistanceMapRefined);
  auto mine = [&](const render::PixelRecord& p) {
    return s.objects[static_cast<size_t>(p.object)].material == material;
  };
  for (M m : methods) {
    scene::Scene t = s;
    t.materials.at(material).relief->method = m;
    ReliefCandidate k{m};
    if (m == M::DistanceMap || m == M::DistanceMapRefined) k.map_bytes = relief::make_maps(t, material).dist->bytes();
    const render::Frame f = render::render_cmodel(t, scene::Filter::Bilinear, render::CmodelOptions{});
    k.psnr_db = render::psnr_covered(f, ref, mine);
    std::vector<relief::StagePixel> px;
    double steps = 0;
    for (const auto& p : f.pixels)
      if (mine(p)) {
        px.push_back(relief::stage_pixel(p.relief_n > 0, static_cast<uint32_t>(p.relief_steps), m));
        steps += p.relief_steps;
      }
    const double n = static_cast<double>(std::max<size_t>(1, px.size()));
    k.cycles_per_px = static_cast<double>(relief::stage_cycles(px)) / n;
    k.steps_per_px = steps / n;
    c.cands.push_back(k);
  }
  pick_relief(c, s.budget.min_psnr_db);
  return c;
}

// The noise unit (docs/blocks/noise-appendix.md §5 "In the RTL texture unit"): in the unit when a material
// is procedural; 2-D cores unless a material moves through time (speed != 0); the fewest octave
// cores K whose C-model render (each material's octaves capped at K, C_K for the capped count)
// meets min_psnr_db against the float reference with every material's own octaves, over the
// procedural pixels (none meeting it: the largest octave count, the authored picture).
NoisePlan plan_noise(const scene::Scene& s) {
  NoisePlan p;
  int kmax = 0;
  for (const auto& [name, m] : s.materials)
    if (m.procedural) {
      p.materials.push_back(name);
      kmax = std::max(kmax, m.procedural->octaves);
      if (m.procedural->speed != 0) p.dims = 3;
      p.water = p.water || m.procedural->kind == scene::ProceduralKind::Water;
    }
  for (const auto& o : s.objects) {
    const auto& pr = s.materials.at(o.material).procedural;
    p.objects.push_back(pr.has_value());
    p.water_objects.push_back(pr && pr->kind == scene::ProceduralKind::Water);
  }
  if (p.materials.empty()) return p;
  p.on = true;
  const auto procedural = [&](int object) { return p.objects.at(static_cast<size_t>(object)); };
  const render::Frame ref = render::render_ref(s);
  for (int k = 1; k <= kmax; ++k) {
    scene::Scene t = s;
    for (auto& [name, m] : t.materials)
      if (m.procedural) m.procedural->octaves = std::min(k, m.procedural->octaves);
    const double db = psnr_objects(render::render_cmodel(t), ref, procedural);
    p.psnr_by_octaves[k] = db;
    if (p.cores == 0 && db >= s.budget.min_psnr_db) p.cores = k;
  }
  if (p.cores == 0) p.cores = kmax;
  return p;
}

// AF with parallax visibility (docs/blocks/afvis.md): tu_afvis is in the unit when a material asks
// for it (relief with af_visibility, the EWA filter). Its cost: the C-model render with relief,
// each pixel's filter-engine clocks with the visibility walker (afvis::Out::clocks) against the
// same pixels through tu_ewa (af_visibility off), and the filter stream's clocks of both
// (ewa::stream_cycles on those pixels: the relief stage in front is the same for both and not
// counted); the engine's cells from the report table (block afvis, rtl top tu_afvis).
AfvisPlan plan_afvis(const scene::Scene& s) {
  AfvisPlan p;
  for (const auto& [name, m] : s.materials)
    if (m.relief && m.relief->af_visibility && m.filter == scene::Filter::Ewa) p.materials.push_back(name);
  p.on = !p.materials.empty();
  if (!p.on) return p;
  render::CmodelOptions o;
  const render::Frame on = render::render_cmodel(s, std::nullopt, o);
  o.afvis = render::AfvisMode::Off;
  const render::Frame off = render::render_cmodel(s, std::nullopt, o);
  std::vector<ewa::PixelCost> con, coff;
  for (const auto* fr : {&on, &off}) {
    const auto wl = sysmodel::scene_workload(s, *fr);
    for (size_t i = 0; i < wl.pixels.size(); ++i) {
      ewa::PixelCost c = sysmodel::cost_of(wl.pixels[i]);
      c.engine = render::engine_of(s.materials.at(s.objects[static_cast<size_t>(fr->pixels[i].object)].material).filter);
      c.afv_walk = fr->pixels[i].afv_clocks;
      (fr == &on ? con : coff).push_back(c);
    }
  }
  for (size_t i = 0; i < con.size() && i < coff.size(); ++i)
    if (con[i].afv_walk) {
      ++p.pixels;
      p.walk_on += double(con[i].afv_walk);
      p.walk_off += double(ewa::walk_cycles(coff[i]));
    }
  if (p.pixels) p.walk_on /= double(p.pixels), p.walk_off /= double(p.pixels);
  const auto front = static_cast<uint64_t>(ewa::texture_unit_front_latency(true));
  p.stream_on = ewa::stream_cycles(con, front);
  p.stream_off = ewa::stream_cycles(coff, front);
  return p;
}

}  // namespace

uint64_t scene_stream_cycles(const scene::Scene& s, const std::function<scene::Filter(const scene::Material&)>& filter_of,
                           bool relief_stage, std::optional<scene::WeightSource> weights, bool ell_recurrence,
                           int clip_variant, const std::vector<bool>& noise_objects, size_t* covered,
                           const std::vector<bool>& water_objects, int noise_slots,
                           const ewa::EngineParams& engine) {
  scene::Scene t = scene::without_relief(s);
  t.footprint = ell_recurrence ? scene::Footprint::Recurrence : scene::Footprint::Analytic;
  for (auto& [name, m] : t.materials) m.filter = filter_of(m);
  render::CmodelOptions o = render::texture_path_only();
  o.weights = weights;
  const render::Frame fr = render::render_cmodel(t, std::nullopt, o);
  if (covered) *covered = fr.pixels.size();
  const auto wl = sysmodel::scene_workload(t, fr);
  std::vector<int> top_level, texfmt;  // per object: its texture's top mip level and storage format
  for (const auto& ob : t.objects) {
    const auto tx = scene::build_texture(t, t.materials.at(ob.material).texture);
    top_level.push_back(tx.num_levels() - 1);
    // A BC1 texture's block address needs the texture: one of another object (the RTL render loads
    // a texture per object) drains too (tu_texture_unit btex_q).
    const int bc1_key = tx.format == static_cast<int>(tex::TexelFormat::Bc1) ? static_cast<int>(texfmt.size() + 1) << 4 : 0;
    texfmt.push_back(tx.format * 2 + (tx.srgb ? 1 : 0) + bc1_key);
  }
  std::vector<ewa::PixelCost> costs;
  for (size_t i = 0; i < wl.pixels.size(); ++i) {
    const auto& w = wl.pixels[i];
    const auto& rec = fr.pixels[i];
    const size_t obj = static_cast<size_t>(rec.object);
    const scene::Filter f = t.materials.at(t.objects[obj].material).filter;
    ewa::PixelCost c = sysmodel::cost_of(w);
    c.engine = render::engine_of(f);
    if (c.engine == ewa::Engine::Trilinear) {
      // A B1-guard pixel is recorded with 1 texel (the workload's guard is EWA's: no level tried).
      c.one_level = ewa::trilinear_one_level(rec.texels == 1, static_cast<int>(std::floor(rec.lod)), top_level[obj]);
    }
    if (c.engine == ewa::Engine::Feline) {
      // A B1-guard pixel is recorded with 1 texel and no probes (one guard pass).
      c.guard = rec.texels == 1 && rec.probes == 0;
      c.probes = c.guard ? 1 : rec.probes;
      c.one_level = ewa::trilinear_one_level(c.guard, static_cast<int>(std::floor(rec.lod)), top_level[obj]);
    }
    c.blocks = static_cast<uint64_t>(rec.ewa_blocks);  // the K = 4 walk's clocks (engine.lanes 4)
    c.texfmt = texfmt[obj];  // a format change drains the engines (tu_texture_unit fk_q)
    c.noise = obj < noise_objects.size() && noise_objects[obj];
    c.water = obj < water_objects.size() && water_objects[obj];
    costs.push_back(c);
  }
  ewa::EngineParams ep = engine;
  ep.clip_variant = clip_variant;
  ep.noise_slots = noise_slots;
  // Noise-unit pixels (II 1) can outrun the relief stage's pass-through, which only the
  // cycle-by-cycle model of the whole unit counts (= the RTL, render --engine rtl).
  if (relief_stage && !ell_recurrence && std::find(noise_objects.begin(), noise_objects.end(), true) != noise_objects.end())
    return ewa::texture_unit_cycles(costs, std::vector<relief::StagePixel>(costs.size()), ep);
  return ewa::stream_cycles(costs, static_cast<uint64_t>(ewa::texture_unit_front_latency(relief_stage, ell_recurrence)), ep);
}

// Feline for an anisotropic material (docs/blocks/feline.md): the probe caps 2, 4, 8, 16 in turn,
// the first whose float render meets min_psnr_db on the material's pixels against the float EWA;
// chosen when its clocks per pixel (the RTL unit's exact cycle model on the material's objects
// alone, C-model probes) are fewer than the EWA's there.
// (FelineChoice in plan.hpp; the chosen cap's float render beside it.)
namespace {
struct FelineResult {
  FelineChoice c;
  std::optional<render::Frame> frame;
};
FelineResult choose_feline(const scene::Scene& s, const std::string& material, const render::Frame& ewa_ref,
                           const std::function<bool(int)>& mine) {
  scene::Scene only = s;
  only.objects.clear();
  for (const auto& o : s.objects)
    if (o.material == material) only.objects.push_back(o);
  auto clocks = [&](scene::Filter f, int cap) {
    scene::Scene t = only;
    t.materials.at(material).feline_max_probes = cap;
    size_t n = 0;
    const uint64_t c = scene_stream_cycles(t, [f](const scene::Material&) { return f; }, false, std::nullopt, false, 0, {}, &n);
    return n ? double(c) / double(n) : 0.0;
  };
  FelineResult res;
  FelineChoice& c = res.c;
  c.why = "feline: ";
  for (const int cap : {2, 4, 8, 16}) {
    scene::Scene t = s;
    t.materials.at(material).feline_max_probes = cap;
    render::Frame fr = render::render_ref(t, scene::Filter::Feline);
    const double p = psnr_objects(fr, ewa_ref, mine);
    c.caps[cap].psnr_db = p;
    c.why += "Nmax " + std::to_string(cap) + " " + fmt("%.2f dB", p);
    if (p < s.budget.min_psnr_db) {
      c.why += ", ";
      continue;
    }
    const double clk = clocks(scene::Filter::Feline, cap), ewa_clk = clocks(scene::Filter::Ewa, cap);
    c.caps[cap].clocks_per_px = clk;
    c.ewa_clocks_per_px = ewa_clk;
    c.why += " at " + fmt("%.2f", clk) + " clocks/px against EWA's " + fmt("%.2f", ewa_clk);
    if (clk < ewa_clk) c.cap = cap, res.frame = std::move(fr);
    return res;  // larger caps cost more clocks
  }
  c.why += "none meets the budget";
  return res;
}
}  // namespace

double Plan::weight_render_db(const TRow& r) const {
  const auto it = weight_render_db_.find(&r);
  return it != weight_render_db_.end() ? it->second : weight_db(r);
}

Plan decide(const scene::Scene& scene_in, const std::vector<TRow>& table, const std::string& report_name,
            double max_cycles) {
  Plan plan;
  scene::Scene s = scene_in;
  // The noise unit is planned on the authored scene; the texture path (filters, footprint, relief)
  // without the procedural descriptions, the float reference included.
  plan.noise = plan_noise(s);
  const NoisePlan& noise = plan.noise;
  plan.afvis = plan_afvis(s);
  for (auto& [name, m] : s.materials) m.procedural.reset();
  auto rows_of = [&](const std::string& block) {
    std::vector<const TRow*> v;
    for (const auto& r : table)
      if (r.block == block && !r.rtl_top.empty()) v.push_back(&r);
    return v;
  };
  auto one = [&](const std::string& block, const std::string& variant) -> const TRow* {
    for (const TRow* r : rows_of(block))
      if (r->variant == variant) return r;
    throw std::runtime_error(report_name + ": no row " + block + "/" + variant + " with an RTL");
  };
  // A block measured per operating point (relief: per view angle and layer count): the preferred
  // variant if measured, else the block's first row with an RTL (its cells are the same).
  auto pick = [&](const std::string& block, const std::string& prefer) -> const TRow* {
    const auto v = rows_of(block);
    if (v.empty()) throw std::runtime_error(report_name + ": no row of " + block + " with an RTL");
    for (const TRow* r : v)
      if (r->variant == prefer) return r;
    return v.front();
  };

  // 1. Footprints and relief per material, from the float reference (level-0 bilinear render: the
  //    footprint is recorded for every pixel whatever the filter).
  const render::Frame bil = render::render_ref(s, scene::Filter::Bilinear);
  if (bil.pixels.empty()) throw std::runtime_error(s.source + ": the scene covers no pixel");
  const Footprints fp = footprints(s, bil);
  const std::map<std::string, size_t>& material_pixels = fp.material_pixels;
  plan.relief = fp.relief, plan.iterative = fp.iterative, plan.pom = fp.pom, plan.distance_map = fp.distance_map;
  const bool relief = fp.relief, iterative = fp.iterative, pom = fp.pom, dist_map = fp.distance_map;
  const int max_layers = fp.max_layers;
  plan.covered_pixels = bil.pixels.size();
  plan.p99_aniso = quantile(fp.aniso, kQuantile), plan.p99_lod = quantile(fp.lod, kQuantile);
  plan.lod_histogram = lod_histogram(fp.lod);
  plan.aniso_histogram = aniso_histogram(fp.aniso);

  // 2. Filter per material (each span picks its engine): the cheapest whose footprint gate passes
  //    on the material's pixels and whose render meets min_psnr_db there against the float EWA
  //    reference (each material meeting it, the scene does: its MSE is their pixel-weighted mean).
  const render::Frame ewa = render::render_ref(s, scene::Filter::Ewa);
  std::optional<render::Frame> tri;
  std::map<std::string, scene::Filter>& mat_filter = plan.filters;
  std::map<std::string, int>& mat_cap = plan.feline_caps;  // Feline materials: the chosen probe cap
  std::map<std::string, render::Frame> feline_frames;     // their float renders at that cap
  std::string& filter_why = plan.filter_why;
  for (const auto& [name, count] : material_pixels) {
    auto mine = [&](int object) { return s.objects[static_cast<size_t>(object)].material == name; };
    std::vector<double> ma, ml;
    for (const auto& p : bil.pixels)
      if (mine(p.object)) ma.push_back(p.aniso), ml.push_back(p.footprint_lod);
    const double qa = quantile(ma, kQuantile), ql = quantile(ml, kQuantile);
    const MaterialFilter f = choose_filter(
        name, ql, qa, s.budget.min_psnr_db, [&] { return psnr_objects(bil, ewa, mine); },
        [&] {
          if (!tri) tri = render::render_ref(s, scene::Filter::Trilinear);
          return psnr_objects(*tri, ewa, mine);
        },
        [&] {
          FelineResult fc = choose_feline(s, name, ewa, mine);
          if (fc.c.cap > 0) feline_frames.emplace(name, std::move(*fc.frame));
          plan.feline_candidates[name] = fc.c;
          return FelineProbe{fc.c.cap, fc.c.why};
        });
    if (f.filter == scene::Filter::Feline) mat_cap[name] = f.feline_cap;
    mat_filter[name] = f.filter;
    filter_why += (filter_why.empty() ? "" : " | ") + f.why;
  }
  auto uses = [&](scene::Filter f) {
    return std::any_of(mat_filter.begin(), mat_filter.end(), [&](const auto& kv) { return kv.second == f; });
  };
  // The scene's most capable filter names the unit's footprint path and its weights.
  const scene::Filter filter = plan.filter = unit_filter(mat_filter);
  // The chosen probe caps from here on (the planned unit's cycles).
  for (const auto& [name, cap] : mat_cap) s.materials.at(name).feline_max_probes = cap;
  // The picture of the plan: each pixel from its material's filter; its PSNR against EWA.
  render::Frame planned_frame = ewa;
  for (const auto& p : planned_frame.pixels) {
    const std::string& mat = s.objects[static_cast<size_t>(p.object)].material;
    const scene::Filter f = mat_filter.at(mat);
    if (f != scene::Filter::Ewa)
      planned_frame.image.at(p.x, p.y) =
          (f == scene::Filter::Bilinear ? bil : f == scene::Filter::Feline ? feline_frames.at(mat) : *tri).image.at(p.x, p.y);
  }
  plan.filter_psnr_db = render::psnr_covered(planned_frame, ewa);
  // texels read by the material's filter (texel bandwidth): as render_ref counts them; Feline its
  // frame's (8 per probe)
  for (size_t i = 0; i < planned_frame.pixels.size(); ++i) {
    auto& p = planned_frame.pixels[i];
    const std::string& mat = s.objects[static_cast<size_t>(p.object)].material;
    const scene::Filter f = mat_filter.at(mat);
    if (f == scene::Filter::Feline) {
      const auto& fp = feline_frames.at(mat).pixels;
      if (i < fp.size() && fp[i].x == p.x && fp[i].y == p.y) p.texels = fp[i].texels;
    } else if (f != scene::Filter::Ewa) {
      p.texels = f == scene::Filter::Bilinear ? 4 : 8;
    }
  }
  const render::Frame* chosen_frame = filter == scene::Filter::Ewa         ? &ewa
                                      : filter == scene::Filter::Feline    ? &feline_frames.begin()->second
                                      : filter == scene::Filter::Trilinear ? &*tri
                                                                           : &bil;

  // 2c. Pipeline per material (planner/pipeline.hpp): object space where it meets the budget for
  //     fewer clocks than the material's screen-space filter, measured by rendering the material
  //     alone through both. The texture-unit top has no object-space path: the choice is
  //     reported; the package and the cycles below are the screen-space unit's.
  for (const auto& [name, f] : mat_filter)
    plan.pipelines.push_back(choose_pipeline(s, name, f, std::count(noise.materials.begin(), noise.materials.end(), name) > 0));

  // 2b. Relief method per material (choose_relief). The planned unit keeps the engines of the
  //     authored methods (the scene must render on it as written); the choice is reported, with the
  //     distance map's memory.
  if (relief) {
    const render::Frame ref_bil = render::render_ref(s, scene::Filter::Bilinear);
    for (const auto& [name, m] : s.materials) {
      if (!m.relief || !material_pixels.count(name)) continue;
      plan.relief_choices.emplace(name, choose_relief(s, name, ref_bil));
    }
  }

  // 3. Blocks and variants from the measured table.
  const std::string psnr_field = s.source + ": /error_budget/min_psnr_db = " + fmt("%g", s.budget.min_psnr_db);
  const std::string texel_field = s.source + ": /error_budget/max_texel_err = " + fmt("%g", s.budget.max_texel_err);
  std::string& cost_basis = plan.cost_basis;
  const TRow* persp = plan.persp = cheapest(rows_of("persp"), [&](const TRow& r) { return r.max_abs <= s.budget.max_texel_err; },
                               [](const TRow& r) { return -r.max_abs; }, texel_field, "persp", "%.4g texel", &cost_basis);
  const TRow* setup = one("persp_setup", "setup");
  std::vector<const TRow*> weight_cands = rows_of("gauss_weight");
  for (const TRow* r : rows_of("weight_table")) weight_cands.push_back(r);
  std::vector<const TRow*> relief_rows;
  // POM: the layer counter and the per-pixel unit (set-up, march, refinement) of the texture
  // unit's relief stage, at 45 degrees with adaptive layers.
  const TRow* pom_layers = pick("pom_layers", "adaptive_4_32");
  const TRow* pom_unit = pick("pom_unit", "45deg_adaptive");
  const TRow* ipx = pick("iter_parallax", "60deg_norm");
  if (pom) relief_rows = {pom_layers, pom_unit};
  if (iterative) relief_rows.push_back(ipx);

  Unit& spec = plan.spec;
  spec.area_only = {setup};
  spec.stages.push_back({{persp}});
  if (relief) spec.stages.push_back({relief_rows});
  const TRow *&weights = plan.weights, *&clip = plan.clip;
  // B2: the scene's footprint variant ("footprint": analytic | recurrence).
  const bool ell_rec = s.footprint == scene::Footprint::Recurrence;
  if (filter != scene::Filter::Bilinear) spec.stages.push_back({{one("ellipse", ell_rec ? "recurrence" : "analytic")}});
  // Weight sources: PSNR of the bit-accurate C-model render (EWA with that source) against the
  // float EWA reference, on the texture path (relief off on both sides: the relief method is its
  // own block). Rows the engine does not implement keep their 20 log10(1/rms).
  std::map<const TRow*, double>& render_db = plan.weight_render_db_;
  if (filter == scene::Filter::Ewa) {
    const scene::Scene flat = scene::without_relief(s);
    const render::Frame ref_flat = render::render_ref(flat, scene::Filter::Ewa);
    for (const TRow* r : weight_cands)
      if (const auto src = engine_source(*r)) {
        render::CmodelOptions o = render::texture_path_only();
        o.weights = src;
        render_db[r] = render::psnr_covered(render::render_cmodel(flat, scene::Filter::Ewa, o), ref_flat);
      }
  }
  auto weight_render_db = [&](const TRow& r) { return plan.weight_render_db(r); };
  auto render_ok = [&](const TRow& r) { return weight_render_db(r) >= s.budget.min_psnr_db; };
  // Clip-volume variants: PSNR of the C-model EWA render with the scene's border weights in that
  // variant (every material, scene::with_clip) against the float EWA with the exact Phi border
  // weights, on the texture path (docs/blocks/ewa.md "Border weights"); one render per variant.
  std::map<std::string, double>& clip_db = plan.clip_db;
  if (filter == scene::Filter::Ewa) {
    const scene::Scene flat = scene::without_relief(s);
    const render::Frame ref_clip = render::render_ref(scene::with_clip(flat, "mm_p3"), scene::Filter::Ewa);
    for (const TRow* r : rows_of("clip_volume"))
      if (!clip_db.count(r->variant))
        clip_db[r->variant] = render::psnr_covered(
            render::render_cmodel(scene::with_clip(flat, r->variant), scene::Filter::Ewa, render::texture_path_only()), ref_clip);
  }
  auto clip_render_db = [&](const TRow& r) { return clip_db.at(r.variant); };
  auto clip_ok = [&](const TRow& r) { return clip_render_db(r) >= s.budget.min_psnr_db; };
  if (filter == scene::Filter::Ewa) {
    weights = cheapest(weight_cands, render_ok, weight_render_db, psnr_field, "EWA weight source", "%.1f dB", &cost_basis);
    clip = cheapest(rows_of("clip_volume"), clip_ok, clip_render_db, psnr_field, "clip_volume", "%.1f dB", &cost_basis);
    spec.stages.push_back({{clip}});
    spec.stages.push_back({{weights}});
  }
  spec.texels_per_pixel = texels_per_pixel(*chosen_frame);

  // Shading: a scene with a light needs the stage, one without leaves it out. Its model is the one
  // the lit materials name, else the cheapest pipelined model (II = 1) whose MAD against Blinn on
  // the thesis grid (the bit-accurate model, brdf::vs_blinn_fx) meets max_brdf_mad.
  const bool shade = plan.shading = !s.lights.empty();
  const TRow*& brdf_row = plan.brdf;
  std::map<const TRow*, double> brdf_mad;
  std::string& shade_why = plan.shade_why;
  shade_why = "no light in the scene: no shading stage";
  if (shade) {
    std::set<std::string> pinned;
    for (const auto& o : s.objects)
      if (const auto& sp = s.materials.at(o.material).specular; sp && sp->model != "auto") pinned.insert(sp->model);
    if (pinned.size() > 1)
      throw BudgetError(s.source + ": /materials: specular models " + *pinned.begin() + " and " + *pinned.rbegin() +
                        ": the unit's shading stage has one BRDF model");
    std::vector<const TRow*> cands;
    for (const TRow* r : rows_of("brdf"))
      if (r->ii <= 1) cands.push_back(r);
    for (const TRow* r : cands) brdf_mad[r] = brdf::vs_blinn_fx(shading::model_of(r->variant)).mad;
    if (pinned.size() == 1) {
      brdf_row = one("brdf", *pinned.begin());
      shade_why = "named by the materials";
    } else {
      const std::string mad_field = s.source + ": /error_budget/max_brdf_mad = " + fmt("%g", s.budget.max_brdf_mad);
      brdf_row = cheapest(cands, [&](const TRow& r) { return brdf_mad.at(&r) <= s.budget.max_brdf_mad; },
                          [&](const TRow& r) { return -brdf_mad.at(&r); }, mad_field, "BRDF model", "%.5f", &cost_basis);
      shade_why = "cheapest with MAD vs Blinn <= " + fmt("%g", s.budget.max_brdf_mad);
    }
    if (brdf_mad.count(brdf_row)) shade_why += " (MAD " + fmt("%.5f", brdf_mad.at(brdf_row)) + ")";
    spec.stages.push_back({{brdf_row}});
  }

  // The full unit: every block, every weight source and relief method, EWA texel walk.
  Unit& full = plan.full;
  full.area_only = {setup};
  full.stages.push_back({{persp}});
  full.stages.push_back({{pom_layers, pom_unit}, {ipx}});
  full.stages.push_back({{one("ellipse", "analytic")}});
  const auto clips = rows_of("clip_volume");
  const TRow* full_clip = clip ? clip : *std::min_element(clips.begin(), clips.end(), [](auto* a, auto* b) { return cost(*a, false) < cost(*b, false); });
  full.stages.push_back({{full_clip}});
  std::vector<std::vector<const TRow*>> all_weights;
  for (const TRow* r : weight_cands) all_weights.push_back({r});
  full.stages.push_back(all_weights);
  full.texels_per_pixel = texels_per_pixel(ewa);
  if (brdf_row) full.stages.push_back({{brdf_row}});

  // 4. RTL configuration.
  const bool has_ewa = uses(scene::Filter::Ewa), has_tri = filter != scene::Filter::Bilinear;
  auto weight_bit = [&](const TRow* w) { return !w ? 0 : w->block == "gauss_weight" ? 1 : w->scheme == "weight_table_1d" ? 2 : 4; };
  auto log2n = [&](const std::string& scheme) {
    for (const TRow* r : weight_cands)
      if (r->scheme == scheme) return static_cast<int>(std::lround(std::log2(std::stod(r->variant.substr(3)))));
    return 0;
  };
  // EWA border weights: in the unit when an EWA material asks for them; their clip volume is the one
  // the materials name (it must have an RTL, and the unit has one), else the plan's choice.
  std::set<std::string> clip_named;
  for (const auto& [name, m] : s.materials)
    if (!m.clip.empty() && mat_filter.count(name) && mat_filter.at(name) == scene::Filter::Ewa) {
      if (ewa::rtl_clip_code(m.clip) < 0)
        throw BudgetError(s.source + ": /materials/" + name + "/clip: " + m.clip +
                          " has no RTL in the EWA walk (tu_ewa_border: mm_p1, mm_p3, mm_p3_estrin)");
      clip_named.insert(m.clip);
    }
  if (clip_named.size() > 1)
    throw BudgetError(s.source + ": /materials: clip variants " + *clip_named.begin() + " and " + *clip_named.rbegin() +
                      ": the unit's EWA walk has one clip volume");
  const int clip_code = !clip_named.empty() ? ewa::rtl_clip_code(*clip_named.begin())
                        : clip && ewa::rtl_clip_code(clip->variant) >= 0 ? ewa::rtl_clip_code(clip->variant) : 0;
  Config planned{has_tri, has_ewa, uses(scene::Filter::Bilinear), uses(scene::Filter::Trilinear), false, relief, pom, iterative, max_layers, weight_bit(weights),
                       log2n("weight_table_1d"), log2n("weight_table_2d"), persp->variant == "klane4" ? 4 : 1,
                       ell_rec && has_tri, false, shading::kUnitModel, /*distance_map, set below*/ false,
                       /*wrap_modes, set below*/ 31, !clip_named.empty(), clip_code};
  planned.feline = uses(scene::Filter::Feline);
  // The full unit: everything in, relief up to the scene format's 256 layers.
  Config& planned_shaded = plan.spec_cfg;
  planned_shaded = planned;
  planned_shaded.shading = shade;
  planned_shaded.distance_map = dist_map;
  const TextureNeeds tn = texture_needs(s);
  planned_shaded.wrap_modes = tn.wrap_modes, planned_shaded.tex_formats = tn.tex_formats;
  planned_shaded.srgb = tn.srgb, planned_shaded.texel_w = tn.texel_w, planned_shaded.bc1 = tn.bc1;
  plan.wrap_names = tn.wrap_names, plan.format_names = tn.format_names;
  planned_shaded.noise = noise.on;
  if (noise.on) planned_shaded.noise_dims = noise.dims, planned_shaded.noise_cores = noise.cores;
  planned_shaded.water = noise.water;
  planned_shaded.afvis = plan.afvis.on;
  if (brdf_row) planned_shaded.shade_model = shading::model_of(brdf_row->variant);
  // The full unit: F_MSH (the thesis's model) when the scene does not need another.
  const Config& everything = plan.full_cfg = [&] {
    Config c{true, true, true, true, true, true, true, true, 256, 7, planned.wtab_log2n, planned.wtab2d_log2n,
             planned.persp_lanes, false, true, brdf_row ? planned_shaded.shade_model : shading::kUnitModel,
             true, 31, true, clip_code, true};
    c.feline = true;
    return c;
  }();

  // 5. Scene cycles of the RTL texture unit (texture path), from the exact cycle model
  //    ewa::stream_cycles on the bit-accurate C-model render's per-pixel work (equal to Verilator:
  //    TextureUnitRtl.CyclesMatchPrediction / MixedFiltersPerSpan): the specialised and the full
  //    unit with the plan's filter per material, and the full unit as authored.
  auto scene_cycles = [&](std::function<scene::Filter(const scene::Material&)> filter_of, bool relief_stage,
                          std::optional<scene::WeightSource> weights, bool rec, int noise_slots = 1) -> uint64_t {
    return scene_stream_cycles(s, filter_of, relief_stage, weights, rec, clip_code, noise.objects, nullptr, noise.water_objects,
                               noise_slots);
  };
  auto authored = [](const scene::Material& m) { return m.filter; };
  auto planned_filter = [&](const scene::Material& m) {
    const auto it = mat_filter.find(m.name);  // a material without pixels: any engine the unit has
    return it == mat_filter.end() ? filter : it->second;
  };
  const auto planned_weights = weights ? engine_source(*weights) : std::nullopt;
  // The shading stage (II = 1, fed one word per pixel) adds its latency once, at the end.
  const uint64_t spec_shade = shade ? static_cast<uint64_t>(brdf::shade::latency(planned_shaded.shade_model)) : 0;
  const uint64_t full_shade = static_cast<uint64_t>(brdf::shade::latency(everything.shade_model));
  uint64_t spec_cycles = scene_cycles(planned_filter, relief, planned_weights, planned.ell_recurrence) + spec_shade;
  // The noise scheme: the octave-serial unit (one core instead of NoiseCores, the same back-end:
  // the smaller by construction) when the frame's clocks with it meet the budget's max_cycles,
  // else the pipelined one (also without a cycle budget).
  if (noise.on) {
    const uint64_t serial = scene_cycles(planned_filter, relief, planned_weights, planned.ell_recurrence, noise.cores) + spec_shade;
    plan.noise_scheme = choose_noise_scheme(max_cycles, spec_cycles, serial, noise.cores);
    const bool pick_serial = plan.noise_scheme.octave_serial;
    planned_shaded.noise_scheme = pick_serial ? 1 : 0;
    if (pick_serial) spec_cycles = serial;
  }
  const uint64_t full_cycles = scene_cycles(planned_filter, true, planned_weights, false) + full_shade;  // the same picture
  const uint64_t authored_cycles = scene_cycles(authored, true, std::nullopt, false) + full_shade;

  plan.spec_cycles = spec_cycles;
  plan.full_cycles = full_cycles;
  plan.authored_cycles = authored_cycles;
  plan.texture_formats = plan::texel_format_plan(s, planned_frame, s.budget.min_psnr_db);
  for (const TRow* r : rows_of("afvis"))
    if (r->cells > 0) plan.afvis.cells = r->cells;
  return plan;
}

}  // namespace tu::plan
