#pragma once

#include <CLI/CLI.hpp>
#include <string>

namespace tu::cli {

struct FilterCompareArgs {
  std::string scene;
  int ss = 16;        // ground truth: samples per pixel side
  std::string plot;   // directory for the PSNR-vs-clocks plot (gnuplot); empty: none
  bool relief = false;  // keep the materials' relief (default: the texture path alone)
};

// `texunit filter-compare SCENE|default` (docs/blocks/feline.md): every filter of the unit and
// Feline at probe caps 2, 4, 8, 16 on one scene: PSNR against the ground truth and the float EWA,
// probes, texels and clocks per pixel, texels per clock.
CLI::App* add_filter_compare(CLI::App& app, FilterCompareArgs& a);
int run_filter_compare(const FilterCompareArgs& a);

}  // namespace tu::cli
