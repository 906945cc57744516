// The object-space pipeline with its per-sample datapath in RTL (`texunit render SCENE --pipeline
// object-space --engine rtl`, docs/blocks/objspace.md): objspace::render_cmodel with every batch of
// samples simulated by the Verilated tu_objspace_sample (random stalls on both sides) and each
// output compared with the C model's splat, the frame compared with render_cmodel's on every
// pixel; the accumulation into the pixel buffer stays in C++.
#pragma once

#include <string>

#include "objspace/objspace.hpp"

namespace tu::cosim {

struct ObjspaceRtlOptions {
  double stall_prob = 0;  // input bubbles and output back-pressure, each cycle
  uint64_t seed = 1;
};
struct ObjspaceRtlRender {
  objspace::Result result;       // the render with the RTL's splats
  uint64_t samples = 0;          // samples simulated
  uint64_t mismatches = 0;       // samples whose RTL splat differs from objspace::splat_fx
  std::string first_mismatch;    // "tile sample (i, j): rtl ... cmodel ..."
  uint64_t differing_pixels = 0; // pixels (colour or sum of weights) differing from render_cmodel's
  uint64_t runs = 0;             // simulation runs (one per batch)
  uint64_t sim_cycles = 0;       // summed over the runs: reset release to the last output
  // The estimate: per run its samples + the scheme's latency (objspace::sample_scheme, the shared
  // cycle estimator); exact without stalls.
  uint64_t predicted_cycles = 0;
  bool hung = false;
  double sim_wall_s = 0;
  bool ok() const { return mismatches == 0 && differing_pixels == 0 && !hung; }
};
ObjspaceRtlRender render_objspace_rtl(const scene::Scene& s, const objspace::Options& opt,
                                      const ObjspaceRtlOptions& ro = {});

}  // namespace tu::cosim
