// Formats of the distance-map relief (docs/blocks/relief.md §13). C model only for now: they move
// into texunit/formats.hpp (and so into tu_formats_pkg.sv) with the RTL tracer stage.
#pragma once

namespace tu::fmt {
inline constexpr int kDmCodeW = 8;   // voxel: safe step code, unsigned, value code * 2^-DmQF texel
inline constexpr int kDmQF = 4;      // quantum 2^-DmQF texel (codes rounded down)
inline constexpr int kDmEtaF = 6;    // tracer position tolerance eta = 2^-DmEtaF texel (in the margin)
inline constexpr int kDmDF = 24;     // ray depth D in [0, 1]: unsigned, DmDF fraction bits (exact accumulator)
inline constexpr int kDmDW = kDmDF + 1;  // D code 0..2^DmDF
inline constexpr int kDmKF = 8;      // K = floor(2^(DmDF + PomUvF - DmQF + DmKF) / ceil(lambda)): fraction bits
inline constexpr int kDmKW = 29;     // K < 2^28 + 1 since lambda >= 1 texel (2^16 codes)
inline constexpr int kDmLambdaW = 32;  // ceil(lambda): texels of ray per unit D, PomUvF fraction bits
inline constexpr int kDmCap = 32;    // default iteration cap
inline constexpr int kDmFinish = 8;  // render: linear steps of the finish (then 4 bisection steps)
}  // namespace tu::fmt
