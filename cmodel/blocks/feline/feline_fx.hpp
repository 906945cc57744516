// Feline probe filter, bit-accurate fixed-point model (docs/blocks/feline.md; float reference
// feline_ref.hpp). Inputs per pixel as the EWA's (ewa::fx::In): u, v (s(PerspUvW).TexUvF, B1) and
// B2's outputs (lmaj, lmin: log2 major / anisotropy-clamped minor semi-axis, s18.10, floored;
// the conic ae, be, ce for the direction; lrho; flags).
//
//  1. Ratio e = lmaj - lmin >= 0 (u.EllLogF, log2 s1/s2). N = min(n >= 1 : e <= Lg[n] + kRatioTol),
//     Lg[n] = floor(log2(n) 2^EllLogF) (a 16-entry table): exactly ceil(2^((e - kRatioTol) /
//     2^EllLogF)) on the decoded e (feline_ref.hpp's tolerance); clamped to Nmax (flag kClamped).
//  2. Probe LOD: log2 rho_p = max(lmin, lmaj - Lg[Nmax]) into the trilinear engine's GL step
//     tex::trilinear_lod (bias, [min_lod, max_lod], magnification, pyramid clamp; u.TexLodF).
//  3. Direction: the EWA's CORDIC (ewa::fx::vectoring on the conic, rotation of theta) -> c, s
//     (s1.EwaCsF).
//  4. Line: s1 = exp2 of lmaj truncated to EwaExpF bits (the EWA's exp2 ROM; clamped to
//     [2^-FelSigF, 2^FelAxisMaxLog2], flag kAxisClamp), u.FelSigF; ratio r = m / s1 =
//     2^-((lmaj - log2 rho_p) truncated to EwaExpF bits) (ROM, floor; m = the clamped minor
//     max(s2, s1 / Nmax)), rho = 1 - r (u0.FelTF); D = s1 - m =
//     s1 rho, R = 1/(N-1) (ROM u1.FelRecipF, nearest; 0 for N = 1), half step h = (D R) (c, s)
//     (each product rounded half up, s.FelSigF), distance step tq = rho R (u0.FelTF, half up).
//  5. Probe i (0 .. N-1), k = 2i - (N-1): position (u, v) + k h rounded half up to TexUvF bits and
//     saturated to PerspUvW (B1's format); t = |k| tq, Q = t^2 >> (2 FelTF - GaussQF) (floor);
//     weight gauss::weight(Q) (u17.16, the EWA's formula unit; w > 0: the inner probes have
//     Q < 1); colour tex::trilinear at the probe LOD.
//  6. acc_c += w c, wsum += w (exact: FelAccW, FelWsumW); colour = ewa::fx::normalise (the EWA's
//     reciprocal unit, round half up, saturate).
// No axes (B2 horizon, point footprint lmaj = -inf): one probe at (u, v) with B2's lrho (kUnit):
// GL trilinear.
#pragma once

#include <array>
#include <cstdint>

#include "ewa/ewa_fx.hpp"
#include "feline/feline_ref.hpp"
#include "texture/trilinear_lod.hpp"

namespace tu::feline::fx {

struct Config {
  int max_probes = kDefaultMaxProbes;  // Nmax, 1 .. FelNMax
  tex::LodParams lod;                  // the GL rule's codes (tex::lod_params)
};

enum Flag : uint32_t {
  kUnit = 1,       // no axes: one probe, B2's lrho
  kClamped = 2,    // ceil(s1 / s2) > Nmax: N = Nmax, the LOD raised to log2(s1 / Nmax)
  kAxisClamp = 4,  // s1 outside [2^-FelSigF, 2^FelAxisMaxLog2] texels: clamped
};

// Per-pixel set-up (the RTL's intermediate comparisons).
struct Setup {
  int n = 1;                 // probes
  int32_t lam = 0;           // log2 rho of the probes, s(EllLogW).EllLogF
  uint32_t lod = 0;          // u(EllLodW).TexLodF after the GL rule
  uint32_t tri_flags = 0;    // tex::TriFlag
  int32_t c = 0, s = 0;      // major axis, s(EwaCsW).EwaCsF
  uint64_t sig1 = 0;         // u(FelSigW).FelSigF
  uint32_t rho = 0;          // 1 - s2/s1, u0.FelTF
  uint64_t delta = 0;        // s1 - s2, u(FelSigW).FelSigF
  uint32_t recip = 0;        // 1/(N-1), u1.FelRecipF
  int64_t hu = 0, hv = 0;    // half step, s(FelStepW).FelSigF
  uint32_t tq = 0;           // distance step, u.FelTF
  uint32_t flags = 0;
  friend bool operator==(const Setup&, const Setup&) = default;
};

struct Probe {
  int64_t u = 0, v = 0;  // s(PerspUvW).TexUvF
  uint32_t q = 0;        // u(GaussQW).GaussQF
  uint32_t w = 0;        // u(GaussSqW).GaussSqF
};

struct Out {
  img::Rgba8 color;
  int probes = 1;
  uint32_t lod = 0, tri_flags = 0, flags = 0;
  int texels = 0;        // 8 per probe, 4 when the LOD is the top level
};

// Lg[n] = floor(log2(n) 2^EllLogF), n = 0 .. FelNMax (Lg[0] unused, 0).
const std::array<int32_t, fmt::kFelNMax + 1>& log2_int_table();
// R[m] = round(2^FelRecipF / m), m = 1 .. FelNMax - 1; R[0] = 0.
const std::array<uint32_t, fmt::kFelNMax>& recip_table();
// Step 1 on a ratio code e >= 0.
int probe_count(int64_t e, int max_probes);

Setup setup(const ewa::fx::In& in, const tex::Texture& t, const Config& cfg);
Probe probe(const Setup& su, const ewa::fx::In& in, int i);
Out filter(const ewa::fx::In& in, const tex::Texture& t, const Config& cfg);

// Float reference on the same B2 outputs (axes 2^lmaj, 2^lmin, the conic's direction in double;
// no axes: one probe at B2's lrho): the quantisation of steps 1-6 alone.
Result filter_ref_b2(const ewa::fx::In& in, const tex::Texture& t, const Params& p);

}  // namespace tu::feline::fx
