#include "texture/texel_format.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace tu::tex {

int bits_per_texel(TexelFormat f) {
  switch (f) {
    case TexelFormat::Rgba8: return 32;
    case TexelFormat::L8:
    case TexelFormat::A8: return 8;
    case TexelFormat::Bc1: return 4;
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
    case TexelFormat::Bc1: break;
  }
  throw std::logic_error("decode_texel: bc1 is block-coded (bc1_decode)");
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
    case TexelFormat::Bc1: break;
  }
  throw std::logic_error("encode_texel: bc1 is block-coded (bc1_encode_block)");
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

img::Rgba8 decode_stored(TexelFormat f, bool srgb, uint32_t word) {
  const img::Rgba8 c = decode_texel(f, word);
  if (!srgb) return c;
  const auto& lin = srgb_decode_table();
  return {lin[c.r], lin[c.g], lin[c.b], c.a};
}

img::Rgba8Image downsample_filtered(const img::Rgba8Image& im, MipFilter f, bool srgb, const Addressing& a) {
  if (f == MipFilter::Box || (f == MipFilter::BoxLinear && !srgb)) return downsample(im);
  const int w = std::max(1, im.width / 2), h = std::max(1, im.height / 2);
  // Channels in linear light (sRGB colour channels through the curve), as doubles in [0, 255].
  auto lin = [&](const img::Rgba8& p, int c) {
    const uint8_t v = c == 0 ? p.r : c == 1 ? p.g : c == 2 ? p.b : p.a;
    return srgb && c < 3 ? 255.0 * srgb_eotf(v / 255.0) : double(v);
  };
  auto code = [&](double v, int c) {
    v = std::clamp(v, 0.0, 255.0);
    return static_cast<uint8_t>(std::lround(srgb && c < 3 ? 255.0 * srgb_oetf(v / 255.0) : v));
  };
  // Taps along one axis of n source texels for destination texel j: (source index, weight).
  auto taps = [&](int n, int j, Wrap mode) {
    std::vector<std::pair<int, double>> t;
    if (n == 1) return std::vector<std::pair<int, double>>{{0, 1.0}};
    int l = 0;
    while ((1 << l) < n) ++l;
    if (f == MipFilter::BoxLinear) return std::vector<std::pair<int, double>>{{2 * j, 0.5}, {2 * j + 1, 0.5}};
    auto sinc = [](double x) { return x == 0 ? 1.0 : std::sin(std::numbers::pi * x) / (std::numbers::pi * x); };
    double sum = 0;
    for (int i = 2 * j - 3; i <= 2 * j + 4; ++i) {
      const double d = (i + 0.5 - (2 * j + 1)) / 2.0;
      const double wgt = sinc(d) * sinc(d / 2);
      const int64_t k = wrap_index(i, l, mode == Wrap::Border ? Wrap::Clamp : mode);
      t.push_back({static_cast<int>(k), wgt});
      sum += wgt;
    }
    for (auto& p : t) p.second /= sum;
    return t;
  };
  img::Rgba8Image out(w, h);
  for (int y = 0; y < h; ++y) {
    const auto ty = taps(im.height, y, a.v);
    for (int x = 0; x < w; ++x) {
      const auto tx = taps(im.width, x, a.u);
      double acc[4] = {0, 0, 0, 0};
      for (const auto& [sy, wy] : ty)
        for (const auto& [sx, wx] : tx)
          for (int c = 0; c < 4; ++c) acc[c] += wx * wy * lin(im.at(sx, sy), c);
      out.at(x, y) = {code(acc[0], 0), code(acc[1], 1), code(acc[2], 2), code(acc[3], 3)};
    }
  }
  return out;
}

namespace {
// One level as bc1 blocks (texels outside a level smaller than 4 x 4 repeat its texels), appended
// to `words` (two per block); the level replaced by its decoded texels.
void bc1_level(img::Rgba8Image& lv, std::vector<uint32_t>& words) {
  int lw = 0, lh = 0;
  while ((1 << lw) < lv.width) ++lw;
  while ((1 << lh) < lv.height) ++lh;
  const int bw = std::max(1, lv.width / 4), bh = std::max(1, lv.height / 4);
  std::vector<uint64_t> blocks;
  for (int by = 0; by < bh; ++by)
    for (int bx = 0; bx < bw; ++bx) {
      img::Rgba8 px[16];
      for (int i = 0; i < 16; ++i) px[i] = lv.at((4 * bx + (i & 3)) % lv.width, (4 * by + (i >> 2)) % lv.height);
      blocks.push_back(bc1_encode_block(px));
      words.push_back(static_cast<uint32_t>(blocks.back()));
      words.push_back(static_cast<uint32_t>(blocks.back() >> 32));
    }
  for (int y = 0; y < lv.height; ++y)
    for (int x = 0; x < lv.width; ++x) {
      const Bc1Texel b = bc1_texel(lw, x, y);
      lv.at(x, y) = bc1_decode(blocks[b.block], b.texel);
    }
}

Texture build_bc1(const std::string& name, img::Rgba8Image base, Addressing a, bool srgb, MipFilter mip) {
  Texture t = Texture::build(name, std::move(base), a);  // validates the size
  t.format = static_cast<int>(TexelFormat::Bc1);
  t.srgb = srgb;
  img::Rgba8 one[16];
  for (auto& p : one) p = a.border;
  const uint64_t border = bc1_encode_block(one);
  t.words = {static_cast<uint32_t>(border), static_cast<uint32_t>(border >> 32)};
  t.addressing.border = bc1_decode(border, 0);
  for (size_t k = 0; k < t.levels.size(); ++k) {
    if (k > 0) t.levels[k] = downsample_filtered(t.levels[k - 1], mip, srgb, a);  // from the decoded level above
    bc1_level(t.levels[k], t.words);
  }
  if (srgb) {
    const auto& lin = srgb_decode_table();
    auto to_linear = [&](img::Rgba8 p) { return img::Rgba8{lin[p.r], lin[p.g], lin[p.b], p.a}; };
    t.addressing.border = to_linear(t.addressing.border);
    for (auto& lv : t.levels)
      for (auto& p : lv.px) p = to_linear(p);
  }
  return t;
}
}  // namespace

Texture build_stored(const std::string& name, img::Rgba8Image base, Addressing a, TexelFormat f, bool srgb,
                     MipFilter mip) {
  auto quantise_image = [f](img::Rgba8Image im) {
    for (auto& p : im.px) p = decode_texel(f, encode_texel(f, p));
    return im;
  };
  if (f == TexelFormat::Bc1) return build_bc1(name, std::move(base), a, srgb, mip);
  Texture t = Texture::build(name, quantise_image(std::move(base)), a);  // validates the size
  for (size_t k = 1; k < t.levels.size(); ++k)
    t.levels[k] = quantise_image(downsample_filtered(t.levels[k - 1], mip, srgb, a));
  t.format = static_cast<int>(f);
  t.srgb = srgb;
  if (f == TexelFormat::Rgba8 && !srgb) return t;  // the RAM holds the levels as they are
  t.words = {encode_texel(f, t.addressing.border)};
  for (const auto& lv : t.levels)
    for (const auto& p : lv.px) t.words.push_back(encode_texel(f, p));  // exact: p is a decoded word
  t.addressing.border = decode_stored(f, srgb, t.words[0]);
  for (auto& lv : t.levels)
    for (auto& p : lv.px) p = decode_stored(f, srgb, encode_texel(f, p));
  return t;
}

namespace {
img::Rgba8 rgb565(uint32_t c) { return decode_texel(TexelFormat::Rgb565, c & 0xffff); }
// The block's four palette entries (exact integer rules, texel_format.hpp).
std::array<img::Rgba8, 4> bc1_palette(uint64_t block) {
  const uint32_t w0 = block & 0xffff, w1 = (block >> 16) & 0xffff;
  const img::Rgba8 c0 = rgb565(w0), c1 = rgb565(w1);
  auto mix = [&](int k0, int k1, int d) {  // (k0 c0 + k1 c1 + d / 2) / d per channel, alpha 255
    auto ch = [&](uint8_t a, uint8_t b) { return static_cast<uint8_t>((k0 * a + k1 * b + d / 2) / d); };
    return img::Rgba8{ch(c0.r, c1.r), ch(c0.g, c1.g), ch(c0.b, c1.b), 255};
  };
  if (w0 > w1) return {c0, c1, mix(2, 1, 3), mix(1, 2, 3)};
  return {c0, c1, mix(1, 1, 2), img::Rgba8{0, 0, 0, 0}};
}
int dist2(img::Rgba8 a, img::Rgba8 b) {
  const int dr = a.r - b.r, dg = a.g - b.g, db = a.b - b.b;
  return dr * dr + dg * dg + db * db;
}
}  // namespace

img::Rgba8 bc1_decode(uint64_t block, int texel) {
  return bc1_palette(block)[static_cast<size_t>((block >> (32 + 2 * (texel & 15))) & 3)];
}

std::array<double, 4> bc1_decode_ref(uint64_t block, int texel) {
  const uint32_t w0 = block & 0xffff, w1 = (block >> 16) & 0xffff;
  const int idx = static_cast<int>((block >> (32 + 2 * (texel & 15))) & 3);
  auto ch = [](uint32_t w, int lsb, int n) { return double((w >> lsb) & ((1u << n) - 1)) * 255.0 / double((1u << n) - 1); };
  const double e0[3] = {ch(w0, 11, 5), ch(w0, 5, 6), ch(w0, 0, 5)}, e1[3] = {ch(w1, 11, 5), ch(w1, 5, 6), ch(w1, 0, 5)};
  std::array<double, 4> c{0, 0, 0, 255};
  const bool four = w0 > w1;
  if (!four && idx == 3) return {0, 0, 0, 0};
  for (int k = 0; k < 3; ++k) {
    const double a = e0[k], b = e1[k];
    c[static_cast<size_t>(k)] = idx == 0 ? a : idx == 1 ? b : !four ? (a + b) / 2 : idx == 2 ? (2 * a + b) / 3 : (a + 2 * b) / 3;
  }
  return c;
}

uint64_t bc1_encode_block(const img::Rgba8 px[16]) {
  bool transparent = false, any = false;
  img::Rgba8 lo{255, 255, 255, 255}, hi{0, 0, 0, 255};
  for (int i = 0; i < 16; ++i) {
    const img::Rgba8 p = px[i];
    if (p.a < 128) {
      transparent = true;
      continue;
    }
    any = true;
    lo = {std::min(lo.r, p.r), std::min(lo.g, p.g), std::min(lo.b, p.b), 255};
    hi = {std::max(hi.r, p.r), std::max(hi.g, p.g), std::max(hi.b, p.b), 255};
  }
  if (!any) lo = hi = {0, 0, 0, 255};
  uint32_t w0 = encode_texel(TexelFormat::Rgb565, hi), w1 = encode_texel(TexelFormat::Rgb565, lo);
  // 4-colour mode wants w0 > w1, the 3-colour one w0 <= w1 (equal words: 3-colour).
  if (transparent ? w0 > w1 : w0 < w1) std::swap(w0, w1);
  uint64_t block = uint64_t(w0) | uint64_t(w1) << 16;
  const auto pal = bc1_palette(block);
  const int colours = w0 > w1 ? 4 : 3;
  for (int i = 0; i < 16; ++i) {
    int best = 0;
    if (px[i].a < 128) {
      best = 3;  // transparent: 3-colour mode (w0 <= w1 above)
    } else {
      for (int k = 1; k < colours; ++k)
        if (dist2(px[i], pal[static_cast<size_t>(k)]) < dist2(px[i], pal[static_cast<size_t>(best)])) best = k;
    }
    block |= uint64_t(best) << (32 + 2 * i);
  }
  return block;
}

Bc1Texel bc1_texel(int lw, int x, int y) {
  const uint64_t per_row = lw >= 2 ? uint64_t(1) << (lw - 2) : 1;
  return {static_cast<uint64_t>(y >> 2) * per_row + static_cast<uint64_t>(x >> 2), 4 * (y & 3) + (x & 3)};
}

uint64_t bc1_blocks(int lw, int lh) {
  return (lw >= 2 ? uint64_t(1) << (lw - 2) : 1) * (lh >= 2 ? uint64_t(1) << (lh - 2) : 1);
}

uint64_t stored_bits(const Texture& t) {
  const auto f = static_cast<TexelFormat>(t.format);
  uint64_t bits = f == TexelFormat::Bc1 ? 64 : static_cast<uint64_t>(bits_per_texel(f));  // the border word / block
  for (const auto& lv : t.levels) {
    int lw = 0, lh = 0;
    while ((1 << lw) < lv.width) ++lw;
    while ((1 << lh) < lv.height) ++lh;
    bits += f == TexelFormat::Bc1 ? 64 * bc1_blocks(lw, lh)
                                  : lv.px.size() * static_cast<uint64_t>(bits_per_texel(f));
  }
  return bits;
}

std::vector<StoredCost> stored_costs(const std::string& name, const img::Rgba8Image& base, Addressing a, bool srgb) {
  const Texture ref = build_stored(name, base, a, TexelFormat::Rgba8, srgb);
  std::vector<StoredCost> out;
  for (int k = 0; k < static_cast<int>(std::size(kTexelFormatNames)); ++k) {
    const auto f = static_cast<TexelFormat>(k);
    const Texture t = build_stored(name, base, a, f, srgb);
    double se = 0;
    const auto& p = t.levels[0].px;
    const auto& q = ref.levels[0].px;
    for (size_t i = 0; i < p.size(); ++i)
      for (int d : {p[i].r - q[i].r, p[i].g - q[i].g, p[i].b - q[i].b, p[i].a - q[i].a}) se += double(d) * d;
    const double mse = se / (4.0 * static_cast<double>(p.size()));
    out.push_back({f, bits_per_texel(f), stored_bits(t), mse == 0 ? INFINITY : 10 * std::log10(255.0 * 255.0 / mse)});
  }
  return out;
}

uint8_t srgb_encode(uint8_t linear) { return static_cast<uint8_t>(std::lround(255 * srgb_oetf(linear / 255.0))); }

}  // namespace tu::tex
