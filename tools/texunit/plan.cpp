// `texunit plan`: see plan.hpp and docs/reading-the-report.md.
#include "plan.hpp"
#include "plan_formats.hpp"
#include "plan_pipeline.hpp"

#include "output.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <tuple>

#include <nlohmann/json.hpp>

#include <set>
#include "brdf/brdf_error.hpp"
#include "brdf/brdf_shade.hpp"
#include "ewa/ewa_cycles.hpp"
#include "pom/relief.hpp"
#include "texture/texel_format.hpp"
#include "texunit/shading.hpp"
#include "texunit/render.hpp"
#include "texunit/texture_unit_model.hpp"
#include "texunit/scene.hpp"

namespace fs = std::filesystem;
using json = nlohmann::json;

extern const char tu_report_table_json[];  // report_table_embed.cpp (embed.cmake)
extern const unsigned long tu_report_table_json_size;

namespace tu::plan {

namespace {

// Footprint thresholds: below them a pixel needs neither mip selection nor an anisotropic filter.
constexpr double kMinifyLod = 0.5;  // footprint LOD (log2 texels per pixel) still served by level 0
constexpr double kIsoAniso = 2.0;   // major / minor still served by an isotropic (trilinear) filter
constexpr double kQuantile = 0.99;  // the gates use the 99th percentile (1% of pixels may exceed)

struct TRow {
  std::string block, variant, scheme, rtl_top;
  double max_abs = 0, rms = 0, ii = 0, cells = -1;  // cells -1: not measured
  double area_um2 = -1, fmax_mhz = -1;               // osu018 standard cells; -1: not measured
  int64_t latency = 0, mul = 0;
  std::string name() const { return block + "/" + variant + (scheme == variant ? "" : " (" + scheme + ")"); }
};

// Cheapest = least osu018 area when every candidate has one; else fewest Yosys cells, else fewest
// multipliers (the basis is recorded in g_cost_basis and printed).
std::string g_cost_basis = "osu018 area (um2)";
double cost(const TRow& r, bool by_area) {
  if (by_area) return r.area_um2;
  return r.cells >= 0 ? r.cells : 1e12 + static_cast<double>(r.mul);
}

constexpr const char* kBuiltInReport = "docs/report/report.json";

// The table of `path`, or the built-in copy of docs/report/report.json when path is empty.
std::vector<TRow> load_table(const std::string& file) {
  const std::string path = file.empty() ? kBuiltInReport : file;
  std::string text(tu_report_table_json, tu_report_table_json_size);
  if (!file.empty()) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw std::runtime_error(path + ": cannot read the report table (run scripts/report.sh)");
    std::ostringstream ss;
    ss << in.rdbuf();
    text = ss.str();
  }
  json j;
  try {
    j = json::parse(text);
  } catch (const json::exception& e) {
    throw std::runtime_error(path + ": malformed JSON (" + e.what() + ")");
  }
  if (!j.is_array()) throw std::runtime_error(path + ": expected a JSON array of report rows");
  std::vector<TRow> rows;
  for (size_t i = 0; i < j.size(); ++i) {
    const auto& r = j[i];
    auto field = [&](const char* k) -> const json& {
      if (!r.is_object() || !r.contains(k))
        throw std::runtime_error(path + ": /" + std::to_string(i) + "/" + k + ": missing");
      return r.at(k);
    };
    auto num = [&](const char* k, bool optional) {
      const json& v = field(k);
      if (v.is_number()) return v.get<double>();
      if (optional && v.is_string()) return -1.0;  // "not measured: ..." or "n/a"
      throw std::runtime_error(path + ": /" + std::to_string(i) + "/" + k + ": expected a number");
    };
    auto str = [&](const char* k) {
      if (!field(k).is_string()) throw std::runtime_error(path + ": /" + std::to_string(i) + "/" + k + ": expected a string");
      return field(k).get<std::string>();
    };
    TRow t;
    t.block = str("block"), t.variant = str("variant"), t.scheme = str("scheme"), t.rtl_top = str("rtl_top");
    t.max_abs = num("max_abs_err", false), t.rms = num("rms_err", false), t.ii = num("ii_cycles", false);
    t.latency = static_cast<int64_t>(num("latency_cycles", true));
    t.cells = num("cells", true);
    t.mul = static_cast<int64_t>(num("multipliers", true));
    // A table written before the standard-cell columns existed: area not measured.
    if (r.contains("area_um2")) t.area_um2 = num("area_um2", true), t.fmax_mhz = num("fmax_mhz", true);
    rows.push_back(t);
  }
  return rows;
}

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[static_cast<size_t>(q * static_cast<double>(v.size() - 1))];
}

// PSNR over a's covered pixels of the objects `keep` accepts (render::psnr_covered).
double psnr_objects(const render::Frame& a, const render::Frame& b, const std::function<bool(int object)>& keep) {
  return render::psnr_covered(a, b, [&](const render::PixelRecord& p) { return keep(p.object); });
}

double texels_per_pixel(const render::Frame& f) {
  double t = 0;
  for (const auto& p : f.pixels) t += p.texels;
  return f.pixels.empty() ? 0 : t / static_cast<double>(f.pixels.size());
}

// Weight-table rows the EWA engine does not implement: 20 log10(1 / rms) with the value range
// [0, 1] as the peak. Weight sources and clip-volume variants are measured on the render
// (weight_render_db, clip_render_db).
double weight_db(const TRow& r) { return r.rms > 0 ? 20 * std::log10(1 / r.rms) : INFINITY; }

// The EWA engine's weight source of a weight row, if the engine implements it (formula, the RTL's
// 1-D and 2-D tables).
std::optional<scene::WeightSource> engine_source(const TRow& r) {
  if (r.block == "gauss_weight") return scene::WeightSource::Formula;
  if (r.scheme == "weight_table_1d") return scene::WeightSource::Table1d;
  if (r.scheme == "weight_table_2d") return scene::WeightSource::Table2d;
  return std::nullopt;
}

// The plan's filter names (mat_filter) as scene filters.
scene::Filter filter_named(const std::string& f) {
  return f == "bilinear" ? scene::Filter::Bilinear : f == "trilinear" ? scene::Filter::Trilinear
         : f == "feline"  ? scene::Filter::Feline   : scene::Filter::Ewa;
}

std::string fmt(const char* f, double x) {
  char b[64];
  std::snprintf(b, sizeof b, f, x);
  return b;
}

// Relief method per material: each candidate method at the material's layers through the
// bit-accurate C-model render (bilinear, so the relief method is the only difference), its PSNR
// on the material's pixels against the float reference (the 256-layer exact march), its cost the
// relief stage's cycles per pixel of the material (relief::stage_cycles over its pixels in raster
// order: exact, = the RTL, ReliefStageCosim); the cheapest meeting min_psnr_db, else the best.
// distance_map_refined is a candidate only where the material authors it (its map takes tens of
// seconds to build on a 256-texel height; on the maps of docs/blocks/relief.md §13.6 it equals
// the classic one).
struct ReliefCandidate {
  scene::ReliefMethod method;
  double psnr_db = 0, cycles_per_px = 0, steps_per_px = 0;
  uint64_t map_bytes = 0;  // distance maps: W x H x D voxels of DmCodeW bits
};
struct ReliefChoice {
  scene::ReliefMethod authored, chosen;
  bool meets = false;
  std::vector<ReliefCandidate> cands;
};
ReliefChoice choose_relief(const scene::Scene& s, const std::string& material, const render::Frame& ref) {
  const auto authored = s.materials.at(material).relief->method;
  ReliefChoice c{authored, authored, false, {}};
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
  const ReliefCandidate* best = nullptr;
  for (const auto& k : c.cands)
    if (k.psnr_db >= s.budget.min_psnr_db && (!best || k.cycles_per_px < best->cycles_per_px)) best = &k;
  c.meets = best != nullptr;
  if (!best)
    for (const auto& k : c.cands)
      if (!best || k.psnr_db > best->psnr_db) best = &k;
  c.chosen = best->method;
  return c;
}

// Cheapest row with an RTL among `cands` meeting `ok`; else a BudgetError naming `field`.
const TRow* cheapest(const std::vector<const TRow*>& cands, const std::function<bool(const TRow&)>& ok,
                     const std::function<double(const TRow&)>& score, const std::string& field,
                     const std::string& what, const char* unit) {
  const TRow* best = nullptr;
  const TRow* closest = nullptr;
  const TRow* no_area = nullptr;
  for (const TRow* r : cands)
    if (ok(*r) && r->area_um2 < 0) no_area = r;
  if (no_area) g_cost_basis = "Yosys cells (" + no_area->name() + " has no osu018 area: run scripts/stdcell.sh)";
  for (const TRow* r : cands) {
    if (!closest || score(*r) > score(*closest)) closest = r;
    if (ok(*r) && (!best || cost(*r, !no_area) < cost(*best, !no_area))) best = r;
  }
  if (!closest) throw std::runtime_error("report table has no " + what + " row with an RTL (run scripts/report.sh)");
  if (!best)
    throw BudgetError(field + ": no " + what + " variant reaches it (best: " + closest->name() + " at " +
                      fmt(unit, std::fabs(score(*closest))) + ")");
  return best;
}

struct Unit {
  std::vector<std::vector<std::vector<const TRow*>>> stages;  // stage -> alternatives -> sequence
  std::vector<const TRow*> area_only;                        // e.g. per-scanline set-up
  double texels_per_pixel = 1;
  std::vector<const TRow*> all() const {
    std::vector<const TRow*> v = area_only;
    for (const auto& s : stages)
      for (const auto& a : s) v.insert(v.end(), a.begin(), a.end());
    return v;
  }
  int64_t latency() const {
    int64_t l = 0;
    for (const auto& s : stages) {
      int64_t m = 0;
      for (const auto& a : s) {
        int64_t sum = 0;
        for (const TRow* r : a) sum += r->latency;
        m = std::max(m, sum);
      }
      l += m;
    }
    return l;
  }
  double ii() const {
    double m = 1;
    for (const TRow* r : all()) m = std::max(m, r->ii);
    return m;
  }
  double cells() const {
    double c = 0;
    for (const TRow* r : all()) c += r->cells < 0 ? 0 : r->cells;
    return c;
  }
  double area_um2() const {
    double a = 0;
    for (const TRow* r : all()) a += r->area_um2 < 0 ? 0 : r->area_um2;
    return a;
  }
  bool area_measured() const {
    const auto v = all();
    return std::all_of(v.begin(), v.end(), [](const TRow* r) { return r->area_um2 >= 0; });
  }
  // The unit's clock: its slowest block's fmax (blocks synthesised alone; the slowest one sets it).
  double fmax_mhz() const {
    double f = INFINITY;
    for (const TRow* r : all()) f = r->fmax_mhz < 0 ? f : std::min(f, r->fmax_mhz);
    return area_measured() ? f : -1;
  }
  bool cells_measured() const {
    return std::all_of(area_only.begin(), area_only.end(), [](const TRow* r) { return r->cells >= 0; }) &&
           std::all_of(stages.begin(), stages.end(), [](const auto& s) {
             return std::all_of(s.begin(), s.end(), [](const auto& a) {
               return std::all_of(a.begin(), a.end(), [](const TRow* r) { return r->cells >= 0; });
             });
           });
  }
};

const char* const kNoArea = "not measured: a block has no osu018 result in the report (scripts/stdcell.sh)";

json unit_json(const Unit& u) {
  json b = json::array();
  for (const TRow* r : u.all()) b.push_back(r->name());
  return {{"blocks", b},
          {"pixel_latency_cycles", u.latency()},
          {"ii_cycles", u.ii()},
          {"texels_per_pixel", u.texels_per_pixel},
          {"cells_sum_of_blocks", u.cells_measured() ? json(u.cells()) : json("not measured: a block has no Yosys cell count in the report (scripts/report.sh)")},
          {"area_um2_sum_of_blocks", u.area_measured() ? json(u.area_um2()) : json(kNoArea)},
          {"fmax_mhz_slowest_block", u.area_measured() ? json(u.fmax_mhz()) : json(kNoArea)}};
}

// The noise unit (docs/blocks/noise.md §5 "In the RTL texture unit"): in the unit when a material
// is procedural; 2-D cores unless a material moves through time (speed != 0); the fewest octave
// cores K whose C-model render (each material's octaves capped at K, C_K for the capped count)
// meets min_psnr_db against the float reference with every material's own octaves, over the
// procedural pixels (none meeting it: the largest octave count, the authored picture).
struct NoisePlan {
  bool on = false, water = false;
  int dims = 2, cores = 0;
  std::vector<std::string> materials;
  json psnr_by_octaves = json::object();
  std::vector<bool> objects;  // per object: procedural
  std::vector<bool> water_objects;  // per object: water (the noise unit's three-pass pixels)
};
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
    p.psnr_by_octaves[std::to_string(k)] = std::isinf(db) ? json("identical") : json(db);
    if (p.cores == 0 && db >= s.budget.min_psnr_db) p.cores = k;
  }
  if (p.cores == 0) p.cores = kmax;
  return p;
}

// The RTL configuration: tu_unit_cfg_pkg, read by the RTL top.
struct Config {
  bool trilinear, ewa, bilinear, tri_filter, nearest, relief, pom, iter_parallax;
  int pom_max_layers, weight_sources, wtab_log2n, wtab2d_log2n, persp_lanes;
  bool ell_recurrence = false;  // B2: the seed's recurrences (tu_ellipse_rec) instead of the analytic unit
  bool shading = false;
  brdf::Model shade_model = shading::kUnitModel;
  bool distance_map = false;  // the distance-map tracer (tu_dm_trace) in the relief stage
  int wrap_modes = 31;  // bit = tex::Wrap code: the modes some texture uses (repeat always)
  bool ewa_clip = false;  // EWA sub-texel border weights (tu_ewa_border in the walk)
  int clip_variant = 0;   // their clip volume: ewa::kRtlClipVariants code
  bool noise = false;  // noise unit (tu_noise_unit) for procedural materials
  int noise_dims = 3, noise_cores = tu::fmt::kNoiseOctaves;
  bool water = true;  // the noise unit's water back-end (tu_noise_unit HasWater)
  int noise_scheme = 0;  // 0 pipelined, 1 octave-serial (tu_noise_unit Serial)
  bool feline = false;  // Feline probe engine (tu_feline)
  bool afvis = true;  // AF with parallax visibility (tu_afvis beside tu_ewa)
  int tex_formats = 127;  // tu_texel_decode: bit = TexelFormat code, the formats some texture uses
  bool srgb = true;       // the sRGB decode tables
  int texel_w = 32;       // texel port / RAM word: the widest stored format's bits per texel
  bool bc1 = true;        // BC1 block fetch (tu_texel_port): 64-bit texel RAM words
};
std::string package(const Config& c, const std::string& origin) {
  std::ostringstream sv;
  sv << "// Generated by " << origin << ": do not edit.\n"
     << "// Unit configuration read by the RTL top; generate blocks leave out what is 0.\n"
     << "package tu_unit_cfg_pkg;\n"
     << "  localparam bit HasTrilinear = 1'b" << c.trilinear << ";  // footprint / LOD (tu_ellipse)\n"
     << "  localparam bit HasEwa = 1'b" << c.ewa << ";  // EWA texel walk, clip volume and weights\n"
     << "  localparam bit HasBilinear = 1'b" << c.bilinear << ";  // bilinear engine (per-span choice with EWA)\n"
     << "  localparam bit HasTriFilter = 1'b" << c.tri_filter << ";  // trilinear engine (tu_trilinear)\n"
     << "  localparam bit HasNearest = 1'b" << c.nearest << ";  // nearest engine (tu_nearest)\n"
     << "  localparam bit HasFeline = 1'b" << c.feline << ";  // Feline probe engine (tu_feline)\n"
     << "  localparam bit HasRelief = 1'b" << c.relief << ";\n"
     << "  localparam bit HasPom = 1'b" << c.pom << ";  // tu_pom_layers + tu_pom_march\n"
     << "  localparam bit HasIterParallax = 1'b" << c.iter_parallax << ";\n"
     << "  localparam bit HasDistanceMap = 1'b" << c.distance_map << ";  // tu_dm_trace\n"
     << "  localparam int PomMaxLayers = " << c.pom_max_layers << ";\n"
     << "  // bit 0: formula (tu_gauss_weight), bit 1: 1-D table, bit 2: 2-D table\n"
     << "  localparam logic [2:0] WeightSources = 3'd" << c.weight_sources << ";\n"
     << "  localparam int WtabLog2N = " << c.wtab_log2n << ";\n"
     << "  localparam int Wtab2dLog2N = " << c.wtab2d_log2n << ";\n"
     << "  localparam int PerspLanes = " << c.persp_lanes << ";\n"
     << "  localparam bit HasShading = 1'b" << c.shading << ";  // shading stage (tu_shade) after the filter\n"
     << "  // brdf::Model code: 0 blinn, 1 schlick, 2 msh, 3 dsh, 4 scos2, 5 st16, 6 qr\n"
     << "  localparam int ShadeModel = " << static_cast<int>(c.shade_model) << ";  // " << brdf::name(c.shade_model) << "\n"
     << "  localparam bit EllRecurrence = 1'b" << c.ell_recurrence
     << ";  // B2: 0 analytic (tu_ellipse), 1 seed recurrences (tu_ellipse_rec)\n"
     << "  // texel addressing (tu_texel_addr): bit = tu_formats_pkg::Wrap* code, 1 = the mode is built\n"
     << "  localparam logic [4:0] WrapModes = 5'd" << c.wrap_modes << ";\n"
     << "  localparam bit HasEwaClip = 1'b" << c.ewa_clip << ";  // EWA sub-texel border weights (tu_ewa_border)\n"
     << "  // clip volume: 0 mm_p1 (tu_clip_p1), 1 mm_p3 (tu_clip_horner), 2 mm_p3_estrin (tu_clip_estrin)\n"
     << "  localparam int EwaClipVariant = " << c.clip_variant << ";  // " << ewa::kRtlClipVariants[static_cast<size_t>(c.clip_variant)] << "\n"
     << "  localparam bit HasNoise = 1'b" << c.noise << ";  // noise unit (tu_noise_unit): procedural materials\n"
     << "  localparam int NoiseDims = " << c.noise_dims << ";  // 2: no material with time, 3: with\n"
     << "  localparam int NoiseCores = " << c.noise_cores << ";  // octave cores: the largest octave count\n"
     << "  localparam bit HasWater = 1'b" << c.water << ";  // water back-end of the noise unit (normal, Lambert)\n"
     << "  localparam int NoiseScheme = " << c.noise_scheme << ";  // 0 pipelined (NoiseCores cores), 1 octave-serial (one core)\n"
     << "  localparam bit HasAfvis = 1'b" << c.afvis << ";  // AF with parallax visibility (tu_afvis)\n"
     << "  // texel decode (tu_texel_decode): bit = tu_formats_pkg::TexFmt* code, 1 = its decode is built\n"
     << "  localparam logic [6:0] TexFormats = 7'd" << c.tex_formats << ";\n"
     << "  localparam bit HasSrgb = 1'b" << c.srgb << ";  // sRGB decode tables (tu_srgb_rom)\n"
     << "  localparam int TexelW = " << c.texel_w << ";  // texel port and RAM word: the widest stored format\n"
     << "  localparam bit HasBc1 = 1'b" << c.bc1 << ";  // BC1 block fetch (tu_texel_port): a 64-bit texel RAM word\n"
     << "endpackage\n";
  return sv.str();
}

// AF with parallax visibility (docs/blocks/afvis.md): tu_afvis is in the unit when a material asks
// for it (relief with af_visibility, the EWA filter). Its cost: the C-model render with relief,
// each pixel's filter-engine clocks with the visibility walker (afvis::Out::clocks) against the
// same pixels through tu_ewa (af_visibility off), and the filter stream's clocks of both
// (ewa::stream_cycles on those pixels: the relief stage in front is the same for both and not
// counted); the engine's cells from the report table (block afvis, rtl top tu_afvis).
struct AfvisPlan {
  bool on = false;
  std::vector<std::string> materials;
  size_t pixels = 0;               // pixels through tu_afvis
  double walk_on = 0, walk_off = 0;  // mean walker clocks per such pixel: tu_afvis, tu_ewa
  uint64_t stream_on = 0, stream_off = 0;  // the scene's filter stream clocks with and without
};
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
struct FelineChoice {
  int cap = 0;  // 0: not chosen
  std::string why;
  json j;
  std::optional<render::Frame> frame;
};
FelineChoice choose_feline(const scene::Scene& s, const std::string& material, const render::Frame& ewa_ref,
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
  FelineChoice c;
  c.j = {{"caps", json::object()}};
  c.why = "feline: ";
  for (const int cap : {2, 4, 8, 16}) {
    scene::Scene t = s;
    t.materials.at(material).feline_max_probes = cap;
    render::Frame fr = render::render_ref(t, scene::Filter::Feline);
    const double p = psnr_objects(fr, ewa_ref, mine);
    c.j["caps"][std::to_string(cap)] = {{"psnr_db", p}};
    c.why += "Nmax " + std::to_string(cap) + " " + fmt("%.2f dB", p);
    if (p < s.budget.min_psnr_db) {
      c.why += ", ";
      continue;
    }
    const double clk = clocks(scene::Filter::Feline, cap), ewa_clk = clocks(scene::Filter::Ewa, cap);
    c.j["caps"][std::to_string(cap)]["clocks_per_px"] = clk;
    c.j["ewa_clocks_per_px"] = ewa_clk;
    c.why += " at " + fmt("%.2f", clk) + " clocks/px against EWA's " + fmt("%.2f", ewa_clk);
    if (clk < ewa_clk) c.cap = cap, c.frame = std::move(fr);
    return c;  // larger caps cost more clocks
  }
  c.why += "none meets the budget";
  return c;
}

int run(const Options& opt) {
  scene::Scene s = opt.scene == "default" ? scene::default_scene() : scene::load(opt.scene);
  // The noise unit is planned on the authored scene; the texture path (filters, footprint, relief)
  // without the procedural descriptions, the float reference included.
  const NoisePlan noise = plan_noise(s);
  const AfvisPlan afv = plan_afvis(s);
  for (auto& [name, m] : s.materials) m.procedural.reset();
  const auto table = load_table(opt.report);
  const std::string report_name = opt.report.empty() ? kBuiltInReport : opt.report;
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
  std::vector<double> aniso, lod;
  std::map<std::string, size_t> material_pixels;
  bool relief = false, iterative = false, pom = false, dist_map = false;
  int max_layers = 0;
  for (const auto& p : bil.pixels) {
    aniso.push_back(p.aniso);
    lod.push_back(p.footprint_lod);
    const auto& m = s.materials.at(s.objects[static_cast<size_t>(p.object)].material);
    ++material_pixels[m.name];
    if (m.relief) {
      relief = true;
      max_layers = std::max(max_layers, m.relief->layers);
      const auto meth = m.relief->method;
      (meth == scene::ReliefMethod::Iterative                                           ? iterative
       : meth == scene::ReliefMethod::DistanceMap || meth == scene::ReliefMethod::DistanceMapRefined ? dist_map
                                                                                         : pom) = true;
    }
  }
  const double q_aniso = quantile(aniso, kQuantile), q_lod = quantile(lod, kQuantile);
  json hist_lod = json::object(), hist_aniso = json::object();
  for (double l : lod) {
    const std::string k = std::to_string(static_cast<int>(std::floor(l)));
    hist_lod[k] = hist_lod.value(k, 0) + 1;
  }
  for (double a : aniso) {
    const std::string k = a < 2 ? "1-2" : a < 4 ? "2-4" : a < 8 ? "4-8" : a < 16 ? "8-16" : "16+";
    hist_aniso[k] = hist_aniso.value(k, 0) + 1;
  }

  // 2. Filter per material (each span picks its engine): the cheapest whose footprint gate passes
  //    on the material's pixels and whose render meets min_psnr_db there against the float EWA
  //    reference (each material meeting it, the scene does: its MSE is their pixel-weighted mean).
  const render::Frame ewa = render::render_ref(s, scene::Filter::Ewa);
  std::optional<render::Frame> tri;
  std::map<std::string, std::string> mat_filter;
  std::map<std::string, int> mat_cap;                    // Feline materials: the chosen probe cap
  std::map<std::string, render::Frame> feline_frames;    // their float renders at that cap
  json feline_json = json::object();
  std::string filter_why;
  for (const auto& [name, count] : material_pixels) {
    auto mine = [&](int object) { return s.objects[static_cast<size_t>(object)].material == name; };
    std::vector<double> ma, ml;
    for (const auto& p : bil.pixels)
      if (mine(p.object)) ma.push_back(p.aniso), ml.push_back(p.footprint_lod);
    const double qa = quantile(ma, kQuantile), ql = quantile(ml, kQuantile);
    std::string f = "ewa", why = name + ": ";
    if (ql <= kMinifyLod && qa <= kIsoAniso) {
      const double p = psnr_objects(bil, ewa, mine);
      why += "bilinear: footprint gate passes, PSNR " + fmt("%.2f", p) + " dB";
      if (p >= s.budget.min_psnr_db) f = "bilinear";
      else why += "; ";
    } else {
      why += "bilinear: footprint gate fails (p99 LOD " + fmt("%.2f", ql) + ", p99 anisotropy " + fmt("%.2f", qa) + "); ";
    }
    if (f == "ewa") {
      if (qa <= kIsoAniso) {
        if (!tri) tri = render::render_ref(s, scene::Filter::Trilinear);
        const double p = psnr_objects(*tri, ewa, mine);
        why += "trilinear: footprint gate passes, PSNR " + fmt("%.2f", p) + " dB";
        if (p >= s.budget.min_psnr_db) f = "trilinear";
      } else {
        why += "trilinear: footprint gate fails (p99 anisotropy " + fmt("%.2f", qa) + ")";
      }
    }
    if (f == "ewa") {
      FelineChoice fc = choose_feline(s, name, ewa, mine);
      why += "; " + fc.why;
      feline_json[name] = fc.j;
      if (fc.cap > 0) {
        f = "feline";
        mat_cap[name] = fc.cap;
        feline_frames.emplace(name, std::move(*fc.frame));
      }
    }
    mat_filter[name] = f;
    filter_why += (filter_why.empty() ? "" : " | ") + why;
  }
  auto uses = [&](const std::string& f) {
    return std::any_of(mat_filter.begin(), mat_filter.end(), [&](const auto& kv) { return kv.second == f; });
  };
  // The scene's most capable filter names the unit's footprint path and its weights.
  const std::string filter = uses("ewa") ? "ewa" : uses("feline") ? "feline" : uses("trilinear") ? "trilinear" : "bilinear";
  // The chosen probe caps from here on (the planned unit's cycles).
  for (const auto& [name, cap] : mat_cap) s.materials.at(name).feline_max_probes = cap;
  // The picture of the plan: each pixel from its material's filter; its PSNR against EWA.
  render::Frame planned_frame = ewa;
  for (const auto& p : planned_frame.pixels) {
    const std::string& mat = s.objects[static_cast<size_t>(p.object)].material;
    const std::string& f = mat_filter.at(mat);
    if (f != "ewa")
      planned_frame.image.at(p.x, p.y) =
          (f == "bilinear" ? bil : f == "feline" ? feline_frames.at(mat) : *tri).image.at(p.x, p.y);
  }
  const double filter_psnr = render::psnr_covered(planned_frame, ewa);
  // texels read by the material's filter (texel bandwidth): as render_ref counts them; Feline its
  // frame's (8 per probe)
  for (size_t i = 0; i < planned_frame.pixels.size(); ++i) {
    auto& p = planned_frame.pixels[i];
    const std::string& mat = s.objects[static_cast<size_t>(p.object)].material;
    const std::string& f = mat_filter.at(mat);
    if (f == "feline") {
      const auto& fp = feline_frames.at(mat).pixels;
      if (i < fp.size() && fp[i].x == p.x && fp[i].y == p.y) p.texels = fp[i].texels;
    } else if (f != "ewa") {
      p.texels = f == "bilinear" ? 4 : 8;
    }
  }
  const render::Frame* chosen_frame = filter == "ewa"         ? &ewa
                                      : filter == "feline"    ? &feline_frames.begin()->second
                                      : filter == "trilinear" ? &*tri
                                                              : &bil;

  // 2c. Pipeline per material (plan_pipeline.hpp): object space where it meets the budget for
  //     fewer clocks than the material's screen-space filter, measured by rendering the material
  //     alone through both. The texture-unit top has no object-space path: the choice is
  //     reported; the package and the cycles below are the screen-space unit's.
  std::vector<PipelineChoice> pipelines;
  for (const auto& [name, f] : mat_filter)
    pipelines.push_back(choose_pipeline(s, name, filter_named(f), std::count(noise.materials.begin(), noise.materials.end(), name) > 0));

  // 2b. Relief method per material (choose_relief). The planned unit keeps the engines of the
  //     authored methods (the scene must render on it as written); the choice is reported, with the
  //     distance map's memory.
  json relief_json = json::object();
  std::string relief_why;
  if (relief) {
    const render::Frame ref_bil = render::render_ref(s, scene::Filter::Bilinear);
    for (const auto& [name, m] : s.materials) {
      if (!m.relief || !material_pixels.count(name)) continue;
      const ReliefChoice c = choose_relief(s, name, ref_bil);
      json cands = json::array();
      std::string line;
      for (const auto& k : c.cands) {
        json j = {{"method", scene::to_string(k.method)}, {"psnr_db", k.psnr_db}, {"cycles_per_px", k.cycles_per_px},
                  {"steps_per_px", k.steps_per_px}};
        if (k.map_bytes)
          j["map"] = {{"voxels", k.map_bytes}, {"bits_per_voxel", tu::fmt::kDmCodeW}, {"bits", k.map_bytes * tu::fmt::kDmCodeW}};
        cands.push_back(j);
        line += std::string(line.empty() ? "" : ", ") + scene::to_string(k.method) + " " + fmt("%.2f dB", k.psnr_db) +
                " " + fmt("%.2f cycles/px", k.cycles_per_px) +
                (k.map_bytes ? " (map " + std::to_string(k.map_bytes) + " voxels x " + std::to_string(tu::fmt::kDmCodeW) +
                                   " bits)"
                             : "");
      }
      relief_json[name] = {{"authored", scene::to_string(c.authored)},
                           {"chosen", scene::to_string(c.chosen)},
                           {"meets_min_psnr_db", c.meets},
                           {"layers", m.relief->layers},
                           {"candidates", cands},
                           {"source", "C-model bilinear render vs the float reference (256-layer march) on the "
                                      "material's pixels; cycles: relief::stage_cycles per pixel of the material"}};
      relief_why += (relief_why.empty() ? "" : "\n") + std::string("  ") + name + ": " + line + "\n    -> " +
                    scene::to_string(c.chosen) + (c.meets ? " (cheapest meeting " : " (best; none meets ") +
                    fmt("%g dB", s.budget.min_psnr_db) + ")" +
                    (c.chosen != c.authored ? std::string("; the scene authors ") + scene::to_string(c.authored) +
                                                  " and the planned unit keeps its engine"
                                            : "");
    }
  }

  // 3. Blocks and variants from the measured table.
  const std::string psnr_field = s.source + ": /error_budget/min_psnr_db = " + fmt("%g", s.budget.min_psnr_db);
  const std::string texel_field = s.source + ": /error_budget/max_texel_err = " + fmt("%g", s.budget.max_texel_err);
  const TRow* persp = cheapest(rows_of("persp"), [&](const TRow& r) { return r.max_abs <= s.budget.max_texel_err; },
                               [](const TRow& r) { return -r.max_abs; }, texel_field, "persp", "%.4g texel");
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

  Unit spec;
  spec.area_only = {setup};
  spec.stages.push_back({{persp}});
  if (relief) spec.stages.push_back({relief_rows});
  const TRow *weights = nullptr, *clip = nullptr;
  // B2: the scene's footprint variant ("footprint": analytic | recurrence).
  const bool ell_rec = s.footprint == scene::Footprint::Recurrence;
  if (filter != "bilinear") spec.stages.push_back({{one("ellipse", ell_rec ? "recurrence" : "analytic")}});
  // Weight sources: PSNR of the bit-accurate C-model render (EWA with that source) against the
  // float EWA reference, on the texture path (relief off on both sides: the relief method is its
  // own block). Rows the engine does not implement keep their 20 log10(1/rms).
  std::map<const TRow*, double> render_db;
  if (filter == "ewa") {
    const scene::Scene flat = scene::without_relief(s);
    const render::Frame ref_flat = render::render_ref(flat, scene::Filter::Ewa);
    for (const TRow* r : weight_cands)
      if (const auto src = engine_source(*r)) {
        render::CmodelOptions o = render::texture_path_only();
        o.weights = src;
        render_db[r] = render::psnr_covered(render::render_cmodel(flat, scene::Filter::Ewa, o), ref_flat);
      }
  }
  auto weight_render_db = [&](const TRow& r) {
    const auto it = render_db.find(&r);
    return it != render_db.end() ? it->second : weight_db(r);
  };
  auto render_ok = [&](const TRow& r) { return weight_render_db(r) >= s.budget.min_psnr_db; };
  // Clip-volume variants: PSNR of the C-model EWA render with the scene's border weights in that
  // variant (every material, scene::with_clip) against the float EWA with the exact Phi border
  // weights, on the texture path (docs/blocks/ewa.md "Border weights"); one render per variant.
  std::map<std::string, double> clip_db;
  if (filter == "ewa") {
    const scene::Scene flat = scene::without_relief(s);
    const render::Frame ref_clip = render::render_ref(scene::with_clip(flat, "mm_p3"), scene::Filter::Ewa);
    for (const TRow* r : rows_of("clip_volume"))
      if (!clip_db.count(r->variant))
        clip_db[r->variant] = render::psnr_covered(
            render::render_cmodel(scene::with_clip(flat, r->variant), scene::Filter::Ewa, render::texture_path_only()), ref_clip);
  }
  auto clip_render_db = [&](const TRow& r) { return clip_db.at(r.variant); };
  auto clip_ok = [&](const TRow& r) { return clip_render_db(r) >= s.budget.min_psnr_db; };
  if (filter == "ewa") {
    weights = cheapest(weight_cands, render_ok, weight_render_db, psnr_field, "EWA weight source", "%.1f dB");
    clip = cheapest(rows_of("clip_volume"), clip_ok, clip_render_db, psnr_field, "clip_volume", "%.1f dB");
    spec.stages.push_back({{clip}});
    spec.stages.push_back({{weights}});
  }
  spec.texels_per_pixel = texels_per_pixel(*chosen_frame);

  // Shading: a scene with a light needs the stage, one without leaves it out. Its model is the one
  // the lit materials name, else the cheapest pipelined model (II = 1) whose MAD against Blinn on
  // the thesis grid (the bit-accurate model, brdf::vs_blinn_fx) meets max_brdf_mad.
  const bool shade = !s.lights.empty();
  const TRow* brdf_row = nullptr;
  std::map<const TRow*, double> brdf_mad;
  std::string shade_why = "no light in the scene: no shading stage";
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
                          [&](const TRow& r) { return -brdf_mad.at(&r); }, mad_field, "BRDF model", "%.5f");
      shade_why = "cheapest with MAD vs Blinn <= " + fmt("%g", s.budget.max_brdf_mad);
    }
    if (brdf_mad.count(brdf_row)) shade_why += " (MAD " + fmt("%.5f", brdf_mad.at(brdf_row)) + ")";
    spec.stages.push_back({{brdf_row}});
  }

  // The full unit: every block, every weight source and relief method, EWA texel walk.
  Unit full;
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
  const bool has_ewa = uses("ewa"), has_tri = filter != "bilinear";
  auto weight_bit = [&](const TRow* w) { return !w ? 0 : w->block == "gauss_weight" ? 1 : w->scheme == "weight_table_1d" ? 2 : 4; };
  auto log2n = [&](const std::string& scheme) {
    for (const TRow* r : weight_cands)
      if (r->scheme == scheme) return static_cast<int>(std::lround(std::log2(std::stod(r->variant.substr(3)))));
    return 0;
  };
  const std::string origin = "`texunit plan " + opt.scene + "` from " + report_name;
  // EWA border weights: in the unit when an EWA material asks for them; their clip volume is the one
  // the materials name (it must have an RTL, and the unit has one), else the plan's choice.
  std::set<std::string> clip_named;
  for (const auto& [name, m] : s.materials)
    if (!m.clip.empty() && mat_filter.count(name) && mat_filter.at(name) == "ewa") {
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
  Config planned{has_tri, has_ewa, uses("bilinear"), uses("trilinear"), false, relief, pom, iterative, max_layers, weight_bit(weights),
                       log2n("weight_table_1d"), log2n("weight_table_2d"), persp->variant == "klane4" ? 4 : 1,
                       ell_rec && has_tri, false, shading::kUnitModel, /*distance_map, set below*/ false,
                       /*wrap_modes, set below*/ 31, !clip_named.empty(), clip_code};
  planned.feline = uses("feline");
  // The full unit: everything in, relief up to the scene format's 256 layers.
  Config planned_shaded = planned;
  planned_shaded.shading = shade;
  planned_shaded.distance_map = dist_map;
  // Wrap modes (tu_texel_addr): repeat always, another mode when a texture an object samples uses it.
  planned_shaded.wrap_modes = 1;
  std::vector<std::string> wrap_names;
  for (const auto& o : s.objects) {
    const auto& a = s.textures.at(s.materials.at(o.material).texture).addressing;
    planned_shaded.wrap_modes |= 1 << static_cast<int>(a.u) | 1 << static_cast<int>(a.v);
  }
  for (int k = 0; k < 5; ++k)
    if (planned_shaded.wrap_modes >> k & 1) wrap_names.push_back(scene::kWrapNames[k]);
  // Texel formats (tu_texel_decode): the formats and sRGB of the textures objects sample (rgba8,
  // the decode's default path, always); the port as wide as the widest of them.
  planned_shaded.tex_formats = 1;
  planned_shaded.srgb = false;
  planned_shaded.texel_w = 0;
  planned_shaded.bc1 = false;
  std::vector<std::string> format_names;
  for (const auto& o : s.objects) {
    const auto& t = s.textures.at(s.materials.at(o.material).texture);
    if (t.format == static_cast<int>(tex::TexelFormat::Bc1)) {  // the block fetch (64-bit RAM words)
      planned_shaded.bc1 = true;
      planned_shaded.srgb = planned_shaded.srgb || t.srgb;
      continue;
    }
    planned_shaded.tex_formats |= 1 << t.format;
    planned_shaded.srgb = planned_shaded.srgb || t.srgb;
    planned_shaded.texel_w = std::max(planned_shaded.texel_w, tex::bits_per_texel(static_cast<tex::TexelFormat>(t.format)));
  }
  if (planned_shaded.texel_w == 0) planned_shaded.texel_w = 32;
  for (int k = 0; k < static_cast<int>(std::size(tex::kTexelFormatNames)); ++k)
    if (planned_shaded.tex_formats >> k & 1) format_names.push_back(tex::kTexelFormatNames[k]);
  if (planned_shaded.bc1) format_names.push_back(tex::format_name(tex::TexelFormat::Bc1));
  planned_shaded.noise = noise.on;
  if (noise.on) planned_shaded.noise_dims = noise.dims, planned_shaded.noise_cores = noise.cores;
  planned_shaded.water = noise.water;
  planned_shaded.afvis = afv.on;
  if (brdf_row) planned_shaded.shade_model = shading::model_of(brdf_row->variant);
  // The full unit: F_MSH (the thesis's model) when the scene does not need another.
  const Config everything = [&] {
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
    return filter_named(it == mat_filter.end() ? filter : it->second);
  };
  const auto planned_weights = weights ? engine_source(*weights) : std::nullopt;
  // The shading stage (II = 1, fed one word per pixel) adds its latency once, at the end.
  const uint64_t spec_shade = shade ? static_cast<uint64_t>(brdf::shade::latency(planned_shaded.shade_model)) : 0;
  const uint64_t full_shade = static_cast<uint64_t>(brdf::shade::latency(everything.shade_model));
  uint64_t spec_cycles = scene_cycles(planned_filter, relief, planned_weights, planned.ell_recurrence) + spec_shade;
  // The noise scheme: the octave-serial unit (one core instead of NoiseCores, the same back-end:
  // the smaller by construction) when the frame's clocks with it meet the budget's max_cycles,
  // else the pipelined one (also without a cycle budget).
  json scheme_json = nullptr;
  if (noise.on) {
    const uint64_t serial = scene_cycles(planned_filter, relief, planned_weights, planned.ell_recurrence, noise.cores) + spec_shade;
    const bool pick_serial = opt.max_cycles > 0 && double(serial) <= opt.max_cycles && noise.cores > 1;
    planned_shaded.noise_scheme = pick_serial ? 1 : 0;
    scheme_json = {{"picked", pick_serial ? "octave_serial" : "pipelined"},
                   {"max_cycles", opt.max_cycles > 0 ? json(opt.max_cycles) : json("none (plan --max-cycles)")},
                   {"pipelined_cycles", spec_cycles},
                   {"octave_serial_cycles", serial},
                   {"cores", {{"pipelined", noise.cores}, {"octave_serial", 1}}},
                   {"why", opt.max_cycles <= 0 ? "no cycle budget: the fastest"
                           : pick_serial ? "the octave-serial unit meets max_cycles with one core"
                           : double(spec_cycles) <= opt.max_cycles ? "only the pipelined unit meets max_cycles"
                                                                        : "no scheme meets max_cycles: the fastest"}};
    if (pick_serial) spec_cycles = serial;
  }
  const uint64_t full_cycles = scene_cycles(planned_filter, true, planned_weights, false) + full_shade;  // the same picture
  const uint64_t authored_cycles = scene_cycles(authored, true, std::nullopt, false) + full_shade;

  const size_t px = bil.pixels.size();
  json out = {{"scene", s.source},
              {"report_table", report_name},
              {"covered_pixels", px},
              {"footprint", {{"p99_lod", q_lod}, {"p99_anisotropy", q_aniso}, {"lod_histogram", hist_lod},
                             {"anisotropy_histogram", hist_aniso}}},
              {"budget", {{"max_texel_err", s.budget.max_texel_err}, {"min_psnr_db", s.budget.min_psnr_db}}},
              {"filter", filter},
              {"filters", mat_filter},
              {"feline_max_probes", mat_cap},
              {"feline_candidates", feline_json},
              {"filter_psnr_db", std::isinf(filter_psnr) ? json("reference") : json(filter_psnr)},
              {"filter_reasons", filter_why},
              {"relief", relief},
              {"relief_methods", relief_json},
              {"shading", shade ? json({{"model", brdf_row->name()}, {"why", shade_why}, {"latency_cycles", brdf_row->latency}})
                                : json(false)},
              {"wrap_modes", wrap_names},
              {"texel_formats", {{"formats", format_names}, {"srgb", planned_shaded.srgb},
                                 {"texel_port_bits", planned_shaded.bc1 ? 64 : planned_shaded.texel_w}}},
              {"texture_formats", plan::texel_format_plan(s, planned_frame, s.budget.min_psnr_db)},
              {"noise", noise.on ? json({{"materials", noise.materials}, {"dims", noise.dims}, {"octave_cores", noise.cores},
                                         {"scheme", scheme_json},
                                         {"latency_cycles", tu::fmt::kNoiseUnitLatency},
                                         {"water", noise.water ? json({{"latency_cycles", tu::fmt::kNoiseWaterLatency},
                                                                       {"clocks_per_pixel", tu::fmt::kWaterPasses}})
                                                               : json(false)},
                                         {"psnr_db_by_octaves", noise.psnr_by_octaves},
                                         {"psnr_source", "C-model render, octaves capped at K, vs the float reference, procedural pixels"}})
                                 : json(false)},
              {"persp", persp->name()},
              {"weights", weights ? json(weights->name()) : json(nullptr)},
              {"weights_db", weights ? json(weight_render_db(*weights)) : json(nullptr)},
              {"weights_db_source", weights && render_db.count(weights) ? "C-model EWA render vs float EWA (texture path)"
                                                                        : "20 log10(1/rms) of the weights"},
              {"clip_volume", clip ? json(clip->name()) : json(nullptr)},
              {"clip_volume_db", clip ? json(clip_render_db(*clip)) : json(nullptr)},
              {"clip_volume_db_source", "C-model EWA render with border weights vs float EWA with exact Phi border weights (texture path)"},
              {"clip_volume_render_db", clip_db},
              {"specialised", unit_json(spec)},
              {"full", unit_json(full)},
              {"scene_cycles", {{"specialised", spec_cycles}, {"full", full_cycles}, {"full_as_authored", authored_cycles},
                                {"model", "ewa::stream_cycles on the C-model render (texture path): equal to the RTL"}}},
              {"scene_us", {{"specialised", spec.area_measured() ? json(double(spec_cycles) / spec.fmax_mhz()) : json(kNoArea)},
                            {"full", full.area_measured() ? json(double(full_cycles) / full.fmax_mhz()) : json(kNoArea)}}},
              {"cheapest_by", g_cost_basis},
              {"area_note", "cells are the sum of the blocks' Yosys cells (each block synthesised alone)"}};
  json pipes = json::object();
  for (const auto& pc : pipelines) {
    json tries = json::array();
    for (const auto& k : pc.tries)
      tries.push_back({{"spacing", k.spacing}, {"rendered", k.rendered}, {"samples", k.samples}, {"holes", k.holes},
                       {"overlaps", k.overlaps}, {"psnr_db", k.rendered ? json(k.psnr_db) : json(nullptr)},
                       {"clocks_per_px", k.rendered ? json(k.clocks_per_px) : json(nullptr)}, {"error", k.error}});
    pipes[pc.material] = {{"pipeline", pc.object_space ? "object-space" : "screen"}, {"screen_filter", pc.screen_filter},
                          {"covered_pixels", pc.covered}, {"screen_clocks_per_px", pc.screen_clocks_per_px},
                          {"object_space_clocks_per_sample", pc.sample_clocks}, {"object_space", tries}, {"why", pc.why}};
  }
  out["pipelines"] = pipes;
  std::optional<double> afv_cells;
  for (const TRow* r : rows_of("afvis"))
    if (r->cells > 0) afv_cells = r->cells;
  out["af_visibility"] =
      afv.on ? json({{"materials", afv.materials}, {"pixels", afv.pixels}, {"walker_clocks_per_px", afv.walk_on},
                     {"ewa_walker_clocks_per_px", afv.walk_off}, {"filter_stream_cycles", afv.stream_on},
                     {"filter_stream_cycles_without", afv.stream_off},
                     {"cells", afv_cells ? json(*afv_cells) : json("not measured: no afvis row with Yosys cells in the report table")},
                     {"source", "C-model render with relief; walker clocks afvis::Out::clocks vs tu_ewa's box + 12; "
                                "ewa::stream_cycles of the filter stream (= Verilator, TextureUnitRtl.AfVisibility*)"}})
             : json(false);
  // Everything is decided before anything is written, and every file is written or none.
  cli::Outputs outs;
  for (const auto& [path, cfg, what] : {std::tuple{opt.out_sv, planned_shaded, "specialised"}, {opt.out_full_sv, everything, "full"}}) {
    if (path.empty()) continue;
    if (!(std::ofstream(outs.stage(path)) << package(cfg, origin + " (" + what + " unit)")))
      throw std::runtime_error(path + ": cannot write the file");
  }
  outs.commit();
  for (const auto& path : {opt.out_sv, opt.out_full_sv})
    if (!path.empty()) std::cerr << "wrote " << path << "\n";
  if (opt.json) {
    std::cout << out.dump(2) << "\n";
    return 0;
  }
  std::printf("scene %s: %zu covered pixels; footprint p99 LOD %.2f, p99 anisotropy %.2f\n", s.source.c_str(), px, q_lod, q_aniso);
  std::printf("budget: max_texel_err %g texel, min_psnr_db %g dB\n", s.budget.max_texel_err, s.budget.min_psnr_db);
  std::string per_mat;
  for (const auto& [name, f] : mat_filter)
    per_mat += (per_mat.empty() ? "" : ", ") + name + " " + f +
               (mat_cap.count(name) ? " (Nmax " + std::to_string(mat_cap.at(name)) + ")" : "");
  std::printf("filters: %s; the plan's picture %s against the float EWA\n  (%s)\n", per_mat.c_str(),
              std::isinf(filter_psnr) ? "is" : (fmt("%.2f", filter_psnr) + " dB").c_str(), filter_why.c_str());
  std::printf("pipeline per material (each material rendered alone, texture path; the top has no object-space path):\n");
  for (const auto& pc : pipelines) std::printf("  %s\n", pc.why.c_str());
  std::string relief_engines;
  for (const auto& [on, name] : {std::pair{pom, "pom"}, {iterative, "iterative"}, {dist_map, "distance map"}})
    if (on) relief_engines += (relief_engines.empty() ? "" : " + ") + std::string(name);
  std::printf("relief: %s\n", relief ? relief_engines.c_str() : "none (no relief hardware)");
  if (!relief_why.empty()) std::printf("relief methods (PSNR vs the float reference, relief stage cycles):\n%s\n", relief_why.c_str());
  std::string wraps;
  for (const auto& w : wrap_names) wraps += (wraps.empty() ? "" : ", ") + w;
  std::printf("wrap modes: %s (the texel addressing leaves out the others)\n", wraps.c_str());
  for (const auto& [name, t] : out["texture_formats"].items())  // plan_formats.hpp
    std::printf("texture %s: %s (authored %s), %.2f texels/pixel: saves %.0f bits of memory, %.2f bits/pixel of "
                "bandwidth\n", name.c_str(), t["picked"].get<std::string>().c_str(), t["authored"].get<std::string>().c_str(),
                t["texels_per_pixel"].get<double>(), t["memory_bits_saved"].get<double>(),
                t["bandwidth_bits_per_pixel_saved"].get<double>());
  std::printf("persp: %s, max %.4g texel\n", persp->name().c_str(), persp->max_abs);
  std::printf("shading: %s\n", shade ? (brdf_row->name() + ", " + shade_why).c_str() : shade_why.c_str());
  if (noise.on)
    std::printf("noise unit: %d-D, %d octaves (latency %d), the fewest meeting %g dB on the procedural "
                "pixels: %s%s\n  scheme %s (%s): %s clocks pipelined, %s octave-serial\n", noise.dims, noise.cores,
                tu::fmt::kNoiseUnitLatency, s.budget.min_psnr_db, noise.psnr_by_octaves.dump().c_str(),
                noise.water ? "; with the water back-end (3 octave sums per water pixel)" : "",
                scheme_json["picked"].get<std::string>().c_str(), scheme_json["why"].get<std::string>().c_str(),
                scheme_json["pipelined_cycles"].dump().c_str(), scheme_json["octave_serial_cycles"].dump().c_str());
  else
    std::printf("noise unit: none (no procedural material)\n");
  if (afv.on) {
    std::string names;
    for (const auto& n : afv.materials) names += (names.empty() ? "" : ", ") + n;
    std::printf("af visibility: tu_afvis in for %s: %zu pixels, %.1f walker clocks/px against %.1f through tu_ewa; filter "
                "stream %llu clocks against %llu (%+.1f %%); cells %s\n", names.c_str(), afv.pixels, afv.walk_on, afv.walk_off,
                (unsigned long long)afv.stream_on, (unsigned long long)afv.stream_off,
                100.0 * (double(afv.stream_on) / double(std::max<uint64_t>(1, afv.stream_off)) - 1),
                afv_cells ? fmt("%.0f (tu_afvis, generic Yosys)", *afv_cells).c_str() : "not measured");
  } else {
    std::printf("af visibility: none (no material asks for it: tu_afvis left out)\n");
  }
  if (weights) std::printf("weights: %s, %.2f dB (%s); clip volume: %s, %.2f dB (C-model EWA render with border "
                           "weights vs float EWA with exact Phi ones, texture path)\n",
                           weights->name().c_str(), weight_render_db(*weights),
                           render_db.count(weights) ? "C-model EWA render vs float EWA, texture path" : "20 log10(1/rms)",
                           clip->name().c_str(), clip_render_db(*clip));
  auto cyc = [&](uint64_t c) {
    return fmt("%.0f", double(c)) + " (" + fmt("%.2f", double(c) / double(std::max<size_t>(1, px))) + "/px)";
  };
  std::printf("\n%-12s %10s %6s %13s %22s %12s %14s %9s %10s\n", "unit", "latency", "II", "texels/pixel", "scene cycles",
              "cells (sum)", "area um2 (sum)", "fmax MHz", "scene us");
  for (const auto& [name, u, c] : {std::tuple<const char*, const Unit*, const uint64_t*>{"specialised", &spec, &spec_cycles},
                                   {"full", &full, &full_cycles}}) {
    const bool a = u->area_measured();
    std::printf("%-12s %10lld %6.2f %13.2f %22s %12s %14s %9s %10s\n", name, static_cast<long long>(u->latency()), u->ii(),
                u->texels_per_pixel, cyc(*c).c_str(), u->cells_measured() ? fmt("%.0f", u->cells()).c_str() : "not measured",
                a ? fmt("%.0f", u->area_um2()).c_str() : "not measured", a ? fmt("%.1f", u->fmax_mhz()).c_str() : "-",
                a ? fmt("%.1f", double(*c) / u->fmax_mhz()).c_str() : "-");
  }
  std::printf("%-12s %10s %6s %13s %22s  (each material's own filter)\n", "full, authored", "", "", "",
              cyc(authored_cycles).c_str());
  std::printf("scene cycles: the RTL texture unit on the scene's texture path, exact cycle model (ewa::stream_cycles\n"
              "  on the C-model render's per-pixel work; = Verilator); specialised and full with the plan's\n"
              "  filter per material (the same picture, bit for bit)\n"
              "cells: sum of the blocks' Yosys cells (each block synthesised alone; texel fetch not included)\n"
              "area: sum of the blocks' osu018 standard-cell area; fmax: the slowest block's (each block alone,\n"
              "  docs/area-timing.md); scene us = scene cycles / fmax; cheapest variant by %s\n",
              g_cost_basis.c_str());
  return 0;
}

}  // namespace tu::plan
