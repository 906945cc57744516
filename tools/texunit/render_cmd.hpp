#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace tu::cli {

struct RenderArgs {
  std::string scene, out_dir, dump, engine = "ref", filter, weights, rtl_unit = "full";
  std::string clip;  // overrides every material's EWA border weights (a clip variant or "off")
  std::string footprint;  // overrides the scene's "footprint" (B2 variant): analytic | recurrence
  std::string mip_filter;  // overrides every texture's "mip_filter" (tex::kMipFilterNames)
  bool no_relief = false;
  int ss = 16;                      // --engine truth: samples per pixel side
  std::string truth_kernel = "box";  // --engine truth: box | gauss
  int feline_max_probes = 0;  // > 0: overrides every material's Feline probe cap
  int threads = 0;  // C-model render and visibility (<= 0: every core)
  bool no_footprint_limit = false;  // procedural materials: every octave, unfiltered
  std::string vs;                   // print the PSNR against this engine's render (ref | cmodel | truth)
  int frames = 1;   // an animation: frame i at every procedural material's time + i * dt
  double dt = 0.04;
  std::string pipeline = "screen";  // screen | object-space (docs/blocks/objspace.md)
  double os_spacing = 1;            // object-space: sample spacing, pixels at the plane distance
  uint64_t max_samples = 1ull << 28;  // object-space: sample cap of the render
  double os_stall_prob = 0;           // object-space rtl: random stalls of the per-sample datapath
};

CLI::App* add_render(CLI::App& app, RenderArgs& a);
std::vector<std::string> clip_choices();  // "off" and every gauss::clip variant
int run_render(const RenderArgs& a);  // throws on bad scenes and unwritable outputs

// The main job's render part: the default scene through the float reference with every filter,
// PNGs (one per filter, plus error heat maps against EWA) in out_dir, and a table on stdout.
// Also pushes the default scene through the Verilated texture-unit top (EWA with each weight
// source, and the bilinear-only top); false when an RTL pixel differs from the C model.
// Renders and simulations on `threads` threads (<= 0: every core).
bool demo_render(const std::string& out_dir, int threads = 0);

}  // namespace tu::cli
