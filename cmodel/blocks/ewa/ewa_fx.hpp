// EWA texture filter (B5), bit-accurate fixed-point model (docs/blocks/ewa.md).
//
// Inputs per pixel: u, v (s(PerspUvW).TexUvF, level-0 texels, centres at i + 1/2) and B2's outputs
// (ellipse::fx::Out: the unclamped conic ae, be, ce; log2 major / clamped minor lmaj, lmin; lod;
// flags). The ellipse is rebuilt from its axes and direction because the conic is unclamped while
// the float reference clamps the minor axis (anisotropy) and both semi-axes to [1, lim] at the walk
// level. Q = xi^2 + eta^2 with xi, eta linear in (du, dv): Heckbert's incremental Q and the 2-D
// weight table's (xi, eta) come from the same exact integers.
//
//  1. L = integer part of lod (render_cmodel: the sampler rule tex::trilinear_lod on lmin, the
//     material's bias, lod clamps and levels), clamped to the pyramid (flag kLodSat when clamped).
//  2. Direction: d = ae - ce, b = be block-normalised (floor shifts) to EwaCordW-3 magnitude bits;
//     CORDIC vectoring -> 2 phi = atan2(b, d) (binary angle, 2 pi = 2^EwaAngW); phi is the conic's
//     larger-eigenvalue (minor-axis) direction; theta = phi + pi/2 reduced to [-pi/2, pi/2) (an
//     axis is defined modulo pi); CORDIC rotation -> c = cos theta, s = sin theta (s1.EwaCsF).
//  3. Axes at level L: ea = clamp(lmaj - L, 0, min(log2 lim_L, EwaAxisMaxLog2)),
//     eb = clamp(lmin - L, 0, ea), truncated to EwaExpF fraction bits; exp2 ROM (u1.16) gives
//     a, b (box) and 1/a, 1/b (floor shifts); k = (c/a, s/a, -s/b, c/b) rounded half up to
//     s.EwaKF. Box half extents hu = sqrt((a c)^2 + (b s)^2), hv = sqrt((a s)^2 + (b c)^2),
//     square root rounded up, to EwaPosF bits (up), plus a margin hu/64 + 2^-EwaPosF that covers the
//     quantisation of k (the walk's ellipse is |k d| < 1, not the (a, b) ellipse; tested).
//     Box > max_texels and L below the top -> L + 1, capped (direction kept).
//  4. Walk row-major; Q by Heckbert's second differences (row start direct); inside iff Q < 1;
//     weight from the formula, the 1-D table (by Q) or the 2-D table (by xi, eta).
//  5. Normalise: wsum leading-one normalised to EwaNrmW bits (floor), reciprocal unit, channel =
//     round_half_up(acc R 2^-(RecipOutF + p)) saturated to 255.
// Border weights (Config::clip, seed 003 §2, docs/blocks/ewa.md "Border weights"): the box grows
// by 1/2 texel per side; a texel with 1/4 <= Q <= 9/4 gets the signed distance d from its centre
// to the ellipse's tangent at the radial projection p / sqrt(Q) of its offset p,
//     d = (1 - r) r / |g|,  r = sqrt(Q),  g = K^T (xi, eta) = grad Q / 2  (exact for a circle),
// and, when |d| <= 1/2, the weight w' v(d) (w' = w(Q) inside, the boundary weight 2^-8 outside;
// v one of the gauss::clip variants); Q < 1/4: inside (w), Q > 9/4 or d < -1/2: 0.
#pragma once

#include <array>
#include <cstdint>
#include <random>
#include <vector>

#include "ellipse/ellipse_fx.hpp"
#include "ewa/ewa_ref.hpp"
#include "gauss/clip.hpp"
#include "texture/texture.hpp"
#include "texunit/formats.hpp"
#include "texunit/schema.hpp"

namespace tu::ewa::fx {

enum class Weights { Formula = 0, Table1d = 1, Table2d = 2 };

struct Config {
  Weights weights = Weights::Formula;
  uint32_t max_texels = kDefaultMaxTexels;  // u(EwaCountW)
  const clip::Variant* clip = nullptr;       // border weights w' v(d); nullptr: off (Q < 1 test)
};

struct In {
  int64_t u = 0, v = 0;  // s(PerspUvW).TexUvF
  ellipse::fx::Out b2;   // ae, be, ce, lmaj, lmin, lod, flags are used
};

// Flag bits: texunit/schema.hpp TU_EWA_FLAG_BITS (kUnitDisc, kAxisClamp, kLodSat, kCapped,
// kNoWeight), shared with the RTL.
#define TU_X_FLAG(name, bit, desc) k##name = 1u << (bit),
enum Flag : uint32_t { TU_EWA_FLAG_BITS(TU_X_FLAG) };
#undef TU_X_FLAG
inline constexpr int kFlagW = schema::kEwaFlagW;

// Per-pixel set-up at the final walk level (intermediate values the RTL compares).
struct PixelSetup {
  int32_t two_phi = 0;           // CORDIC vectoring result, binary angle s(EwaAngW)
  int32_t theta = 0;             // major-axis angle in [-2^(EwaAngW-2), 2^(EwaAngW-2))
  int32_t c = 0, s = 0;          // s(EwaCsW).EwaCsF
  int level = 0;
  uint32_t ea = 0, eb = 0;       // log2 semi-axes at L, u.EwaExpF
  uint32_t a = 0, b = 0;         // u(EwaAW).EwaE2F
  uint32_t inv_a = 0, inv_b = 0; // u(EwaE2W).EwaE2F
  int32_t kxu = 0, kxv = 0, kyu = 0, kyv = 0;  // s(EwaKW).EwaKF
  int64_t cu = 0, cv = 0;        // centre at L, texel i at i: EwaPosF fraction bits
  uint32_t hu = 0, hv = 0;       // u(EwaHW).EwaPosF
  int64_t x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  uint64_t box = 0;
  uint32_t flags = 0;
  friend bool operator==(const PixelSetup&, const PixelSetup&) = default;
};

struct Out {
  img::Rgba8 color;
  int level = 0;
  uint32_t texels_visited = 0, texels_inside = 0;
  bool capped = false;
  uint32_t flags = 0;
  uint32_t lane_blocks = 0;  // 2 x 2 blocks of the walked box: the K = 4 walk's clocks (ewa_lanes.hpp)
};

// Walk extremes, for the width proofs (testbench/unit/ewa_fx_test.cpp).
struct WalkStats {
  int64_t max_abs_d = 0;     // |du|, |dv| codes
  int64_t max_abs_xi = 0;    // |xi|, |eta| codes
  uint64_t max_q = 0;        // Q code, incl. increments dQ
  uint64_t max_ddq = 0;
  uint64_t wsum = 0, max_acc = 0;
  int64_t max_abs_g = 0;     // border walk: |gu|, |gv| codes of band-tested texels
  uint64_t max_root = 0;     // border walk: r, |g| codes
  std::vector<int64_t>* q_trace = nullptr;  // when set: Q of every walked texel, in walk order
};

// Border distance of one walked texel (Config::clip on). Zones: Q < 1/4 inside, Q > 9/4 outside
// (no d needed: |g| <= r (1 + 2^-13) since b >= 1, so d > 1/2 resp. d < -1/2 there); otherwise
// d = (1 - r) r / |g| as a ClipIn code (s13.12, half up in magnitude), band iff |d| <= 1/2.
enum class Zone { Inside, Band, Outside };
struct Border {
  Zone zone = Zone::Inside;
  int32_t d = 0;             // ClipIn code (Band only)
  int32_t gu = 0, gv = 0;    // s(EwaGradW).EwaGradF (zone test passed: 1/4 <= Q <= 9/4)
  uint32_t r = 0, g = 0;     // u(EwaRootW).EwaGradF
};
Border border(const PixelSetup& su, int64_t q, int64_t xi, int64_t eta);
// The border weight of a texel: zone, d and the weight source's w (w(Q) inside, 2^-8 outside),
// (w v(d) + 2^15) >> 16 in the band (u17.16).
uint32_t border_weight(const PixelSetup& su, const Config& cfg, int64_t q, int64_t xi, int64_t eta);
// The same from a computed Border and the weight source's w at Q (used for Q < 1 only): the
// datapath after d (block ewa_border, rtl/ewa/tu_ewa_border.sv).
uint32_t apply_border(const Border& b, int64_t q, uint32_t w, const clip::Variant& v);
// Box growth of the border walk: 1/2 texel per side (EwaPosF codes).
inline constexpr uint32_t kBorderGrow = 1u << (fmt::kEwaPosF - 1);

// ROMs (generated into rtl/generated/ by `texunit gen-rtl`).
const std::array<int32_t, fmt::kEwaCordIter>& atan_table();   // round(atan(2^-i) 2^AngW / 2pi)
const std::array<uint32_t, 1u << fmt::kEwaExpF>& exp2_table();  // round(2^(i/2^ExpF) 2^E2F)
int32_t cordic_gain_code();  // round(prod 1/sqrt(1 + 2^-2i) 2^EwaCsF), the rotation start x

// Step 2: 2 phi from the conic (block-normalised d = ae - ce, b = be); 0 for d = b = 0.
int32_t vectoring(int64_t d, int64_t b);
// Rotation: angle (binary, |theta| <= quarter turn) -> cos, sin codes.
void rotation(int32_t theta, int32_t* c, int32_t* s);
// exp2 of u.EwaExpF: 2^e and 2^-e as u.EwaE2F (floor shifts).
uint32_t exp2_pos(uint32_t e);
uint32_t exp2_neg(uint32_t e);

// Steps 1-3 (set-up incl. the cap loop).
PixelSetup setup(const In& in, const tex::Texture& t, const Config& cfg);
// Steps 4-5. `direct` evaluates Q = xi^2 + eta^2 at every texel instead of the incremental
// traversal (must give the same bits); stats, when given, records the walk's extremes.
Out filter(const In& in, const tex::Texture& t, const Config& cfg, bool direct = false,
           WalkStats* stats = nullptr);
// The walk and normalisation on an explicit set-up (tests drive extreme set-ups with it).
Out walk(const PixelSetup& su, const tex::Texture& t, const Config& cfg, bool direct = false,
         WalkStats* stats = nullptr);

// Normalisation: round_half_up(acc / wsum) via the reciprocal unit, saturated to 255; wsum > 0.
uint32_t normalise(uint64_t acc, uint64_t wsum);

// A random pixel of the vector set and the tests: B2 (analytic) outputs of
// ellipse::fx::random_local footprints (anisotropy up to 1024 before the clamp, random
// orientation, major axis 2^-6 .. 2^14 texels), u, v anywhere in [-1024, 1024) texels;
// max_lod 8 (a 256 x 256 texture) or, one pixel in 8, 12 (lod saturates at the texture's top).
In random_in(std::mt19937_64& rng);
// The same pixel from a float local map (B1 output rounded to s.TexUvF, B2 analytic).
In in_from_local(const ellipse::fx::Local& l, uint32_t laniso = 4 << fmt::kEllLogF,
                 uint32_t max_lod = 8);
// A local map (q = 1/2) whose footprint has the given major semi-axis (texels per pixel),
// anisotropy (0: a line) and major-axis angle, centred at (u, v) texels: curated test pixels.
ellipse::fx::Local footprint_local(double major, double aniso, double theta, double u, double v);
// Float reference on the same B2 outputs: semi-axes 2^lmaj, 2^lmin, the conic's direction in
// double; horizon / point footprints -> unit disc (ewa_ref.hpp filter_axes).
// clip: the float border weights (ewa::Params::clip).
Result filter_ref_b2(const In& in, const tex::Texture& t, uint32_t max_texels, bool clip = false);
// The same with every float parameter (max_aniso is not used: B2's axes are already clamped).
Result filter_ref_b2(const In& in, const tex::Texture& t, const Params& p);
// The major-axis angle of B2's conic codes in double (radians; 0 for a circle).
double theta_ref_b2(const ellipse::fx::Out& o);

// Real major-axis angle of a set-up (radians, in [-pi/2, pi/2)).
double theta_value(int32_t theta);

}  // namespace tu::ewa::fx
