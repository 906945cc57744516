// The texture unit as a sysmodel pipeline, and a scene's pixel stream with its per-pixel work.
#pragma once

#include <string>

#include "ewa/ewa_cycles.hpp"
#include "texunit/render.hpp"
#include "texunit/scene.hpp"
#include "texunit/sysmodel.hpp"

namespace tu::sysmodel {

// Spans of a scene: per row, maximal runs of consecutive covered pixels of one triangle, in
// row-major order (the order the render engines feed the unit). `frame` (render_cmodel with the
// EWA filter, as the RTL render engine uses it) supplies the per-pixel work: texels walked,
// levels tried, empty weight sum, B1 guard; its pixels are the covered pixels, row-major.
Workload scene_workload(const scene::Scene& s, const render::Frame& frame);

// A pixel's EWA cost for the RTL cycle model (ewa_cycles.hpp) from its workload.
ewa::PixelCost cost_of(const PixelWork& w);

// Buffer depths of the unit (the RTL's FIFOs).
struct UnitConfig {
  int span_fifo = 2;   // spans waiting for the per-scanline set-up
  int pixel_fifo = 4;  // B2 -> filter FIFO (tu_fifo FifoDepth): decouples the fixed pipes from the walk
  bool relief_stage = true;  // HasRelief (the full unit): tu_relief_stage between B1/B2 and the FIFO
  int relief_fifo = 32;      // its sideband FIFO (tu_relief_stage FifoDepth)
  ewa::EngineParams ewa;  // tu_ewa structure parameters (CORDIC unroll, square-root step)
  int miss_penalty = 0;   // texel cache (texel_cache.hpp): clocks the walker stalls per miss
};

// span set-up -> expander -> B1 || B2 -> [relief stage] -> FIFO -> EWA set-up -> EWA walker
// (tu_texture_unit; relief pixels are not modelled: the texture path, as the RTL render engine).
// Latencies and IIs come from formats.hpp and the blocks' scheduler graphs.
Pipeline texture_unit(const UnitConfig& c = {});

}  // namespace tu::sysmodel
