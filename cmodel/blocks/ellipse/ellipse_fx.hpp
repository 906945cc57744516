// Pixel footprint (B2), bit-accurate fixed-point model: ellipse coefficients, axes, anisotropy
// clamp and mip LOD. Two Jacobian variants share everything after the Jacobian:
//   * Analytic (production, rtl/ellipse/tu_ellipse.sv): numerators nUx, nVx, nUy, nVy of the
//     derivatives (common denominator q^2), ellipse scaled by q^4, Fe' = (det3 * (1/q))^2: no
//     division beyond B1's reciprocal of q.
//   * Forward difference (seed recurrences, corrected): Ux = nUx / (q (q+G)), Uy = nUy / (q (q+H)),
//     two reciprocals + four multiplies per pixel.
// Numerators come from the B1 quantised coefficients (persp::Unit::Coefs, PerspF = 40 fraction
// bits) exactly (80 fraction bits, i128), by direct evaluation or by the seed-001 §2.7
// recurrences (x-numerators + M, + N per row, y-numerators - M, - N per pixel); both give the same
// bits (exact integers), then are rounded half up to s(EllNumW).EllNumF.
//
// Formats (cmodel/include/texunit/formats.hpp, docs/blocks/ellipse.md):
//   n*   : s48.32 numerators (analytic) or Jacobian entries (forward difference), texels*q^2 / px
//   q    : s44.40 (B1 accumulator); horizon guard q < 2^-PerspGuardLog2 (incl. q <= 0)
//   det3 : per-triangle determinant of [[A,B,C],[D,E,F],[G,H,I]] (set-up), floating point:
//          det3 = dm * 2^(dexp - (EllDetW - 2)), dm s(EllDetW) normalised (|dm| in [2^(W-2), 2^(W-1))
//          or 0), dexp s(EllDetExpW)
//   ae,ce,be: the exact sums n^2 + n^2, -2 (n n + n n) (2 EllNumF fraction bits) in block floating
//          point: codes (u64, u64, s64) = sum >> eexp (floor), eexp = max(0, msb(Ae'+Ce') - 61),
//          value = code * 2^(eexp - 2 EllNumF)
//   f    : |f| = fm * 2^(fexp - 31), fm u32 (1.31, truncated), fexp s8;  Fe' = f^2
//          analytic f = det3 / q (via 1/q = R 2^(PerspF - e)), forward difference f = det J
//   LOD unit: s = Ae'+Ce', d = Ae'-Ce', b = Be' (exact sums), block-normalised to EllNrmW bits (floor shifts),
//          r = isqrt(d^2 + b^2) (floor), lam = s + r (= 2 sigma_max^2, scaled);
//          L(x) = log2 by leading one + EllLogMantW-bit mantissa + (EllLogF+1) squarings (trunc);
//          2 log2(major) = L(lam) - 1 - 4 log2(q),  2 log2(minor) = 2 L(f) - L(lam) + 1,
//          logs kept with EllLogF+1 fraction bits, halved (floor) to s(EllLogW).EllLogF;
//          minor_c = max(minor, major - log2(max_aniso)); lod = clamp(floor(minor_c), 0, max_lod)
//          as u(EllLodW).EllLodF.
//   GL LOD (trilinear's rho, the OpenGL / Vulkan rule): Px' = nUx^2 + nVx^2, Py' = nUy^2 + nVy^2
//          (exact, u(EllRhoW) at 2 EllNumF fraction bits: the squared length of the pixel's x and
//          y steps in texels, times q^4), lrho = log2 rho = (L(max(Px', Py')) - 2 EllNumF
//          - 4 log2(q)) / 2 floored to s(EllLogW).EllLogF (kLogNegInf when both are 0). No square
//          root, no anisotropy clamp; the sampler (tex::trilinear_lod) adds bias and clamps.
#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include "ellipse/ellipse_ref.hpp"
#include "persp/persp.hpp"
#include "texunit/fixed.hpp"
#include "texunit/formats.hpp"
#include "texunit/schema.hpp"

namespace tu::ellipse::fx {

using Coefs = persp::Unit::Coefs;

// Exact numerators at 2*PerspF fraction bits.
struct ExactNum {
  i128 nux, nvx, nuy, nvy;
};
ExactNum numerators_direct(const Coefs& c, int x, int y);
// The same from B1's accumulators at the pixel (persp::Unit::direct(c, x, y)).
ExactNum numerators_at(const Coefs& c, const persp::Unit::Acc& s);
// The corrected seed recurrences walked over a span [x0, x0 + n) of row y.
std::vector<ExactNum> numerators_span(const Coefs& c, int x0, int y, int n);

// Block inputs for one pixel (raw codes).
struct In {
  int64_t nux = 0, nvx = 0, nuy = 0, nvy = 0;  // s48.32
  int64_t q = 0;                               // s44.40
  int64_t dm = 0;                              // det3 mantissa, s40
  int32_t dexp = 0;                            // det3 exponent, s8
  uint32_t laniso = 4 << fmt::kEllLogF;         // log2(max aniso), u14.10 (default 16:1)
  uint32_t max_lod = 12;                       // u4.0
};

// Flag bits: texunit/schema.hpp TU_ELL_FLAG_BITS (kHorizon, kDegenerate, kAnisoClamp, kLodSat,
// kMagnify), shared with the RTL.
#define TU_X_FLAG(name, bit, desc) k##name = 1u << (bit),
enum Flag : uint32_t { TU_ELL_FLAG_BITS(TU_X_FLAG) };
#undef TU_X_FLAG

struct Out {
  uint64_t ae = 0, ce = 0;  // block floating point, value = code * 2^(eexp - 2 EllNumF)
  int64_t be = 0;
  uint32_t eexp = 0;        // u(EllEexpW)
  uint32_t fm = 0;          // u32 (1.31)
  int32_t fexp = 0;         // s8
  int32_t lmaj = 0, lmin = 0;  // log2 major, log2 minor_clamped, s18.10 (kLogNegInf if none)
  int32_t lrho = 0;         // GL LOD log2 rho, s18.10 (kLogNegInf if none; 0 at the horizon)
  uint32_t lod = 0;         // u12.8
  uint32_t flags = 0;
  friend bool operator==(const Out&, const Out&) = default;
};
inline constexpr int32_t kLogNegInf = -(1 << (fmt::kEllLogW - 1));

// Round an exact numerator (2 PerspF fraction bits) to s48.32; saturates.
int64_t round_num(i128 n);
// det3 of the quantised coefficients (minors rounded to PerspF fraction bits first), normalised
// (mantissa truncated toward zero).
void det3(const Coefs& c, int64_t* dm, int32_t* dexp);
double det3_value(const In& in);
In make_in(const Coefs& c, int x, int y, uint32_t laniso = 4 << fmt::kEllLogF, uint32_t max_lod = 12);
// det3 of a triangle (its normalised float form), and make_in with it and B1's accumulators at the
// pixel given: a render computes both once (per triangle, per pixel) for B1 and B2.
struct Det3 {
  int64_t dm = 0;
  int32_t dexp = 0;
};
Det3 det3(const Coefs& c);
In make_in(const Coefs& c, const persp::Unit::Acc& s, const Det3& d, uint32_t laniso, uint32_t max_lod);

// A local projective map around pixel (0, 0): q, Jacobian J (texels per pixel), dq/dx = G,
// dq/dy = H and (u, v) at the pixel. Any such tuple is the view of some plane.
struct Local {
  double q = 1, ux = 1, vx = 0, uy = 0, vy = 1, g = 0, h = 0, u = 0, v = 0;
};
Coef9 local_map(const Local& l);
// Block inputs at pixel (0, 0) of a float map: numerators, q and det3 rounded to nearest (and
// saturated) to their formats; G, H codes (s44.40) for the forward-difference variant.
In in_from_map(const Coef9& k, uint32_t laniso = 4 << fmt::kEllLogF, uint32_t max_lod = 12);
int64_t q_code(double v);
// Random local map of the random vector set: q in [2^-9, 1], major axis 2^[-6, 14) texels with
// q^2 major < 2^13, anisotropy up to 1024, random orientation and sign, |G|, |H| <= q/64.
Local random_local(std::mt19937_64& rng);

// Production (analytic) unit.
Out analytic(const In& in);
// Forward-difference unit (corrected seed recurrences, rtl/ellipse/tu_ellipse_rec.sv): same
// inputs plus q(x+1) = q + G and q(y+1) = q + H (s(EllRecQW).PerspF, the span walk's registers);
// n* of `in` are the same numerators (dm, dexp unused). Structure, as the RTL:
//   front (rec_front): horizon guard on q, q+G, q+H (< 2^-PerspGuardLog2, incl. <= 0);
//     dX = q (q+G), dY = q (q+H) exact (u(EllRecDW), 2 PerspF frac), each normalised to the
//     RecipMantW-bit truncated mantissa and inverted by recip::core (R u25.24, faithful);
//     Ux = round_half_up(nUx R 2^-(RecipOutF + e - 2 PerspF)), saturated to s(EllNumW).EllNumF
//     (the same for Vx with dX, Uy, Vy with dY); det J = Ux Vy - Uy Vx exact (s(EllRecJdW),
//     2 EllNumF frac) normalised to the det3 float format (dm truncated); a guarded pixel goes
//     on with q := 0;
//   back end: analytic() on (J, q := 1, det J): log2 q = 0 and 1/q = R(1.0) = 1 exactly, so
//     Ae.. are the unscaled ellipse of J, f = det J, log2 major from J alone.
// Error: the departure log2(1 + G/q) of the forward difference from the derivative (documented
// in docs/blocks/ellipse.md) plus the analytic unit's bounds; every width is exact except the
// faithful reciprocal (2^-24 relative) and the rounding of J to EllNumF bits.
// The back end's input (q := 0 on the horizon: analytic() flags it and zeroes every output).
In rec_front(const In& in, int64_t qg, int64_t qh);
Out recurrence(const In& in, int64_t qg, int64_t qh);
// The same with G, H of the triangle (s44.40): recurrence(in, in.q + g, in.q + h).
Out forward_difference(const In& in, int64_t g, int64_t h);
// The unit on pixel (x, y) of a triangle, as the texture unit runs it: numerators, q and det3 of
// the quantised coefficients (make_in), analytic or (recurrence) the seed's forward differences
// with q + G, q + H.
Out pixel(const Coefs& c, int x, int y, uint32_t laniso, uint32_t max_lod, bool recurrence);
Out pixel(const Coefs& c, const persp::Unit::Acc& s, const Det3& d, uint32_t laniso, uint32_t max_lod, bool recurrence);

// Log2 unit: x > 0 -> log2(x) with EllLogF + 1 fraction bits (truncating squarings).
// log2_fx_serial is the hardware's algorithm (EllLogF + 1 truncating squarings of the
// EllLogMantW-bit mantissa); log2_fx gives the same bits from a staircase table of the
// squarings' result over the mantissas (equal on every mantissa: EllipseFx.Log2TableExhaustive).
int64_t log2_fx(u128 x);
int64_t log2_fx_serial(u128 x);
// The fraction part alone for a mantissa m in [2^(EllLogMantW-1), 2^EllLogMantW).
uint32_t log2_frac(uint64_t m);
uint32_t log2_frac_serial(uint64_t m);
// Integer square root, floor: isqrt_serial is the bit-serial restoring algorithm (one result
// bit per step); isqrt gives the same result from a floating-point estimate and an exact
// correction (EllipseFx.IsqrtFastEqualsSerial).
uint64_t isqrt(u128 x);
uint64_t isqrt_serial(u128 x);

// Real values of the outputs.
double lod_value(const Out& o);
double log_value(int32_t l);  // -inf for kLogNegInf
double fe_value(const Out& o);  // Fe' = f^2
double coef_value(double code, const Out& o);

}  // namespace tu::ellipse::fx
