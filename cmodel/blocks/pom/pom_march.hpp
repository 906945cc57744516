// POM march + refinement (seed-000 note §1.3, §3.2 items 4-7, §5; docs/blocks/relief.md §3)
// and iterative parallax (seed-002 note), bit-accurate fixed point.
//
// Depth map: 8-bit codes, depth = code/255 (0 = top surface, 255 = deepest), sampled NEAREST at
// level 0 with REPEAT wrap inside the march (texture sides powers of two).
//
// POM march (per pixel):
//   a    = max(|Vz|, PomVzMin)                  guard: |Vz| -> 0 and Vz = 0 (88.2 deg cap)
//   back = Vz < 0                               the view is mirrored into the front half-space
//   1/a  = recip::eval(a)                        (shared reciprocal unit, faithful)
//   P    = round(Vxy * S / a)                    uv units (PomUvF), |P| < 64
//   dT   = round(P * recip(N))                   same reciprocal unit, N in 1..63
//   T_0 = T, h_0 = tex(T_0); i = 0
//   while 255*i < h_i*N:  T_{i+1} = T_i - dT, h_{i+1} = tex(T_{i+1}), i++      (exact rule)
//   steps k = i (<= N), fetches k+1 (the previous sample stays in a register: no re-fetch)
//   k = 0:  T'' = T  (depth 0 under the pixel, w = 0)
//   k > 0:  a_ = 255*k - h_k*N >= 0, b_ = h_{k-1}*N - 255*(k-1) > 0, den = a_+b_ in [1, 2^15)
//           w = round(a_ * recip(den)) in [0, 1] (PomWF bits),  T'' = T_k + round(w * dT)
//   out: wrap = fract(T'') ; otherwise discard = T'' outside [0,1]^2 (the shader's test)
// Degenerate view vector (Vx = Vy = 0): P = 0, the march still runs, T'' = T.
#pragma once

#include <cstdint>
#include <vector>

#include "texunit/formats.hpp"
#include "texunit/image.hpp"

namespace tu::pom {

inline constexpr int64_t kUvOne = int64_t(1) << fmt::kPomUvF;

// Nearest, REPEAT: texel (floor(u*W) mod W, floor(v*H) mod H). Sides must be powers of two.
uint8_t tex_nearest(const img::Gray8& depth, int64_t u, int64_t v);
uint8_t tex_nearest_f(const img::Gray8& depth, double u, double v);

struct View {
  int32_t vx = 0, vy = 0, vz = 1 << fmt::kPomVzF;  // s16.14 tangent-space view (towards the eye)
  uint32_t scale = 0;                               // S, u0.16
};

struct Parallax {
  int64_t pu = 0, pv = 0;  // P, PomUvF fraction bits
  bool back = false;       // Vz < 0
  bool clamped = false;    // |Vz| < PomVzMin was raised to PomVzMin
};
Parallax parallax(const View& v);

struct MarchOut {
  int64_t u = 0, v = 0;    // T'', PomUvF bits (fract-wrapped when wrap)
  uint32_t steps = 0;      // k: march iterations (fetches = k + 1)
  uint32_t w = 0;          // refinement weight, PomWF bits
  bool discard = false;    // !wrap and T'' outside [0,1]^2
  bool back = false, clamped = false;
};

// The bit-accurate march = setup -> march_core -> refine (the three RTL stages of tu_pom_unit).
// u, v: PomUvF bits. n: 1..63.
MarchOut march(const img::Gray8& depth, int64_t u, int64_t v, const View& view, uint32_t n,
               bool wrap);

// The march loop alone (the RTL engine tu_pom_march): from T = (u, v), step dT = (du, dv),
// N layers. Returns T_k, k, and the refinement operands a = 255k - h_k N, den = a + b
// (b = h_{k-1} N - 255(k-1)); k = 0 gives a = den = 0.
struct MarchCore {
  int64_t u = 0, v = 0;
  uint32_t steps = 0, a = 0, den = 0;
};
MarchCore march_core(const img::Gray8& depth, int64_t u, int64_t v, int64_t du, int64_t dv,
                     uint32_t n);

// Set-up (RTL tu_pom_setup): a = max(|Vz|, PomVzMin), P = Vxy*S/a, dT = P*recip(N), flags.
struct Setup {
  int64_t du = 0, dv = 0;  // dT, PomUvF bits
  bool back = false, clamped = false;
};
Setup setup(const View& view, uint32_t n);

// Refinement (RTL tu_pom_refine): from the march result and dT: w = a*recip(den) (k > 0),
// T'' = T_k + w*dT, then wrap (fract) or the discard test. Sets u, v, steps, w, discard.
MarchOut refine(const MarchCore& c, int64_t du, int64_t dv, bool wrap);

// Cycle estimators for a stream of pixels with march steps k_i, no stalls, counted up to and
// including the last output's cycle. tu_pom_march: k + 1 compares per pixel, the next pixel is
// accepted in the last compare cycle of the previous one, the last output registers 2 cycles
// later:  march_cycles = sum(k_i + 1) + 2.  tu_pom_unit: set-up and refinement of other pixels
// overlap the march, so only the first set-up and the last refinement add:
//   unit_cycles = march_cycles + PomSetupLatency + PomRefineLatency.
uint64_t march_cycles(const std::vector<uint32_t>& steps);
uint64_t unit_cycles(const std::vector<uint32_t>& steps);

// Float reference (double): the same |Vz| guard, P = Vxy/a*S and dT = P/N unquantised, the same
// exact loop rule, exact refinement weight. Any n >= 1 (the quality reference uses 256).
struct MarchRef {
  double u = 0, v = 0;    // T'' wrapped to [0,1)
  double tu = 0, tv = 0;  // T'' before the wrap
  uint32_t steps = 0;
};
MarchRef march_ref(const img::Gray8& depth, double u, double v, double vx, double vy, double vz,
                   double scale, uint32_t n);

// Iterative parallax (seed 002, reconstructed formulas (2), (3)), in POM's depth convention:
//   D_0 = 0, T_0 = T;  d_i = depth(T_i) - D_i;  stop if |d_i| < eps
//   T_{i+1} = T_i - d_i*(su, sv);  D_{i+1} = D_i + d_i*sh         (3 multiplies, 4 adds)
// (su, sv, sh) is the step direction: the seed's normalised V gives su,sv = S*Vxy, sh = |Vz|
// (no divide); the "P-normalised" variant uses su,sv = P, sh = 1 (one divide per pixel, one
// step lands exactly on a flat surface). depth code c -> c*257 (PomUvF bits, 255 -> 65535).
// The first iteration is offset limiting (seed formula (1)). cap iterations at most; when the
// cap is reached with |d| >= eps, `nonconv` is raised and the last T is returned.
struct IpxDir {
  int64_t su = 0, sv = 0, sh = 0;  // PomUvF bits
};
IpxDir ipx_dir_seed(const View& v);      // S*Vxy, |Vz| (guarded)
IpxDir ipx_dir_normalised(const View& v);  // P, 1

struct IpxOut {
  int64_t u = 0, v = 0;    // PomUvF bits, fract-wrapped
  uint32_t iters = 0;      // updates done (fetches = iters + 1)
  bool nonconv = false;
};
IpxOut iter_parallax(const img::Gray8& depth, int64_t u, int64_t v, const IpxDir& dir,
                     uint32_t cap = fmt::kIpxCap, uint32_t eps = fmt::kIpxEps);

}  // namespace tu::pom
