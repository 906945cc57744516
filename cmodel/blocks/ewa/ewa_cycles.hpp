// Cycle model of the EWA RTL (rtl/ewa/tu_ewa.sv, docs/blocks/ewa.md "RTL"): exact clock counts
// of a pixel stream with no back-pressure, from the C model's per-pixel counts (levels tried,
// box texels, empty weight sum). The engine is a set-up unit and a walker joined by a one-record
// hand-over, so pixel i+1's set-up overlaps pixel i's walk:
//   set-up : accept a_i, record ready at a_i + S(levels_i), S(n) = 2 + 2 I/U + n (6 + R/S) + 2
//   hand   : h_i = max(a_i + S, walker free); the set-up accepts again at h_i + 1
//   walker : output valid at o_i = h_i + 1 + box_i + D + 6 (empty weight sum: + D + 1 + 2),
//            taken at once, free again at o_i + 1; drain D = 5, + the border-weight pipeline's
//            latency (border_latency) for a pixel with border weights (clip)
//   B1-guard pixel (texture unit): S = 1, output valid at h_i + 3
// (I = EwaCordIter CORDIC iterations, U = iterations per clock, R/S = square-root clocks.)
// Multi-texel engine (EngineParams::lanes = 4: tu_ewa EwaLanes = 4, tu_ewa_walk_lanes; issue 23):
//   set-up : EngineParams::setup_units set-up units taking pixels in turn (unit i mod n): pixel i
//            accepted at a_i = max(arrival, a_{i-1} + 1, h_{i-n} + 1)
//   hand   : h_i = max(a_i + S_i, h_{i-1} + f_{i-1}, o_{i-D} + 1): the walker takes a record in
//            the clock it issues its last block; at most D = out_depth pixels between hand-over
//            and output (the output FIFO's credits)
//   walker : f_i = 2 x 2 blocks of the box (B1 guard: 1) issued at h_i + 1 .. h_i + f_i; the
//            drain and normalisation are a pipeline, so pixel i+1's blocks follow at once; output
//            valid at o_i = h_i + f_i + 12 (+ border_latency for every pixel of a unit with
//            border weights, lane_clip: one pipeline depth for all pixels keeps them in order)
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <string>
#include <vector>

#include "ewa/ewa_fx.hpp"
#include "feline/feline_cycles.hpp"
#include "pom/relief.hpp"

namespace tu::ewa {

// Set-up units tu_ewa can have (its Setups parameter, with Lanes = 4).
inline constexpr int kMaxSetupUnits = 4;

// RTL structure parameters (tu_ewa CordUnroll, SqrtStep) and the fixed stage counts.
struct EngineParams {
  int cord_unroll = 2;
  int sqrt_step = 4;
  int root_w = 16;  // radicand root bits (tu_ewa_setup RootW)
  int clip_variant = 0;  // tu_ewa ClipVariant (kRtlClipVariants index): the border pipeline's latency
  int noise_slots = 1;   // tu_noise_unit issue clocks per octave sum: 1 pipelined, NoiseCores octave-serial
  int lanes = 1;         // tu_ewa EwaLanes: 1 (tu_ewa_walk, one texel per clock) or 4 (tu_ewa_walk_lanes, 2 x 2)
  int setup_units = 1;   // tu_ewa EwaSetups: set-up units taking pixels in turn (1 .. kMaxSetupUnits)
  int out_depth = 8;     // lanes 4: tu_ewa_walk_lanes OutDepth (pixels between hand-over and output)
  bool lane_clip = false;  // lanes 4: the engine has border weights (HasClip): every pixel pays their latency
};
// The multi-texel engine as the unit builds it (tu_texture_unit EwaLanes = 4, EwaSetups = 3, no
// border weights; the corridor unit model): three set-up units keep up with the 2 x 2 walk on the
// default scene (two leave it set-up bound: docs/blocks/ewa.md).
inline EngineParams four_lane_engine() {
  EngineParams p;
  p.lanes = 4;
  p.setup_units = 3;
  return p;
}
// The multi-texel walker's latency from its last block's issue to the output (lanes 4): the
// sequential walker's drain and normalisation (EwaDrainCycles + EwaNormCycles + 1).
int lane_walk_latency(const EngineParams& p);

// The clip-volume variants tu_ewa_border has (its ClipVariant codes 0, 1, 2), by C-model name
// (gauss::clip); the unit configuration's EwaClipVariant is one of them.
inline constexpr std::array<const char*, 3> kRtlClipVariants = {"mm_p1", "mm_p3", "mm_p3_estrin"};
// ClipVariant code of a C-model variant name; -1 when tu_ewa_border has no RTL for it.
int rtl_clip_code(const std::string& variant);
// Latency of tu_ewa_border with that clip volume: S1, S2, the roots (EwaRootW), S27, the division
// (ClipInF), S40, the clip volume's pipeline, the weight register (the vector block ewa_border's).
int border_latency(int clip_code);

// The texture unit's filter engines (tu_texture_unit filt_i codes, texunit/schema.hpp).
using Engine = schema::Engine;

struct PixelCost {
  int levels = 1;          // levels tried (1 + cap fallbacks)
  uint64_t box = 1;        // texels walked
  bool no_weight = false;  // empty weight sum: nearest-texel path
  bool guard = false;      // B1 guard pixel (render engines): one texel, no set-up or walk
  Engine engine = Engine::Ewa;  // the texture-unit engine that filters the pixel
  bool one_level = false;  // trilinear: one bilinear pass (B1 guard, or the lod at the top level)
  bool clip = false;       // EWA with sub-texel border weights (the grown box is in `box`)
  bool noise = false;      // procedural: the noise unit (tu_noise_unit), not `engine`
  bool water = false;      // noise: a water pixel (WaterPasses octave sums, NoiseWaterLatency)
  int probes = 1;          // Feline: trilinear probes N (one_level: they blend one level)
  // AF with parallax visibility (tu_afvis, docs/blocks/afvis.md): > 0 for a pixel of the
  // visibility engine, its walker's clocks from the hand-over to output valid (afvis::Out::clocks);
  // the engine has its own EWA set-up (setup_cycles) and takes turns with the others.
  uint64_t afv_walk = 0;
  uint64_t blocks = 1;     // EWA, lanes 4: 2 x 2 blocks of the box (ewa::fx::Out::lane_blocks)
  // The texture's storage format (tex::Texture format * 2 + srgb): the unit decodes the texel words
  // of all pixels in flight with one format, so a change waits like an engine switch.
  int texfmt = 0;
};

// Per-pixel counts of the C model's result.
// in: the pixel's B2 outputs (lod, flags, lmaj); level, flags, box: the C model's result.
PixelCost pixel_cost(const fx::In& in, int level, uint32_t flags, uint64_t box, int top_level);

int setup_cycles(const PixelCost& c, const EngineParams& p = {});
int walk_cycles(const PixelCost& c, const EngineParams& p = {});  // hand-over to output valid

// Clock cycles from the first input offered (cycle 0, arriving at the engine at `first_arrival`;
// later pixels are always waiting) to the cycle after the last output: what the co-simulation
// harness measures as sim_cycles with no stalls.
// Pixels for the bilinear engine: accepted at a, output at a + 6, accepts again at a + 7; for the
// trilinear engine: output at a + 15 (one pass: a + 8), accepts again the clock after; for the
// nearest engine: output at a + 3, accepts again at a + 4; for the noise unit (pipelined): output at
// a + NoiseUnitLatency, accepts again at a + 1; a water pixel issues its WaterPasses octave sums
// on the clocks f, f + 1, f + 2 (accepted at a = f + 2), output at a + NoiseWaterLatency, the
// next pass at a + 1. The octave-serial noise unit issues each sum's octaves on noise_slots
// clocks: a pixel is accepted at f + passes noise_slots - 1. The engines (the noise unit one of them, its water pixels a kind of their
// own) take turns, so the first pixel after a switch is accepted the cycle after the other
// engine's last output (tu_texture_unit, tu_noise_unit).
uint64_t stream_cycles(const std::vector<PixelCost>& px, uint64_t first_arrival = 0,
                       const EngineParams& p = {});

// The same engines one pixel at a time: pixel c at the engines' input from cycle `avail` on
// (stream_cycles: every pixel from first_arrival). Returns its acceptance and output cycles.
class StreamModel {
 public:
  explicit StreamModel(const EngineParams& p = {}) : p_(p) {}
  struct Times {
    uint64_t accept = 0, out = 0;
  };
  Times add(const PixelCost& c, uint64_t avail);
  uint64_t cycles() const { return any_ ? last_out_ + 1 : 0; }

 private:
  EngineParams p_;
  // lanes 4: the set-up units' free cycles (taken in turn), the last acceptance, the walker's
  // next hand-over, the outputs still holding a credit (the last out_depth)
  uint64_t unit_free_[kMaxSetupUnits] = {}, ewa_accept_ = 0, lane_free_ = 0;
  size_t unit_next_ = 0;
  bool ewa_any_ = false;
  std::deque<uint64_t> lane_outs_;
  uint64_t setup_free_ = 0, walker_free_ = 0, bil_free_ = 0, tri_free_ = 0, nst_free_ = 0, noise_free_ = 0, last_out_ = 0;
  uint64_t afv_setup_free_ = 0, afv_walker_free_ = 0;
  bool any_ = false, last_noise_ = false, last_water_ = false, last_afv_ = false;
  int last_fmt_ = 0;
  Engine last_engine_ = Engine::Ewa;
  feline::EngineModel fel_;  // the Feline engine (feline/feline_cycles.hpp)
};

// The full texture unit (tu_texture_unit with its relief stage) on a stream of covered pixels,
// no back-pressure: the front (span set-up, expander, B1 and B2 pipelines under global stall,
// joined), the relief stage cycle by cycle (relief::StageModel: pixel i shifted or not, its march
// steps or iterations), the filter FIFO (4) and the engines (StreamModel, each pixel from the
// clock after it entered the FIFO). px[i], relief_px[i]: pixel i's filter work and relief step.
// Counted as stream_cycles. Without shifted pixels it equals stream_cycles(px,
// texture_unit_front_latency(true)).
uint64_t texture_unit_cycles(const std::vector<PixelCost>& px, const std::vector<relief::StagePixel>& relief_px,
                             const EngineParams& p = {});

// The bilinear-only top (tu_texture_unit HasEwa = 0, tu_bilinear): 7 clocks per pixel (accept,
// four texel reads, last data, output), pixels back to back.
uint64_t bilinear_stream_cycles(uint64_t pixels, uint64_t first_arrival = 0);

// tu_relief_stage: a pixel without a shift leaves its sideband FIFO one clock after entering
// (relief::stage_cycles; the SystemC model's relief stage bypass).
inline constexpr int kReliefStagePassLatency = 1;

// tu_trilinear runs one bilinear pass (not two) for a B1-guard pixel or when floor(lod) reaches
// the texture's top level.
inline bool trilinear_one_level(bool guard, int lod_floor, int top_level) {
  return guard || lod_floor >= top_level;
}

// Front-end latency of tu_texture_unit: span accepted at cycle 0 -> first pixel at the filter
// engine's input: span set-up (2) + expander register (1) + B1 (PerspLatency) + FIFO (1), + 1 with
// the relief stage (HasRelief: a pixel without a shift passes tu_relief_stage's sideband FIFO in
// one clock, relief::stage_cycles). With the recurrence ellipse (EllRecurrence: tu_ellipse_rec,
// EllRecLatency > PerspLatency; B1's output waits in a FIFO) B2 sets the join instead of B1.
int texture_unit_front_latency(bool relief_stage, bool ell_recurrence = false);

}  // namespace tu::ewa
