// Object-space texturing (seed 003 §5, docs/blocks/objspace.md): each triangle is rotated parallel
// to the screen, textured there on a regular sample grid with ONE mip level per polygon, every
// textured sample is rotated back, projected and splatted to its four covering pixels with
// bilinear area weights; a pixel's colour is I = sum s_i I_i / sum s_i.
//
// Per triangle (set-up, float in both engines, as B1's set-up):
//   view-space vertices; unit normal N = (B - A) x (C - A) / |.|, oriented away from the eye;
//   [FIX] d = sqrt(Ny^2 + Nz^2) (the seed prints a minus); cos a = Nz / d, sin a = Ny / d
//   (d = 0: cos a = 1, sin a = 0); cos b = d, sin b = Nx. R = Ry(b) Rx(a) maps N to +z, the plane
//   to z'' = D (its distance from the eye); the seed's printed x', y', z' are R's rows (tested).
//   The triangle is clipped to the view frustum (near plane, the four sides 2 pixels out) so that
//   only its visible part is sampled; sample grid: spacing h = D * spacing * 2 tan(fovy/2) / height
//   (one pixel at distance D for spacing 1), anchored at multiples of h in the rotated plane, so
//   that the triangles of one plane share one lattice; tiles of 2^PerspXyW samples per side.
//   Texture: uv affine in the grid indices; lambda = log2(max column norm of d(u,v)/d(i,j)), one
//   per polygon, trilinear at that lambda. Rotate back + project: a 3x3 projective map from the
//   grid indices (i, j) to pixel-centre coordinates (pixel (x, y) centre at (x, y)):
//   px = (a i + b j + c) / (g i + h j + k), q = Z / Zmax in (0, 1] (the same form as B1).
// Per sample, float reference: that map in double, floor / fraction, four bilinear weights.
// Per sample, C model (bit-accurate): the map quantised to B1's formats and evaluated by B1's
//   unit (persp::Unit: guard, reciprocal, round half up to s(PerspUvW).PerspUvF pixels), splat
//   weights from the PerspUvF-bit fractions fx, fy: w11 = fx fy, w10 = fx (1 - fy), w01 =
//   (1 - fx) fy, w00 = (1 - fx)(1 - fy), exact in u(ObjSplatWW).ObjSplatWF (sum exactly 1).
//   Accumulation per pixel: sum w (u(ObjAccWW).ObjSplatWF) and sum w c per channel
//   (u(ObjAccCW).ObjSplatWF), saturating (flag); I = round half up (sum w c / sum w), exact.
// Visibility: a sample's weight lands on a pixel only when that pixel's centre sees the same
// object (render::visibility); off-screen, guarded (q < 2^-PerspGuardLog2) and other-surface
// splats are counted, never hidden. Holes (covered pixels with sum s_i = 0) are painted the
// background colour and counted; overlaps (pixels with sum s_i > 4 samples' worth) counted.
// Error bound of the per-sample C model against the float reference (measured, objspace_test and
// `texunit objspace-error`): see docs/blocks/objspace.md.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "persp/persp.hpp"
#include "texunit/render.hpp"

namespace tu::objspace {

// The rotation that brings a plane of unit normal n parallel to the screen (seed 003 §5).
struct Rotation {
  double cos_a = 1, sin_a = 0, cos_b = 1, sin_b = 0;
  double m[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};  // R = Ry(b) Rx(a): R n = (0, 0, 1)
  bool x_normal = false;                             // d = 0: the normal along x (alpha free, 0)
};
Rotation rotation(const double n[3]);
void rotate(const Rotation& r, const double p[3], double out[3]);       // R p
void rotate_back(const Rotation& r, const double p[3], double out[3]);  // R^T p
// The seed's printed per-point formulas (x', y', z' of the thesis), for the test against R.
void rotate_seed(const Rotation& r, const double nz, const double p[3], double out[3]);

struct Options {
  double spacing = 1;             // sample spacing in pixels at the plane's distance D
  uint64_t max_samples = 1ull << 28;  // whole render; more: std::runtime_error naming the object
};

// One tile of a triangle's sample grid: indices i in [0, ni), j in [0, nj).
struct Tile {
  int ni = 0, nj = 0;
  persp::Coef9 screen;         // (i, j) -> pixel-centre coordinates px, py; q = Z / Zmax
  double u0, ui, uj, v0, vi, vj;  // level-0 texels: u = u0 + ui i + uj j
  // The tile's clipped polygon in grid units (edge functions e(i, j) = a i + b j + c >= 0 inside).
  std::vector<double> ea, eb, ec;
  bool inside(int i, int j) const;
};
struct TriangleSetup {
  int object = -1, triangle = -1;
  Rotation rot;
  double dist = 0;     // D: the plane's distance from the eye
  double h = 0;        // grid spacing, scene units
  double lambda = 0;   // the polygon's mip level (GL lambda, clamped to [0, top])
  std::vector<Tile> tiles;  // empty: nothing visible (clipped away, or the plane contains the eye)
  uint64_t grid = 0;        // grid points in the tiles' rectangles (an upper bound of the samples)
};
std::vector<TriangleSetup> setup(const scene::Scene& s, const Options& opt = {});

struct Stats {
  uint64_t triangles = 0, tiles = 0;
  uint64_t samples = 0;           // grid points inside the visible polygons: textured samples
  uint64_t off_screen = 0;        // whose four pixels are all outside the image
  uint64_t guarded = 0;           // C model: B1 guard (q < 2^-PerspGuardLog2): dropped
  uint64_t splats = 0;            // (sample, pixel) pairs with a weight landing on its own object
  uint64_t foreign = 0;           // (sample, pixel) pairs dropped: the pixel sees another surface
  uint64_t covered = 0;           // covered pixels of the frame
  uint64_t holes = 0;             // covered pixels with sum s_i = 0 (background colour)
  uint64_t overlaps = 0;          // covered pixels with sum s_i > 4
  uint64_t acc_saturated = 0;     // C model: accumulator saturation (pixels)
  double max_weight = 0;          // max sum s_i of a pixel (samples' worth)
  double samples_per_pixel() const { return covered ? double(samples) / double(covered) : 0; }
};
struct Result {
  render::Frame frame;  // records: texels = 8 x (sum s_i rounded), lod = the polygon's lambda
  Stats stats;
};
// ---- the per-sample datapath (C model) ----
struct Splat {
  int64_t x = 0, y = 0;   // top-left covering pixel floor(px), floor(py)
  uint32_t w[4] = {};     // (x, y), (x + 1, y), (x, y + 1), (x + 1, y + 1): u(ObjSplatWW).ObjSplatWF
  bool guard = false;     // B1 guard: no position
  friend bool operator==(const Splat&, const Splat&) = default;
};
Splat splat_fx(const persp::Unit::Coefs& k, int i, int j);

// The per-sample datapath applied to a batch of samples (in order): out[k] = the splat of
// sample k. Empty: the C model (splat_fx); `texunit render --pipeline object-space --engine rtl`
// passes the Verilated tu_objspace_sample (the accumulation stays in C++).
struct SampleIn {
  const persp::Unit::Coefs* k;  // the tile's quantised map
  int i, j;
};
using Datapath = std::function<void(const std::vector<SampleIn>& in, std::vector<Splat>& out)>;

Result render_ref(const scene::Scene& s, const Options& opt = {});
Result render_cmodel(const scene::Scene& s, const Options& opt = {}, const Datapath& datapath = {});
struct SplatRef {
  double px = 0, py = 0;
  double w[4] = {};
};
SplatRef splat_ref(const persp::Coef9& k, int i, int j);

// ---- scenes shared by the tests and the vector sets (vectors/generator/objspace_block.cpp) ----
// One textured quad (64 x 64 checkerboard, trilinear) seen from the origin looking down -z
// (fovy 60 degrees, w x h pixels); `vertices` is the JSON array of its four corners.
scene::Scene quad_scene(const std::string& vertices, int w = 64, int h = 48);
// A random plane in front of the eye (orientation, distance 1..41; every vertex at least |z| / 2
// in front, so D > 0): the JSON vertices for quad_scene.
std::string random_quad_vertices(std::mt19937_64& rng);
// The stiff planes: a grazing floor to 12 units, a floor 0.002 below the eye to 150 units
// (89.999 degrees), a quad on the near plane (magnification), a quad at 800 units.
const std::vector<std::string>& stiff_quad_vertices();

}  // namespace tu::objspace
