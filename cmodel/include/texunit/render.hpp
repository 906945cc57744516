// Rendering a scene: visibility (nearest triangle per pixel centre), texture coordinates,
// footprint and filtering. render_ref is the float reference (double throughout) that the C model
// and the RTL are measured against.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "ewa/ewa_cycles.hpp"
#include "texunit/image.hpp"
#include "texunit/scene.hpp"

namespace tu::render {

struct PixelRecord {
  int x = 0, y = 0;
  int object = -1;
  double u = 0, v = 0;  // level-0 texels
  double lod = 0;       // mip level used (EWA: the walk's level; trilinear: the blend position)
  int texels = 0;       // texels read
  int texels_inside = 0;  // EWA: texels with a non-zero weight (cycle-independent count)
  uint32_t b2_flags = 0;   // C-model engine: B2 flags (ellipse_fx.hpp; kHorizon = B1 guard)
  uint32_t ewa_flags = 0;  // C-model engine, EWA: ewa::fx flags (ewa_fx.hpp)
  int levels = 0;          // C-model engine, EWA: mip levels the set-up tried (ewa::pixel_cost)
  double aniso = 1;          // footprint anisotropy major / minor (after the material's clamp)
  double footprint_lod = 0;  // log2 of the clamped minor axis, in [0, coarsest level] (`texunit plan`)
  img::Rgba8 color;
  int relief_n = 0;     // relief materials: layers N of the material's method (0: no relief)
  int relief_steps = 0; // relief materials: march steps (POM) or iterations (iterative)
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
// Each object's material (resolved once per render instead of per pixel by name).
std::vector<const scene::Material*> object_materials(const scene::Scene& s);

// Set-up of an object's triangles (uv in level-0 texels of a tex_w x tex_h texture): the float
// coefficients, and the same quantised to B1's formats. A persp::SetupError names the file and
// the object as scene::object_where does, then the triangle.
std::vector<persp::Coef9> setup_ref(const scene::Scene& s, size_t object, int tex_w, int tex_h);
std::vector<persp::Unit::Coefs> setup_fx(const scene::Scene& s, size_t object, int tex_w, int tex_h);

// Float reference render. `filter`, when given, overrides every material's filter.
Frame render_ref(const scene::Scene& s, std::optional<scene::Filter> filter = {});

// Bit-accurate C-model render (docs/blocks/ewa.md): per covered pixel (same visibility as the
// reference) B1 persp::Unit on the quantised coefficients, B2 ellipse::fx::analytic, then the
// fixed nearest / bilinear / trilinear (lod = B2's lod: lmin floored to TexLodF bits, clamped to
// the top level) or EWA fx with the material's weight source and a 1024-texel cap.
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
  // Threads for visibility and the pixels (rows; <= 0: every core). The frame is the same for
  // any count; a render with a uv_shift hook runs on one thread.
  int threads = 0;
};
// The options of the texture path alone (relief off), for comparisons with the RTL top.
inline CmodelOptions texture_path_only() {
  CmodelOptions o;
  o.relief = false;
  return o;
}
// log2(max anisotropy) as B2's laniso input (u(EllAnisoW).EllLogF, rounded, saturated); the RTL
// render engine sets the same.
uint32_t laniso_code(double max_aniso);

// The RTL texture unit's engine for a material's filter (its filt_i code).
ewa::Engine engine_of(scene::Filter f);
Frame render_cmodel(const scene::Scene& s, std::optional<scene::Filter> filter = {},
                    const CmodelOptions& opt = {});

// |a - b| per pixel (max over RGB) mapped to a blue-red heat map, `full_scale` levels = red.
img::Rgba8Image error_heatmap(const img::Rgba8Image& a, const img::Rgba8Image& b, int full_scale);

// Layer-count debug image (the seed's debug mode) when a material has adaptive relief: grey
// (N - 4) / (Nmax - 4) on that material's pixels, black elsewhere; nullopt otherwise.
std::optional<img::Gray8> layers_image(const scene::Scene& s, const Frame& f);

// One CSV row per covered pixel: x,y,u,v,lod,texels,r,g,b,a (atomic write).
void write_dump_csv(const std::string& path, const Frame& f);

}  // namespace tu::render
