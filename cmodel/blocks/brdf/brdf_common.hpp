// Shared part of the bit-accurate BRDF specular models (docs/blocks/brdf.md): formats, the front
// end every model starts with, the reciprocal of a positive fixed-point value (the reciprocal
// block's core), and the 2^-q cut-off.
//
// Front end (one pipeline stage in every RTL model):
//   c  = clamp(N.H, 0, 1)           u21.20 (c > 1 or n outside [1, 1000] raises `flag`)
//   t  = 1 - c                      u21.20, exact (so u = 0 exactly at c = 1)
//   u  = n * t                      u30.20, exact (the one quantity every model depends on)
//   cut = c < c_cut                 c_cut: the per-material cut-off code (cut_code), F = 0 below
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "reciprocal/reciprocal.hpp"
#include "texunit/fixed.hpp"
#include "texunit/formats.hpp"

namespace tu::brdf {

using CIn = SFixed<fmt::kBrdfCW, fmt::kBrdfCF>;    // N.H as delivered
using C = UFixed<fmt::kBrdfClW, fmt::kBrdfCF>;     // clamped c, also t = 1 - c
using U = UFixed<fmt::kBrdfUW, fmt::kBrdfCF>;      // u = n (1 - c)
using D = UFixed<fmt::kBrdfDW, fmt::kBrdfDF>;      // divisors, >= 1
using W1 = UFixed<fmt::kBrdfWF + 1, fmt::kBrdfWF>; // values in [0, 2): squares, 1/D^2, bases
using Out = UFixed<fmt::kBrdfOutW, fmt::kBrdfOutF>;

enum class Model { Blinn, Schlick, Msh, Dsh, Scos2, St16, Qr };
inline constexpr Model kModels[] = {Model::Blinn, Model::Schlick, Model::Msh, Model::Dsh,
                                    Model::Scos2, Model::St16, Model::Qr};
std::string name(Model m);  // "blinn", "schlick", "msh", "dsh", "scos2", "st16", "qr"

struct In {
  uint64_t c = 0;     // BrdfCW-bit two's-complement code of N.H
  uint64_t n = 0;     // BrdfNW-bit exponent
  uint64_t ccut = 0;  // BrdfClW-bit cut-off code (cut_code(model, n))
};
struct Result {
  uint64_t f = 0;     // Out code
  bool flag = false;  // c > 1 clamped, or n outside [1, BrdfNMax] clamped
};

struct Front {
  C c, t;
  U u;
  int n = 1;
  bool cut = false, flag = false;
};
Front front(const In& in);

// 1/v for a positive raw code v with f fraction bits: the leading one of v is found (msb p),
// the top RecipMantW bits left-justified (truncated) are the mantissa M in [1, 2), and
// 1/v = R * 2^(f - p) with R = recip::core(M) (< 1 ULP of 2^-RecipOutF from 1/M).
struct Recip {
  recip::Out r;
  int p = 0;
};
Recip recip_of(u128 v);

// Round a raw code (non-negative) right by d bits, half up; the RTL's (x + 2^(d-1)) >> d.
inline u128 rnd(u128 v, int d) { return d <= 0 ? v << -d : (v + (u128(1) << (d - 1))) >> d; }
// Saturate to the output format.
inline uint64_t sat_out(u128 v) {
  return v > u128(Out::kMaxRaw) ? static_cast<uint64_t>(Out::kMaxRaw) : static_cast<uint64_t>(v);
}

// Float reference of a model at a real c in [0, 1] (brdf_ref.hpp) used by the cut-off.
double ref_value(Model m, double c, int n);
// Smallest c code (BrdfCF fraction bits) with ref_value >= 2^-q; F is monotone in c. Codes
// below it are cut off (F = 0). q = BrdfCutQ = OutF + 1 makes the cut lossless: the float
// value below it rounds to 0 anyway.
uint64_t cut_code(Model m, int n, int q = fmt::kBrdfCutQ);

// The bit-accurate model (dispatch to brdf_<model>.hpp).
Result eval(Model m, const In& in);
// F as a real number.
inline double value(uint64_t f) { return static_cast<double>(f) / (1 << fmt::kBrdfOutF); }

}  // namespace tu::brdf
