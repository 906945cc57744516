// The RTL render engine: a scene's covered pixels pushed through the Verilated texture unit
// (rtl/top/tu_texture_unit.sv, the Verilator top; its texel and depth RAMs and its view and shade
// streams modelled in C++: sync_read_ram.hpp, stream_source.hpp) as spans, and compared pixel by
// pixel with the C-model engine (render::render_cmodel).
//   * spans: maximal runs of consecutive covered pixels of one row with the same triangle (the
//     same visibility as the other engines), with the B1 quantised coefficients, the per-triangle
//     B2 constants (exact numerator constants and det3, ellipse::fx) and the material;
//   * textures: every object's texture with its pyramid in the texel RAM model (preloaded: no
//     clock is spent loading it, nor the depth maps, views and shade words);
//   * filters: each material's filter (or the override), ewa or bilinear, chosen per span (filt_i);
//     EWA with each material's (or the given) weight source and the 1024-texel cap;
//   * units: the full unit (HasEwa = HasBilinear = 1) or the bilinear-only unit (HasEwa = 0, what
//     `texunit plan` writes for a scene without minification), checked against render_cmodel.
//   * relief (option): each material's POM relief through the unit's relief stage, the depth maps
//     in the depth RAM model and one view word per pixel of a relief span (relief::pixel_view,
//     quantised; the complexity texel for adaptive layers) in the view stream model; without the
//     option (or on a unit without relief) the texture path alone is compared;
//   * shading: the full unit has the shading stage (HasShading, model ShadeModel = shade_model):
//     one shade word per covered pixel (shading::Setup::fx_in, brdf::shade::pack) in the shade
//     stream model, `on` = 0 in a scene without a light (the colour passes unchanged).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "ewa/ewa_cycles.hpp"
#include "texunit/render.hpp"
#include "texunit/scene.hpp"
#include "texunit/shading.hpp"

namespace tu::cosim {

struct RtlRenderOptions {
  bool has_ewa = true;                         // false: the bilinear-only unit (every filter must be bilinear)
  // The unit `texunit plan docs/scenes/corridor.json` writes (testbench/cosim/rtl/corridor/tu_unit_cfg_pkg.sv:
  // the EWA engine with the 1-D weight table and iterative parallax; no bilinear, trilinear, nearest
  // or POM march) instead of the full unit. Its model is verilated with the multi-texel EWA engine
  // (EwaLanes = 4, EwaSetups = 3: kCorridorEwa; issue 23), so the corridor unit is the K = 4 unit.
  bool corridor_unit = false;
  // 4: the full unit with the K = 4 EWA engine (EwaLanes 4, EwaSetups 3; BC1 on its four bank
  // ports), verilated only with -DTU_COSIM_K4_UNIT=ON (else std::invalid_argument)
  int ewa_lanes = 1;
  std::optional<scene::Filter> filter;         // overrides every material's filter (ewa or bilinear)
  bool relief = false;                         // apply each material's relief (POM or iterative; full unit)
  std::optional<scene::WeightSource> weights;  // overrides every material's EWA weight source
  double stall_prob = 0;                       // random input bubbles / output stalls
  uint64_t seed = 1;
  int threads = 0;  // for the C-model render and visibility (<= 0: every core); same result
  brdf::Model shade_model = shading::kUnitModel;  // the Verilated full unit's ShadeModel
  // The full unit's EWA border weights: HasEwaClip = 1, EwaClipVariant = 0 (rtl/0_pkg/tu_unit_cfg_pkg.sv):
  // a material's clip must name this variant (the corridor and bilinear-only units have none).
  std::string clip_variant = "mm_p1";
};

// The corridor unit model's EWA structure (testbench/cosim/CMakeLists.txt -GEwaLanes=4 -GEwaSetups=3;
// no border weights): the cycle model's parameters.
inline ewa::EngineParams corridor_ewa_params() { return ewa::four_lane_engine(); }
// The full unit verilated with EwaLanes 4, EwaSetups 3 (-DTU_COSIM_K4_UNIT=ON): the same engine with
// the full unit's border weights (HasEwaClip = 1), so every pixel's output is the border pipeline's
// latency later (lane_clip; tu_ewa_walk_lanes BL), plain pixels too: each drain at a texture,
// format or engine change costs those clocks.
inline ewa::EngineParams full_unit_k4_ewa_params() {
  ewa::EngineParams p = ewa::four_lane_engine();
  p.lane_clip = true;
  return p;
}

struct RtlRender {
  render::Frame frame;               // RTL pixels
  uint64_t spans = 0;
  uint64_t cycles = 0;               // measured: first span offered to the last pixel out
  uint64_t predicted_cycles = 0;     // ewa::texture_unit_cycles (full unit) / stream_cycles (no stalls)
  uint64_t mismatches = 0;           // pixels differing from render_cmodel (any field)
  std::string first_mismatch;
  bool hung = false;
  uint64_t extra_outputs = 0;
  double sim_wall_s = 0;             // Verilator run only
  bool ok() const { return mismatches == 0 && !hung && extra_outputs == 0; }
};

// Throws std::runtime_error naming the scene when its textures do not fit the RAM model, and
// std::invalid_argument naming the material when its filter is not one the unit has.
RtlRender render_rtl(const scene::Scene& s, const RtlRenderOptions& o = {});

}  // namespace tu::cosim
