// Texel formats (texture/texel_format.hpp): every word of every packed format decoded by bit
// replication against the exact expansion, the encode of the decode recovers every word, the
// nearest-code encode of every 8-bit value, and the sRGB table over its 256 codes and back.
#include <gtest/gtest.h>

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

}  // namespace
