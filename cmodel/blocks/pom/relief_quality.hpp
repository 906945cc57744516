// Relief quality vs cost (docs/blocks/relief-appendix.md §5): procedural depth maps, a textured render of
// the shifted uv, PSNR against a dense 256-layer exact-refinement march (pom::march_ref).
#pragma once

#include <string>
#include <vector>

#include "texunit/image.hpp"

namespace tu::pom {

// 128x128-style procedural depth maps (side: power of two). depth code 0 = top, 255 = deepest.
img::Gray8 map_smooth(int side);  // low-frequency sinusoid bumps
img::Gray8 map_bricks(int side);  // flat bricks, bevelled edges, deep mortar (steep steps)
img::Gray8 map_noisy(int side);   // 3-octave value noise + per-texel noise (rocky)
// Photographic-like grey height maps (255 = top, as a PNG would hold them; depth = 255 - h):
img::Gray8 height_fbm(int side);     // 6-octave fBm value noise
img::Gray8 height_gravel(int side);  // cellular pebbles (domes of random height) + grain
img::Gray8 height_bark(int side);    // vertical ridges warped by noise, deep cracks
img::Gray8 height_stone(int side);   // ridged multifractal with cracks (rough stone)

// Render albedo at (u, v) (analytic, continuous, period 1/8): 8-bit value.
double albedo(double u, double v);

struct QualityParams {
  int side = 128;        // texture and image size (pixels = texels, one tile)
  double scale = 0.05;   // height scale S
  double azimuth = 30;   // degrees
  std::vector<double> angles = {0, 45, 60, 80, 85};
  std::string debug_dir; // if set: layer-count debug PNGs (N per pixel) are written here, and
                         // with compare the generated height maps (height_NAME.png)
  // If set: this height map (first channel, 255 = top; square, power of two, 16..kMaxHeightSide)
  // instead of the three procedural maps; its side is the texture and image side.
  std::string height_png;
  // Also the distance-map methods (classic, refined; plain and with the linear+binary finish),
  // linear+binary search, a PSNR against relief::exact_hit, and the photographic-like maps
  // (fbm, gravel, bark, stone) after the three procedural ones.
  bool compare = false;
  int dm_layers = 16;
  double dm_step_deg = 10;
};
inline constexpr int kMaxHeightSide = 512;
// A height map PNG as a depth map (depth = 255 - height); throws std::invalid_argument naming the
// file when it is not square or not a power of two in [16, kMaxHeightSide].
img::Gray8 depth_from_height(const std::string& path);

struct QualityRow {
  std::string map, method;
  double angle = 0;
  double psnr = 0;        // dB, +inf when identical
  double steps = 0;       // mean march steps / iterations per pixel
  double fetches = 0;     // mean depth fetches per pixel (steps + 1)
  double nonconv = 0;     // fraction of pixels flagged non-converged (iterative only)
  double ref_steps = 0;   // mean steps of the 256-layer reference
  double psnr_exact = 0;  // dB against the exact intersection (compare only)
  double cycles = 0;      // modelled cycles per pixel: one depth / map read per clock
                          // (POM k + 1 as tu_pom_march, iterative k + 3 as tu_iter_parallax)
};

std::vector<QualityRow> quality(const QualityParams& p);
std::string quality_markdown(const std::vector<QualityRow>& rows);

}  // namespace tu::pom
