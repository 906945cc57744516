// Anisotropic filtering with parallax visibility (seed 003 §6, issue 16; docs/blocks/afvis.md):
// the EWA walk keeps only the footprint texels that the eye can see over the relief.
//
// Visibility of a walked texel t (level L of the colour texture): its surface point is its centre
// c_t (in texture repeats, PomUvF codes) at depth d0 = depth(c_t) (the NEAREST box height field
// POM marches on: depth code / 255, 0 = top, REPEAT). The ray towards the eye is c_t + s P at
// depth d0 - s (s in units of the full relief depth), P = pom::parallax of the pixel's view
// (|Vz| guard, Vz < 0 mirrored, as the relief step). t is visible iff the ray stays at or above
// the box field: in every depth cell it enters (at distance s_e), d0 - s_e <= h_cell.
//
// Step rule: a 2-D DDA over the depth cells the projected ray crosses, exact on integers (no
// division): n_u, n_v = the ray's length in uv codes to the next cell boundary in u, v (cells are
// 2^(PomUvF - log2 side) codes); the next crossing is along u iff n_u |Pv| <= n_v |Pu| (the exact
// order of n_u / |Pu| and n_v / |Pv|; a corner is taken u first, then v: both neighbours are
// tested); at a crossing along u the ray's depth is d0 - 255 n_u / |Pu| (codes), so
//     occluded  iff  (d0 - h - bias) |Pu| > 255 n_u      (entered more than bias below the top)
//     visible   iff  (d0 - dmin - bias) |Pu| <= 255 n_u  (the ray is within bias of the map's
//                                                  highest point dmin: nothing can occlude; stop)
// (and the same along v with |Pv|). d0 <= dmin + bias or P = 0: visible at once. One depth read per
// clock: steps = 1 (d0) + cells entered. At most AfvStepMax cells are entered; a trace reaching
// the cap is declared visible (flag, counted): a bounded latency, measured how often it happens.
// Error: none against the same trace in exact arithmetic on the same codes (AfvisFx.*); against the
// ideal (exact P and centre, double) the quantisation of P (2^-16 repeats) and of the centre flips
// texels on exact grazing ties only; against the bilinear field of the truth renderer the box
// model differs by up to one depth texel of slope (measured: docs/blocks/afvis.md §3).
//
// Row rule (the seed's item 4): in each walk row, of the texels with weight w > 0 in walk order
// k = 0..n-1: trace forward from k = 0 until the first occluded texel a (none: the whole row is
// visible), then backward from n - 1 until the first occluded texel b; texels a..b are excluded
// without being traced. Rule::Every traces every texel with w > 0 (the exact visible set).
// No buffer of counted texels is needed (the seed's item 3): the walk visits each box texel once.
//
// Weights: colour = sum over visible texels of w c / sum of their w (ewa::fx::finish, the same
// normalisation as the plain walk). No visible texel (wsum = 0): the level-L texel nearest the
// pixel's (shifted) centre, flags kNoWeight (finish) and Out::no_visible.
// A map with no occluder (every d0 <= dmin, e.g. flat) gives exactly the plain walk's Out.
// Formats (formats.hpp Afv*): |P| u22 (PomUvF), n u23, n |P| products u45, depth test s32, step
// counter u7; proven on the largest traces by AfvisFx.WidthsHold.
#pragma once

#include <cstdint>
#include <vector>

#include "ewa/ewa_fx.hpp"
#include "pom/pom_march.hpp"
#include "texture/texture.hpp"
#include "texunit/image.hpp"

namespace tu::afvis {

enum class Rule { Every = 0, Row = 1 };
// The trace's default bias in depth codes (docs/blocks/afvis-appendix.md §4: measured against the truth).
inline constexpr int kDefaultBias = 16;

// The relief seen by one pixel.
struct Relief {
  const img::Gray8* depth = nullptr;  // d0 and, unless trace_map is set, the cells of the trace
  const img::Gray8* trace_map = nullptr;  // optional: cells from this map (a coarse min-depth level)
  uint8_t dmin = 0;    // the smallest depth code of the trace map (its highest point)
  int64_t pu = 0, pv = 0;  // P: pom::parallax(view).pu, pv (PomUvF codes)
  int lw = 0, lh = 0;  // log2 of the colour texture's level-0 sides (texel centres -> repeats)
  int bias = kDefaultBias;  // depth codes, 0..255 (trace)
};

// The smallest depth code of a map.
uint8_t min_depth(const img::Gray8& depth);
// Level k of the min-depth (max-height) pyramid: each 2^k x 2^k block of the map as one cell
// holding its minimum (sides / 2^k, at least 1). Tracing on it (Relief::trace_map) is the cheaper,
// conservative rule: up to 2^k fewer cells per trace; a texel is occluded at least as often.
img::Gray8 min_depth_pyramid(const img::Gray8& depth, int k);

// One texel's trace (the visibility unit's per-texel work).
struct Trace {
  bool visible = true;
  bool capped = false;  // AfvStepMax cells entered without a decision: declared visible
  uint32_t steps = 0;   // depth reads: 1 (d0) + cells entered
};
// Every intermediate of a trace for the width proofs.
struct TraceStats {
  int64_t max_n = 0, max_cross = 0, max_abs_test = 0;
};
// u, v: the surface point in repeats (PomUvF codes, any integer part); d0 its depth code.
// bias (depth codes): a cell occludes only when the ray enters it more than bias below its top
// (the shadow-ray epsilon against the box model's self-occlusion on slopes and grain).
Trace trace(const img::Gray8& cells, uint8_t dmin, uint8_t d0, int64_t u, int64_t v, int64_t pu,
            int64_t pv, int bias = 0, TraceStats* st = nullptr);

// A level-L texel's centre in repeats (PomUvF codes): ((x + 1/2) 2^L) / 2^lw, floored beyond
// 2^-PomUvF (exact while L + PomUvF - 1 >= lw).
int64_t centre_code(int64_t x, int level, int lw);

// The row rule on n texels of a row (walk order): vis(k) traces texel k and returns its
// visibility; mask[k] = 1 for the texels kept. Every: vis on each texel.
template <class Vis>
void apply_rule(Rule rule, size_t n, Vis&& vis, std::vector<char>* mask) {
  mask->assign(n, 0);
  if (rule == Rule::Every) {
    for (size_t k = 0; k < n; ++k) (*mask)[k] = vis(k) ? 1 : 0;
    return;
  }
  size_t a = 0;
  while (a < n && vis(a)) (*mask)[a++] = 1;
  if (a == n) return;           // no occluded texel in the row
  for (size_t k = n - 1; k > a && vis(k); --k) (*mask)[k] = 1;  // backward to the next occluded
}

struct Config {
  ewa::fx::Config ewa;
  Rule rule = Rule::Row;
};

struct Out {
  ewa::fx::Out ewa;         // colour, level, texels visited / inside (w > 0), flags
  uint32_t visible = 0;     // texels kept (w > 0 and visible)
  uint32_t traced = 0;      // texels traced (Row: fewer than inside when a row has occluders)
  uint32_t steps = 0;       // depth reads of the traces (the visibility unit's clocks)
  uint32_t capped = 0;      // traces that reached AfvStepMax
  bool no_visible = false;  // fallback: the nearest texel at L
  // Clocks of the RTL walker (rtl/ewa/tu_afvis_walk.sv) from the record hand-over to output valid:
  // 1 + sum over the box rows of (row texels + AfvRowCycles + the row's trace clocks) + 1 +
  // (EwaNormCycles, or 3 for the nearest-texel fallback); a trace takes steps + 2 clocks when the
  // texel is visible, steps + 1 when occluded (walk_clocks).
  uint64_t clocks = 0;
  uint32_t max_row = 0;  // the most texels with w > 0 in one row (the walker's row buffer, AfvRowMax)
};

// The walker's clocks for one trace (tu_afvis_walk: d0 read, one cell per clock, the decision
// one clock after the last read's data).
inline uint64_t trace_clocks(const Trace& t) { return t.steps + (t.visible ? 2u : 1u); }

// The plain walk's set-up (ewa::fx::setup) then the visibility walk.
Out filter(const ewa::fx::In& in, const tex::Texture& t, const Config& cfg, const Relief& r);
// On an explicit set-up; walk order as ewa::fx::walk (row-major), weights ewa::fx::texel_weight.
Out walk(const ewa::fx::PixelSetup& su, const tex::Texture& t, const Config& cfg, const Relief& r,
         TraceStats* st = nullptr);

}  // namespace tu::afvis
