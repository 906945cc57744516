// The plan of `texunit plan` as data: decide() reads a scene and the measured report table and
// returns every decision (filter per material, relief method, Feline probe cap, noise scheme, the
// cheapest variant per block under the budget, the RTL configuration) with the measurements
// behind it (PSNRs, cycles, area). tools/texunit/plan.cpp prints it and writes the package.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "brdf/brdf_shade.hpp"
#include "ewa/ewa_cycles.hpp"
#include "planner/pipeline.hpp"
#include "planner/policy.hpp"
#include "texunit/formats.hpp"
#include "texunit/render.hpp"
#include "texunit/scene.hpp"
#include "texunit/shading.hpp"

namespace tu::plan {

// Clocks of the RTL texture unit (texture path) for a scene with `filter_of` choosing each
// material's filter: ewa::stream_cycles on the C-model render's per-pixel work (exact against
// Verilator, TextureUnitRtl.CyclesMatchPrediction); clip_variant: the unit's EwaClipVariant (the
// border pipeline's latency for materials with border weights); noise_objects[o]: object o's pixels
// go to the noise unit (a procedural material; TextureUnitRtl.ProceduralSceneEqualsCModelCyclesPredicted);
// covered (if given): the render's covered pixels.
uint64_t scene_stream_cycles(const scene::Scene& s, const std::function<scene::Filter(const scene::Material&)>& filter_of,
                             bool relief_stage, std::optional<scene::WeightSource> weights = std::nullopt,
                             bool ell_recurrence = false, int clip_variant = 0,
                             const std::vector<bool>& noise_objects = {}, size_t* covered = nullptr,
                             const std::vector<bool>& water_objects = {}, int noise_slots = 1,
                             const ewa::EngineParams& engine = {});

// The RTL configuration: tu_unit_cfg_pkg, read by the RTL top (tools/texunit/plan.cpp package()).
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

// Step 1 of the plan: per covered pixel of a render (the float bilinear reference, which records
// every pixel's footprint) its anisotropy and footprint LOD; pixels per material; the relief
// engines the authored materials need (POM: pom_fixed / pom_adaptive; distance map: both
// distance-map methods) and their largest layer count.
struct Footprints {
  std::vector<double> aniso, lod;
  std::map<std::string, size_t> material_pixels;
  bool relief = false, pom = false, iterative = false, distance_map = false;
  int max_layers = 0;
};
Footprints footprints(const scene::Scene& s, const render::Frame& f);
// Histograms of the JSON: LOD by floor (key "-1", "0", ...), anisotropy in "1-2", "2-4", "4-8",
// "8-16", "16+" (each bin [lo, hi)).
std::map<std::string, int> lod_histogram(const std::vector<double>& lod);
std::map<std::string, int> aniso_histogram(const std::vector<double>& aniso);

// What the texel addressing and decode need for the textures the scene's objects sample: the wrap
// modes (bit = tex::Wrap code; repeat always), the storage formats (bit = TexelFormat code; rgba8,
// the decode's default path, always; BC1 as the block fetch instead), sRGB, and the texel port's
// width (the widest non-BC1 format's bits per texel; 32 when there is none).
struct TextureNeeds {
  int wrap_modes = 1;
  std::vector<std::string> wrap_names;
  int tex_formats = 1;
  bool srgb = false, bc1 = false;
  int texel_w = 32;
  std::vector<std::string> format_names;
};
TextureNeeds texture_needs(const scene::Scene& s);

// Feline for an anisotropic material (docs/blocks/feline.md): the probe caps 2, 4, 8, 16 in turn,
// the first whose float render meets min_psnr_db on the material's pixels against the float EWA;
// chosen when its clocks per pixel (the RTL unit's exact cycle model on the material's objects
// alone, C-model probes) are fewer than the EWA's there.
struct FelineCap {
  double psnr_db = 0;
  std::optional<double> clocks_per_px;  // measured for the first cap meeting the budget
};
struct FelineChoice {
  int cap = 0;  // 0: not chosen
  std::string why;
  std::map<int, FelineCap> caps;           // the caps tried
  std::optional<double> ewa_clocks_per_px;  // with the first cap meeting the budget
};

// Relief method per material: each candidate method at the material's layers through the
// bit-accurate C-model render; the cheapest meeting min_psnr_db, else the best.
struct ReliefCandidate {
  scene::ReliefMethod method;
  double psnr_db = 0, cycles_per_px = 0, steps_per_px = 0;
  uint64_t map_bytes = 0;  // distance maps: W x H x D voxels of DmCodeW bits
};
struct ReliefChoice {
  scene::ReliefMethod authored, chosen;
  bool meets = false;
  int layers = 0;
  std::vector<ReliefCandidate> cands;
};
// Sets c.chosen (unchanged when there is no candidate) and c.meets: the candidate with the fewest
// cycles per pixel among those meeting min_psnr_db (the first of equals), else the one with the
// highest PSNR.
void pick_relief(ReliefChoice& c, double min_psnr_db);

// The noise unit (docs/blocks/noise-appendix.md §5): in the unit when a material is procedural.
struct NoisePlan {
  bool on = false, water = false;
  int dims = 2, cores = 0;
  std::vector<std::string> materials;
  std::map<int, double> psnr_by_octaves;  // octave cap K -> PSNR (infinite: identical)
  std::vector<bool> objects;        // per object: procedural
  std::vector<bool> water_objects;  // per object: water (the noise unit's three-pass pixels)
};
// The noise scheme: octave-serial when it meets max_cycles (and has more than one octave core).
struct NoiseScheme {
  bool octave_serial = false;
  double max_cycles = 0;  // 0: none
  uint64_t pipelined_cycles = 0, octave_serial_cycles = 0;
  std::string why;
};
// The scheme for the frame's clocks with each (max_cycles <= 0: no budget, the pipelined unit);
// `cores`: the pipelined unit's octave cores (with one, octave-serial saves nothing).
NoiseScheme choose_noise_scheme(double max_cycles, uint64_t pipelined, uint64_t serial, int cores);

// AF with parallax visibility (docs/blocks/afvis.md): tu_afvis in the unit when a material asks.
struct AfvisPlan {
  bool on = false;
  std::vector<std::string> materials;
  size_t pixels = 0;                 // pixels through tu_afvis
  double walk_on = 0, walk_off = 0;  // mean walker clocks per such pixel: tu_afvis, tu_ewa
  uint64_t stream_on = 0, stream_off = 0;  // the scene's filter stream clocks with and without
  std::optional<double> cells;       // tu_afvis's Yosys cells from the report table
};

struct Plan {
  size_t covered_pixels = 0;
  double p99_lod = 0, p99_aniso = 0;
  std::map<std::string, int> lod_histogram, aniso_histogram;  // floor(LOD); "1-2", "2-4", ..., "16+"
  // Filters: per material (the materials with pixels), the unit's (the most capable of them).
  std::map<std::string, scene::Filter> filters;
  scene::Filter filter = scene::Filter::Bilinear;
  std::map<std::string, int> feline_caps;               // Feline materials: the chosen probe cap
  std::map<std::string, FelineChoice> feline_candidates;  // materials that reached the Feline step
  double filter_psnr_db = 0;  // the plan's picture against the float EWA (infinite: identical)
  std::string filter_why;
  std::vector<PipelineChoice> pipelines;
  // Relief: the engines of the authored methods; the method per material (reported).
  bool relief = false, pom = false, iterative = false, distance_map = false;
  std::map<std::string, ReliefChoice> relief_choices;
  // Blocks (rows of the caller's report table).
  const TRow* persp = nullptr;
  const TRow* weights = nullptr;  // EWA units only
  const TRow* clip = nullptr;     // EWA units only
  std::map<const TRow*, double> weight_render_db_;  // weight rows the engine implements
  std::map<std::string, double> clip_db;            // clip variant -> render PSNR
  double weight_render_db(const TRow& r) const;     // render PSNR, else 20 log10(1/rms)
  bool weight_db_from_render(const TRow& r) const { return weight_render_db_.count(&r) > 0; }
  bool shading = false;
  const TRow* brdf = nullptr;
  std::string shade_why;
  NoisePlan noise;
  NoiseScheme noise_scheme;
  AfvisPlan afvis;
  std::vector<std::string> wrap_names, format_names;
  nlohmann::json texture_formats;  // planner/formats.hpp
  Unit spec, full;
  Config spec_cfg{}, full_cfg{};
  uint64_t spec_cycles = 0, full_cycles = 0, authored_cycles = 0;
  std::string cost_basis = kCostByArea;
};

// The plan of `authored` against `table` (named `table_name` in errors; the plan keeps pointers
// into it); max_cycles: the frame's cycle budget on the planned unit (0: none).
Plan decide(const scene::Scene& authored, const std::vector<TRow>& table, const std::string& table_name,
            double max_cycles);

}  // namespace tu::plan
