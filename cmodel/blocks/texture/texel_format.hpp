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
#include <string>
#include <vector>

#include "texture/texture.hpp"
#include "texunit/image.hpp"

namespace tu::tex {

// The codes: schema.hpp TU_TEXEL_FORMAT_CODES (the RTL's TexFmt*, tu_texel_decode), and bc1.
#define TU_X_FMT(name, code, desc) name = (code),
enum class TexelFormat { TU_TEXEL_FORMAT_CODES(TU_X_FMT) Bc1 = 7 };
#undef TU_X_FMT
inline constexpr const char* kTexelFormatNames[] = {"rgba8", "rgb565", "rgba5551", "rgba4444", "l8", "la8", "a8", "bc1"};

int bits_per_texel(TexelFormat f);  // bc1: 4 (64 bits per 4x4 block)
inline const char* format_name(TexelFormat f) { return kTexelFormatNames[static_cast<int>(f)]; }
// Expansion of an n-bit field (1 <= n <= 8) to 8 bits by bit replication.
uint8_t expand_bits(uint32_t x, int n);
// The format's word (low bits_per_texel bits) -> RGBA8, bit replication.
img::Rgba8 decode_texel(TexelFormat f, uint32_t word);
// RGBA8 -> the format's nearest word (rounding above).
uint32_t encode_texel(TexelFormat f, img::Rgba8 c);
// decode_texel, then (srgb) the colour channels through srgb_decode_table(): what tu_texel_decode
// returns for a stored word.
img::Rgba8 decode_stored(TexelFormat f, bool srgb, uint32_t word);

// BC1 (DXT1, D3D BC1_UNORM / Vulkan BC1_RGBA_UNORM_BLOCK), 4 bits per texel: a 4x4 block of 64
// bits, c0 = bits [15:0], c1 = [31:16] (RGB565), the 2-bit index of texel (x, y) of the block at
// bits 32 + 2 (4 y + x). Endpoints expanded 565 -> 888 by bit replication (expand_bits); the
// palette per channel, exact integer rules (this model's choice; D3D and Vulkan define the
// interpolants on real values and accept an error of 3 % of the range; ours is within 1/3 code of
// the real value on the expanded endpoints):
//   c0 > c1 (as 16-bit words): p0 = c0, p1 = c1, p2 = (2 c0 + c1 + 1) / 3, p3 = (c0 + 2 c1 + 1) / 3
//                              (floor division: the nearest integer, no ties), alpha 255
//   c0 <= c1:                  p0, p1 as above, p2 = (c0 + c1 + 1) >> 1 (round half up), alpha 255,
//                              p3 = (0, 0, 0, 0) transparent black
// The encoder (test data and textures stored as bc1) is the simple one: per block the bounding box
// of the opaque texels' colours as endpoints (quantised to 565), 4-colour mode unless a texel is
// transparent (alpha < 128: 3-colour mode, index 3) or the endpoints are equal, each texel the
// nearest palette entry (squared RGB distance, lowest index on a tie).
uint64_t bc1_encode_block(const img::Rgba8 px[16]);  // px[4 y + x]
img::Rgba8 bc1_decode(uint64_t block, int texel);   // texel = 4 y + x
// Reference: the palette on real values, p2 = (2 c0 + c1) / 3 ... of the exact expansions
// c * 255 / 31 (63), per channel (r, g, b, a) in [0, 255].
std::array<double, 4> bc1_decode_ref(uint64_t block, int texel);
// Block addressing of a level 2^lw x 2^lh stored as bc1: blocks row-major, max(1, 2^lw / 4) per row
// (a level narrower or lower than 4 texels fills one block's top-left part); texel (x, y) (inside
// the level) is texel 4 (y & 3) + (x & 3) of block (y >> 2) max(1, 2^lw / 4) + (x >> 2).
struct Bc1Texel {
  uint64_t block;
  int texel;
};
Bc1Texel bc1_texel(int lw, int x, int y);
uint64_t bc1_blocks(int lw, int lh);  // blocks of one level

// sRGB: the decode table (sRGB code -> linear 8-bit code) and the encode back (linear 8-bit ->
// nearest sRGB code), and the curves in double (x in [0, 1]).
const std::array<uint8_t, 256>& srgb_decode_table();
uint8_t srgb_encode(uint8_t linear);
double srgb_eotf(double x);  // sRGB -> linear
double srgb_oetf(double x);  // linear -> sRGB

// Mip generation (the scene's `mip_filter`, docs/blocks/texture.md "Mip generation"): level k + 1
// from the stored (decoded, still sRGB-encoded for srgb) level k, then quantised to the format:
//   box         the 2x2 box per channel on the stored codes, (a + b + c + d + 2) >> 2 (GL's usual
//               generation; for sRGB textures it averages encoded values)
//   box_linear  gamma-correct box: for sRGB textures the colour channels averaged in linear light
//               (EOTF in double, mean, OETF, nearest code); alpha and non-sRGB textures as box
//   lanczos2    separable Lanczos-2 (sinc(d) sinc(d / 2), |d| < 2 in level-k+1 texels: 8 x 8 taps
//               of level k at d = +-1/4, +-3/4, +-5/4, +-7/4), normalised, in linear light for
//               sRGB, edges by the texture's wrap (border: clamp), result clamped to [0, 255] and
//               rounded to the nearest code; a 1-texel side is not filtered along that axis
enum class MipFilter { Box, BoxLinear, Lanczos2 };
inline constexpr const char* kMipFilterNames[] = {"box", "box_linear", "lanczos2"};
img::Rgba8Image downsample_filtered(const img::Rgba8Image& im, MipFilter f, bool srgb, const Addressing& a);

// A texture stored in format f (PNG converted on load): the base quantised to f (encode, then
// decode: what the unit's decode stage returns), each mip level the 2x2 box of the stored level
// above (round half up, as Texture::build) quantised again; with srgb the colour channels of every
// level then decoded to linear by the table (the filters work on linear values; alpha is linear).
// The box runs on stored codes (sRGB-encoded for srgb), as today's pyramid does.
// The border colour is a texel of the texture (the word at base - 1, tex::texel_addr): it is
// stored in f like any texel (quantised; missing channels as decode fills them) and, with srgb,
// taken as sRGB-encoded and decoded like the texels; GL keeps it at float precision and linear.
// t.words: the RAM words (border word, then every level) in f before decode (the RTL decodes them).
// bc1: each level encoded block by block (bc1_encode_block) from the 2x2 box of the decoded level
// above; t.words = two words per block (low: endpoints, high: indices), the border first as a
// block of one colour (border in 565, alpha 255, or transparent black when its alpha < 128).
Texture build_stored(const std::string& name, img::Rgba8Image base, Addressing a, TexelFormat f, bool srgb,
                     MipFilter mip = MipFilter::Box);

// Memory and quality of a texture per storage format (texunit plan, docs/blocks/texture.md
// "Formats in the plan"). stored_bits: the texel RAM's bits for the pyramid and its border word
// as the format packs them (bits_per_texel per texel; bc1: 64 per 4x4 block, a level smaller
// than 4 x 4 one block). StoredCost: for a texture built from `base` in format f (srgb as
// given), those bits and the PSNR over R, G, B and A (8-bit peak) of its decoded level 0 against
// the rgba8 texture's (+inf: identical).
uint64_t stored_bits(const Texture& t);
struct StoredCost {
  TexelFormat format;
  int bits_per_texel;
  uint64_t memory_bits;
  double psnr_db;
};
std::vector<StoredCost> stored_costs(const std::string& name, const img::Rgba8Image& base, Addressing a, bool srgb);

}  // namespace tu::tex
