#include "texture.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>
#include "texunit/convert.hpp"

namespace tu::tex {

namespace {
constexpr int kUvF = fmt::kTexUvF;
constexpr int kWF = fmt::kTexWeightF;
constexpr int64_t kOne = int64_t(1) << kWF;

bool pow2(int x) { return x > 0 && (x & (x - 1)) == 0; }

int log2_of(int size) { return std::countr_zero(static_cast<unsigned>(size)); }  // a power of two
int level_log2(int l0, int level) { return std::max(0, l0 - level); }

uint8_t ch(const Rgba8& c, int i) { return i == 0 ? c.r : i == 1 ? c.g : i == 2 ? c.b : c.a; }
void set_ch(Rgba8& c, int i, uint8_t v) { (i == 0 ? c.r : i == 1 ? c.g : i == 2 ? c.b : c.a) = v; }

thread_local std::vector<uint64_t>* trace_out = nullptr;  // TexelTrace
thread_local uint64_t trace_base = 0;

// Level-L position u / 2^L - 1/2, exact: kUvF + level fraction bits.
int64_t level_pos(int64_t u, int level) { return u - (int64_t(1) << (kUvF + level - 1)); }
}  // namespace

int64_t wrap_index_ref(double i, int size, Wrap w) {
  const double n = size;
  auto mod = [](double a, double b) { return a - b * std::floor(a / b); };
  auto mirror = [](double a) { return a >= 0 ? a : -(1 + a); };
  double r = 0;
  switch (w) {
    case Wrap::Repeat: r = mod(i, n); break;
    case Wrap::Mirror: r = (n - 1) - mirror(mod(i, 2 * n) - n); break;
    case Wrap::Clamp: r = std::clamp(i, 0.0, n - 1); break;
    case Wrap::Border: r = i >= 0 && i < n ? i : -1; break;
    case Wrap::MirrorOnce: r = std::clamp(mirror(i), 0.0, n - 1); break;
  }
  return static_cast<int64_t>(r);
}

uint64_t pyramid_words(int lw, int lh) {
  uint64_t n = 0;
  for (int k = 0; k <= std::max(lw, lh); ++k) n += uint64_t(1) << (level_log2(lw, k) + level_log2(lh, k));
  return n;
}

uint64_t texel_addr(uint64_t base, int lw, int lh, const Addressing& a, int level, int64_t x, int64_t y) {
  const uint64_t mask = (uint64_t(1) << fmt::kTexAddrW) - 1;
  const int wl = level_log2(lw, level), hl = level_log2(lh, level);
  const int64_t xi = wrap_index(x, wl, a.u), yi = wrap_index(y, hl, a.v);
  if (xi < 0 || yi < 0) return (base - 1) & mask;
  uint64_t lbase = 0;  // levels k < L, as the RTL's loop (k < TexMaxLevels)
  for (int k = 0; k < std::min(level, fmt::kTexMaxLevels); ++k)
    lbase += uint64_t(1) << (level_log2(lw, k) + level_log2(lh, k));
  return (base + lbase + (static_cast<uint64_t>(yi) << wl) + static_cast<uint64_t>(xi)) & mask;
}

Rgba8Image downsample(const Rgba8Image& im) {
  const int w = std::max(1, im.width / 2), h = std::max(1, im.height / 2);
  Rgba8Image out(w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const int x0 = std::min(2 * x, im.width - 1), x1 = std::min(2 * x + 1, im.width - 1);
      const int y0 = std::min(2 * y, im.height - 1), y1 = std::min(2 * y + 1, im.height - 1);
      for (int c = 0; c < 4; ++c) {
        const int s = ch(im.at(x0, y0), c) + ch(im.at(x1, y0), c) + ch(im.at(x0, y1), c) +
                      ch(im.at(x1, y1), c);
        set_ch(out.at(x, y), c, static_cast<uint8_t>((s + 2) >> 2));
      }
    }
  }
  return out;
}

Texture Texture::build(const std::string& name, Rgba8Image base, Addressing a) {
  if (base.width <= 0 || base.height <= 0)
    throw std::invalid_argument(name + ": empty texture");
  if (!pow2(base.width) || !pow2(base.height))
    throw std::invalid_argument(name + ": texture size " + std::to_string(base.width) + "x" +
                                std::to_string(base.height) +
                                " is not a power of two (mip pyramid and repeat need one)");
  const int max_side = 1 << (fmt::kTexMaxLevels - 1);
  if (base.width > max_side || base.height > max_side)
    throw std::invalid_argument(name + ": texture larger than " + std::to_string(max_side) +
                                " texels on a side");
  Texture t;
  t.name = name;
  t.addressing = a;
  t.levels.push_back(std::move(base));
  while (t.levels.back().width > 1 || t.levels.back().height > 1)
    t.levels.push_back(downsample(t.levels.back()));
  return t;
}

TexelTrace::TexelTrace(std::vector<uint64_t>* out, uint64_t base) : prev_out_(trace_out), prev_base_(trace_base) {
  trace_out = out;
  trace_base = base;
}
TexelTrace::~TexelTrace() {
  trace_out = prev_out_;
  trace_base = prev_base_;
}
bool TexelTrace::active() { return trace_out != nullptr; }

Rgba8 Texture::fetch(int level, int64_t x, int64_t y) const {
  const size_t l = static_cast<size_t>(std::clamp(level, 0, num_levels() - 1));
  const auto& im = levels[l];
  const int64_t xi = wrap_index(x, log2_of(im.width), addressing.u);
  const int64_t yi = wrap_index(y, log2_of(im.height), addressing.v);
  if (xi < 0 || yi < 0) {  // the border word, at base - 1 (tu_texel_addr)
    if (trace_out) trace_out->push_back(trace_base - 1);
    return addressing.border;
  }
  if (trace_out) {
    uint64_t a = trace_base;
    for (size_t k = 0; k < l; ++k) a += uint64_t(levels[k].width) * uint64_t(levels[k].height);
    trace_out->push_back(a + uint64_t(yi) * uint64_t(im.width) + uint64_t(xi));
  }
  return im.at(static_cast<int>(xi), static_cast<int>(yi));
}

Rgba8Image checkerboard(int size, int cells, Rgba8 a, Rgba8 b) {
  Rgba8Image im(size, size);
  const int cell = std::max(1, size / std::max(1, cells));
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) im.at(x, y) = (((x / cell) + (y / cell)) & 1) ? b : a;
  return im;
}

Bricks bricks(int size) {
  Bricks out{Rgba8Image(size, size), img::Gray8(size, size)};
  const int bh = std::max(2, size / 8), bw = 2 * bh, mortar = std::max(1, bh / 8);
  for (int y = 0; y < size; ++y) {
    const int row = y / bh, yy = y % bh;
    const int shift = (row & 1) ? bw / 2 : 0;
    for (int x = 0; x < size; ++x) {
      const int xx = (x + shift) % bw;
      const int brick = ((x + shift) / bw) * 7 + row * 13;
      const int edge = std::min({xx, bw - 1 - xx, yy, bh - 1 - yy});
      const bool in_mortar = edge < mortar;
      // Bevelled bricks: height rises over 2 mortar widths from the groove.
      const int hgt = in_mortar ? 0 : std::min(255, 128 + 127 * (edge - mortar + 1) / (2 * mortar));
      out.height.at(x, y) = static_cast<uint8_t>(hgt);
      const int tint = (brick * 37) % 40;
      out.color.at(x, y) = in_mortar ? Rgba8{180, 175, 165, 255}
                                      : Rgba8{static_cast<uint8_t>(150 + tint),
                                              static_cast<uint8_t>(60 + tint / 2),
                                              static_cast<uint8_t>(40 + tint / 3), 255};
    }
  }
  return out;
}

Rgba8 nearest(const Texture& t, int level, int64_t u, int64_t v) {
  return t.fetch(level, (u >> level) >> kUvF, (v >> level) >> kUvF);
}

Rgba8 bilinear(const Texture& t, int level, int64_t u, int64_t v) {
  const int fb = kUvF + level;  // fraction bits of the level-L position
  const int64_t su = level_pos(u, level), sv = level_pos(v, level);
  const int64_t x0 = su >> fb, y0 = sv >> fb;
  // Weight: the top TexWeightF bits of the fraction (truncated).
  const int64_t fx = (su & ((int64_t(1) << fb) - 1)) >> (fb - kWF);
  const int64_t fy = (sv & ((int64_t(1) << fb) - 1)) >> (fb - kWF);
  const Rgba8 c00 = t.fetch(level, x0, y0), c10 = t.fetch(level, x0 + 1, y0);
  const Rgba8 c01 = t.fetch(level, x0, y0 + 1), c11 = t.fetch(level, x0 + 1, y0 + 1);
  Rgba8 out;
  for (int c = 0; c < 4; ++c) {
    const int64_t top = ch(c00, c) * (kOne - fx) + ch(c10, c) * fx;
    const int64_t bot = ch(c01, c) * (kOne - fx) + ch(c11, c) * fx;
    const int64_t s = top * (kOne - fy) + bot * fy;  // 8 + 2*kWF bits
    set_ch(out, c, static_cast<uint8_t>((s + (int64_t(1) << (2 * kWF - 1))) >> (2 * kWF)));
  }
  return out;
}

Rgba8 trilinear(const Texture& t, uint32_t lod, int64_t u, int64_t v) {
  const int max_level = t.num_levels() - 1;
  const int l = static_cast<int>(lod >> fmt::kTexLodF);
  if (l >= max_level) return bilinear(t, max_level, u, v);
  const int64_t f = lod & ((1u << fmt::kTexLodF) - 1);
  const Rgba8 a = bilinear(t, l, u, v), b = bilinear(t, l + 1, u, v);
  const int64_t one = int64_t(1) << fmt::kTexLodF;
  Rgba8 out;
  for (int c = 0; c < 4; ++c)
    set_ch(out, c, static_cast<uint8_t>((ch(a, c) * (one - f) + ch(b, c) * f +
                                         (int64_t(1) << (fmt::kTexLodF - 1))) >> fmt::kTexLodF));
  return out;
}

RgbaF bilinear_ref(const Texture& t, int level, double u, double v) {
  const double su = std::ldexp(u, -level) - 0.5, sv = std::ldexp(v, -level) - 0.5;
  const double fx0 = std::floor(su), fy0 = std::floor(sv);
  const double fx = su - fx0, fy = sv - fy0;
  // Clamped to +-2^62 so that x0 + 1 below cannot overflow (a far texel wraps or clamps anyway).
  const int64_t x0 = sat_cast<int64_t>(std::clamp(fx0, -0x1p62, 0x1p62));
  const int64_t y0 = sat_cast<int64_t>(std::clamp(fy0, -0x1p62, 0x1p62));
  const Rgba8 c00 = t.fetch(level, x0, y0), c10 = t.fetch(level, x0 + 1, y0);
  const Rgba8 c01 = t.fetch(level, x0, y0 + 1), c11 = t.fetch(level, x0 + 1, y0 + 1);
  double o[4];
  for (int c = 0; c < 4; ++c)
    o[c] = (ch(c00, c) * (1 - fx) + ch(c10, c) * fx) * (1 - fy) +
           (ch(c01, c) * (1 - fx) + ch(c11, c) * fx) * fy;
  return {o[0], o[1], o[2], o[3]};
}

RgbaF trilinear_ref(const Texture& t, double lod, double u, double v) {
  const int max_level = t.num_levels() - 1;
  lod = std::max(lod, 0.0);
  const int l = static_cast<int>(std::min<int64_t>(floor_i64(lod), max_level));
  if (l >= max_level) return bilinear_ref(t, max_level, u, v);
  const double f = lod - l;
  const RgbaF a = bilinear_ref(t, l, u, v), b = bilinear_ref(t, l + 1, u, v);
  return {a.r + (b.r - a.r) * f, a.g + (b.g - a.g) * f, a.b + (b.b - a.b) * f,
          a.a + (b.a - a.a) * f};
}

double psnr(const Rgba8Image& a, const Rgba8Image& b) {
  if (a.width != b.width || a.height != b.height || a.px.empty())
    throw std::invalid_argument("psnr: images differ in size");
  double se = 0;
  for (size_t i = 0; i < a.px.size(); ++i) {
    const double dr = a.px[i].r - b.px[i].r, dg = a.px[i].g - b.px[i].g,
                 db = a.px[i].b - b.px[i].b;
    se += dr * dr + dg * dg + db * db;
  }
  if (se == 0) return std::numeric_limits<double>::infinity();
  const double mse = se / (3.0 * static_cast<double>(a.px.size()));
  return 10 * std::log10(255.0 * 255.0 / mse);
}

}  // namespace tu::tex
