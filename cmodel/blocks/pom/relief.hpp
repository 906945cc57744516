// Relief in the render path (docs/blocks/relief-appendix.md §9): a material's height map shifts (u, v)
// before filtering.
//
//  * Tangent frame (float): from the triangle's uv mapping, T = dP/du, B = dP/dv (uv in texture
//    repeats) and the unit normal N facing the eye; the height axis is N * sqrt(|T x B|) (one
//    texture repeat of depth, the unit of the material's `scale`). The view vector (towards the
//    eye) in that basis, normalised, is the tangent-space view V.
//  * Float reference: pom::march_ref with 256 layers and the exact refinement (whatever the
//    material's method: it is the ideal the methods are measured against).
//  * Bit-accurate: shift_uv_fx, the per-pixel function of the C-model render engine, running the
//    material's method on codes (the RTL tu_pom_unit / tu_iter_parallax arithmetic).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "distmap/distance_map.hpp"
#include "persp/persp.hpp"
#include "pom/pom_march.hpp"
#include "texunit/image.hpp"
#include "texunit/scene.hpp"

namespace tu::relief {

using Method = scene::ReliefMethod;

// Depth map (255 - height: POM's convention, 0 = top) and its complexity map (adaptive N).
// Sides must be powers of two (std::invalid_argument otherwise).
struct Maps {
  img::Gray8 depth, complexity;
  std::shared_ptr<const dm::Map> dist;  // DistanceMap methods: built by make_maps(scene, material)
};
Maps make_maps(const img::Gray8& height);
// The maps of a material's relief: the builtin bricks texture gives its height map, any other
// texture its first channel (level 0). A SceneError names the material's field when the sides
// are not powers of two (or, for a distance map, not square, or scale * side < 1 texel).
Maps make_maps(const scene::Scene& s, const std::string& material);

// Tangent-space view (unit vector, towards the eye) at the point p0 + s e1 + r e2 of triangle t
// (uv in texture repeats) seen from `eye`. Returns false for a degenerate uv mapping.
struct TangentView {
  double x = 0, y = 0, z = 1;
};
bool tangent_view(const persp::Triangle& t, const double eye[3], double s, double r,
                  TangentView* out);

// The tangent-space view at pixel (x, y) of triangle `triangle` of object `object` (the ray
// through the pixel centre, as both render engines use it). False: the ray misses the triangle's
// plane or the uv mapping is degenerate (no shift).
bool pixel_view(const scene::Scene& s, int object, int triangle, int x, int y, TangentView* out);
// The same with the camera's rays prepared once (`rays` built from s.camera).
bool pixel_view(const persp::RayCaster& rays, const scene::Scene& s, int object, int triangle,
                int x, int y, TangentView* out);
// The view as the fixed-point unit takes it: s16.14 components, S in u0.16 (clamped to < 1).
pom::View quantise(const TangentView& v, double scale);

// Float reference: shifted (u, v) in texture repeats (not wrapped: u + shift).
struct RefShift {
  double u = 0, v = 0;
  uint32_t steps = 0;  // of the 256-layer march
};
RefShift shift_uv_ref(const Maps& m, double u, double v, const TangentView& view, double scale);

// Layers N of a POM method at (u, v) (PomUvF codes): PomFixed: layers; PomAdaptive:
// pom::layers(Vz, complexity(u, v), 4, layers); layers clamped to 1..63. Iterative: the cap.
uint32_t layers_at(const Maps& m, int64_t u, int64_t v, const pom::View& view, Method method,
                   int layers);

// Bit-accurate per-pixel shift.
// In : u, v  texture coordinates in texture repeats, PomUvF (16) fraction bits, any integer part
//      view  pom::View (s16.14 tangent-space view, S u0.16), e.g. quantise(tangent_view(...))
//      method, layers: PomFixed N = layers; PomAdaptive Nmin = 4, Nmax = layers, N from
//      pom::layers(Vz, complexity at (u, v)); Iterative: cap = layers, direction (P, 1);
//      DistanceMap*: dm::trace through m.dist, cap = dm_cap(layers), finish DmFinish steps;
//      steps = map steps + finish reads (<= 63).
//      layers is clamped to 1..63 (the unit's PomNW bits).
// Out: u, v  shifted coordinates (same units; the integer part of the input is kept, so a
//      REPEAT texture lookup is unchanged by the wrap of the march), steps = march steps or
//      iterations, n = layers used (POM) or the cap, discard = the shifted point left the
//      texture's [0,1]^2 (only when wrap = false), nonconv = iterative cap hit.
struct FxShift {
  int64_t u = 0, v = 0;
  uint32_t steps = 0, n = 0;
  bool discard = false, nonconv = false;
  bool vz_guard = false;  // POM: |Vz| < PomVzMin was raised (pom::Parallax::clamped)
  bool back = false;      // POM: Vz < 0 (mirrored)
};
// Guard flags of a pixel's relief step (render::PixelRecord::relief_flags, --dump).
enum ReliefFlag : uint32_t {
  kReliefVzGuard = 1,  // POM: |Vz| raised to PomVzMin (grazing view)
  kReliefNonConv = 2,  // iterative: the iteration cap was reached with |d| >= eps
  kReliefBack = 4,     // POM: Vz < 0, the view mirrored into the front half-space
};
FxShift shift_uv_fx(const Maps& m, int64_t u, int64_t v, const pom::View& view, Method method,
                    int layers, bool wrap = true);

// The per-pixel relief step of the texture unit (render engine and RTL tu_relief_stage): B1's u, v
// codes (level-0 texels of a 2^lw x 2^lh colour texture, TexUvF fraction bits) become texture
// repeats with PomUvF bits (shift_code: exact while lw <= PomUvF - TexUvF, floored beyond), the
// method shifts them (shift_uv_fx, wrap: the repeat part is kept aside) and they come back
// (floored). u, v: shifted codes; n: layers used (POM) or the iteration cap; steps: march steps
// or iterations (for the cycle estimators).
struct TexelShift {
  int64_t u = 0, v = 0;
  uint32_t n = 0, steps = 0;
  uint32_t flags = 0;  // ReliefFlag
};
TexelShift shift_texel_uv_fx(const Maps& m, int64_t u, int64_t v, int lw, int lh,
                             const pom::View& view, Method method, int layers);
// The distance-map tracer's cap: layers clamped to 1..DmCapMax (so that its map steps plus the
// finish's reads fit the unit's PomNW-bit step count).
uint32_t dm_cap(int layers);
// c * 2^by (by >= 0) or floor(c * 2^by) (by < 0).
int64_t shift_code(int64_t c, int by);

// Stream cycles of tu_relief_stage with no back-pressure (every input offered from cycle 0, the
// output always ready, view words with their pixels), counted up to and including the last
// output's cycle. Pixel: shift = the relief path runs (rel && !guard && view ok), steps = its march
// steps or iterations k, iter = iterative parallax. A cycle-by-cycle model of the stage's
// structure: the sideband FIFO (fifo_depth entries), tu_pom_layers (PomLayersLatency),
// tu_pom_unit (set-up pipeline; the march engine with its output register, k + 1 cycles per pixel
// in a stream; the iterative engine, Idle -> k + 1 tests -> Done, k + 3 cycles per pixel; a pixel
// enters an engine only when the other one holds none; refinement pipeline; global stall per
// pipeline) and the head-of-line join.
struct StagePixel {
  bool shift = false;
  uint32_t steps = 0;
  bool iter = false;
};
uint64_t stage_cycles(const std::vector<StagePixel>& px, int fifo_depth = 32);
// A pixel of method m as the stage model sees it (steps: shift_texel_uv_fx's). The distance-map
// tracer (tu_dm_trace) holds one pixel at a time like the iterative engine (Idle, Run, Done) and
// is handed over by the same rule; its Run lasts DmSetupCycles + 2 + steps clocks (set-up, the
// first read, one clock per map read and per finish read), i.e. that of an iterative pixel with
// DmSetupCycles + 1 + steps iterations.
StagePixel stage_pixel(bool shift, uint32_t steps, Method m);

// The same model one clock at a time, for a stage inside the texture unit (ewa::texture_unit_cycles):
// the pixels px are offered in order; each clock, in_ready(out_ready) (from the registered state,
// the pixel offered next and whether the output is taken) is read, then step(in_valid, out_ready)
// advances the state.
class StageModel {
 public:
  explicit StageModel(const std::vector<StagePixel>& px, int fifo_depth = 32);
  bool in_ready(bool out_ready) const { return comb(out_ready).in_ready; }
  struct Fired {
    bool in = false, out = false;
  };
  Fired step(bool in_valid, bool out_ready);
  size_t outputs() const { return fifo_head_; }

 private:
  using Pipe = std::vector<int>;  // pixel indices per stage, -1: empty
  struct Comb {                   // this clock's combinational signals
    bool out = false, r_en = false, out_free = false, go = false, finish = false;
    bool m_fire = false, i_fire = false, s_en = false, l_en = false, in_ready = false;
  };
  Comb comb(bool out_ready) const;
  const std::vector<StagePixel>& px_;
  int fifo_depth_;
  Pipe lay_, set_, ref_;
  std::vector<int> fifo_;  // indices, oldest first
  size_t fifo_head_ = 0, next_ = 0;
  bool run_ = false;          // march engine: a pixel marching
  int cur_ = -1, mout_ = -1;  // its pixel, the pixel in its output register
  uint32_t i_ = 0;
  enum { kIdle, kRun, kDone } ist_ = kIdle;  // iterative engine (tu_iter_parallax)
  int icur_ = -1;
  uint32_t ii_ = 0;
};

}  // namespace tu::relief
