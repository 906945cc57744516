// Textures for the texture unit (B5): RGBA8 mip pyramids, wrap modes, built-in procedural
// textures, and the baseline filters (nearest, bilinear, trilinear) in bit-accurate fixed point
// with float references.
//
// Coordinates: u, v in level-0 texels, the B1 output format s(PerspUvW).TexUvF (raw int64 codes);
// texel centres at (i + 1/2). A level-L sample position is u / 2^L - 1/2, exact (TexUvF + L
// fraction bits). Bilinear: i0 = floor(position), weights fx, fy = the top TexWeightF bits of its
// fraction (truncated); per channel
//   c = round_half_up( ((c00 (1-fx) + c10 fx)(1-fy) + (c01 (1-fx) + c11 fx) fy) ),
// exact in integers (weights out of 2^TexWeightF). Bound: |c - bilinear_ref| <= 1/2 at level 0
// (weights exact while TexWeightF = TexUvF), and <= 1/2 + 2 * 255 * 2^-TexWeightF at deeper levels
// (weight truncation). Trilinear: levels L = floor(lod) and L+1 blended by t = frac(lod) with
// TexLodF bits, round half up: one more 1/2.
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "texunit/formats.hpp"
#include "texunit/image.hpp"
#include "texunit/schema.hpp"

namespace tu::tex {

using img::Rgba8;
using img::Rgba8Image;

// Wrap (address) mode of one axis: schema.hpp TU_WRAP_CODES, the RTL's Wrap* codes.
using Wrap = schema::Wrap;

// Texel index along one axis of a level 2^l texels long, for any integer texel coordinate x
// (negative included, the whole int64 range: no overflow), or -1 for the border colour
// (Wrap::Border outside [0, 2^l - 1]). Exact integer rules, the ones tu_texel_addr implements:
//   Repeat      x & m                         (m = 2^l - 1; two's complement: right for x < 0)
//   Mirror      bit l of x ? ~x & m : x & m   (period 2^(l+1), mirrored every other repeat)
//   Clamp       clamp(x, 0, m)
//   Border      x in [0, m] ? x : -1
//   MirrorOnce  clamp(x < 0 ? ~x : x, 0, m)   (~x = -1 - x: the texel mirrored about -1/2)
inline int64_t wrap_index(int64_t x, int l, Wrap w) {  // inline: per texel
  const int64_t m = (int64_t(1) << l) - 1;
  switch (w) {
    case Wrap::Repeat: return x & m;
    case Wrap::Mirror: return ((x >> l) & 1) ? ~x & m : x & m;
    case Wrap::Clamp: return std::clamp<int64_t>(x, 0, m);
    case Wrap::Border: return x >= 0 && x <= m ? x : -1;
    case Wrap::MirrorOnce: return std::min(x < 0 ? ~x : x, m);
  }
  return x & m;
}
// Float reference: the OpenGL 4.6 definitions (§8.14.2, Table 8.20: mirror(a) = a >= 0 ? a :
// -(1 + a); MIRRORED_REPEAT (size - 1) - mirror((i mod 2 size) - size); ...) evaluated in double
// on an integer-valued i (|i| < 2^52), -1 for the border colour. Test: Texture.WrapIndexMatchesGlRules.
int64_t wrap_index_ref(double i, int size, Wrap w);

// Sampler address state of a texture: the wrap mode of each axis and the border colour.
struct Addressing {
  Wrap u = Wrap::Repeat, v = Wrap::Repeat;
  Rgba8 border{0, 0, 0, 0};
  bool uses(Wrap w) const { return u == w || v == w; }
};

// A power-of-two RGBA8 texture with its box-filtered mip pyramid (level 0 = base, down to 1x1
// along the longer side; a 1-wide side stays 1). Throws std::invalid_argument naming `name` for
// an empty or non-power-of-two image, or one larger than 2^(TexMaxLevels-1).
struct Texture {
  std::string name;
  Addressing addressing;
  std::vector<Rgba8Image> levels;
  // Stored format (texel_format.hpp): the texel RAM's words, the border word (base - 1) then every
  // level, in the format's packing before decode; empty for an RGBA8 texture (words = levels).
  int format = 0;  // schema::TexelFormat code
  bool srgb = false;
  std::vector<uint32_t> words;

  static Texture build(const std::string& name, Rgba8Image base, Addressing a);
  static Texture build(const std::string& name, Rgba8Image base, Wrap wrap) {  // both axes, black border
    return build(name, std::move(base), Addressing{wrap, wrap, {}});
  }
  int num_levels() const { return static_cast<int>(levels.size()); }
  // Texel with the wrap modes applied (any integer coordinates, negative included); the border
  // colour when either axis is Wrap::Border and outside the level.
  Rgba8 fetch(int level, int64_t x, int64_t y) const;
};

// Texel address trace (texel bandwidth, the SystemC texel cache): while a TexelTrace lives on a
// thread, every Texture::fetch on that thread appends its texel's word address in the RTL's texel
// RAM layout (tu_texel_addr: the levels one after another, row-major, after the wrap) plus `base`.
class TexelTrace {
 public:
  TexelTrace(std::vector<uint64_t>* out, uint64_t base);
  ~TexelTrace();
  TexelTrace(const TexelTrace&) = delete;
  TexelTrace& operator=(const TexelTrace&) = delete;
  // True while a trace records on this thread (readers that bypass Texture::fetch for speed
  // must then call it, so that every read is recorded).
  static bool active();

 private:
  std::vector<uint64_t>* prev_out_;
  uint64_t prev_base_;
};
// Texel-RAM layout (tu_texel_addr, the co-simulation's texel RAM): one word holding the border
// colour at base - 1, then the levels of a 2^lw x 2^lh texture one after another from level 0 at
// base, row-major: pyramid_words = sum over levels k <= max(lw, lh) of 2^(max(0, lw - k) + max(0, lh - k)).
uint64_t pyramid_words(int lw, int lh);
// The word address tu_texel_addr computes for level L texel (x, y), modulo 2^TexAddrW:
// base + levelbase(L) + y' 2^wl + x' with (x', y') = wrap_index per axis at the level's size, or
// base - 1 (the border word) when either axis gives -1. level in [0, 15]; a level above the top
// is addressed past the pyramid as the RTL does (engines never issue one).
uint64_t texel_addr(uint64_t base, int lw, int lh, const Addressing& a, int level, int64_t x, int64_t y);

// 2x2 box filter, round half up per channel (odd sizes never occur: power-of-two only).
Rgba8Image downsample(const Rgba8Image& im);

// Built-in procedural textures (deterministic).
Rgba8Image checkerboard(int size, int cells, Rgba8 a = {230, 230, 230, 255},
                        Rgba8 b = {30, 30, 30, 255});
struct Bricks {
  Rgba8Image color;
  img::Gray8 height;  // 255 = brick top, 0 = mortar groove
};
Bricks bricks(int size);

// Fixed-point filters on raw coordinate codes (TexUvF fraction bits).
Rgba8 nearest(const Texture& t, int level, int64_t u, int64_t v);
Rgba8 bilinear(const Texture& t, int level, int64_t u, int64_t v);
Rgba8 trilinear(const Texture& t, uint32_t lod, int64_t u, int64_t v);  // lod: u?.TexLodF

// Float references (double), same conventions, results not rounded.
struct RgbaF {
  double r = 0, g = 0, b = 0, a = 0;
};
RgbaF bilinear_ref(const Texture& t, int level, double u, double v);
RgbaF trilinear_ref(const Texture& t, double lod, double u, double v);

// Peak signal-to-noise ratio over RGB (8-bit peak), +inf for identical images.
double psnr(const Rgba8Image& a, const Rgba8Image& b);

}  // namespace tu::tex
