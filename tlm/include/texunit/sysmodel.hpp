// Transaction-level, cycle-approximate SystemC model of the texture-unit pipeline (docs/systemc.md).
//
// The pipeline is a chain of stages (one sc_module each) joined by sc_fifo channels whose depths
// are the RTL's buffer depths. A stage is described by its latency and initiation interval, each
// an affine function of the item's data-dependent work (texels walked, march steps, ...) taken from
// the C model's per-pixel results:  latency = lat0 + lat_per_work * work,
//                                   ii      = ii0  + ii_per_work  * work.
// Fixed pipelines have lat_per_work = ii_per_work = 0 and hold at most `capacity` items
// (tu_pipe_valid: one per register stage); a one-pixel-in-flight engine (POM march, EWA walk)
// has capacity 1. An expanding stage (the span walker in front of tu_persp) turns one span into
// its pixels, one pixel per ii cycles.
//
// Time: one clock cycle = one SystemC ns. Items move through the sc_fifos in zero time (the
// valid/ready handshake of the cycle they leave the producer); what a register between blocks
// costs is the link's `latency`. Cycle 0 is the cycle the first span is accepted.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace tu::sysmodel {

// Per-pixel work, from the C model (one entry per covered pixel, stream order).
struct PixelWork {
  uint32_t texels = 0;   // EWA: bounding-box texels walked (the walker's clocks)
  uint32_t levels = 0;   // EWA: mip levels the set-up tried (1 + texel-cap raises)
  uint32_t steps = 0;    // relief: march steps (0: no relief on this pixel)
  bool relief = false;   // the pixel's material has relief (it enters the relief unit)
  bool no_weight = false;  // EWA: no texel had weight (the walker's nearest-texel fallback)
  bool guard = false;      // B1 guard: no texture coordinates, the filter's short path
  uint32_t misses = 0;     // texel-cache misses of its reads (texel_cache.hpp; 0: the ideal RAM)
};

// A run of covered pixels on one scanline of one triangle: the unit of set-up.
struct Span {
  int object = 0, triangle = 0, y = 0, x0 = 0;
  uint32_t first = 0;  // index of its first pixel in Workload::pixels
  uint32_t count = 0;  // pixels (>= 1)
};

struct Workload {
  std::vector<Span> spans;
  std::vector<PixelWork> pixels;  // spans' pixels, in order
};

struct Timing {
  int latency = 0, ii = 1;
};

// Which per-pixel quantity drives a data-dependent stage.
enum class Work { None, Texels, Levels, Steps };

struct StageSpec {
  std::string name;       // block name (RTL module)
  int lat0 = 1, ii0 = 1;  // cycles
  int lat_per_work = 0, ii_per_work = 0;
  Work work = Work::None;
  int capacity = 1;          // items in flight
  bool expand = false;       // span in, its pixels out
  bool relief_only = false;  // only relief pixels use it; the others pass in `bypass_latency`
  int bypass_latency = 0;
  int fifo_depth = 2;        // depth of the sc_fifo in front of the stage
  int link_latency = 0;      // registers between the previous stage and this one
  // Direct valid/ready link from the previous stage (no buffer): the producer keeps the item
  // (and its slot) until this stage takes it, and frees the slot `release` cycles after that
  // (e.g. an FSM that returns to its accept state one clock after the hand-over).
  bool direct = false;
  int release = 0;           // of this stage's own slot after its consumer took an item
  // When set, a pixel's {latency, ii} come from this cycle model (e.g. a block's exact FSM
  // count) instead of the affine form; `work` still names what it reports as work.
  std::function<Timing(const PixelWork&)> timing;
};

struct Pipeline {
  std::string name;
  std::vector<StageSpec> stages;  // stage 0 receives spans (it or a later stage must expand)
};

struct BlockStats {
  std::string name;
  uint64_t items = 0;    // items accepted (spans or pixels)
  uint64_t busy = 0;     // cycles issuing: sum of ii over its items
  uint64_t stalled = 0;  // cycles an output waited for room downstream (back-pressure)
  uint64_t starved = 0;  // cycles with room but no input
  uint64_t work = 0;     // sum of the per-item work
};

struct Result {
  uint64_t total_cycles = 0;  // cycle of the last pixel's output handshake (cycle 0: first span)
  uint64_t pixels = 0;
  std::vector<BlockStats> blocks;
  double sim_seconds = 0;     // wall time of the SystemC simulation alone
};

// Runs one simulation (a fresh SystemC context each call). Throws std::invalid_argument on a
// malformed pipeline (no expanding stage, capacity < 1, ...).
Result simulate(const Pipeline& p, const Workload& w);

// Work value of `w` for `kind`.
uint32_t work_of(const PixelWork& w, Work kind);

// Per-block table (busy, utilisation = busy / total, stalled, starved, work) and its JSON form.
std::string table(const Result& r);
nlohmann::json to_json(const Result& r);

}  // namespace tu::sysmodel
