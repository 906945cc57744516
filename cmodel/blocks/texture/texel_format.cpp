#include "texture/texel_format.hpp"

#include <cmath>

namespace tu::tex {

int bits_per_texel(TexelFormat f) {
  switch (f) {
    case TexelFormat::Rgba8: return 32;
    case TexelFormat::L8:
    case TexelFormat::A8: return 8;
    default: return 16;
  }
}

uint8_t expand_bits(uint32_t x, int n) {
  x &= (1u << n) - 1;
  if (n == 1) return x ? 255 : 0;
  uint32_t v = 0;
  for (int sh = 8 - n; sh > -n; sh -= n) v |= sh >= 0 ? x << sh : x >> -sh;  // replicate to 8 bits
  return static_cast<uint8_t>(v);
}

namespace {
uint32_t quantise(uint8_t c, int n) { return (uint32_t(c) * ((1u << n) - 1) + 127) / 255; }
uint8_t luma(img::Rgba8 c) { return static_cast<uint8_t>((77u * c.r + 150u * c.g + 29u * c.b + 128) >> 8); }
}  // namespace

img::Rgba8 decode_texel(TexelFormat f, uint32_t w) {
  auto field = [&](int lsb, int n) { return expand_bits(w >> lsb, n); };
  switch (f) {
    case TexelFormat::Rgba8: return {uint8_t(w), uint8_t(w >> 8), uint8_t(w >> 16), uint8_t(w >> 24)};
    case TexelFormat::Rgb565: return {field(11, 5), field(5, 6), field(0, 5), 255};
    case TexelFormat::Rgba5551: return {field(11, 5), field(6, 5), field(1, 5), field(0, 1)};
    case TexelFormat::Rgba4444: return {field(12, 4), field(8, 4), field(4, 4), field(0, 4)};
    case TexelFormat::L8: return {uint8_t(w), uint8_t(w), uint8_t(w), 255};
    case TexelFormat::La8: return {uint8_t(w), uint8_t(w), uint8_t(w), uint8_t(w >> 8)};
    case TexelFormat::A8: return {0, 0, 0, uint8_t(w)};
  }
  return {};
}

uint32_t encode_texel(TexelFormat f, img::Rgba8 c) {
  switch (f) {
    case TexelFormat::Rgba8: return uint32_t(c.r) | uint32_t(c.g) << 8 | uint32_t(c.b) << 16 | uint32_t(c.a) << 24;
    case TexelFormat::Rgb565: return quantise(c.r, 5) << 11 | quantise(c.g, 6) << 5 | quantise(c.b, 5);
    case TexelFormat::Rgba5551:
      return quantise(c.r, 5) << 11 | quantise(c.g, 5) << 6 | quantise(c.b, 5) << 1 | quantise(c.a, 1);
    case TexelFormat::Rgba4444:
      return quantise(c.r, 4) << 12 | quantise(c.g, 4) << 8 | quantise(c.b, 4) << 4 | quantise(c.a, 4);
    case TexelFormat::L8: return luma(c);
    case TexelFormat::La8: return luma(c) | uint32_t(c.a) << 8;
    case TexelFormat::A8: return c.a;
  }
  return 0;
}

double srgb_eotf(double x) { return x <= 0.04045 ? x / 12.92 : std::pow((x + 0.055) / 1.055, 2.4); }
double srgb_oetf(double x) { return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1 / 2.4) - 0.055; }

const std::array<uint8_t, 256>& srgb_decode_table() {
  static const std::array<uint8_t, 256> t = [] {
    std::array<uint8_t, 256> a{};
    for (int c = 0; c < 256; ++c) a[static_cast<size_t>(c)] = static_cast<uint8_t>(std::lround(255 * srgb_eotf(c / 255.0)));
    return a;
  }();
  return t;
}

Texture build_stored(const std::string& name, img::Rgba8Image base, Addressing a, TexelFormat f, bool srgb) {
  auto quantise_image = [f](img::Rgba8Image im) {
    for (auto& p : im.px) p = decode_texel(f, encode_texel(f, p));
    return im;
  };
  Texture t = Texture::build(name, quantise_image(std::move(base)), a);  // validates the size
  for (size_t k = 1; k < t.levels.size(); ++k) t.levels[k] = quantise_image(downsample(t.levels[k - 1]));
  if (srgb) {
    const auto& lin = srgb_decode_table();
    for (auto& lv : t.levels)
      for (auto& p : lv.px) p = {lin[p.r], lin[p.g], lin[p.b], p.a};
  }
  return t;
}

uint8_t srgb_encode(uint8_t linear) { return static_cast<uint8_t>(std::lround(255 * srgb_oetf(linear / 255.0))); }

}  // namespace tu::tex
