// Shading stage of the texture unit (docs/blocks/brdf.md "In the unit"), bit-accurate: the
// filtered colour t (RGBA8) modulated by one light, diffuse + specular, with the unit's BRDF model.
//   N, L, H  unit vectors per pixel          s(ShadeVecW).ShadeVecF, rounded to nearest by the
//                                            set-up (texunit/shading.hpp), any length accepted
//   nl, nh = N.L, N.H                        exact (2 ShadeVecF fraction bits, ShadeDotW), then
//                                            round half up to BrdfCF, saturated to s(BrdfCW)
//   d  = round_half_up(clamp(nl, 0, 1))      u(ShadeDiffW).ShadeColF (0..256)
//   F  = BRDF(model, c = nh, n, c_cut)       u9.8 (brdf::eval), 0 when nl <= 0 (light behind)
//   E  = amb + round_half_up(lc d)           u(ShadeEW).ShadeColF per channel
//   out = min(255, round_half_up((t E 2^8 + 255 ks F) / 2^16))   per RGB channel; alpha = t.a
// ks = the material's specular colour times the light colour, lc the light colour, amb the
// ambient level: u(ShadeColW).ShadeColF codes (0 .. 511/256). `on` = 0 passes t unchanged.
// Error bound against the float formula (ref_channels) at the same vector and colour codes:
// |out - ref| <= 0.5 + 255 (2^-9 + lc 2^-9) + 255 ks (2^-9 + 2n 2^-21) output LSB (the output, d,
// lc d and F roundings, c rounded to BrdfCF bits; 2.0 LSB at lc = ks = 1 and n = 1), checked and
// measured by BrdfShade.ErrorAgainstTheFloatFormula (docs/blocks/brdf.md §6).
#pragma once

#include <array>
#include <cstdint>

#include "brdf_common.hpp"
#include "texunit/image.hpp"

namespace tu::brdf::shade {

struct Vec {
  int64_t x = 0, y = 0, z = 0;  // ShadeVecW-bit signed values
};
struct In {
  bool on = false;
  Vec n, l, h;
  uint32_t nexp = 1;     // specular exponent (BrdfNW bits)
  uint64_t ccut = 0;     // cut-off code of the model at nexp (brdf::cut_code)
  uint32_t ks[3] = {0, 0, 0}, lc[3] = {0, 0, 0}, amb = 0;  // ShadeColW codes
};
struct Result {
  img::Rgba8 rgba;
  uint32_t d = 0;   // diffuse code
  uint64_t f = 0;   // BRDF output code (0 when the light is behind)
  bool flag = false;  // the BRDF block's flag
};

// N.x code rounded half up to BrdfCF fraction bits and saturated to s(BrdfCW): the BRDF's c input.
int64_t dot(const Vec& a, const Vec& b);
Result eval(Model m, const In& in, img::Rgba8 t);

// Float formula of the stage at real unit vectors and colours (the render reference):
// out = clamp(t (amb + lc max(0, N.L)) + 255 ks F_model(clamp(N.H, 0, 1)) [N.L > 0], 0, 255).
struct RefIn {
  double n[3] = {0, 0, 1}, l[3] = {0, 0, 1}, h[3] = {0, 0, 1};
  int nexp = 1;
  double ks[3] = {0, 0, 0}, lc[3] = {0, 0, 0}, amb = 0;
};
// Unrounded channel values (r, g, b), and the same rounded and clamped to RGBA8.
std::array<double, 3> ref_channels(Model m, const RefIn& in, img::Rgba8 t);
img::Rgba8 ref(Model m, const RefIn& in, img::Rgba8 t);

// Quantisers of the set-up: a vector component to s(ShadeVecW).ShadeVecF (nearest, saturated),
// a colour to u(ShadeColW).ShadeColF (nearest, clamped to [0, 511/256]).
int64_t vec_code(double x);
uint32_t col_code(double x);
// The fixed-point input of the float one, with the model's cut-off code at r.nexp (brdf::cut_code).
In quantise(const RefIn& r, uint64_t ccut);

// The shade port word (ShadeWordW bits in 32-bit words, word 0 least significant): from the most
// significant used bit down {on, Nx, Ny, Nz, Lx, Ly, Lz, Hx, Hy, Hz, n, c_cut, ks rgb, lc rgb, amb}.
inline constexpr int kWordWords = fmt::kShadeWordW / 32;
std::array<uint32_t, kWordWords> pack(const In& in);

// Latency of the stage in the texture-unit top (tu_shade): the model's BRDF pipeline; the dot
// products and the combination are combinational at its input and output.
int latency(Model m);

}  // namespace tu::brdf::shade
