#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "texture/texel_format.hpp"
#include "texunit/scene.hpp"

namespace tu::cli {

// One filter on one scene: PSNR over the covered pixels against the box truth and the float EWA;
// per pixel: probes, texels read, clocks (the RTL unit's exact cycle model, = Verilator).
struct FilterRow {
  std::string name;
  double psnr_truth = 0, psnr_ewa = 0, probes = 0, texels = 0, clocks = 0;
};
struct FilterComparison {
  std::string source;  // the scene's name
  int width = 0, height = 0, ss = 0;
  size_t covered = 0;
  std::string mip_filter;       // the pyramid every texture was built with; empty: each texture's own
  uint64_t truth_hash = 0;      // FNV-1a of the truth image (equal hashes: the same truth)
  std::vector<FilterRow> rows;  // nearest, bilinear, trilinear, feline N<=2..16, ewa, ewa K=4
};
// The measurement behind `texunit filter-compare` and the report's `filters` group, on the scene's
// texture path (relief off). mip: build every texture's pyramid with this filter (the scene's
// `mip_filter`, docs/blocks/texture.md "Mip generation"); nullopt: each texture's own field (box
// unless the scene says otherwise). The engines, the float EWA and the truth all see that pyramid
// (the truth samples level 0 alone, so it does not depend on it: truth_hash shows it).
FilterComparison compare_filters(const scene::Scene& s, int ss, std::optional<tex::MipFilter> mip = std::nullopt);

struct FilterCompareArgs {
  std::string scene;
  int ss = 16;        // ground truth: samples per pixel side
  std::string plot;   // directory for the PSNR-vs-clocks plot (gnuplot); empty: none
  bool relief = false;  // keep the materials' relief (default: the texture path alone)
  std::vector<std::string> mip_filters;  // --mip-filter: one table per pyramid (kMipFilterNames); empty: the scene's
};

// `texunit filter-compare SCENE|default` (docs/blocks/feline.md): every filter of the unit and
// Feline at probe caps 2, 4, 8, 16 on one scene: PSNR against the ground truth and the float EWA,
// probes, texels and clocks per pixel, texels per clock. --mip-filter box,box_linear,lanczos2 (or
// all): one table per pyramid, then PSNR vs truth per filter and pyramid side by side.
CLI::App* add_filter_compare(CLI::App& app, FilterCompareArgs& a);
int run_filter_compare(const FilterCompareArgs& a);

}  // namespace tu::cli
