// AF with parallax visibility against the truth (docs/blocks/afvis-appendix.md §4): a scene with relief
// materials rendered by the C model with plain EWA and with each visibility rule, on several
// height maps and two camera heights, against the supersampled truth with exact relief
// (render_truth). Figures on the relief pixels: PSNR, sharpness (gradient energy on the truth's
// relief edges, relative to the truth's), texels walked, traced, visibility steps per pixel.
#pragma once

#include <string>
#include <vector>

#include "afvis/afvis.hpp"
#include "texunit/scene.hpp"

namespace tu::afvis {

struct QualityParams {
  // Height maps: "bricks" (the builtin's height) or a pom:: photographic-like map
  // ("fbm", "gravel", "bark", "stone", 256 x 256) written as a PNG into tmp_dir.
  std::vector<std::string> maps = {"bricks", "gravel", "bark"};
  // Camera heights as multiples of the scene camera's height above y = 0 (its look_at height kept).
  std::vector<double> heights = {1, 3};
  int ss = 8;          // truth samples per pixel side
  int threads = 0;     // C-model renders (0: every core)
  std::string tmp_dir; // where the height PNGs go (required when a map is not "bricks")
  int bias = kDefaultBias;  // the trace's bias (depth codes), every variant
};

struct QualityRow {
  std::string map;
  double height = 1;         // the camera height multiple
  double view_deg = 0;       // mean angle of the view from the relief's normal, relief pixels
  std::string variant;       // plain, every, row, pyramid2, row+pyramid2
  size_t pixels = 0;         // relief pixels
  double psnr = 0;           // dB against the truth on the relief pixels
  double sharpness = 0;      // gradient energy on the truth's edge pixels / the truth's
  double texels = 0;         // bounding-box texels walked per relief pixel (the EWA's clocks)
  double inside = 0;         // texels with w > 0 per relief pixel
  double visible = 0;        // texels kept per relief pixel
  double traced = 0;         // traces per relief pixel
  double steps = 0;          // visibility depth reads per relief pixel
  double no_visible = 0;     // fraction of relief pixels with the nearest-texel fallback
  double cost_pct = 0;       // steps / (texels + 12): clocks added by a serial visibility unit
};

// Every relief material of `s` gets af_visibility per variant (the flag in the file is ignored).
std::vector<QualityRow> quality(const scene::Scene& s, const QualityParams& p);
std::string quality_markdown(const std::vector<QualityRow>& rows);
// The plot of the table: PSNR gain over plain EWA (same map and camera) against the added clocks,
// one series per variant: DIR/afvis_gain_vs_clocks.{dat,gp,png} (gnuplot; std::runtime_error and
// nothing left behind when it fails).
void write_quality_plot(const std::vector<QualityRow>& rows, const std::string& dir);

}  // namespace tu::afvis
