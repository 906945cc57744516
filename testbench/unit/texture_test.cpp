// Textures: mip pyramid, wrap modes, procedural textures, and the fixed-point filters against
// their float references (exhaustive over sub-texel positions on a small texture).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>

#include "texture/texture.hpp"

namespace {
using namespace tu;
using namespace tu::tex;

constexpr int64_t kUnit = int64_t(1) << fmt::kTexUvF;

Rgba8Image noise(int w, int h, uint64_t seed) {
  std::mt19937_64 rng(seed);
  Rgba8Image im(w, h);
  for (auto& p : im.px) p = {uint8_t(rng()), uint8_t(rng()), uint8_t(rng()), uint8_t(rng())};
  return im;
}

TEST(Texture, MipPyramidIsABoxFilterDownToOneTexel) {
  const auto t = Texture::build("noise", noise(16, 4, 1), Wrap::Repeat);
  ASSERT_EQ(t.num_levels(), 5);  // 16x4, 8x2, 4x1, 2x1, 1x1
  EXPECT_EQ(t.levels[2].width, 4);
  EXPECT_EQ(t.levels[2].height, 1);
  EXPECT_EQ(t.levels[4].width, 1);
  const auto& l0 = t.levels[0];
  const auto& l1 = t.levels[1];
  const int s = l0.at(2, 0).g + l0.at(3, 0).g + l0.at(2, 1).g + l0.at(3, 1).g;
  EXPECT_EQ(l1.at(1, 0).g, (s + 2) / 4);
  // A checkerboard of 1-texel cells averages to the mid grey at level 1.
  const auto c = Texture::build("c", checkerboard(8, 8, {200, 200, 200, 255}, {100, 100, 100, 255}),
                                Wrap::Repeat);
  for (const auto& p : c.levels[1].px) EXPECT_EQ(p.r, 150);
}

TEST(Texture, RejectsNonPowerOfTwoAndEmptyNamingTheTexture) {
  try {
    Texture::build("wall.png", Rgba8Image(48, 64), Wrap::Repeat);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "wall.png: texture size 48x64 is not a power of two (mip pyramid and repeat need one)");
  }
  EXPECT_THROW(Texture::build("e", Rgba8Image(), Wrap::Clamp), std::invalid_argument);
  EXPECT_THROW(Texture::build("big", Rgba8Image(8192, 1), Wrap::Clamp), std::invalid_argument);
}

TEST(Texture, WrapModes) {
  const auto r = Texture::build("r", noise(8, 8, 2), Wrap::Repeat);
  const auto c = Texture::build("c", noise(8, 8, 2), Wrap::Clamp);
  EXPECT_EQ(r.fetch(0, -1, 3), r.levels[0].at(7, 3));
  EXPECT_EQ(r.fetch(0, 8, -9), r.levels[0].at(0, 7));
  EXPECT_EQ(c.fetch(0, -1, 3), c.levels[0].at(0, 3));
  EXPECT_EQ(c.fetch(0, 100, 100), c.levels[0].at(7, 7));
}

TEST(Texture, WrapIndexMatchesGlRules) {
  // Exhaustive over every axis length 2^0..2^12 and every coordinate within three repeats on
  // either side (plus one), each mode: the integer rules equal the GL definitions in double.
  int64_t n_checked = 0;
  for (int l = 0; l < fmt::kTexMaxLevels; ++l) {
    const int64_t n = int64_t(1) << l;
    for (int m = 0; m < 5; ++m) {
      const Wrap w = Wrap(m);
      for (int64_t x = -3 * n - 1; x <= 3 * n + 1; ++x, ++n_checked)
        ASSERT_EQ(wrap_index(x, l, w), wrap_index_ref(double(x), int(n), w)) << "l " << l << " mode " << m << " x " << x;
    }
  }
  std::printf("wrap_index = GL rules on %lld (size, mode, x) cases\n", static_cast<long long>(n_checked));
  // The whole int64 range is defined (no overflow): the extremes wrap, clamp or mirror as stated.
  for (int l : {0, 5, 12}) {
    const int64_t m = (int64_t(1) << l) - 1;
    for (int64_t x : {INT64_MIN, INT64_MIN + 1, INT64_MAX}) {
      EXPECT_EQ(wrap_index(x, l, Wrap::Repeat), x & m);
      EXPECT_EQ(wrap_index(x, l, Wrap::Clamp), x < 0 ? 0 : m);
      EXPECT_EQ(wrap_index(x, l, Wrap::Border), -1);
      EXPECT_EQ(wrap_index(x, l, Wrap::MirrorOnce), m);  // |x| far beyond the edge
      const int64_t mi = wrap_index(x, l, Wrap::Mirror);
      EXPECT_TRUE(mi >= 0 && mi <= m);
    }
  }
  // Mirror once: -1 -> 0, -2 -> 1 (mirrored about -1/2), then clamped.
  EXPECT_EQ(wrap_index(-1, 3, Wrap::MirrorOnce), 0);
  EXPECT_EQ(wrap_index(-2, 3, Wrap::MirrorOnce), 1);
  EXPECT_EQ(wrap_index(-20, 3, Wrap::MirrorOnce), 7);
  // Mirrored repeat: 8 -> 7, 15 -> 0, 16 -> 0, -1 -> 0, -9 -> 7 on 8 texels.
  for (auto [x, i] : {std::pair<int64_t, int64_t>{8, 7}, {15, 0}, {16, 0}, {-1, 0}, {-9, 7}})
    EXPECT_EQ(wrap_index(x, 3, Wrap::Mirror), i) << x;
}

TEST(Texture, PerAxisWrapAndBorderColour) {
  const Rgba8 border{1, 2, 3, 4};
  const auto t = Texture::build("t", noise(8, 4, 7), Addressing{Wrap::Border, Wrap::Mirror, border});
  EXPECT_EQ(t.fetch(0, -1, 0), border);
  EXPECT_EQ(t.fetch(0, 8, 2), border);
  EXPECT_EQ(t.fetch(0, 3, 4), t.levels[0].at(3, 3));   // v mirrored
  EXPECT_EQ(t.fetch(0, 3, -1), t.levels[0].at(3, 0));
  EXPECT_EQ(t.fetch(1, 4, 0), border);                 // level 1 is 4 wide
  EXPECT_EQ(t.fetch(1, 3, 2), t.levels[1].at(3, 1));   // level 1 is 2 high: 2 mirrors to 1
  // Bilinear across the border edge blends with the border colour (GL CLAMP_TO_BORDER).
  const Rgba8 half = bilinear(t, 0, 0, (kUnit * 3) / 2);  // u = 0: halfway between texel -1 and 0
  const Rgba8 in = t.levels[0].at(0, 1);
  EXPECT_EQ(half.r, (border.r + in.r + 1) / 2);
}

TEST(Texture, TexelAddrFollowsTheLayout) {
  // Level L texel (x, y) of a 2^lw x 2^lh pyramid at base: the levels one after another,
  // row-major; border texels read base - 1; 2^TexAddrW wraps.
  for (auto [lw, lh] : {std::pair{3, 1}, {0, 4}, {12, 12}}) {
    const uint64_t base = 1000;
    uint64_t lbase = base;
    for (int level = 0; level <= std::max(lw, lh); ++level) {
      const int wl = std::max(0, lw - level), hl = std::max(0, lh - level);
      const Addressing rep{};
      EXPECT_EQ(texel_addr(base, lw, lh, rep, level, 0, 0), lbase);
      EXPECT_EQ(texel_addr(base, lw, lh, rep, level, (1 << wl) - 1, (1 << hl) - 1), lbase + (uint64_t(1) << (wl + hl)) - 1);
      EXPECT_EQ(texel_addr(base, lw, lh, rep, level, -1, 0), lbase + (uint64_t(1) << wl) - 1);
      EXPECT_EQ(texel_addr(base, lw, lh, Addressing{Wrap::Clamp, Wrap::Border, {}}, level, 0, -1), base - 1);
      lbase += uint64_t(1) << (wl + hl);
    }
    EXPECT_EQ(lbase - base, pyramid_words(lw, lh));
  }
  EXPECT_EQ(texel_addr(0, 2, 2, Addressing{Wrap::Border, Wrap::Border, {}}, 0, 4, 0), (uint64_t(1) << fmt::kTexAddrW) - 1);
}

TEST(Texture, NearestAndBilinearHitTexelCentresExactly) {
  const auto t = Texture::build("n", noise(8, 8, 3), Wrap::Repeat);
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 8; ++x) {
      const int64_t u = x * kUnit + kUnit / 2, v = y * kUnit + kUnit / 2;
      EXPECT_EQ(nearest(t, 0, u, v), t.levels[0].at(x, y));
      EXPECT_EQ(bilinear(t, 0, u, v), t.levels[0].at(x, y));
    }
  }
}

TEST(Texture, BilinearWithinItsBoundOfTheFloatReference) {
  // Every sub-texel position of a whole 4x4 texture (and beyond its edges, wrapping), level 0
  // and level 1: weights are exact at TexWeightF = TexUvF, so only the final rounding remains.
  for (Wrap w : {Wrap::Repeat, Wrap::Mirror, Wrap::Clamp, Wrap::Border, Wrap::MirrorOnce}) {
    const auto t = Texture::build("b", noise(4, 4, 4), Addressing{w, w, {9, 99, 199, 250}});
    for (int level = 0; level < 2; ++level) {
      double max_err = 0;
      for (int64_t v = -kUnit; v < 5 * kUnit; v += 3) {
        for (int64_t u = -kUnit; u < 5 * kUnit; u += 1) {
          const Rgba8 f = bilinear(t, level, u, v);
          const RgbaF r = bilinear_ref(t, level, std::ldexp(double(u), -fmt::kTexUvF),
                                       std::ldexp(double(v), -fmt::kTexUvF));
          max_err = std::max({max_err, std::fabs(f.r - r.r), std::fabs(f.g - r.g),
                              std::fabs(f.b - r.b), std::fabs(f.a - r.a)});
        }
      }
      // Level 0: exact weights, only the final rounding. Deeper: plus weight truncation.
      const double bound = level == 0 ? 0.5 : 0.5 + 2 * 255 * std::ldexp(1.0, -fmt::kTexWeightF);
      std::printf("bilinear wrap %d level %d: max error %.4f (bound %.4f)\n", int(w), level,
                  max_err, bound);
      EXPECT_LE(max_err, bound) << "wrap " << int(w) << " level " << level;
    }
  }
}

TEST(Texture, TrilinearBlendsNeighbouringLevels) {
  const auto t = Texture::build("t", noise(16, 16, 5), Wrap::Repeat);
  std::mt19937_64 rng(6);
  double max_err = 0;
  for (int i = 0; i < 20000; ++i) {
    const int64_t u = static_cast<int64_t>(rng() % (32 * kUnit)) - 8 * kUnit;
    const int64_t v = static_cast<int64_t>(rng() % (32 * kUnit)) - 8 * kUnit;
    const uint32_t lod = static_cast<uint32_t>(rng() % (6u << fmt::kTexLodF));
    const Rgba8 f = trilinear(t, lod, u, v);
    const RgbaF r = trilinear_ref(t, std::ldexp(double(lod), -fmt::kTexLodF),
                                  std::ldexp(double(u), -fmt::kTexUvF),
                                  std::ldexp(double(v), -fmt::kTexUvF));
    max_err = std::max({max_err, std::fabs(f.r - r.r), std::fabs(f.g - r.g), std::fabs(f.b - r.b)});
  }
  // Bilinear bound at a deeper level plus the blend's rounding.
  const double bound = 1.0 + 2 * 255 * std::ldexp(1.0, -fmt::kTexWeightF);
  std::printf("trilinear: max error %.4f (bound %.4f)\n", max_err, bound);
  EXPECT_LE(max_err, bound);
  // lod with zero fraction is exactly the bilinear of that level; beyond the last level clamps.
  EXPECT_EQ(trilinear(t, 2u << fmt::kTexLodF, 77, 300), bilinear(t, 2, 77, 300));
  EXPECT_EQ(trilinear(t, 9u << fmt::kTexLodF, 77, 300), bilinear(t, 4, 77, 300));
}

TEST(Texture, ProceduralBricksHaveMortarGroovesAndRaisedBricks) {
  const auto b = bricks(64);
  int zeros = 0, tops = 0;
  for (auto h : b.height.px) {
    zeros += h == 0;
    tops += h == 255;
  }
  EXPECT_GT(zeros, 64 * 64 / 20);
  EXPECT_GT(tops, 64 * 64 / 4);
  EXPECT_EQ(b.height.at(0, 0), 0);  // a corner is mortar
  const auto c = checkerboard(64, 8);
  EXPECT_NE(c.at(0, 0), c.at(8, 0));
  EXPECT_EQ(c.at(0, 0), c.at(8, 8));
}

TEST(Texture, PsnrAndPngRoundTrip) {
  const auto a = noise(16, 16, 7);
  EXPECT_TRUE(std::isinf(psnr(a, a)));
  auto b = a;
  b.px[0].r = static_cast<uint8_t>(b.px[0].r ^ 0x10);
  EXPECT_NEAR(psnr(a, b), 10 * std::log10(255.0 * 255 / (256.0 / (3 * 256))), 1e-9);
  const auto path = std::filesystem::temp_directory_path() / "tu_texture_test.png";
  img::write_png_rgba(path.string(), a);
  EXPECT_EQ(img::read_png_rgba(path.string()).px, a.px);
  std::filesystem::remove(path);
  EXPECT_THROW(img::read_png_rgba("/nonexistent.png"), std::runtime_error);
}
}  // namespace
