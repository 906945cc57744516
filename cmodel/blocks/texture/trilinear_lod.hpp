// Trilinear's level of detail: the OpenGL / Vulkan rule (GL 4.6 §8.14, Vulkan "Level-of-detail
// operation"), as LINEAR_MIPMAP_LINEAR with LINEAR magnification uses it.
//
//   rho^2  = max(Ux^2 + Vx^2, Uy^2 + Vy^2)      level-0 texels per pixel step, no square root
//   lambda = log2 rho + bias, clamped to [min_lod, max_lod]
//   lambda <= 0: magnification (level 0 bilinear, flag kTriMagnify)
//   otherwise the pair floor(lambda), + 1 blended by frac(lambda); lambda >= top: the top level
//   alone (flag kTriLodSat). No anisotropy clamp (the EWA keeps its own rule).
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
};
// Material values (levels) to codes (bias rounded half up; |bias| <= 16, lods in [0, 15.99]).
LodParams lod_params(double bias, double min_lod, double max_lod);

struct TriLod {
  uint32_t lod = 0;  // u(EllLodW).TexLodF, in [0, top << TexLodF]
  uint32_t flags = 0;
};
TriLod trilinear_lod(int32_t lrho, const LodParams& p, int top);

// The rule from log2 rho on (bias, clamps, magnification, pyramid): the float reference of the
// step tex::trilinear_lod; -inf gives magnification. Flags as above.
double lod_rule_ref(double log2_rho, double bias, double min_lod, double max_lod, int top,
                    uint32_t* flags = nullptr);
// Float reference on the Jacobian (texels per pixel); flags as above.
double trilinear_lod_ref(double ux, double vx, double uy, double vy, double bias, double min_lod,
                         double max_lod, int top, uint32_t* flags = nullptr);

}  // namespace tu::tex
