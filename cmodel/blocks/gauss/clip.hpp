// Clip volume of the Gaussian texel body (seed 003 §2, docs/blocks/gaussian.md):
//     v(d) = Phi(d / 0.2),  d in [-0.5, 0.5],  v(-d) = 1 - v(d).
// Every variant evaluates an approximation p(a) on a = min(|d|, 0.5) in [0, 0.5] and folds:
//     v = p(a) for d >= 0,  v = 1 - p(a) for d < 0   (exact in codes: out(d) + out(-d) = 2^16).
// Formats (formats.hpp): d s13.12 (codes outside [-0.5, 0.5] clamp to the domain edge),
// a u12.12, coefficients s22.18, accumulators and truncated products s24.18 (floor),
// output u16.16 rounded half up, p saturated to [1, 2^16 - 1] codes.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "texunit/fixed.hpp"
#include "texunit/formats.hpp"

namespace tu::clip {

using In = SFixed<fmt::kClipInW, fmt::kClipInF>;
using A = UFixed<fmt::kClipAW, fmt::kClipInF>;
using Coef = SFixed<fmt::kClipCoefW, fmt::kClipCoefF>;
using Acc = SFixed<fmt::kClipAccW, fmt::kClipCoefF>;
using Out = UFixed<fmt::kClipOutW, fmt::kClipOutF>;

inline constexpr int kHalfCode = 1 << (fmt::kClipInF - 1);  // a code of 0.5

enum class Scheme {
  Horner,     // acc = c_n; acc = c_k + floor(acc * a), k = n-1..0 (also the shared-multiplier FSM)
  Estrin3,    // (c0 + floor(c1 a)) + floor((c2 + floor(c3 a)) * floor(a*a)), degree 3 only
  Piecewise,  // segment s = #{breakpoints <= a}; c0[s] + floor(c1[s] * a)
  Uniform,    // segment s = min(a >> shift, n-1) (a table, no comparators); c0[s] + floor(c1[s] a)
};

struct Variant {
  std::string name;    // e.g. seed_p2, mm_p3
  std::string origin;  // where the coefficients come from
  Scheme scheme;
  std::vector<int64_t> c;       // Horner/Estrin: raw Coef codes c0..cn (ClipCoefF fraction bits)
  std::vector<double> printed;  // the coefficients as printed (seed) / exact double of c
  // Piecewise/Uniform: per segment (c0, c1) raw codes and, for Piecewise, breakpoint codes of a.
  std::vector<int64_t> seg_c0, seg_c1, breaks;
  int uniform_shift = 0;
  int degree() const { return scheme == Scheme::Horner || scheme == Scheme::Estrin3
                                  ? static_cast<int>(c.size()) - 1 : 1; }
};

// All modelled variants: seed_p1, seed_p2, seed_p3, mm_p1, mm_p2, mm_p3, mm_p3_estrin, mm_p4,
// tab16 (16 uniform linear segments).
const std::vector<Variant>& variants();
const Variant& variant(const std::string& name);  // throws std::invalid_argument

// p(a) code (u16.16, saturated to [1, 2^16-1]) for an a code in [0, kHalfCode].
uint32_t eval_half(const Variant& v, uint32_t a_code);
// Full block: d code (ClipInW-bit two's complement, sign-extended) -> v code.
uint32_t eval(const Variant& v, int32_t d_code);
// a = min(|d|, 0.5) and the sign, as the hardware front end computes them.
uint32_t abs_clamp(int32_t d_code);

// The polynomial / segment line with the stored (hardware) coefficients, in double: the
// "approximation" part of the error; eval() - approx() is the "rounding" part.
double approx_half(const Variant& v, double a);
// Reference: Phi(a / 0.2) with d clamped to [-0.5, 0.5].
double reference(double d);

struct ErrorStats {
  double max_abs = 0;       // max |hw - ref| over every input code
  double max_approx = 0;    // max |poly(stored coefficients) - ref|
  double max_round = 0;     // max |hw - poly|
  double rms = 0;
  double max_ulp = 0;       // max_abs in output LSBs
  bool monotonic_half = true;  // p non-decreasing on a in [0, 0.5]
  bool monotonic_full = true;  // v non-decreasing over all d codes (fails if p(0) != 1/2)
  bool symmetric = true;       // out(d) + out(-d) == 2^16 for every d != 0
  uint64_t codes = 0;
};
// Exhaustive over all 2^ClipInW input codes.
ErrorStats exhaustive(const Variant& v);

}  // namespace tu::clip
