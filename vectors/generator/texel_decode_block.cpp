// Vector sets for the texel decode stage (tu_texel_decode, tex::decode_stored): a stored texel-RAM
// word in its storage format (TexFmt* codes) with or without sRGB -> RGBA8. The stiff set is
// exhaustive: every word of every format (2^bits; rgba8: every 16-bit low half, plus every byte
// value in the high channels, so each channel sees all 256 codes), each with sRGB off and on.
// Reference: the exact expansion x * 255 / (2^n - 1) of each n-bit field in double, with sRGB the
// IEC 61966-2-1 curve 255 EOTF(x / (2^n - 1)) on the colour channels (no table). Error unit: 8-bit
// codes, the largest over the four channels.
#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "block.hpp"
#include "texture/texel_format.hpp"

namespace tu::blocks {

namespace {
using tex::TexelFormat;
constexpr int kFormats = 7;

// The exact value of each channel in [0, 255] (r, g, b, a) of word w in format f, sRGB applied.
std::array<double, 4> ref_texel(TexelFormat f, bool srgb, uint32_t w) {
  auto fld = [&](int lsb, int n) { return double((w >> lsb) & ((1u << n) - 1)) * 255.0 / double((1u << n) - 1); };
  std::array<double, 4> c{};
  switch (f) {
    case TexelFormat::Rgba8: c = {fld(0, 8), fld(8, 8), fld(16, 8), fld(24, 8)}; break;
    case TexelFormat::Rgb565: c = {fld(11, 5), fld(5, 6), fld(0, 5), 255}; break;
    case TexelFormat::Rgba5551: c = {fld(11, 5), fld(6, 5), fld(1, 5), fld(0, 1)}; break;
    case TexelFormat::Rgba4444: c = {fld(12, 4), fld(8, 4), fld(4, 4), fld(0, 4)}; break;
    case TexelFormat::L8: c = {fld(0, 8), fld(0, 8), fld(0, 8), 255}; break;
    case TexelFormat::La8: c = {fld(0, 8), fld(0, 8), fld(0, 8), fld(8, 8)}; break;
    case TexelFormat::A8: c = {0, 0, 0, fld(0, 8)}; break;
    case TexelFormat::Bc1: break;  // block-coded: block bc1_decode
  }
  if (srgb)
    for (int k = 0; k < 3; ++k) c[static_cast<size_t>(k)] = 255.0 * tex::srgb_eotf(c[static_cast<size_t>(k)] / 255.0);
  return c;
}

Row row(int f, bool srgb, uint32_t w) { return {uint64_t(f), uint64_t(srgb), w}; }

// Every word of format f (see the file comment for rgba8).
std::vector<uint32_t> every_word(TexelFormat f) {
  std::vector<uint32_t> ws;
  if (f == TexelFormat::Rgba8) {
    for (uint32_t w = 0; w < (1u << 16); ++w) ws.push_back(w);
    for (uint32_t hi = 1; hi < (1u << 16); hi += 1) ws.push_back(hi << 16 | (hi * 0x9e37u & 0xffffu));
    return ws;
  }
  for (uint32_t w = 0; w < (1u << tex::bits_per_texel(f)); ++w) ws.push_back(w);
  return ws;
}

std::vector<Row> golden_inputs() {
  // Each format at its extremes and one field at a time at full scale, sRGB off and on.
  std::vector<Row> rows;
  const uint32_t words[kFormats][6] = {
      {0x00000000, 0xffffffff, 0x000000ff, 0x0000ff00, 0x00ff0000, 0x80402010},
      {0x0000, 0xffff, 0xf800, 0x07e0, 0x001f, 0x8410},
      {0x0000, 0xffff, 0xf800, 0x07c0, 0x003e, 0x0001},
      {0x0000, 0xffff, 0xf000, 0x0f00, 0x00f0, 0x000f},
      {0x00, 0xff, 0x01, 0x80, 0x7f, 0xfe},
      {0x0000, 0xffff, 0x00ff, 0xff00, 0x8040, 0x0180},
      {0x00, 0xff, 0x01, 0x80, 0x7f, 0xfe}};
  for (int srgb = 0; srgb < 2; ++srgb)
    for (int f = 0; f < kFormats; ++f)
      for (uint32_t w : words[f]) rows.push_back(row(f, srgb != 0, w));
  return rows;
}

std::vector<Row> stiff_inputs() {
  std::vector<Row> rows;
  for (int srgb = 0; srgb < 2; ++srgb)
    for (int f = 0; f < kFormats; ++f)
      for (uint32_t w : every_word(TexelFormat(f))) rows.push_back(row(f, srgb != 0, w));
  return rows;
}

std::vector<Row> random_inputs(uint64_t count, uint64_t seed) {
  return random_rows(count, seed, [](std::mt19937_64& rng) {
    const int f = int(rng() % kFormats);
    const int bits = tex::bits_per_texel(TexelFormat(f));
    const uint64_t mask = bits >= 32 ? 0xffffffffull : (uint64_t(1) << bits) - 1;
    return row(f, (rng() & 1) != 0, static_cast<uint32_t>(rng() & mask));
  });
}
}  // namespace

Block make_texel_decode() {
  Block b;
  b.name = "texel_decode";
  b.description = "texel decode: stored word (rgba8, rgb565, rgba5551, rgba4444, l8, la8, a8) + sRGB -> RGBA8";
  b.fields = {field("fmt", vec::Role::In, "u3.0"),      field("srgb", vec::Role::In, "u1.0"),
              field("word", vec::Role::In, "u32.0"),    field("rgba", vec::Role::Out, "u32.0"),
              field("ref_r", vec::Role::Ref, "f64"),    field("ref_g", vec::Role::Ref, "f64"),
              field("ref_b", vec::Role::Ref, "f64"),    field("ref_a", vec::Role::Ref, "f64")};
  b.sets = {"golden", "stiff", "random"};
  b.inputs = standard_sets(golden_inputs, stiff_inputs, random_inputs);
  // fmt 7 (bc1) is block-coded: block bc1_decode; the decode stage has the packed formats 0..6.
  auto check = [](const Row& r) {
    if (r[0] > 6) throw std::invalid_argument("texel_decode: field fmt = " + std::to_string(r[0]) + " (0..6)");
  };
  b.model = [check](const Row& r) {
    check(r);
    const img::Rgba8 c = tex::decode_stored(TexelFormat(r[0]), r[1] != 0, static_cast<uint32_t>(r[2]));
    return Row{uint64_t(c.r) | uint64_t(c.g) << 8 | uint64_t(c.b) << 16 | uint64_t(c.a) << 24};
  };
  b.ref = [check](const Row& r) {
    check(r);
    const auto c = ref_texel(TexelFormat(r[0]), r[1] != 0, static_cast<uint32_t>(r[2]));
    return Row{vec::f64_bits(c[0]), vec::f64_bits(c[1]), vec::f64_bits(c[2]), vec::f64_bits(c[3])};
  };
  b.error = [](const Row&, const Row& out, const Row& ref) {
    ErrPoint e;
    for (int k = 0; k < 4; ++k)
      e.abs = std::max(e.abs, std::fabs(double((out[0] >> (8 * k)) & 0xff) - vec::bits_f64(ref[static_cast<size_t>(k)])));
    e.ulp = e.abs;
    return e;
  };
  b.latency_cycles = 1;  // tu_texel_decode_sim's output register (the decode is combinational)
  b.ii_cycles = 1;
  return b;
}

}  // namespace tu::blocks
