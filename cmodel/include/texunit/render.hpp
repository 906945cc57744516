// Rendering a scene: visibility (nearest triangle per pixel centre), texture coordinates,
// footprint and filtering. render_ref is the float reference (double throughout) that the C model
// and the RTL are measured against.
#pragma once

#include <iosfwd>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "brdf/brdf_common.hpp"
#include "ellipse/ellipse_ref.hpp"
#include "afvis/afvis.hpp"
#include "ewa/ewa_cycles.hpp"
#include "noise/noise_proc.hpp"
#include "texture/trilinear_lod.hpp"
#include "texunit/image.hpp"
#include "texunit/scene.hpp"

namespace tu::render {

struct PixelRecord {
  int x = 0, y = 0;
  int object = -1;
  double u = 0, v = 0;  // level-0 texels
  double lod = 0;       // mip level used (EWA: the walk's level; trilinear: GL lambda, the blend position)
  int texels = 0;       // texels read
  int texels_inside = 0;  // EWA: texels with a non-zero weight (cycle-independent count)
  uint32_t b2_flags = 0;   // C-model engine: B2 flags (ellipse_fx.hpp; kHorizon = B1 guard)
  uint32_t ewa_flags = 0;  // C-model engine, EWA: ewa::fx flags (ewa_fx.hpp)
  int levels = 0;          // C-model engine, EWA: mip levels the set-up tried (ewa::pixel_cost)
  int ewa_blocks = 0;      // C-model engine, EWA: 2 x 2 blocks of the box (the K = 4 walk's clocks)
  uint32_t tri_flags = 0;  // trilinear: tex::TriFlag (magnify, min/max lod clamp, pyramid clamp)
  uint32_t relief_flags = 0;  // relief materials: relief::ReliefFlag (Vz guard, non-convergence)
  double aniso = 1;          // footprint anisotropy major / minor (after the material's clamp)
  double footprint_lod = 0;  // log2 of the clamped minor axis, in [0, coarsest level] (`texunit plan`)
  img::Rgba8 color;
  int relief_n = 0;     // relief materials: layers N of the material's method (0: no relief)
  int relief_steps = 0; // relief materials: march steps (POM) or iterations (iterative)
  int probes = 0;       // Feline: trilinear probes N (0: another filter)
  // CmodelOptions::trace_texels: the filter's texel reads in order (tex::TexelTrace word
  // addresses; texture i of the scene's textures at i << 32).
  std::vector<uint64_t> texel_addrs;
  // AF with parallax visibility (C-model engine): texels traced, depth reads, texels kept.
  int afv_traced = 0, afv_steps = 0, afv_visible = 0;
  uint64_t afv_clocks = 0;  // the visibility walker's clocks (afvis::Out::clocks; 0: not an afvis pixel)
};

struct Frame {
  img::Rgba8Image image;
  std::vector<PixelRecord> pixels;  // covered pixels, row-major
};

// Index of the nearest triangle hit at each pixel centre: object and triangle, or -1.
struct Cover {
  int object = -1, triangle = -1;
};
// Rows on `threads` threads (<= 0: every core); the same result for any count.
std::vector<Cover> visibility(const scene::Scene& s, int threads = 0);
size_t covered(const std::vector<Cover>& cov);  // pixels with an object
// The unit's spans: maximal runs of one row's pixels covered by the same triangle, row-major
// (the order of the covered pixels in Frame::pixels); `width` is the camera's.
struct CoverRun {
  int y = 0, x0 = 0, x1 = 0;  // pixels x0 .. x1 (inclusive) of row y
  Cover c;
};
std::vector<CoverRun> cover_runs(const std::vector<Cover>& cov, int width);
// Each object's material (resolved once per render instead of per pixel by name).
std::vector<const scene::Material*> object_materials(const scene::Scene& s);

// Set-up of an object's triangles (uv in level-0 texels of a tex_w x tex_h texture): the float
// coefficients, and B1's: each triangle rebased by whole periods of its wrap modes
// (persp::rebased; docs/blocks/persp.md "uv rebase"), then quantised to B1's formats. Every
// engine's lowering (C model, RTL harness, Icarus stimulus, planner) calls setup_fx; the float
// engines call it too, so that what B1 cannot set up is refused everywhere. A persp::SetupError
// names the file and the object as scene::object_where does, then the triangle (and for an
// overflow, the reason).
std::vector<persp::Coef9> setup_ref(const scene::Scene& s, size_t object, int tex_w, int tex_h);
std::vector<persp::Unit::Coefs> setup_fx(const scene::Scene& s, size_t object, int tex_w, int tex_h);

// Float reference render. `filter`, when given, overrides every material's filter; scenes with a
// light are shaded (brdf::shade::ref on the filtered colour; "auto" models: `shade_model`, else the
// unit's, texunit/shading.hpp).
Frame render_ref(const scene::Scene& s, std::optional<scene::Filter> filter = {},
                 std::optional<brdf::Model> shade_model = {});

// Bit-accurate C-model render (docs/blocks/ewa.md): per covered pixel (same visibility as the
// reference) B1 persp::Unit on the quantised coefficients, B2 ellipse::fx::analytic, then the
// fixed nearest / bilinear / trilinear (the GL LOD rule on B2's lrho, tex::trilinear_lod, with the
// material's bias and min / max lod) or EWA fx with the material's weight source and a 1024-texel cap.
enum class AfvisMode { Scene, On, Off };
struct CmodelOptions {
  // Per-pixel uv-shift step between B1 and the filter (relief mapping hooks in here): pixel,
  // object, and the B1 u, v codes (s(PerspUvW).TexUvF) to modify in place.
  std::function<void(int x, int y, int object, int64_t* u, int64_t* v)> uv_shift;
  std::optional<scene::WeightSource> weights;  // overrides every material's EWA weight source
  bool progress = false;  // a simple progress bar on stderr
  // Relief materials: the material's method shifts (u, v) bit-accurately (relief::shift_texel_uv_fx,
  // the tu_pom_unit / tu_iter_parallax arithmetic) before uv_shift and the filter. false: the
  // texture path alone, as the RTL texture-unit top (no relief stage yet) computes it.
  bool relief = true;
  // Procedural materials take their colour from the noise unit (false: their texture, as the RTL
  // texture-unit top, which has no noise unit yet, renders them).
  bool procedural = true;
  // Threads for visibility and the pixels (rows; <= 0: every core). The frame is the same for
  // any count; a render with a uv_shift hook runs on one thread.
  int threads = 0;
  // Shading stage (scenes with a light): the model of materials whose specular model is "auto"
  // (the unit's; texunit/shading.hpp kUnitModel when not given).
  std::optional<brdf::Model> shade_model;
  // Record every pixel's texel reads (PixelRecord::texel_addrs; the texel-cache model).
  bool trace_texels = false;
  // AF with parallax visibility (docs/blocks/afvis.md) on EWA relief pixels: Scene = the
  // material's af_visibility flag, On / Off = every relief material / none (comparisons); the rule
  // and the min-depth pyramid level the trace runs on (0: the depth map itself).
  AfvisMode afvis = AfvisMode::Scene;
  afvis::Rule afvis_rule = afvis::Rule::Row;
  int afvis_pyramid = 0;
  int afvis_bias = afvis::kDefaultBias;  // the trace's bias (depth codes)
  // EWA walk lanes K (ewa::fx::filter_lanes: 1 sequential, 2, 4): the same frame for every K
  // (RenderCmodel.EwaLanesGiveTheSameFrame); not applied to AF-with-visibility pixels.
  int ewa_lanes = 1;
};
// The options of the texture path alone (relief off), for comparisons with the RTL top.
inline CmodelOptions texture_path_only() {
  CmodelOptions o;
  o.relief = false;
  o.procedural = false;
  return o;
}
// log2(max anisotropy) as B2's laniso input (u(EllAnisoW).EllLogF, rounded, saturated); the RTL
// render engine sets the same.
uint32_t laniso_code(double max_aniso);
// The material's sampler LOD state as codes (bias, min / max lod, base / max level).
tex::LodParams lod_params(const scene::Material& m);

// The RTL texture unit's engine for a material's filter (its filt_i code).
ewa::Engine engine_of(scene::Filter f);
Frame render_cmodel(const scene::Scene& s, std::optional<scene::Filter> filter = {},
                    const CmodelOptions& opt = {});

// Procedural materials (docs/blocks/noise-appendix.md §5): the material's noise description in noise
// units (its texture of width tex_w fixes the uv grid), and the float reference's colour at level-0
// texel (u, v) with the pixel's Jacobian (the GL rule's rho limits the octaves).
noise::ProcParams procedural_params(const scene::Material& m, int tex_w);
// Per object: its material's parameters when procedural (texs: the objects' textures).
std::vector<std::optional<noise::ProcParams>> procedural_objects(const scene::Scene& s,
                                                                 const std::vector<tex::Texture>& texs);
img::Rgba8 procedural_ref(const noise::ProcParams& p, double u, double v, const ellipse::Jacobian& j);

// Ground truth (docs/blocks/texture.md "Ground truth"): per covered pixel, ss x ss stratified
// jittered samples (deterministic) of the surface seen at the pixel centre, each the level-0 texel
// at the exact perspective (u, v) (point sampled, REPEAT / CLAMP as the texture), on relief
// materials after the exact ray / height-field intersection (relief::exact_hit); box-weighted over
// the pixel square, or Gaussian-weighted over the unit disc like the EWA's pixel model. Samples
// beyond the horizon (q <= 0) are dropped. Records: u, v at the centre, texels = ss^2.
enum class TruthKernel { Box, Gaussian };
struct TruthOptions {
  int ss = 16;
  TruthKernel kernel = TruthKernel::Box;
  bool relief = true;     // false: the texture path alone (relief materials as flat)
  bool progress = false;  // a progress bar on stderr
};
Frame render_truth(const scene::Scene& s, const TruthOptions& opt = {});

// PSNR (RGB, 8-bit peak) over a's covered pixels that `keep` accepts (all by default), against the
// same pixels of b: the background, equal in every render, would inflate a whole-image PSNR.
// +inf when equal, NaN when no pixel is kept.
double psnr_covered(const Frame& a, const Frame& b, const std::function<bool(const PixelRecord&)>& keep = {});
// The pixels of objects whose material has relief (the relief PSNR of issue 13 item 3).
std::function<bool(const PixelRecord&)> relief_pixels(const scene::Scene& s);

// |a - b| per pixel (max over RGB) mapped to a blue-red heat map, `full_scale` levels = red.
img::Rgba8Image error_heatmap(const img::Rgba8Image& a, const img::Rgba8Image& b, int full_scale);

// Layer-count debug image (the seed's debug mode) when a material has adaptive relief: grey
// (N - 4) / (Nmax - 4) on that material's pixels, black elsewhere; nullopt otherwise.
std::optional<img::Gray8> layers_image(const scene::Scene& s, const Frame& f);

// The per-pixel guard flags the C model raises (B1, B2, trilinear, EWA, relief), one description
// for the --dump columns and the per-flag counts `render` prints.
struct PixelFlag {
  const char* name;
  uint32_t PixelRecord::*field;
  uint32_t mask;
  bool on(const PixelRecord& p) const { return (p.*field & mask) != 0; }
};
const std::vector<PixelFlag>& pixel_flags();
std::vector<size_t> flag_counts(const Frame& f);  // pixels with each flag, pixel_flags() order

// One CSV row per covered pixel (all or none, texunit/output.hpp): x,y,u,v,lod,texels,r,g,b,a,
// relief_n (layers N), relief_steps (march steps or iterations), then one 0/1 column per
// pixel_flags() entry. The stream overload writes the same text to a caller's checked stream.
void write_dump_csv(const std::string& path, const Frame& f);
void write_dump_csv(std::ostream& out, const Frame& f);

}  // namespace tu::render
