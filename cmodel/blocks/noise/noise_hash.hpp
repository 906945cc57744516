// Lattice hash of improved noise through the permutation ROM (Perlin's 256-entry table; the
// reference's doubled 512-entry table is the same ROM addressed modulo 256, i.e. 8-bit wrapping
// adds). Corner (cx, cy, cz) of the cell with lattice indices X, Y, Z (NoiseLatW bits) hashes to
//     h = p[p[p[X + cx] + Y + cy] + Z + cz]       (all sums mod 256),
// the reference's AA, AB, BA, BB (+1) chain. Exact; rtl/generated/tu_noise_perm_rom.sv is this
// table (texunit gen-rtl).
#pragma once

#include <cstdint>

#include "noise/noise_ref.hpp"

namespace tu::noise {

inline uint8_t perm_rom(uint32_t i) { return permutation()[i & 255]; }

inline uint8_t corner_hash(uint32_t X, uint32_t Y, uint32_t Z, uint32_t cx, uint32_t cy, uint32_t cz) {
  return perm_rom(perm_rom(perm_rom(X + cx) + Y + cy) + Z + cz);
}

}  // namespace tu::noise
