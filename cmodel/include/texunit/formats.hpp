// texunit formats: the ONE description of word lengths, fraction bits and constants shared by the
// C model and the RTL. `texunit gen-rtl` writes rtl/0_pkg/tu_formats_pkg.sv from this list;
// the test GeneratedRtl.IsFresh fails when the committed package differs from this file.
//
// Naming: <Block><Signal><W|F>; W = word length, F = fraction bits. Signedness is in the comment
// and in the C-model type that uses the constant.
#pragma once

#include <cstdint>

// X(name, value, description). Values may use earlier names (prefixed k) as constant expressions.
#define TU_FORMAT_PARAMS(X)                                                                      \
  /* Reciprocal unit (docs/blocks/reciprocal.md) */                                             \
  X(RecipInW, 24, "input code q: signed, caller-defined fraction bits")                          \
  X(RecipMantW, 24, "normalised mantissa M in [1,2): unsigned, RecipMantW-1 fraction bits")     \
  X(RecipIdxW, 8, "segment index: top fraction bits of M")                                      \
  X(RecipDxW, kRecipMantW - 1 - kRecipIdxW, "offset in segment: unsigned, RecipMantW-1 frac")   \
  X(RecipShiftW, 5, "exponent p = msb position of q, 0..RecipInW-2")                             \
  X(RecipC2W, 14, "quadratic coefficient c2: unsigned")                                         \
  X(RecipC2F, 12, "")                                                                           \
  X(RecipT1W, 18, "t1 = c2*dx, truncated: unsigned")                                            \
  X(RecipT1F, 22, "")                                                                           \
  X(RecipC1W, 25, "linear coefficient c1: signed")                                              \
  X(RecipC1F, 22, "")                                                                           \
  X(RecipSW, 25, "s = c1 + t1: signed")                                                         \
  X(RecipT2W, 26, "t2 = s*dx, truncated: signed")                                               \
  X(RecipT2F, 30, "")                                                                           \
  X(RecipC0W, 32, "constant coefficient c0: unsigned")                                          \
  X(RecipC0F, 30, "")                                                                           \
  X(RecipOutW, 25, "reciprocal mantissa R in (0.5,1]: unsigned, RecipOutF fraction bits")       \
  X(RecipOutF, 24, "")                                                                          \
  /* Perlin noise unit (docs/blocks/noise.md) */                                                \
  X(NoiseCoordW, 32, "input coordinates x, y, z: signed, NoiseTF fraction bits (s32.16)")        \
  X(NoiseLatW, 8, "lattice index floor(x) & 255: the period-256 wrap of the permutation")       \
  X(NoiseTF, 16, "local coordinate t = frac(x) in [0,1): unsigned, NoiseTF bits (u16.16)")      \
  X(NoiseFadeIF, 24, "fade intermediates t^2, t^3 (u24.24) and b = t(6t-15)+10: frac bits")     \
  X(NoiseFadeBW, 28, "b = t(6t-15)+10 in (1,10]: unsigned, NoiseFadeIF fraction bits, half up") \
  X(NoiseSW, 17, "fade s = t^3 b in [0,1]: unsigned, NoiseTF fraction bits, half up")           \
  X(NoiseDW, 17, "corner offsets t, t-1 in [-1,1): signed, NoiseTF fraction bits")              \
  X(NoiseValW, 19, "gradient dots and lerps in [-2,2]: signed, NoiseTF fraction bits")          \
  X(NoiseOctaves, 4, "fBm octaves K: noise(2^i x) 2^-i, i < K")                                 \
  X(NoiseAccW, kNoiseValW + kNoiseOctaves, "fBm sum: signed, NoiseTF+K-1 fraction bits, exact") \
  X(NoiseNormF, 18, "normalisation constants 1/(2 B (2 - 2^(1-K))): NoiseNormF fraction bits")  \
  X(NoiseBound3E4, 10364, "bound of |noise3| in 1e-4 (sup 1.0363538, docs/blocks/noise.md)")    \
  X(NoiseBound2E4, 10000, "bound of |noise2| in 1e-4 (per-axis bound, exact sup)")              \
  X(NoiseNorm3, static_cast<int>(((int64_t(1) << (kNoiseNormF + kNoiseOctaves - 1)) * 10000 /    \
                                  (int64_t(kNoiseBound3E4) * ((1 << kNoiseOctaves) - 1)) + 1) / 2), \
    "3-D normalisation constant, round half up: unsigned, NoiseNormF fraction bits")          \
  X(NoiseNorm2, static_cast<int>(((int64_t(1) << (kNoiseNormF + kNoiseOctaves - 1)) * 10000 /    \
                                  (int64_t(kNoiseBound2E4) * ((1 << kNoiseOctaves) - 1)) + 1) / 2), \
    "2-D normalisation constant, round half up: unsigned, NoiseNormF fraction bits")          \
  X(NoiseNormW, kNoiseNormF, "normalisation constant word: unsigned (value < 1)")              \
  X(NoiseOutW, 17, "fbm in [0,1]: unsigned, NoiseTF fraction bits, round half up, clamped")      \
  X(NoiseCoreLatency, 6, "noise core: 3 hash levels (fade beside), dots + x lerp, y, z lerp")   \
  X(NoisePipeLatency, kNoiseCoreLatency + 1, "pipelined scheme (K cores) + sum/normalise, II 1") \
  X(NoiseSerialLatency, kNoiseCoreLatency + kNoiseOctaves, "octave-serial scheme (one core)")   \
  X(NoiseSerialIi, kNoiseOctaves, "octave-serial scheme: one sample per K clocks")              \
  /* Noise unit in the texture unit: procedural materials (docs/blocks/noise-appendix.md §5) */ \
  X(NoiseFreqF, 24, "frequency f/W, lattice cells per level-0 texel: fraction bits")            \
  X(NoiseFreqW, 32, "frequency code: unsigned (f/W < 256)")                                     \
  X(NoiseWeightW, 11, "octave weight in [0,1]: unsigned, EllLogF fraction bits (exact clamp)")  \
  X(NoiseGainF, 8, "smoke opacity gain: fraction bits")                                         \
  X(NoiseGainW, 16, "smoke opacity gain code: unsigned (gain < 256)")                           \
  X(NoiseUnitLatency, kNoiseCoreLatency + 3, "tu_noise_unit pipelined: coords, cores, sum, value") \
  /* Water in the noise unit: three octave sums per pixel, normal, Lambert (docs/blocks/noise-appendix.md §5) */ \
  X(WaterAmpF, 8, "water height amplitude a (cells): fraction bits")                            \
  X(WaterAmpW, 13, "water amplitude code: unsigned (a < 32)")                                   \
  X(WaterStepCode, 8, "finite-difference step 2^-8 cells = 2^WaterStepCode codes of s32.16")    \
  X(WaterSlopeF, kNoiseTF + kNoiseOctaves - 1 - (kNoiseTF - kWaterStepCode) + kWaterAmpF,        \
    "slope g = -a dP/dx: fraction bits (exact product of the amplitude and the sum difference)") \
  X(WaterSlopeW, 31, "slope g: signed, saturated to |g| < 2^(WaterSlopeW-1-WaterSlopeF) (guard)") \
  X(WaterLightW, kNoiseTF + 2, "unit light component: signed, NoiseTF fraction bits")          \
  X(WaterQuoW, kNoiseTF + 1, "shade quotient n.L / |n|: unsigned, NoiseTF fraction bits (< 2)") \
  X(WaterPasses, 3, "octave sums per water pixel: P(x, y), P(x + h, y), P(x, y + h)")          \
  X(NoiseWaterLatency, kNoiseUnitLatency - 1 + 2 + kWaterSlopeW + kWaterQuoW + 1,                 \
    "tu_noise_unit water, from the last pass: front, slopes, |n|^2 and n.L, isqrt, divide, colour") \
  /* Gaussian pixel model: clip volume, weight, weight tables (docs/blocks/gaussian.md) */      \
  X(ClipInW, 13, "clip distance d: signed, ClipInF fraction bits; domain [-0.5, 0.5], clamped")  \
  X(ClipInF, 12, "")                                                                            \
  X(ClipAW, 12, "a = min(|d|, 0.5): unsigned, ClipInF fraction bits")                           \
  X(ClipCoefW, 22, "polynomial / segment coefficients: signed, ClipCoefF fraction bits")        \
  X(ClipCoefF, 18, "")                                                                          \
  X(ClipAccW, 24, "Horner/Estrin accumulators and truncated products: signed, ClipCoefF frac")  \
  X(ClipOutW, 16, "v: unsigned, ClipOutF fraction bits, round half up, p in [1, 2^16-1] codes") \
  X(ClipOutF, 16, "")                                                                           \
  X(ClipP1Latency, 2, "comparator + segment table + one multiply-add, II = 1")                  \
  X(ClipHornerLatency, 4, "degree-3 Horner, fully pipelined, II = 1")                           \
  X(ClipEstrinLatency, 3, "degree-3 Estrin (a^2 beside c1*a, c3*a), II = 1")                   \
  X(ClipSeqLatency, 4, "degree-3 Horner on one shared multiplier (FSM)")                        \
  X(ClipSeqIi, 4, "initiation interval of the shared-multiplier scheme")                        \
  X(GaussQW, 16, "normalised quadratic form Q: unsigned, GaussQF fraction bits")                \
  X(GaussQF, 14, "")                                                                            \
  X(GaussTW, 16, "t = 1 - Q/2 in [0.5, 1]: unsigned, GaussTF fraction bits")                    \
  X(GaussTF, 15, "")                                                                            \
  X(GaussSqW, 17, "t^2, t^4 and w = t^8: unsigned, GaussSqF fraction bits, round half up")      \
  X(GaussSqF, 16, "")                                                                           \
  X(GaussLatency, 3, "three squarings, one per stage, II = 1")                                  \
  X(WtabEntryW, 16, "weight-table entry: unsigned, WtabEntryW fraction bits, saturating")       \
  X(GaussXiW, 16, "ellipse-frame coordinates xi, eta (2-D weight table): signed, GaussXiF frac") \
  X(GaussXiF, 14, "")                                                                           \
  X(RecipLatency, 5, "pipeline latency in cycles, II = 1")                        \
  X(RecipCoreLatency, 4, "tu_recip_core (lookup, c2*dx, s*dx, c0 + t2): 4 stages, II = 1")  \
  /* Adaptive POM layer counter (docs/blocks/relief.md) */                                     \
  X(PomVzW, 16, "view-vector z: signed, PomVzF fraction bits (|Vz| > 1 saturates to 1)")        \
  X(PomVzF, 14, "")                                                                             \
  X(PomIdxF, 11, "ROM index: round_half_up(min(|Vz|,1) * 2^PomIdxF), unsigned")                 \
  X(PomIdxW, kPomIdxF + 1, "index 0..2^PomIdxF (2^PomIdxF + 1 ROM entries)")                    \
  X(PomFW, 17, "F = (1-|Vz|)^0.8: unsigned, PomFF fraction bits, round to nearest, F(0)=1")     \
  X(PomFF, 16, "")                                                                              \
  X(PomCW, 8, "complexity code C*255: unsigned integer")                                        \
  X(PomNW, 6, "layer counts Nmin, Nmax, N: unsigned integers 0..63")                            \
  X(PomTW, 17, "T = 255*(Nmax-2*Nmin) + Nmax*code: signed integer")                            \
  X(PomPW, 33, "P = F*T: signed, PomFF fraction bits (exact)")                                  \
  X(PomQW, 16, "y = floor(P / 2^(PomFF+1)) + 255*PomBias: unsigned integer, < 2^15")            \
  X(PomBias, 64, "bias (in units of 255) that makes y non-negative")                            \
  X(PomDivM, 32897, "floor(y/255) = (y*PomDivM) >> PomDivS, exact for y < 66052")              \
  X(PomDivS, 23, "")                                                                            \
  X(PomLayersLatency, 3, "pom_layers pipeline latency in cycles, II = 1")                      \
  X(PomUvW, 32, "POM march uv: signed, PomUvF fraction bits (1.0 = one texture)")              \
  X(PomUvF, 16, "")                                                                             \
  X(PomSF, 16, "height scale S: unsigned u0.PomSF (S < 1)")                                   \
  X(PomVzMin, 512, "|Vz| guard: |Vz| clamped to >= PomVzMin * 2^-PomVzF (2^-5, 88.2 deg)")    \
  X(PomWF, 16, "refinement weight w = a/(a+b) in [0,1]: unsigned, PomWF fraction bits")        \
  X(PomWW, kPomWF + 1, "w code 0..2^PomWF")                                                   \
  X(PomSW, 16, "height scale S code: unsigned, PomSF fraction bits")                          \
  X(PomDenW, 16, "refinement operands a, den = a + b: unsigned integers < 2^15")              \
  X(PomSetupLatency, 7, "tu_pom_setup: normalise, 4 reciprocal stages, P, dT; II = 1")        \
  X(PomRefineLatency, 7, "tu_pom_refine: normalise, 4 reciprocal stages, w, T''; II = 1")     \
  X(IpxCap, 16, "iterative parallax: default iteration cap")                                  \
  X(IpxEps, 256, "iterative parallax: default threshold |d| < IpxEps * 2^-PomUvF (2^-8)")      \
  /* Distance-map relief tracer (docs/blocks/relief.md §13, tu_dm_trace) */                     \
  X(DmCodeW, 8, "voxel: safe step code, unsigned, value code * 2^-DmQF texel")                \
  X(DmQF, 4, "step quantum 2^-DmQF texel (codes rounded down)")                                \
  X(DmEtaF, 6, "tracer position tolerance eta = 2^-DmEtaF texel (inside the map's margin)")    \
  X(DmDF, 24, "ray depth D in [0, 1]: unsigned, DmDF fraction bits (exact accumulator)")       \
  X(DmDW, kDmDF + 1, "D code 0..2^DmDF")                                                      \
  X(DmKF, 8, "K = floor(2^(DmDF + PomUvF - DmQF + DmKF) / lambda): fraction bits")           \
  X(DmKW, 29, "K <= 2^28 since lambda >= 1 texel (2^16 codes)")                               \
  X(DmLambdaW, 32, "lambda = ceil(sqrt(L2)): texels of ray per unit D, PomUvF fraction bits")   \
  X(DmL2W, 64, "L2 = (W Pu)^2 + (W Pv)^2 + (S W)^2: unsigned, 2 PomUvF fraction bits")          \
  X(DmLayersW, 8, "distance-map layers D: unsigned 1..255")                                    \
  X(DmCap, 32, "default iteration cap")                                                       \
  X(DmFinish, 8, "linear steps of one layer in the finish (then DmBisect bisection steps)")   \
  X(DmBisect, 4, "bisection steps of the finish")                                              \
  X(DmCapMax, (1 << kPomNW) - 1 - 1 - kDmFinish - kDmBisect, "cap 1..DmCapMax: steps + finish reads fit PomNW bits") \
  X(DmSetupBits, 4, "tu_dm_trace: square-root / quotient bits per clock of its set-up")        \
  X(DmSetupCycles, 1 + 2 * (32 / kDmSetupBits), "tu_dm_trace set-up: L2, isqrt, K = 2^44 / lambda") \
  /* Perspective divide (docs/blocks/persp.md) */                                               \
  X(PerspXyW, 12, "pixel indices x, y and span offset n: unsigned, 0..4095")                    \
  X(PerspF, 40, "fraction bits of coefficients A..I and of accumulators p_u, p_v, q")           \
  X(PerspPW, kPerspF + 14, "A..F, p_u, p_v: signed, PerspF fraction bits, |p| < 2^13")          \
  X(PerspQW, kPerspF + 4, "G..I, q: signed, PerspF fraction bits, |q| < 8")                     \
  X(PerspGuardLog2, 10, "guard: q < 2^-PerspGuardLog2 (incl. q <= 0) -> flag, u, v saturated")  \
  X(PerspUvW, 32, "u, v: signed texels, PerspUvF fraction bits, round half up, saturate")       \
  X(PerspUvF, 8, "")                                                                            \
  /* Textures and baseline filters (docs/blocks/texture.md) */                                 \
  X(TexUvF, kPerspUvF, "texel coordinates: fraction bits of the B1 output")                  \
  X(TexWeightF, 8, "bilinear weights out of 2^TexWeightF (truncated from TexUvF bits)")     \
  X(TexLodF, 8, "LOD fraction bits: trilinear blend weight")                                 \
  X(TexMaxLevels, 13, "mip levels: up to 4096 texels on a side")                             \
  X(TexAddrW, 26, "texel RAM word address (RGBA8 words, all levels of several textures)")     \
  X(TexRamLog2Words, 20, "simulation texel RAM of the texture-unit top: 2^N RGBA8 words")      \
  X(PerspLatency, 8, "per-pixel pipeline latency in cycles, II = 1")                          \
  X(PerspSetupLatency, 2, "per-scanline set-up (tu_persp_setup) latency in cycles, II = 1")   \
  /* Texel-depth variant of B1 (docs/blocks/persp.md "Texel-depth variant", rtl/persp/tu_texel_depth.sv) */ \
  X(TexelDepthWF, 24, "w in [0, 1]: unsigned, TexelDepthWF fraction bits, round half up, clamped") \
  X(TexelDepthAccW, kPerspQW - 1 + kPerspXyW, "N = m q2, D = m2 q(m): unsigned, PerspF frac, exact when unguarded") \
  X(TexelDepthLatency, 10, "per-pixel pipeline latency in cycles, II = 1")                  \
  /* Object-space pipeline (docs/blocks/objspace.md): splat weights and pixel accumulators */ \
  X(ObjSplatWF, 2 * kPerspUvF, "splat weight: fraction bits (product of two PerspUvF fractions)") \
  X(ObjSplatWW, kObjSplatWF + 1, "splat weight code 0..2^ObjSplatWF: unsigned, exact")       \
  X(ObjAccWW, 40, "pixel weight sum: unsigned, ObjSplatWF frac (< 2^24 samples), saturating")  \
  X(ObjAccCW, 48, "pixel colour sum per channel: unsigned, ObjSplatWF frac, saturating")      \
  X(ObjUvCoefF, 32, "uv plane coefficients u0, ui, uj (level-0 texels): signed int64, frac bits") \
  /* Ellipse parameters and LOD (docs/blocks/ellipse.md) */                                    \
  X(EllNumW, 48, "derivative numerators nUx..nVy (or Jacobian entries): signed, EllNumF frac") \
  X(EllNumF, 32, "")                                                                            \
  X(EllNxW, 112, "exact numerators (span set-up, tu_texture_unit): signed, 2 PerspF frac, |n| < 2^30") \
  X(EllDetW, 40, "det3 of the 3x3 map (per triangle): signed normalised mantissa")            \
  X(EllDetExpW, 8, "det3 exponent: signed, det3 = dm * 2^(dexp - (EllDetW - 2))")              \
  X(EllCoefW, 64, "Ae', Ce' (unsigned), Be' (signed) codes: exact sums >> EllEexp (floor)")     \
  X(EllEexpW, 6, "shared exponent of Ae', Be', Ce': value = code * 2^(eexp - 2 EllNumF)")      \
  X(EllFmW, 32, "|f| mantissa (1.31, truncated); Fe' = f^2, f = det3/q")                         \
  X(EllFexpW, 8, "|f| exponent: signed, |f| = fm * 2^(fexp - 31)")                              \
  X(EllNrmW, 24, "LOD unit: s = Ae'+Ce' block-normalised to this many bits (floor shifts)")     \
  X(EllLogMantW, 24, "log2 unit mantissa (1.23, truncated); EllLogF+1 squarings")               \
  X(EllLogF, 10, "log2 of the axes: EllLogF fraction bits (internal EllLogF+1)")                \
  X(EllLogW, 18, "log2 major / minor_clamped: signed, EllLogF fraction bits")                   \
  X(EllAnisoW, 14, "log2(max anisotropy): unsigned, EllLogF fraction bits (default 16:1)")      \
  X(EllLodW, 12, "lod: unsigned, EllLodF fraction bits, floor, clamped to [0, max_lod]")        \
  X(EllLodF, 8, "")                                                                             \
  X(EllMaxLodW, 4, "max_lod (log2 of the texture size): unsigned integer")                      \
  X(EllRhoW, 96, "GL LOD sums Px' = nUx^2 + nVx^2, Py' = nUy^2 + nVy^2 (by screen axis): exact, unsigned, 2 EllNumF frac") \
  X(TexLodBiasW, 14, "trilinear lod bias: signed, TexLodF fraction bits (|bias| <= 16 levels)")  \
  X(EllLatency, 5, "analytic ellipse/LOD pipeline latency in cycles, II = 1")               \
  /* Recurrence (forward-difference) ellipse, seed 001 sec. 2 (tu_ellipse_rec, docs/blocks/ellipse.md) */ \
  X(EllRecQW, kPerspQW + 1, "q(x+1) = q + G, q(y+1) = q + H (span-walk registers): signed, PerspF frac") \
  X(EllRecDW, 2 * kPerspQW + 1, "denominators q (q+G), q (q+H): unsigned, 2 PerspF frac, exact (guarded > 0)") \
  X(EllRecPW, kEllNumW + kRecipOutW, "n * R before rounding to a Jacobian entry: signed, exact") \
  X(EllRecJdW, 2 * kEllNumW + 1, "det J = Ux Vy - Uy Vx: signed, 2 EllNumF frac, exact; -> det3 float format") \
  X(EllRecFrontLatency, 6, "Jacobian front: reciprocal core (4) + J register + det J register") \
  X(EllRecLatency, kEllRecFrontLatency + kEllLatency, "recurrence ellipse/LOD latency in cycles, II = 1") \
  /* EWA filter, bit-accurate (docs/blocks/ewa.md) */                                          \
  X(EwaCordW, 24, "CORDIC x, y datapath: signed; d = Ae'-Ce', b = Be' block-normalised to W-3 bits") \
  X(EwaCordIter, 16, "CORDIC iterations (vectoring and rotation)")                            \
  X(EwaAngW, 18, "binary angle: signed, 2 pi = 2^EwaAngW (wraps), atan table entries")        \
  X(EwaCsW, 16, "cos / sin of the major-axis angle: signed, EwaCsF fraction bits (s1.14)")    \
  X(EwaCsF, 14, "")                                                                            \
  X(EwaExpF, 8, "log2 of the semi-axes at the walk level: EwaExpF fraction bits (truncated)") \
  X(EwaAxisMaxLog2, 7, "semi-axes clamped to 2^EwaAxisMaxLog2 texels (flag)")                \
  X(EwaE2W, 17, "exp2 ROM entry 2^(i/2^EwaExpF): unsigned, EwaE2F fraction bits (u1.16)")    \
  X(EwaE2F, 16, "")                                                                            \
  X(EwaAW, 24, "semi-axes a, b = 2^ea (box only): unsigned, EwaE2F fraction bits")           \
  X(EwaKW, 18, "frame coefficients kxu, kxv, kyu, kyv: signed, EwaKF fraction bits, half up") \
  X(EwaKF, 16, "")                                                                             \
  X(EwaPosF, 6, "texel-space centre cu, cv, half extents hu, hv and offsets du, dv: frac bits") \
  X(EwaDW, 16, "offsets du, dv from the centre: signed, EwaPosF fraction bits")               \
  X(EwaHW, 15, "half extents hu, hv (rounded up + margin): unsigned, EwaPosF fraction bits")  \
  X(EwaXiW, 32, "xi, eta = k . (du, dv): signed, EwaKF + EwaPosF fraction bits (exact)")      \
  X(EwaQW, 63, "Q = xi^2 + eta^2, ddQ: unsigned; dQ: signed EwaQW+1; 2 (EwaKF + EwaPosF) frac, exact") \
  X(EwaCountW, 17, "texel counters (box, inside) and the max_texels cap: unsigned integers") \
  X(EwaWsumW, 33, "weight sum: unsigned, GaussSqF fraction bits (exact)")                      \
  X(EwaAccW, 41, "per-channel weighted sum: unsigned, GaussSqF fraction bits (exact)")       \
  X(EwaNrmW, 23, "weight sum normalised to a positive RecipInW-bit code: msb at bit EwaNrmW-1") \
  X(EwaGradW, 24, "border distance (clip on): g = K^T (xi, eta) = grad Q / 2, floor: signed, EwaGradF frac; band only") \
  X(EwaGradF, 22, "")                                                                           \
  X(EwaRootW, 24, "border: r = floor(sqrt Q), |g| = floor(sqrt(gu^2 + gv^2)): unsigned, EwaGradF frac") \
  /* BRDF specular models (docs/blocks/brdf.md) */                                           \
  X(BrdfCW, 22, "c = N.H input: signed, BrdfCF fraction bits; clamped to [0, 1] (c > 1 flags)") \
  X(BrdfCF, 20, "")                                                                            \
  X(BrdfClW, 21, "clamped c and t = 1 - c (exact): unsigned, BrdfCF fraction bits")             \
  X(BrdfNW, 10, "specular exponent n: unsigned integer, clamped to [1, BrdfNMax] (flag)")      \
  X(BrdfNMax, 1000, "largest n")                                                               \
  X(BrdfUW, 30, "u = n (1 - c) (exact): unsigned, BrdfCF fraction bits, [0, 1000]")            \
  X(BrdfDW, 32, "divisors n(1-c) + k c (Schlick k=1, MSH 1.25, SCOS2 2) in [1, 1000]: unsigned")       \
  X(BrdfDF, 22, "  BrdfDF fraction bits, exact (monotone in c); 1/D by the reciprocal core")            \
  X(BrdfWF, 24, "internal values (squares, 1/D^2, base, G): BrdfWF fraction bits, half up")    \
  X(BrdfKF, 24, "constants 1.6, 0.1, 0.786: unsigned, BrdfKF fraction bits, round to nearest") \
  X(BrdfK16, 26843546, "1.6 * 2^BrdfKF rounded (F_MSH 2/1.25; 1.6 * 2^24 = 26843545.6)")      \
  X(BrdfK01, 1677722, "0.1 * 2^BrdfKF rounded (F_dsh c + 0.1, F_SCOS2 0.1 u)")                \
  X(BrdfK786, 13186892, "0.786 * 2^BrdfKF rounded (F_QR; 13186891.776)")                       \
  X(BrdfBlinnF, 28, "Blinn square-and-multiply: unsigned, BrdfBlinnF fraction bits, half up") \
  X(BrdfEF, 30, "F_dsh divisor E = 1.953125 w^2 + 1.5 (exact from w^2): BrdfEF fraction bits") \
  X(BrdfEW, 51, "  E word length (E < 2^21)")                                                  \
  X(BrdfOutW, 9, "specular F: unsigned, BrdfOutF fraction bits, half up (F_MSH peaks at 1.024)") \
  X(BrdfOutF, 8, "")                                                                           \
  X(BrdfCutQ, 9, "cut-off 2^-q: c below the model's c_cut(n) gives F = 0 (q = OutF+1: lossless)") \
  X(BrdfSchlickLatency, 6, "front + D, reciprocal (4), c R scaled; II = 1")                    \
  X(BrdfMshLatency, 7, "front + D + 1.6c, reciprocal (4), R^2, 1.6c R^2 scaled; II = 1")        \
  X(BrdfMshSeqLatency, 9, "F_MSH on one shared multiplier (FSM) + the reciprocal core")        \
  X(BrdfMshSeqIi, 9, "initiation interval of the shared-multiplier F_MSH")                     \
  X(BrdfScos2Latency, 7, "front + D + numerator, reciprocal (4), base, base^2; II = 1")        \
  X(BrdfSt16Latency, 5, "front + base, four squarings; II = 1")                                 \
  X(BrdfQrLatency, 2, "front + 1 - 0.786u, c w; II = 1")                                       \
  X(BrdfBlinnLatency, 11, "front, 10 square-and-multiply stages; II = 1")                      \
  X(BrdfDshLatency, 11, "front, c^8 / (c+0.1)^8 squarings, w^2, E, two reciprocals; II = 1")       \
  /* Shading stage of the texture unit (docs/blocks/brdf.md "In the unit") */                 \
  X(ShadeVecW, 22, "unit vectors N, L, H per pixel: signed, ShadeVecF fraction bits, nearest")  \
  X(ShadeVecF, 20, "  (c = N.H to BrdfCF = 20 fraction bits: note 8.4)")                       \
  X(ShadeDotW, 47, "N.L, N.H: sum of three exact products, signed, 2 ShadeVecF fraction bits")  \
  X(ShadeColW, 9, "light colour, specular colour ks*lc, ambient: unsigned, ShadeColF fraction") \
  X(ShadeColF, 8, "  bits (0 .. 511/256), round to nearest")                                   \
  X(ShadeDiffW, 9, "diffuse d = clamp(N.L, 0, 1): unsigned, ShadeColF fraction bits, half up")  \
  X(ShadeEW, 10, "E = ambient + lc d (lc d rounded half up to ShadeColF): unsigned, ShadeColF") \
  X(ShadeWordW, 320, "shade port word: {on, N, L, H, n, c_cut, ks*lc rgb, lc rgb, ambient}")   \
  X(EwaDrainCycles, 5, "tu_ewa_walk: clocks from the last texel to the accumulated sums")        \
  X(EwaNormCycles, 6, "tu_ewa_walk normalisation: mantissa, 4 reciprocal stages, round")       \
  /* Feline probe filter (docs/blocks/feline.md) */                                             \
  X(FelNMax, 16, "largest probe cap Nmax (material feline_max_probes, 1..FelNMax)")             \
  X(FelProbeW, 5, "probe count N and the cap: unsigned integers, 1..FelNMax")                   \
  X(FelSigF, 16, "major semi-axis sigma1 (level-0 texels, from EwaExpF-bit log): frac bits")     \
  X(FelAxisMaxLog2, 13, "sigma1 clamped to 2^FelAxisMaxLog2 texels (flag; > TexMaxLevels - 1)")  \
  X(FelSigW, 30, "sigma1 and D = sigma1 - sigma2: unsigned, FelSigF fraction bits")              \
  X(FelRecipF, 16, "1/(N-1) ROM: unsigned u1.FelRecipF, round to nearest")                      \
  X(FelStepW, 32, "half step (D / (N-1)) (c, s) between probes: signed, FelSigF fraction bits")   \
  X(FelTF, 16, "probe distance t = d / sigma1 in [0, 1) and its step: unsigned, FelTF frac")   \
  X(FelWsumW, 21, "weight sum over <= FelNMax probes: unsigned, GaussSqF fraction bits (exact)") \
  X(FelAccW, 29, "per-channel weighted sum: unsigned, GaussSqF fraction bits (exact)")         \
  /* AF with parallax visibility (docs/blocks/afvis.md): the per-texel trace, in PomUvF codes */ \
  X(AfvStepMax, 64, "visibility trace: at most this many depth cells entered per texel (flag)") \
  X(AfvStepW, 7, "trace step counter 0..AfvStepMax: unsigned integer")                         \
  X(AfvPW, 22, "|Pu|, |Pv| (pom::parallax, < 2^(PomUvF+5)): unsigned magnitude, PomUvF bits")  \
  X(AfvDistW, 23, "n: ray length to the next cell boundary, |P| s units: unsigned, PomUvF bits") \
  X(AfvCrossW, 45, "crossing order e = n_u |Pv|, n_v |Pu|: unsigned, exact products")          \
  X(AfvTestW, 32, "depth test (d0 - h) |P| vs 255 n: exact, signed, PomUvF bits")  \
  X(AfvRowLog2, 9, "walker row buffer: 2^AfvRowLog2 entries (a row has <= 2 (2^EwaAxisMaxLog2 + 2) + 1 texels)") \
  X(AfvRowCycles, 6, "walker clocks per box row besides its texels and traces: 5 drain + 1 row start")

namespace tu::fmt {
#define TU_X_DECLARE(name, value, desc) inline constexpr int k##name = (value);
TU_FORMAT_PARAMS(TU_X_DECLARE)
#undef TU_X_DECLARE
}  // namespace tu::fmt
