// Distance maps for sphere-traced relief (seed 003 §7, Donnelly, GPU Gems 2 ch. 8;
// docs/blocks/relief.md §13). Units: texels of the (square) depth map; the relief depth
// Z = scale * W texels, so the tangent-space geometry is isotropic.
//
// Solid V (what the tracer must not enter): voxel (i, j, k), k = 0..D-1 the layer from the top,
// has its centre at (i + 1/2, j + 1/2, (k + 1/2) h), h = Z / D, and is *inside* iff its centre is
// at or below the depth sample of its column: (k + 1/2) / D >= code / 255 (exact integer test
// 255 (2k + 1) >= 2 D code). V = the union of the closed boxes of the inside voxels and the
// half-space z >= Z (the map's bottom; every depth is <= 1). x, y wrap (REPEAT).
//
// Classic map: DT(c) = Euclidean distance from the centre c to the nearest inside centre (exact,
// separable Felzenszwalb-Huttenlocher transform, x and y periodic, a virtual inside layer D for
// the bottom). Safe value C(c) = DT(c) - 2 delta - eta, delta = half the voxel diagonal
// sqrt(2 + h^2) / 2, eta = 2^-DmEtaF texel (the tracer's position rounding). Proof that a step
// never enters V: the tracer's exact ray point p lies within delta + eta of the centre of the
// voxel it reads; every point x with |x - p| <= C(c) has dist(x, I) >= DT(c) - C(c) - delta - eta
// and every point of V is within delta of an inside centre, so dist(x, V) >= 0.
//
// Refined map (the seed's visibility-aware value, reconstructed): per voxel, the smallest free
// length along the view directions that can *reach* the voxel without crossing the surface,
// made safe for the discrete set of directions and the voxel's extent:
//   Omega   rings theta_r = r * step (r = 0..90/step, last ring 90 deg), n_r = ceil(2 pi
//           sin(theta_r) / step) azimuths: every downward direction is within alpha = step of one
//           member (half a ring + half an azimuth arc), chord eps = 2 sin(alpha / 2).
//   mu      = delta + eta: how far the tracer's point is from the voxel centre.
//   L(c, w) = the largest t with B(c + s w) >= mu + s eps for every s in [0, t], B(x) a lower
//           bound of dist(x, V) (DT of the voxel holding x - |x - centre| - delta); found by
//           conservative marching (B - mu - s eps is (1 + eps)-Lipschitz).
//   hidden  w is excluded at c when some point c - s w (s > 0, above the top plane) has
//           Bin(c - s w) >= mu + s eps, Bin a lower bound of the depth inside V: then every ray
//           within alpha of w through a point within mu of c crossed the surface before it.
//   R(c)    = max(C(c), min over the non-excluded w of L(c, w)) (the vertical is never excluded).
// Safety: the tracer's ray (p, w') reached p without entering V (induction); its nearest member w
// is not excluded (else p - s w' would be inside V above p) and L(c, w) is a safe step for
// (p, w'): |p + s w' - (c + s w)| <= mu + s eps. So R(c) <= max of two safe steps.
//
// Quantisation: code = min(255, floor(value / q)), q = 2^-DmQF texel: round down keeps it safe.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "texunit/formats.hpp"
#include "texunit/image.hpp"

namespace tu::dm {

inline constexpr int kQuantumBits = 4;  // fmt::kDmQF (static_assert in the .cpp)
inline constexpr double kQuantum = 1.0 / (1 << kQuantumBits);
inline constexpr int kMaxLayers = 255;
inline constexpr int kMaxSide = 512;

struct Params {
  int layers = 16;         // D
  double scale = 0.05;     // relief depth in texture repeats (the material's scale), rounded to
                           // the view's u0.16 code as the tracer uses it
  bool refined = false;
  double direction_step_deg = 10;  // Omega's ring and azimuth spacing (refined only)
  int threads = 0;         // <= 0: every hardware thread (result independent of the count)
};

// Exact squared-distance transform over the extended grid (layers -1..D): per voxel the squared
// distance from its centre to the nearest centre with member != 0 (x, y periodic, z spacing h);
// +inf if there is none. member is indexed like Map::index_ext.
std::vector<double> edt3(const std::vector<uint8_t>& member, int w, int hgt, int layers_ext,
                         double h);
// The same by brute force (tests).
std::vector<double> edt3_brute(const std::vector<uint8_t>& member, int w, int hgt, int layers_ext,
                               double h);

struct Map {
  int w = 0, h = 0, layers = 0;
  uint32_t scale_code = 0;  // S, u0.16 (PomSF): the map is built for scale = scale_code * 2^-16
  double scale = 0, depth_texels = 0, layer_texels = 0;  // Z and h
  double delta = 0, eta = 0, margin = 0;                 // margin = 2 delta + eta
  bool refined = false;
  double direction_step_deg = 0, eps = 0;
  int directions = 0;
  std::vector<uint8_t> code;     // W*H*D, x fastest, then y, then layer (0 = top)
  std::vector<float> safe;       // the safe distance before quantisation (texels), same order
  std::vector<uint8_t> inside;   // extended grid (layers -1..D), index_ext
  std::vector<float> dt_in, dt_out;  // extended grid: distance to the nearest inside / outside centre
  size_t index(int x, int y, int k) const {
    return (static_cast<size_t>(k) * static_cast<size_t>(h) + static_cast<size_t>(y)) * static_cast<size_t>(w) +
           static_cast<size_t>(x);
  }
  size_t index_ext(int x, int y, int k) const { return index(x, y, k + 1); }  // k = -1..D
  uint8_t at(int x, int y, int k) const { return code[index(x, y, k)]; }
  size_t bytes() const { return code.size(); }
  // Lower bounds at a point (texels, x and y wrapped): dist(p, V) and dist(p, outside of V).
  double lower_dist(double x, double y, double z) const;
  double lower_depth_inside(double x, double y, double z) const;
};

// depth: POM convention (255 - height; 0 = top). Throws std::invalid_argument for a map that is
// not square, not a power of two in [1, kMaxSide], layers outside 1..kMaxLayers, or a relief
// depth Z = scale * W below one texel.
Map build(const img::Gray8& depth, const Params& p);

// Omega (unit vectors, z > 0 downwards into the relief) for a ring spacing in degrees.
struct Dir {
  double x, y, z;
};
std::vector<Dir> directions(double step_deg);

// Exact geometry of V (float, for the proofs' tests and the seed's worked example):
// distance from p to V (brute force over the boxes), free length from p along unit direction d
// until V is entered (at most max_t), and whether the segment from p back along -d
// to the top plane z = 0 stays out of V's interior.
double exact_dist(const Map& m, double x, double y, double z);
double exact_free_length(const Map& m, double x, double y, double z, const Dir& d, double max_t = 1024);
bool exact_reaches(const Map& m, double x, double y, double z, const Dir& d);

// The JSON header of the file format (docs/blocks/relief.md §13): the raw file holds Map::code.
std::string header_json(const Map& m, const std::string& raw_name);
// Layer k as a grey image (code as grey), for viewing.
img::Gray8 slice(const Map& m, int k);

}  // namespace tu::dm
