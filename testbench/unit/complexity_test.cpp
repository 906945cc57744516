// Complexity map (seed-000 note §1.2, §4 test vectors, §5 flat map).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "complexity/complexity.hpp"
#include "texunit/image.hpp"

namespace {
using namespace tu;

img::Gray8 ramp_x(int w, int h, int slope) {
  img::Gray8 im(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) im.at(x, y) = static_cast<uint8_t>(slope * x);
  return im;
}

TEST(Complexity, CodeTableOf24Levels) {
  // Note §1.2.4: (k/23*255).astype(uint8), non-uniform step 121 -> 133.
  const int expect[24] = {0,   11,  22,  33,  44,  55,  66,  77,  88,  99,  110, 121,
                          133, 144, 155, 166, 177, 188, 199, 210, 221, 232, 243, 255};
  for (int k = 0; k < 24; ++k) EXPECT_EQ(complexity::level_code(k, 24), expect[k]) << k;
}

TEST(Complexity, RampGainEightAndReflectBorder) {
  // Ramp of 1 code per pixel: interior Gx = 8 (1-2-1 weights x 2-pixel span), Gy = 0;
  // reflect-101 makes the first and last columns read 0.
  const auto im = ramp_x(16, 8, 1);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 16; ++x) {
      int gx = 0, gy = 0;
      complexity::sobel_at(im, x, y, gx, gy);
      EXPECT_EQ(gy, 0);
      EXPECT_EQ(gx, (x == 0 || x == 15) ? 0 : 8) << x << "," << y;
    }
  // Without dilation the border columns stay at level 0 and the interior is the max (255).
  complexity::Params p;
  p.dilate = 1;
  const auto c = complexity::complexity_map(im, p);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 16; ++x) EXPECT_EQ(c.at(x, y), (x == 0 || x == 15) ? 0 : 255) << x;
  // With the 11x11 dilation the border is covered by its neighbours.
  const auto d = complexity::complexity_map(im);
  for (uint8_t v : d.px) EXPECT_EQ(v, 255);
  // Steeper ramp: gain is linear (slope 3 -> 24), relative map unchanged.
  int gx = 0, gy = 0;
  complexity::sobel_at(ramp_x(16, 8, 3), 5, 4, gx, gy);
  EXPECT_EQ(gx, 24);
}

TEST(Complexity, StepEdgeWidenedByFivePixels) {
  // Vertical step at x = 32 (0 | 255): Sobel responds on columns 31 and 32 only; the 11x11 max
  // filter widens that by 5 px each side: columns 26..37.
  img::Gray8 im(64, 20);
  for (int y = 0; y < 20; ++y)
    for (int x = 32; x < 64; ++x) im.at(x, y) = 255;
  const auto g = complexity::sobel_sq(im);
  for (int x = 0; x < 64; ++x) EXPECT_EQ(g[static_cast<size_t>(x)] > 0, x == 31 || x == 32) << x;
  const auto c = complexity::complexity_map(im);
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 64; ++x) EXPECT_EQ(c.at(x, y), (x >= 26 && x <= 37) ? 255 : 0) << x;
  // A horizontal step: same widening in y, and the dilate parameter controls the width.
  img::Gray8 hs(10, 40);
  for (int y = 20; y < 40; ++y)
    for (int x = 0; x < 10; ++x) hs.at(x, y) = 200;
  complexity::Params p;
  p.dilate = 3;
  const auto ch = complexity::complexity_map(hs, p);
  for (int y = 0; y < 40; ++y) EXPECT_EQ(ch.at(4, y), (y >= 18 && y <= 21) ? 255 : 0) << y;
}

TEST(Complexity, FlatMapIsAllZeroNotNaN) {
  for (uint8_t v : {0, 1, 128, 255}) {
    const img::Gray8 im(33, 17, v);
    const auto c = complexity::complexity_map(im);
    for (uint8_t o : c.px) EXPECT_EQ(o, 0);
  }
  const img::Gray8 one(1, 1, 77);  // 1x1 image: reflect-101 degenerates to the pixel itself
  EXPECT_EQ(complexity::complexity_map(one).px[0], 0);
}

TEST(Complexity, GammaAndLevelsHitEveryCode) {
  // Isolated single-pixel bumps of height v on a 0 background, no dilation: the largest |G| around
  // a bump is 2v (its 4-neighbours), so r = v / 255 with one extra bump of 255 setting the max,
  // and the level is round(23 * r^0.8). For each level k take the smallest v reaching it.
  const int n = 24;
  img::Gray8 im(8 * (n + 1), 8);
  im.at(8 * n + 4, 4) = 255;
  std::vector<int> vals;
  for (int k = 0; k < n; ++k) {
    // smallest v in 1..255 whose level is k: r = v/255, level = round(23 * r^0.8)
    int v = 255;
    for (int t = 1; t <= 255; ++t)
      if (static_cast<int>(std::nearbyint(23 * std::pow(t / 255.0, 0.8))) == k) { v = t; break; }
    if (k == 0) v = 0;
    vals.push_back(v);
    im.at(8 * k + 4, 4) = static_cast<uint8_t>(v);
  }
  complexity::Params p;
  p.dilate = 1;
  const auto lv = complexity::levels(im, p);
  for (int k = 0; k < n; ++k) {
    int best = 0;
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        best = std::max(best, lv[static_cast<size_t>((4 + dy) * 8 * (n + 1) + 8 * k + 4 + dx)]);
    EXPECT_EQ(best, k) << "v=" << vals[static_cast<size_t>(k)];
  }
}

TEST(Complexity, RejectsOutOfRangeParameters) {
  const img::Gray8 im(4, 4, 0);
  for (auto p : {complexity::Params{1, 0.8, 11}, complexity::Params{257, 0.8, 11},
                 complexity::Params{24, 0.0, 11}, complexity::Params{24, -1, 11},
                 complexity::Params{24, 0.8, 10}, complexity::Params{24, 0.8, 0}})
    EXPECT_THROW(complexity::complexity_map(im, p), std::invalid_argument);
}

TEST(Image, PngRoundTripAndErrorsNameTheFile) {
  const auto dir = std::filesystem::temp_directory_path() / "tu_image_test";
  std::filesystem::create_directories(dir);
  img::Gray8 im(7, 5);
  for (size_t i = 0; i < im.px.size(); ++i) im.px[i] = static_cast<uint8_t>(i * 37);
  const auto p = (dir / "a.png").string();
  img::write_png_gray(p, im);
  EXPECT_FALSE(std::filesystem::exists(p + ".tmp"));
  const auto back = img::read_png_channel0(p);
  EXPECT_EQ(back.width, 7);
  EXPECT_EQ(back.height, 5);
  EXPECT_EQ(back.px, im.px);
  const auto missing = (dir / "missing.png").string();
  try {
    img::read_png_channel0(missing);
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("missing.png"), std::string::npos);
  }
  const auto bad = (dir / "bad.png").string();
  std::ofstream(bad) << "not a png";
  try {
    img::read_png_channel0(bad);
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("bad.png"), std::string::npos);
  }
  const auto nodir = (dir / "no_such_dir" / "x.png").string();
  EXPECT_THROW(img::write_png_gray(nodir, im), std::runtime_error);
  EXPECT_FALSE(std::filesystem::exists(nodir));
  std::filesystem::remove_all(dir);
}

}  // namespace
