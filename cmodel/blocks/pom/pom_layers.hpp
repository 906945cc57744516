// Adaptive POM layer counter (seed-000 note §1.4; docs/blocks/relief.md), block `pom_layers`.
//
//   a   = min(|Vz|, 1)                  Vz: s16.14 code (PomVzW/PomVzF); Vz < 0 uses |Vz| and
//                                       raises `neg` (a back-facing view: the march must flip P)
//   idx = round_half_up(a * 2^11)       0..2048 (PomIdxW = 12 bits)
//   f   = ROM[idx] = round((1 - idx/2^11)^0.8 * 2^16)   u17.16, f(0) = 1 exactly
//   N   = floor(Nmin + F*((Nmax/2 - Nmin) + (Nmax/2)*C)),  C = code/255
//       = Nmin + floor(f * T / (2 * 255 * 2^16)),  T = 255*(Nmax - 2*Nmin) + Nmax*code  (exact)
//   out = clamp(N, lo, hi), lo = max(Nmin, 1), hi = max(Nmax, lo)   (N >= 1 always)
// The floor of the exact rational is computed as: q = floor(f*T / 2^17) (arithmetic shift),
// y = q + 255*PomBias >= 0, floor(y/255) = (y*PomDivM) >> PomDivS (exact for the y range;
// exhaustively checked), N = Nmin + that - PomBias. Only F is rounded; the rest is exact.
#pragma once

#include <cstdint>
#include <vector>

#include "texunit/formats.hpp"

namespace tu::pom {

inline constexpr uint32_t kDefaultNmin = 4;
inline constexpr uint32_t kDefaultNmax = 32;
inline constexpr int kRomSize = (1 << fmt::kPomIdxF) + 1;

// |Vz| -> ROM index (vz is the sign-extended PomVzW-bit code).
uint32_t vz_index(int32_t vz);
// ROM of F codes, kRomSize entries (shared with the RTL via texunit gen-rtl).
const std::vector<uint32_t>& f_table();
// floor(y / 255) by the constant multiply of the RTL.
uint32_t div255(uint32_t y);

struct Layers {
  uint32_t n = 0;    // layer count, PomNW bits
  bool neg = false;  // Vz < 0
};

// The bit-accurate unit. nmin, nmax are PomNW-bit codes.
Layers layers(int32_t vz, uint32_t code, uint32_t nmin = kDefaultNmin, uint32_t nmax = kDefaultNmax);
// Same from a ROM index (the exhaustive test's domain).
uint32_t layers_idx(uint32_t idx, uint32_t code, uint32_t nmin = kDefaultNmin,
                    uint32_t nmax = kDefaultNmax);

// Float reference (double): the seed's formula with F = (1 - a)^0.8 at the real a = min(|vz|, 1),
// truncated and clamped like the unit. `exact` (optional) receives the unfloored value.
uint32_t layers_ref(double a, double c, uint32_t nmin = kDefaultNmin,
                    uint32_t nmax = kDefaultNmax, double* exact = nullptr);

}  // namespace tu::pom
