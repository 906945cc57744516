// Texel storage formats (issue 24 step 3): the packed formats GL / Vulkan / D3D define and their
// expansion to the unit's 8-bit channels, and the sRGB transfer function.
//
// Formats (the scene's `format` names), one texel in the low bits of a texel-RAM word, first
// channel most significant as GL's packed UNSIGNED_SHORT_* types:
//   rgba8     32 bits  A[31:24] B[23:16] G[15:8] R[7:0] (the RAM's RGBA8 word, unchanged)
//   rgb565    16 bits  R[15:11] G[10:5] B[4:0]            A = 255
//   rgba5551  16 bits  R[15:11] G[10:6] B[5:1] A[0]
//   rgba4444  16 bits  R[15:12] G[11:8] B[7:4] A[3:0]
//   l8         8 bits  L[7:0]                             (L, L, L, 255)
//   la8       16 bits  A[15:8] L[7:0]                     (L, L, L, A)
//   a8         8 bits  A[7:0]                             (0, 0, 0, A)
// Decode: an n-bit field x to 8 bits by bit replication, x << (8 - n) | x >> (2n - 8) (n >= 4),
// 1 bit to 0 / 255 -- what D3D and Vulkan implementations use for UNORM expansion; its distance
// from the exact x * 255 / (2^n - 1) is measured exhaustively (TexelFormat.*).
// Encode (PNG converted on load): the nearest code, q = floor((c (2^n - 1) + 127) / 255) (no ties:
// 255 is odd); L = (77 R + 150 G + 29 B + 128) >> 8 (BT.601 luma, integer weights summing to 256).
// sRGB (GL SRGB8_ALPHA8): colour channels decoded to linear before filtering by a 256-entry table,
// linear = round(255 EOTF(c / 255)), EOTF the IEC 61966-2-1 piecewise curve; alpha is linear.
#pragma once

#include <array>
#include <cstdint>

#include "texture/texture.hpp"
#include "texunit/image.hpp"

namespace tu::tex {

// The codes are the order below (the RTL decode stage will take them from schema.hpp).
enum class TexelFormat { Rgba8, Rgb565, Rgba5551, Rgba4444, L8, La8, A8 };
inline constexpr const char* kTexelFormatNames[] = {"rgba8", "rgb565", "rgba5551", "rgba4444", "l8", "la8", "a8"};

int bits_per_texel(TexelFormat f);
inline const char* format_name(TexelFormat f) { return kTexelFormatNames[static_cast<int>(f)]; }
// Expansion of an n-bit field (1 <= n <= 8) to 8 bits by bit replication.
uint8_t expand_bits(uint32_t x, int n);
// The format's word (low bits_per_texel bits) -> RGBA8, bit replication.
img::Rgba8 decode_texel(TexelFormat f, uint32_t word);
// RGBA8 -> the format's nearest word (rounding above).
uint32_t encode_texel(TexelFormat f, img::Rgba8 c);

// sRGB: the decode table (sRGB code -> linear 8-bit code) and the encode back (linear 8-bit ->
// nearest sRGB code), and the curves in double (x in [0, 1]).
const std::array<uint8_t, 256>& srgb_decode_table();
uint8_t srgb_encode(uint8_t linear);
double srgb_eotf(double x);  // sRGB -> linear
double srgb_oetf(double x);  // linear -> sRGB

// A texture stored in format f (PNG converted on load): the base quantised to f (encode, then
// decode: what the unit's decode stage returns), each mip level the 2x2 box of the stored level
// above (round half up, as Texture::build) quantised again; with srgb the colour channels of every
// level then decoded to linear by the table (the filters work on linear values; alpha is linear).
// The box runs on stored codes (sRGB-encoded for srgb), as today's pyramid does.
Texture build_stored(const std::string& name, img::Rgba8Image base, Addressing a, TexelFormat f, bool srgb);

}  // namespace tu::tex
