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

#include <cstdint>
#include <string>
#include <vector>

#include "texunit/formats.hpp"
#include "texunit/image.hpp"

namespace tu::tex {

using img::Rgba8;
using img::Rgba8Image;

enum class Wrap { Repeat, Clamp };

// A power-of-two RGBA8 texture with its box-filtered mip pyramid (level 0 = base, down to 1x1
// along the longer side; a 1-wide side stays 1). Throws std::invalid_argument naming `name` for
// an empty or non-power-of-two image, or one larger than 2^(TexMaxLevels-1).
struct Texture {
  std::string name;
  Wrap wrap = Wrap::Repeat;
  std::vector<Rgba8Image> levels;

  static Texture build(const std::string& name, Rgba8Image base, Wrap wrap);
  int num_levels() const { return static_cast<int>(levels.size()); }
  // Texel with the wrap mode applied (any integer coordinates, negative included).
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

 private:
  std::vector<uint64_t>* prev_out_;
  uint64_t prev_base_;
};

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
