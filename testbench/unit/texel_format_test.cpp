// Texel formats (texture/texel_format.hpp): every word of every packed format decoded by bit
// replication against the exact expansion, the encode of the decode recovers every word, the
// nearest-code encode of every 8-bit value, and the sRGB table over its 256 codes and back.
#include <gtest/gtest.h>

#include <bit>
#include <random>

#include <cmath>
#include <cstdio>

#include "texture/texel_format.hpp"

namespace {
using namespace tu;
using tex::TexelFormat;

constexpr TexelFormat kFormats[] = {TexelFormat::Rgba8, TexelFormat::Rgb565, TexelFormat::Rgba5551,
                                    TexelFormat::Rgba4444, TexelFormat::L8, TexelFormat::La8, TexelFormat::A8};

// Bit replication = the nearest 8-bit code of x * 255 / (2^n - 1) for n = 4 and 8 (exact), within
// one code for n = 5, 6 (measured: the largest distance printed); monotone in x; 0 -> 0, max -> 255.
TEST(TexelFormat, BitReplicationExhaustive) {
  for (int n = 1; n <= 8; ++n) {
    double worst = 0;
    int prev = -1;
    for (uint32_t x = 0; x < (1u << n); ++x) {
      const int e = tex::expand_bits(x, n);
      const double exact = x * 255.0 / ((1u << n) - 1);
      worst = std::max(worst, std::fabs(e - exact));
      ASSERT_GT(e, prev) << n << " " << x;
      prev = e;
    }
    EXPECT_EQ(tex::expand_bits(0, n), 0);
    EXPECT_EQ(tex::expand_bits((1u << n) - 1, n), 255);
    std::printf("%d-bit field: max |replicated - x*255/(2^n-1)| = %.4f codes\n", n, worst);
    EXPECT_LT(worst, n == 1 || n == 2 || n == 4 || n == 8 ? 1e-9 : 1.0);
  }
}

// Every word of every format (2^bits_per_texel, rgba8: its four channels separately): the decode
// places each field in its channel, and encode(decode(w)) == w (the nearest code of a replicated
// value is the code itself).
TEST(TexelFormat, EveryWordDecodesAndEncodesBack) {
  for (const TexelFormat f : kFormats) {
    const int bits = f == TexelFormat::Rgba8 ? 16 : tex::bits_per_texel(f);  // rgba8: see below
    uint64_t words = 0;
    for (uint32_t w = 0; w < (1u << bits); ++w, ++words) {
      const img::Rgba8 c = tex::decode_texel(f, w);
      if (f == TexelFormat::L8 || f == TexelFormat::La8) {
        ASSERT_EQ(c.r, c.g);
        ASSERT_EQ(c.g, c.b);
      }
      if (f == TexelFormat::A8) ASSERT_EQ(c.r | c.g | c.b, 0);
      if (f == TexelFormat::Rgb565 || f == TexelFormat::L8) ASSERT_EQ(c.a, 255);
      ASSERT_EQ(tex::encode_texel(f, c), w) << tex::format_name(f) << " " << w;
    }
    std::printf("%s: %llu words, decode then encode = identity\n", tex::format_name(f), (unsigned long long)words);
  }
  // rgba8 is the identity on every channel value.
  for (uint32_t v = 0; v < 256; ++v) {
    const uint32_t w = v | (255 - v) << 8 | v << 16 | (v ^ 0x5a) << 24;
    EXPECT_EQ(tex::encode_texel(TexelFormat::Rgba8, tex::decode_texel(TexelFormat::Rgba8, w)), w);
  }
}

// Encode (PNG conversion on load) of every 8-bit value per channel: the nearest code, so the
// decoded value is within half a quantisation step (255 / (2^n - 1) / 2) plus the replication
// error; printed per format.
TEST(TexelFormat, EncodeIsTheNearestCode) {
  for (const TexelFormat f : {TexelFormat::Rgb565, TexelFormat::Rgba5551, TexelFormat::Rgba4444}) {
    int worst = 0;
    for (int c = 0; c < 256; ++c) {
      const img::Rgba8 in{uint8_t(c), uint8_t(c), uint8_t(c), uint8_t(c)};
      const img::Rgba8 out = tex::decode_texel(f, tex::encode_texel(f, in));
      for (int k : {out.r - c, out.g - c, out.b - c}) worst = std::max(worst, std::abs(k));
    }
    std::printf("%s: max |decode(encode(c)) - c| = %d codes over the 256 values\n", tex::format_name(f), worst);
    EXPECT_LE(worst, f == TexelFormat::Rgba4444 ? 8 : 4);  // half a 4-bit step 8.5, a 5-bit step 4.1
  }
  // L8 takes the BT.601 luma.
  EXPECT_EQ(tex::encode_texel(TexelFormat::L8, {255, 0, 0, 255}), 77u);
  EXPECT_EQ(tex::encode_texel(TexelFormat::L8, {255, 255, 255, 0}), 255u);
  EXPECT_EQ(tex::encode_texel(TexelFormat::A8, {1, 2, 3, 200}), 200u);
}

// sRGB decode table over its 256 codes against the IEC 61966-2-1 curve in double, and the encode
// back: round trip sRGB -> linear 8 bits -> sRGB.
TEST(TexelFormat, SrgbTableExhaustive) {
  const auto& t = tex::srgb_decode_table();
  double worst = 0;
  int prev = -1, trip_worst = 0, trip_exact = 0;
  for (int c = 0; c < 256; ++c) {
    const double exact = 255 * tex::srgb_eotf(c / 255.0);
    worst = std::max(worst, std::fabs(t[static_cast<size_t>(c)] - exact));
    ASSERT_GE(t[static_cast<size_t>(c)], prev);  // monotone (not strictly: 8-bit linear merges dark codes)
    prev = t[static_cast<size_t>(c)];
    const int back = tex::srgb_encode(t[static_cast<size_t>(c)]);
    trip_worst = std::max(trip_worst, std::abs(back - c));
    trip_exact += back == c;
  }
  std::printf("sRGB decode: max |table - 255 EOTF(c/255)| = %.4f codes (bound 1/2); round trip: %d of 256 codes "
              "exact, max error %d sRGB codes\n", worst, trip_exact, trip_worst);
  EXPECT_LE(worst, 0.5);
  EXPECT_EQ(t[0], 0);
  EXPECT_EQ(t[255], 255);
  // The curves invert each other in double.
  for (int c = 0; c < 256; ++c) EXPECT_NEAR(tex::srgb_oetf(tex::srgb_eotf(c / 255.0)), c / 255.0, 1e-12);
  // Linear -> sRGB encode of every linear code is the nearest sRGB code.
  for (int l = 0; l < 256; ++l) {
    const double exact = 255 * tex::srgb_oetf(l / 255.0);
    EXPECT_LE(std::fabs(tex::srgb_encode(static_cast<uint8_t>(l)) - exact), 0.5) << l;
  }
}

// The texel RAM image of a stored texture (Texture::words, what the RTL's decode stage reads): the
// border word first, then every level; each word decodes (tex::decode_stored) to the texel the C
// model filters, the border colour included (stored in the format and sRGB-decoded like a texel).
TEST(TexelFormat, StoredWordsDecodeToTheFilteredTexels) {
  for (const TexelFormat f : kFormats)
    for (const bool srgb : {false, true}) {
      tex::Addressing a{tex::Wrap::Border, tex::Wrap::Repeat, {200, 100, 50, 128}};
      const tex::Texture t = tex::build_stored("t", tex::bricks(16).color, a, f, srgb);
      EXPECT_EQ(t.format, static_cast<int>(f));
      EXPECT_EQ(t.srgb, srgb);
      if (f == TexelFormat::Rgba8 && !srgb) {  // the RAM holds the levels themselves
        EXPECT_TRUE(t.words.empty());
        EXPECT_EQ(t.addressing.border, a.border);
        continue;
      }
      ASSERT_FALSE(t.words.empty());
      EXPECT_EQ(t.words[0], tex::encode_texel(f, a.border));
      EXPECT_EQ(t.addressing.border, tex::decode_stored(f, srgb, t.words[0]));
      size_t k = 1;
      for (const auto& lv : t.levels)
        for (const auto& p : lv.px) {
          ASSERT_LT(k, t.words.size());
          ASSERT_LT(uint64_t(t.words[k]), uint64_t(1) << tex::bits_per_texel(f));
          ASSERT_EQ(tex::decode_stored(f, srgb, t.words[k++]), p) << tex::format_name(f) << " srgb " << srgb;
        }
      EXPECT_EQ(k, t.words.size());
    }
  // The border colour takes the format's channels: rgb565 has no alpha, a8 no colour.
  const tex::Addressing a{tex::Wrap::Border, tex::Wrap::Border, {200, 100, 50, 128}};
  EXPECT_EQ(tex::build_stored("t", tex::bricks(4).color, a, TexelFormat::Rgb565, false).addressing.border,
            (img::Rgba8{198, 101, 49, 255}));
  EXPECT_EQ(tex::build_stored("t", tex::bricks(4).color, a, TexelFormat::A8, false).addressing.border,
            (img::Rgba8{0, 0, 0, 128}));
}

// BC1 (DXT1): hand-made blocks with known texels in both modes (texel_format.hpp's exact rules).
TEST(TexelFormat, Bc1HandMadeBlocks) {
  const uint64_t idx = 0xe4e4e4e4ull << 32;  // texel t: index t mod 4
  auto rgba = [](int r, int g, int b, int a) { return img::Rgba8{uint8_t(r), uint8_t(g), uint8_t(b), uint8_t(a)}; };
  // c0 = red > c1 = blue: 4 colours, (2 c0 + c1 + 1) / 3 and (c0 + 2 c1 + 1) / 3.
  const uint64_t four = 0xf800 | uint64_t(0x001f) << 16 | idx;
  const img::Rgba8 want4[4] = {rgba(255, 0, 0, 255), rgba(0, 0, 255, 255), rgba(170, 0, 85, 255), rgba(85, 0, 170, 255)};
  // c0 = blue < c1 = red: 3 colours + transparent black, (c0 + c1 + 1) >> 1.
  const uint64_t three = 0x001f | uint64_t(0xf800) << 16 | idx;
  const img::Rgba8 want3[4] = {rgba(0, 0, 255, 255), rgba(255, 0, 0, 255), rgba(128, 0, 128, 255), rgba(0, 0, 0, 0)};
  // c0 = c1 = 0x7bef (R 15, G 31, B 15): 3-colour mode, every entry (123, 125, 123) but the transparent one.
  const uint64_t equal = 0x7bef | uint64_t(0x7bef) << 16 | idx;
  for (int t = 0; t < 16; ++t) {
    EXPECT_EQ(tex::bc1_decode(four, t), want4[t % 4]) << t;
    EXPECT_EQ(tex::bc1_decode(three, t), want3[t % 4]) << t;
    EXPECT_EQ(tex::bc1_decode(equal, t), t % 4 == 3 ? rgba(0, 0, 0, 0) : rgba(123, 125, 123, 255)) << t;
  }
  // Against the palette on real values: random blocks, every texel, within replication + rounding.
  std::mt19937_64 rng(24);
  double worst = 0;
  for (int n = 0; n < 20000; ++n) {
    const uint64_t b = rng();
    for (int t = 0; t < 16; ++t) {
      const img::Rgba8 c = tex::bc1_decode(b, t);
      const auto r = tex::bc1_decode_ref(b, t);
      for (int k = 0; k < 4; ++k)
        worst = std::max(worst, std::fabs(double(k == 0 ? c.r : k == 1 ? c.g : k == 2 ? c.b : c.a) - r[static_cast<size_t>(k)]));
    }
  }
  std::printf("bc1: max |decode - palette on real values| = %.4f codes over 320,000 texels\n", worst);
  EXPECT_LE(worst, 0.7143 + 0.5 + 1e-9);  // 6-bit replication (TexelFormat.BitReplicationExhaustive) + rounding
  // Block addressing: texel (5, 6) of an 8-wide level is texel 9 of block 3; 2-wide: one block per row.
  EXPECT_EQ(tex::bc1_texel(3, 5, 6).block, 3u);
  EXPECT_EQ(tex::bc1_texel(3, 5, 6).texel, 9);
  EXPECT_EQ(tex::bc1_texel(1, 1, 1).block, 0u);
  EXPECT_EQ(tex::bc1_texel(1, 1, 1).texel, 5);
  EXPECT_EQ(tex::bc1_blocks(8, 8), 64u * 64u);
  EXPECT_EQ(tex::bc1_blocks(0, 1), 1u);
}

// The BC1 encoder (bounding box + nearest index): exact on two-colour blocks of 565 colours, the
// transparent texels kept, and a bc1 texture's words decode to the texels the C model filters.
TEST(TexelFormat, Bc1EncoderAndStoredTexture) {
  img::Rgba8 px[16];
  // 565-exact colours, a >= b in every channel: the bounding box's corners are a and b.
  const img::Rgba8 a{255, 130, 0, 255}, b{8, 4, 0, 255};
  for (int i = 0; i < 16; ++i) px[i] = (i * 7) % 3 ? a : b;
  uint64_t blk = tex::bc1_encode_block(px);
  EXPECT_GT(blk & 0xffff, (blk >> 16) & 0xffff);  // 4-colour mode
  for (int i = 0; i < 16; ++i) EXPECT_EQ(tex::bc1_decode(blk, i), px[i]) << i;
  px[5] = {10, 20, 30, 0};  // a transparent texel: 3-colour mode, index 3
  blk = tex::bc1_encode_block(px);
  EXPECT_LE(blk & 0xffff, (blk >> 16) & 0xffff);
  EXPECT_EQ(tex::bc1_decode(blk, 5), (img::Rgba8{0, 0, 0, 0}));
  for (int i = 0; i < 16; ++i)
    if (i != 5) {
      EXPECT_EQ(tex::bc1_decode(blk, i), px[i]) << i;
    }
  // A stored bc1 texture (bricks 16 x 16, border): words = border block + every level's blocks.
  const tex::Addressing ad{tex::Wrap::Border, tex::Wrap::Repeat, {200, 100, 50, 255}};
  const tex::Texture t = tex::build_stored("t", tex::bricks(16).color, ad, TexelFormat::Bc1, false);
  size_t blocks = 1;
  for (const auto& lv : t.levels) blocks += tex::bc1_blocks(std::countr_zero(unsigned(lv.width)), std::countr_zero(unsigned(lv.height)));
  ASSERT_EQ(t.words.size(), 2 * blocks);
  EXPECT_EQ(t.addressing.border, (img::Rgba8{198, 101, 49, 255}));  // the border in 565
  EXPECT_EQ(tex::stored_bits(t), 64u * blocks);
  size_t w = 2;
  for (const auto& lv : t.levels) {
    const int lw = std::countr_zero(unsigned(lv.width));
    for (int y = 0; y < lv.height; ++y)
      for (int x = 0; x < lv.width; ++x) {
        const auto bt = tex::bc1_texel(lw, x, y);
        const uint64_t word = t.words[w + 2 * bt.block] | uint64_t(t.words[w + 2 * bt.block + 1]) << 32;
        ASSERT_EQ(tex::bc1_decode(word, bt.texel), lv.at(x, y)) << lv.width << " " << x << "," << y;
      }
    w += 2 * tex::bc1_blocks(lw, std::countr_zero(unsigned(lv.height)));
  }
  // The encoder's quality on the bricks: decoded level 0 against rgba8 (stored_costs).
  for (const auto& c : tex::stored_costs("bricks", tex::bricks(256).color, {}, false))
    std::printf("bricks 256: %-8s %2d bits/texel, %8llu bits, %.2f dB\n", tex::format_name(c.format), c.bits_per_texel,
                (unsigned long long)c.memory_bits, c.psnr_db);
}

// Mip generation filters (texel_format.hpp): box = downsample; box_linear = box without sRGB,
// the mean in linear light with it; lanczos2 keeps a constant image and is normalised.
TEST(TexelFormat, MipFilters) {
  const tex::Addressing rep{};
  const img::Rgba8Image br = tex::bricks(32).color;
  EXPECT_EQ(tex::downsample_filtered(br, tex::MipFilter::Box, true, rep).px, tex::downsample(br).px);
  EXPECT_EQ(tex::downsample_filtered(br, tex::MipFilter::BoxLinear, false, rep).px, tex::downsample(br).px);
  // A black / white checker of texels: the box gives 128, in linear light sRGB 0.5 -> code 188.
  img::Rgba8Image ck(4, 4);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) ck.at(x, y) = (x + y) % 2 ? img::Rgba8{255, 255, 255, 255} : img::Rgba8{0, 0, 0, 255};
  EXPECT_EQ(tex::downsample_filtered(ck, tex::MipFilter::Box, true, rep).at(0, 0), (img::Rgba8{128, 128, 128, 255}));
  EXPECT_EQ(tex::downsample_filtered(ck, tex::MipFilter::BoxLinear, true, rep).at(1, 1), (img::Rgba8{188, 188, 188, 255}));
  EXPECT_NEAR(tex::downsample_filtered(ck, tex::MipFilter::Lanczos2, false, rep).at(0, 1).r, 127.5, 0.5);
  // Constant images stay constant (weights sum to 1), also along a 1-texel side and with clamp.
  img::Rgba8Image flat(8, 1);
  for (auto& p : flat.px) p = {77, 150, 29, 200};
  const tex::Addressing clamp{tex::Wrap::Clamp, tex::Wrap::Border, {}};
  for (const auto f : {tex::MipFilter::BoxLinear, tex::MipFilter::Lanczos2})
    for (const bool srgb : {false, true})
      for (const auto& p : tex::downsample_filtered(flat, f, srgb, clamp).px) EXPECT_EQ(p, flat.px[0]);
  // Lanczos-2 sharpens a step (its negative lobes), box does not.
  img::Rgba8Image step(16, 1);
  for (int x = 0; x < 16; ++x) step.at(x, 0) = x < 8 ? img::Rgba8{40, 40, 40, 255} : img::Rgba8{200, 200, 200, 255};
  const auto lz = tex::downsample_filtered(step, tex::MipFilter::Lanczos2, false, clamp);
  EXPECT_EQ(lz.at(2, 0).r, 39);   // undershoot before the edge (40 - 160 * 0.0179 / 2.019)
  EXPECT_EQ(lz.at(5, 0).r, 201);  // overshoot after it
  EXPECT_EQ(tex::downsample_filtered(step, tex::MipFilter::Box, false, clamp).at(2, 0).r, 40);
  // Every scene texture builds with each filter; the pyramid's base level is unchanged.
  for (const auto f : {tex::MipFilter::Box, tex::MipFilter::BoxLinear, tex::MipFilter::Lanczos2}) {
    const auto t = tex::build_stored("t", br, rep, TexelFormat::Rgb565, true, f);
    EXPECT_EQ(t.levels.size(), 6u);
    EXPECT_EQ(t.levels[0].px, tex::build_stored("t", br, rep, TexelFormat::Rgb565, true).levels[0].px);
  }
}

}  // namespace
