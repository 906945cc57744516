// Helpers shared by the POM vector blocks: 32-bit codes, the engines' depth ROM (bricks 64x64)
// and a view vector from angles.
#pragma once

#include <cmath>
#include <cstdint>

#include "pom/pom_march.hpp"
#include "pom/relief_quality.hpp"
#include "vector_file.hpp"

namespace tu::blocks::pomvec {

inline uint64_t c32(int64_t v) { return static_cast<uint64_t>(v) & 0xffffffffull; }
inline int64_t s32(uint64_t x) { return vec::sext(x, 32); }
inline uint64_t c16(int64_t v) { return static_cast<uint64_t>(v) & 0xffffull; }
inline int64_t s16(uint64_t x) { return vec::sext(x, 16); }

// The depth map held by the RTL engines' ROM model.
inline const img::Gray8& depth() {
  static const img::Gray8 d = pom::map_bricks(64);
  return d;
}

// Tangent-space view at angle th_deg from the normal, azimuth ph_deg; height scale s.
inline pom::View view(double th_deg, double ph_deg, double s) {
  const double th = th_deg * M_PI / 180, ph = ph_deg * M_PI / 180;
  pom::View v;
  v.vx = static_cast<int32_t>(std::lround(std::sin(th) * std::cos(ph) * 16384));
  v.vy = static_cast<int32_t>(std::lround(std::sin(th) * std::sin(ph) * 16384));
  v.vz = static_cast<int32_t>(std::lround(std::cos(th) * 16384));
  v.scale = static_cast<uint32_t>(std::lround(s * 65536));
  return v;
}

// Wrapped uv distance in 2^-16 units.
inline double wrapped_lsb(double a, double b) {
  double x = std::fabs(a - b);
  x -= std::floor(x);
  return std::min(x, 1 - x) * 65536.0;
}

// The scene pixel stream of the cycle tests and the report: a 64x64-pixel tile of the bricks map
// (texel centres), S = 0.05, azimuth 30 degrees, view angle `deg`. Rows hold inputs, C-model
// outputs and references of `block`: pom_unit and pom_march with N = n (n = 0: adaptive, N from
// pom::layers of the map's complexity, 4..32); iter_parallax with the seed direction (n = 0) or
// the P-normalised one (n = 1).
vec::VectorFile scene_vectors(const std::string& block, double deg, int n);

}  // namespace tu::blocks::pomvec
