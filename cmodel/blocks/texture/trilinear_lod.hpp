// Trilinear's level of detail: the OpenGL / Vulkan rule (GL 4.6 §8.14, Vulkan "Level-of-detail
// operation"), as LINEAR_MIPMAP_LINEAR with LINEAR magnification uses it.
//
//   rho^2  = max(Ux^2 + Vx^2, Uy^2 + Vy^2)      level-0 texels per pixel step, no square root
//   lambda = log2 rho - base + bias, clamped to [min_lod, max_lod] (min_lod wins if above max_lod)
//   lambda <= 0: magnification (level base, flag kTriMagnify)
//   otherwise level base + lambda: the pair floor, + 1 blended by the fraction; base + lambda >=
//   top: the top level alone (flag kTriLodSat). No anisotropy clamp.
// Levels (GL TEXTURE_BASE_LEVEL / TEXTURE_MAX_LEVEL, tex::level_range): base = min(base_level,
// pyramid top), top = clamp(max_level, base, pyramid top); rho is measured at level 0, so
// log2 rho - base is GL's log2 rho of the base level. The same step on the EWA's clamped minor
// axis (B2 lmin) chooses the EWA's level, on Feline's its probes' level.
// Derivatives are analytic per pixel (B2's numerators of the exact Jacobian), where a GPU takes
// them as differences over 2x2 quads.
//
// Bit-accurate form: B2 outputs lrho = log2 rho (ellipse::fx::Out::lrho, s(EllLogW).EllLogF,
// floored); lambda = (lrho >> (EllLogF - TexLodF)) + bias, all codes with TexLodF = 8 fraction
// bits (D3D11 asks 8, Vulkan's mipmapPrecisionBits >= 4); bias s(TexLodBiasW).TexLodF; min_lod,
// max_lod, output u(EllLodW).TexLodF.
// Bound: -2^-10 <= lambda_ref - lod < 2^-8 + 2^-9 away from the clamps (the floor to TexLodF bits,
// 2^-8, plus the floor to EllLogF bits, B2's numerator rounding, the log2 unit's truncation and
// log2 q from B1's 24-bit mantissa of q); measured -9.67e-4 .. 3.90e-3 levels on 119,927 random
// footprints (TrilinearLod.FixedMatchesFloatReference); on the decoded lrho alone the floor is the
// only loss, max 2.93e-3 < 2^-8 on every lrho code (TrilinearLod.ExhaustiveOverLrhoCodes).
#pragma once

#include <algorithm>
#include <cstdint>

#include "texunit/formats.hpp"

namespace tu::tex {

enum TriFlag : uint32_t {
  kTriMagnify = 1,   // lambda <= 0: level 0
  kTriLodClamp = 2,  // min_lod > 0 raised lambda, or max_lod lowered it
  kTriLodSat = 4,    // lambda >= the top level: one level
};

struct LodParams {  // TexLodF-bit codes
  int32_t bias = 0;
  uint32_t min_lod = 0;
  uint32_t max_lod = ((1u << fmt::kEllLodW) - 1);
  uint32_t base_level = 0;   // integer levels (material base_level, max_level; GL's 1000 default)
  uint32_t max_level = 1000;
};
// Material values (levels) to codes (bias rounded half up; |bias| <= 16, lods in [0, 15.99]).
LodParams lod_params(double bias, double min_lod, double max_lod, int base_level = 0, int max_level = 1000);

// The levels a material samples on a pyramid whose top level is `top`: base = min(base_level, top),
// top = clamp(max_level, base, top). base_level > max_level (GL: an incomplete texture) samples
// the base level alone; base_level above the pyramid, its top level.
struct LevelRange {
  int base = 0, top = 0;
};
LevelRange level_range(int base_level, int max_level, int top);
inline LevelRange level_range(const LodParams& p, int top) {
  return level_range(static_cast<int>(std::min<uint32_t>(p.base_level, 1000)),
                     static_cast<int>(std::min<uint32_t>(p.max_level, 1000)), top);
}

struct TriLod {
  uint32_t lod = 0;  // u(EllLodW).TexLodF, in [base << TexLodF, top << TexLodF] (level_range)
  uint32_t flags = 0;
};
TriLod trilinear_lod(int32_t lrho, const LodParams& p, int top);

// The rule from log2 rho on (bias, clamps, magnification, pyramid): the float reference of the
// step tex::trilinear_lod; -inf gives magnification. Flags as above.
double lod_rule_ref(double log2_rho, double bias, double min_lod, double max_lod, int top,
                    uint32_t* flags = nullptr, int base_level = 0, int max_level = 1000);
// Float reference on the Jacobian (texels per pixel); flags as above.
double trilinear_lod_ref(double ux, double vx, double uy, double vy, double bias, double min_lod,
                         double max_lod, int top, uint32_t* flags = nullptr, int base_level = 0,
                         int max_level = 1000);

}  // namespace tu::tex
