// texunit schema: the ONE description of the codes, flag bits and records the C model and the RTL
// exchange (beside formats.hpp, which holds the widths). `texunit gen-rtl` writes them into
// rtl/0_pkg/tu_formats_pkg.sv (enums, flag-bit indices, record widths) and
// rtl/generated/tu_records.svh (packed structs); GeneratedRtl.IsFresh checks both.
//
// Why records go to an `include file and not into the package: Icarus Verilog 11 aborts on a
// package-qualified struct type (tu_formats_pkg::rec_t) and Yosys 0.23 parses no `import`, so the
// structs are declared once at compilation-unit scope (include guard); their fields are plain
// logic vectors (an enum-typed field inside such a struct breaks Yosys 0.23).
#pragma once

#include <cstdint>

#include "texunit/formats.hpp"

// ---- codes: X(Name, code, description) ----
// Filter engine of a span (tu_texture_unit filt_i; SV tu_formats_pkg::EngBilinear ...).
#define TU_ENGINE_CODES(X)                                                    \
  X(Bilinear, 0, "bilinear at level 0 (tu_bilinear)")                         \
  X(Ewa, 1, "EWA (tu_ewa)")                                                   \
  X(Trilinear, 2, "trilinear between floor(lod) and the next (tu_trilinear)") \
  X(Nearest, 3, "nearest texel at level 0 (tu_nearest)")                     \
  X(Feline, 4, "Feline probes along the major axis (tu_feline)")
// EWA weight source (tu_ewa wsrc_i; SV tu_formats_pkg::WsrcFormula ...).
#define TU_WEIGHT_SOURCE_CODES(X)                               \
  X(Formula, 0, "Gaussian formula (tu_gauss_weight)")           \
  X(Table1d, 1, "1-D weight table over Q (tu_weight_table_1d)") \
  X(Table2d, 2, "2-D weight table over (xi, eta) (tu_weight_table_2d)")
// Texture wrap (address) mode of one axis, the GL / Vulkan sampler modes (tex::Wrap, tu_texel_addr
// wrap_i; SV tu_formats_pkg::WrapRepeat ...). Bit `code` of tu_unit_cfg_pkg::WrapModes keeps a mode.
#define TU_WRAP_CODES(X)                                                                  \
  X(Repeat, 0, "x mod size (GL_REPEAT)")                                                  \
  X(Mirror, 1, "mirrored repeat, period 2 size (GL_MIRRORED_REPEAT)")                     \
  X(Clamp, 2, "clamp to [0, size - 1] (GL_CLAMP_TO_EDGE)")                                \
  X(Border, 3, "outside [0, size - 1]: the border colour (GL_CLAMP_TO_BORDER)")           \
  X(MirrorOnce, 4, "clamp(x < 0 ? -1 - x : x) to [0, size - 1] (GL_MIRROR_CLAMP_TO_EDGE)")
// Texel storage format of a texture (tex::TexelFormat, the scene's `format`; tu_texel_decode fmt_i;
// SV tu_formats_pkg::TexFmtRgba8 ...). Bit `code` of tu_unit_cfg_pkg::TexFormats keeps its decode.
#define TU_TEXEL_FORMAT_CODES(X)                                         \
  X(Rgba8, 0, "32 bits: A[31:24] B[23:16] G[15:8] R[7:0]")                \
  X(Rgb565, 1, "16 bits: R[15:11] G[10:5] B[4:0], A = 255")                \
  X(Rgba5551, 2, "16 bits: R[15:11] G[10:6] B[5:1] A[0]")                   \
  X(Rgba4444, 3, "16 bits: R[15:12] G[11:8] B[7:4] A[3:0]")                 \
  X(L8, 4, "8 bits: L[7:0] -> (L, L, L, 255)")                            \
  X(La8, 5, "16 bits: A[15:8] L[7:0] -> (L, L, L, A)")                     \
  X(A8, 6, "8 bits: A[7:0] -> (0, 0, 0, A)")
// (tex::TexelFormat::Bc1 = 7, BC1 blocks, is C++ only: tu_texel_decode never sees it; the unit
// names it TexFmtBc1 in tu_texture_unit and fetches its blocks through tu_texel_port, HasBc1.)

// ---- flag bits: X(Name, bit, description) ----
// EWA filter output (ewa::fx::Flag, tu_ewa flags_o; SV tu_formats_pkg::EwaFlagUnitDisc ...).
#define TU_EWA_FLAG_BITS(X)                                                               \
  X(UnitDisc, 0, "B2 horizon or point footprint (no axes): unit disc at the sampler level")         \
  X(AxisClamp, 1, "log2 major at level L above min(log2 lim_L, EwaAxisMaxLog2): clamped") \
  X(LodSat, 2, "integer lod above the texture's top level: clamped")                      \
  X(Capped, 3, "the box exceeded max_texels: level raised")                               \
  X(NoWeight, 4, "weight sum 0 (unreachable while a, b >= 1; nearest texel at L)")
// Footprint unit (ellipse::fx::Flag, tu_ellipse flags_o; SV tu_formats_pkg::EllFlagHorizon ...).
#define TU_ELL_FLAG_BITS(X)                                               \
  X(Horizon, 0, "q below the guard: no footprint, every other output 0")  \
  X(Degenerate, 1, "Fe' == 0 (line) or ae == ce == be == 0 (point)")      \
  X(AnisoClamp, 2, "minor axis grown to major / max_aniso")               \
  X(LodSat, 3, "footprint larger than the coarsest level: lod = max_lod") \
  X(Magnify, 4, "minor_c < 1 texel: lod = 0")

// ---- records (SV `typedef struct packed tu_<name>_t`, first field most significant) ----
// X(field, width, description); a width is a C++ constant expression over tu::fmt (kName) and the
// widths above (kEngineW, kWsrcW, record widths kMaterialW ...); the SV text is the same
// expression over tu_formats_pkg.
// Material fields a pixel carries to the filter.
#define TU_REC_MATERIAL(X)                                             \
  X(tbase, kTexAddrW, "colour texture: base word address in the texel RAM") \
  X(tlw, 4, "colour texture: log2 width")                              \
  X(tlh, 4, "colour texture: log2 height")                             \
  X(twrapu, kWrapW, "colour texture: wrap mode along u (Wrap* codes)")   \
  X(twrapv, kWrapW, "colour texture: wrap mode along v (Wrap* codes)")   \
  X(wsrc, kWsrcW, "EWA weight source (Wsrc* codes)")                   \
  X(cap, kEwaCountW, "EWA texel cap")                                  \
  X(filt, kEngineW, "filter engine (Eng* codes)")                     \
  X(clip, 1, "EWA sub-texel border weights (the unit's EwaClipVariant)") \
  X(tlbase, 4, "colour texture: base level (tex::level_range), nearest and bilinear sample it") \
  X(lbias, kTexLodBiasW, "Feline probe lod: the sampler rule's bias (s14.8)")     \
  X(lminlod, kEllLodW, "Feline probe lod: min lod")                               \
  X(lmaxlod, kEllLodW, "Feline probe lod: max lod")                               \
  X(ltop, 4, "Feline probe lod: the top level of the material's range")          \
  X(fnmax, kFelProbeW, "Feline probe cap Nmax (1..FelNMax)")                     \
  X(tfmt, kTexFmtW, "colour texture: storage format (TexFmt* codes, tu_texel_decode)") \
  X(tsrgb, 1, "colour texture: sRGB colour channels (decoded to linear by tu_texel_decode)")
// Material relief fields, used up by the relief stage.
#define TU_REC_RELIEF(X)                             \
  X(rel, 1, "POM relief on")                         \
  X(radapt, 1, "adaptive layer count")               \
  X(riter, 1, "iterative parallax (cap = rlayers)")  \
  X(rlayers, kPomNW, "layers (1..63)")               \
  X(rscale, kPomSW, "height scale S")                \
  X(hbase, kTexAddrW, "depth map: base word address") \
  X(hlw, 4, "depth map: log2 width")                 \
  X(hlh, 4, "depth map: log2 height")                 \
  X(rdm, 1, "distance map (cap = rlayers, relief::dm_cap)") \
  X(dlayers, kDmLayersW, "distance map: layers")    \
  X(dbase, kTexAddrW, "distance map: base word address in the depth RAM") \
  X(afv, 1, "AF with parallax visibility on the material's EWA pixels (tu_afvis)") \
  X(admin, 8, "afvis: the depth map's smallest code")  \
  X(abias, 8, "afvis: trace bias, depth codes")         \
  X(arule, 1, "afvis: 0 trace every texel, 1 the seed's row rule")
// Per-triangle footprint constants a pixel carries to tu_ellipse.
#define TU_REC_TRI(X)                        \
  X(dm, kEllDetW, "det3 mantissa")           \
  X(dexp, kEllDetExpW, "det3 exponent")      \
  X(laniso, kEllAnisoW, "log2(max anisotropy)") \
  X(maxlod, kEllMaxLodW, "max lod")          \
  X(lbias, kTexLodBiasW, "trilinear lod bias (s14.8)") \
  X(lminlod, kEllLodW, "trilinear min lod")  \
  X(lmaxlod, kEllLodW, "trilinear max lod") \
  X(lbase, 4, "sampler levels: base (tex::level_range)") \
  X(ltop, 4, "sampler levels: top (tex::level_range)")
// Procedural material constants (noise::ProcCodes, docs/blocks/noise-appendix.md §5) for tu_noise_unit.
#define TU_REC_PROC(X)                                                       \
  X(on, 1, "procedural colour: the noise unit, not a filter engine")         \
  X(smoke, 1, "smoke (turbulence, opacity) instead of fbm")                  \
  X(limit, 1, "footprint-limited octaves")                                   \
  X(noct, 3, "octaves K (1..NoiseOctaves)")                                  \
  X(freq, kNoiseFreqW, "lattice cells per level-0 texel, NoiseFreqF bits")   \
  X(lfreq, kEllLogW, "log2(freq) + lod bias, signed, EllLogF bits")          \
  X(sx, kNoiseCoordW, "seed shift x, s32.16")                                \
  X(sy, kNoiseCoordW, "seed shift y, s32.16")                                \
  X(z, kNoiseCoordW, "speed t, s32.16 (0: the 2-D slice)")                   \
  X(norm, kNoiseNormW, "C_K, NoiseNormF bits")                               \
  X(mabs, kNoiseValW, "smoke: E|noise|, s19.16")                             \
  X(thr, kNoiseOutW, "smoke threshold, u17.16")                              \
  X(gain, kNoiseGainW, "smoke gain, NoiseGainF bits")                        \
  X(c0, 24, "colour at value 0, {b, g, r}")                                  \
  X(c1, 24, "colour at value 1, {b, g, r}")                                  \
  X(water, 1, "water: Lambert of the finite-difference normal (three sums)") \
  X(amp, kWaterAmpW, "water amplitude a, WaterAmpF bits")                   \
  X(lx, kWaterLightW, "water unit light x (along u), s.NoiseTF")            \
  X(ly, kWaterLightW, "water unit light y, s.NoiseTF")                      \
  X(lz, kWaterLightW, "water unit light z (the normal), s.NoiseTF")
// A pixel on its way to the filter: position, B1 span set-up overflow, material.
#define TU_REC_FPIX(X)                       \
  X(x, kPerspXyW, "pixel x")                 \
  X(y, kPerspXyW, "pixel y")                 \
  X(ovf, 1, "B1 span set-up overflow")       \
  X(mat, kMaterialW, "material (tu_material_t)") \
  X(proc, kProcW, "procedural material (tu_proc_t)")
// A pixel before the relief stage.
#define TU_REC_PIX(X)                        \
  X(fpix, kFpixW, "tu_fpix_t")               \
  X(rel, kReliefW, "relief fields (tu_relief_t)")

// X(Name, fields macro, description); a record's width is kNameW (SV tu_formats_pkg::NameW), its
// type tu_name_t.
#define TU_RECORDS(X)                                         \
  X(Material, TU_REC_MATERIAL, "material fields of a pixel")  \
  X(Relief, TU_REC_RELIEF, "material relief fields")          \
  X(Tri, TU_REC_TRI, "per-triangle footprint constants")      \
  X(Proc, TU_REC_PROC, "procedural material constants")       \
  X(Fpix, TU_REC_FPIX, "pixel on its way to the filter")      \
  X(Pix, TU_REC_PIX, "pixel before the relief stage")

namespace tu::schema {
using namespace tu::fmt;

#define TU_X_ENUM(name, code, desc) name = (code),
enum class Engine { TU_ENGINE_CODES(TU_X_ENUM) };
enum class WeightSource { TU_WEIGHT_SOURCE_CODES(TU_X_ENUM) };
enum class Wrap { TU_WRAP_CODES(TU_X_ENUM) };
#undef TU_X_ENUM
inline constexpr int kEngineW = 3;
inline constexpr int kWsrcW = 2;
inline constexpr int kWrapW = 3;
inline constexpr int kTexFmtW = 3;
#define TU_X_COUNT(name, code, desc) +1
inline constexpr int kEwaFlagW = 0 TU_EWA_FLAG_BITS(TU_X_COUNT);
inline constexpr int kEllFlagW = 0 TU_ELL_FLAG_BITS(TU_X_COUNT);
#undef TU_X_COUNT
#define TU_X_MAX(name, code, desc) && (code) < (1 << W)
#define W kEngineW
static_assert(true TU_ENGINE_CODES(TU_X_MAX), "an engine code does not fit kEngineW");
#undef W
#define W kWsrcW
static_assert(true TU_WEIGHT_SOURCE_CODES(TU_X_MAX), "a weight-source code does not fit kWsrcW");
#undef W
#define W kWrapW
static_assert(true TU_WRAP_CODES(TU_X_MAX), "a wrap code does not fit kWrapW");
#undef W
#define W kTexFmtW
static_assert(true TU_TEXEL_FORMAT_CODES(TU_X_MAX), "a texel-format code does not fit kTexFmtW");
#undef W
#undef TU_X_MAX

#define TU_X_FIELD_W(field, width, desc) +(width)
#define TU_X_RECORD_W(name, fields, desc) inline constexpr int k##name##W = 0 fields(TU_X_FIELD_W);
TU_RECORDS(TU_X_RECORD_W)
#undef TU_X_RECORD_W
#undef TU_X_FIELD_W
}  // namespace tu::schema
