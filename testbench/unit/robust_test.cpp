// Robustness (docs/robustness.md): set-up errors name the file and the object, float->int
// conversions are defined for every double, and every block's C model, float reference and error
// metric are defined (no UB: the ASan/UBSan build runs this) on every code its vector fields can
// hold, corner codes included. The libFuzzer targets (fuzz/) search the same space further.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <unistd.h>

#include <stb/stb_image_write.h>  // implementation in cmodel/src/image.cpp

#include <filesystem>
#include <fstream>

#include "block.hpp"
#include "pom/relief_quality.hpp"
#include "texunit/convert.hpp"
#include "texunit/output.hpp"
#include "texunit/render.hpp"

namespace {
using namespace tu;

// A 32x24 scene with a floor and a triangle whose plane contains the eye (y = 1).
std::string edge_on_scene() {
  return R"({"texunit_scene": 1,
  "camera": {"position": [0, 1, 0], "look_at": [0, 0.5, -5], "width": 32, "height": 24},
  "textures": {"c": {"builtin": "checkerboard", "size": 16}},
  "materials": {"m": {"texture": "c"}},
  "objects": [
    {"name": "floor", "type": "quad", "material": "m",
     "vertices": [[-5, 0, -1], [5, 0, -1], [5, 0, -20], [-5, 0, -20]], "uv": [[0, 0], [1, 0], [1, 4], [0, 4]]},
    {"name": "edge", "type": "triangle", "material": "m",
     "vertices": [[-1, 1, -2], [1, 1, -3], [0, 1, -4]], "uv": [[0, 0], [1, 0], [0, 1]]}]})";
}

TEST(Robust, SetupErrorNamesFileAndObjectInRefAndCmodel) {
  const auto s = scene::parse(edge_on_scene(), "s.json", ".");
  const std::string want = "s.json: object 'edge' (/objects/1): persp set-up: triangle 'edge': its plane contains the eye";
  for (int engine = 0; engine < 2; ++engine) {
    try {
      engine ? (void)render::render_cmodel(s) : (void)render::render_ref(s);
      ADD_FAILURE() << "engine " << engine << " accepted an edge-on triangle";
    } catch (const persp::SetupError& e) {
      EXPECT_EQ(e.what(), want) << "engine " << engine;
    }
  }
}

TEST(Robust, SaturatingConversionsAreDefinedEverywhere) {
  constexpr auto kMax = std::numeric_limits<int64_t>::max(), kMin = std::numeric_limits<int64_t>::min();
  EXPECT_EQ(sat_cast<int64_t>(std::nan("")), 0);
  EXPECT_EQ(sat_cast<int64_t>(INFINITY), kMax);
  EXPECT_EQ(sat_cast<int64_t>(-INFINITY), kMin);
  EXPECT_EQ(sat_cast<int64_t>(1e300), kMax);
  EXPECT_EQ(sat_cast<int64_t>(0x1p63), kMax);
  EXPECT_EQ(sat_cast<int64_t>(-0x1p63), kMin);
  EXPECT_EQ(sat_cast<int64_t>(0x1p62), int64_t(1) << 62);
  EXPECT_EQ(sat_cast<int32_t>(-1e10), std::numeric_limits<int32_t>::min());
  EXPECT_EQ(sat_cast<uint8_t>(-3.0), 0);
  EXPECT_EQ(sat_cast<uint8_t>(300.0), 255);
  EXPECT_EQ(floor_i64(-2.5), -3);
  EXPECT_EQ(ceil_i64(-2.5), -2);
  EXPECT_EQ(round_i64(2.5), 3);
}

TEST(Robust, FloatFiltersAreDefinedForAnyCoordinate) {
  const auto t = tex::Texture::build("flat", img::Rgba8Image(16, 16, {10, 200, 77, 255}), tex::Wrap::Repeat);
  for (double u : {0.0, 1e18, -1e308, 1e308, double(INFINITY), std::nan("")}) {
    (void)tex::bilinear_ref(t, 0, u, 3.5);
    (void)tex::trilinear_ref(t, u, 3.5, u);
    const auto r = ewa::filter_axes(t, u, 3.5, 2, 1, 0.3, {});
    EXPECT_LE(r.texels_visited, 1024 * 4) << u;
  }
}

// Corner codes of a field: 0, 1, the signed extremes and all ones.
std::vector<uint64_t> corners(const vec::FieldFormat& f) {
  const uint64_t all = f.w >= 64 ? ~uint64_t(0) : (uint64_t(1) << f.w) - 1;
  const uint64_t half = uint64_t(1) << (f.w - 1);
  return {0, 1, half - 1, half, all};
}

TEST(Robust, EveryBlockIsDefinedOnCornerAndRandomCodes) {
  std::mt19937_64 rng(13);
  for (const auto& b : blocks::all()) {
    std::vector<vec::Field> in;
    for (const auto& f : b.fields)
      if (f.role == vec::Role::In) in.push_back(f);
    std::vector<blocks::Row> rows;
    for (size_t k = 0; k < 5; ++k) {  // every field at the same corner, then each field alone
      blocks::Row r;
      for (const auto& f : in) r.push_back(corners(f.fmt)[k]);
      rows.push_back(r);
    }
    for (size_t i = 0; i < in.size(); ++i)
      for (uint64_t c : corners(in[i].fmt)) {
        blocks::Row r = rows[0];
        r[i] = c;
        rows.push_back(r);
      }
    for (int n = 0; n < 200; ++n) {
      blocks::Row r;
      for (const auto& f : in) r.push_back(f.fmt.w >= 64 ? rng() : rng() & ((uint64_t(1) << f.fmt.w) - 1));
      rows.push_back(r);
    }
    int rejected = 0;
    for (const auto& r : rows) {
      try {
        const auto out = b.model(r);
        const auto ref = b.ref(r);
        (void)b.error(r, out, ref);
      } catch (const std::invalid_argument&) {
        ++rejected;  // a documented rejection of an illegal code (e.g. ewa's wsrc = 3)
      }
    }
    EXPECT_LT(rejected, static_cast<int>(rows.size())) << b.name << ": every row rejected";
  }
}
TEST(Robust, TexturesReadEveryStbFormatAndCheckTheSizeFromTheHeader) {
  const auto dir = std::filesystem::temp_directory_path() / ("tu_robust_img_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  // A JPEG (was refused as "not a PNG"): read, 16x8, colours within JPEG's loss.
  std::vector<uint8_t> px(16 * 8 * 3, 200);
  const std::string jpg = (dir / "t.jpg").string();
  std::string bytes;  // stb's file writers are compiled out (texunit/output.hpp writes every file)
  const auto append = [](void* ctx, void* p, int n) { static_cast<std::string*>(ctx)->append(static_cast<const char*>(p), static_cast<size_t>(n)); };
  ASSERT_TRUE(stbi_write_jpg_to_func(append, &bytes, 16, 8, 3, px.data(), 95));
  tu::out::write_atomic(jpg, bytes);
  const auto im = img::read_png_rgba(jpg);
  EXPECT_EQ(im.width, 16);
  EXPECT_EQ(im.height, 8);
  EXPECT_NEAR(im.px[0].r, 200, 3);
  // An 8192x8192 PNG header without pixel data: refused from the header, before decoding.
  const unsigned char hdr[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0, 0, 0, 13, 'I', 'H', 'D', 'R',
                               0, 0, 0x20, 0, 0, 0, 0x20, 0, 8, 6, 0, 0, 0, 0, 0, 0, 0};
  const std::string big = (dir / "big.png").string();
  std::ofstream(big, std::ios::binary).write(reinterpret_cast<const char*>(hdr), sizeof hdr);
  try {
    (void)img::read_png_rgba(big);
    ADD_FAILURE() << "accepted an 8192x8192 image";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), big + ": the image is 8192x8192 pixels; at most 4096 per side are read");
  }
  std::filesystem::remove_all(dir);
}

TEST(Robust, ReliefQualityOfAUsersHeightMap) {
  const auto dir = std::filesystem::temp_directory_path() / ("tu_robust_rq_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  img::Gray8 h(16, 16);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) h.at(x, y) = static_cast<uint8_t>((x / 4 + y / 4) % 2 ? 255 : 64);
  const std::string path = (dir / "steps.png").string();
  img::write_png_gray(path, h);
  EXPECT_EQ(pom::depth_from_height(path).at(0, 0), 255 - 64);
  pom::QualityParams p;
  p.height_png = path;
  p.angles = {0, 60};
  const auto rows = pom::quality(p);
  ASSERT_EQ(rows.size(), 16u);  // 8 methods x 2 angles, one map
  EXPECT_EQ(rows[0].map, "steps");
  EXPECT_GT(rows[0].psnr, 30);  // head-on: (almost) no shift
  img::write_png_gray(path, img::Gray8(16, 32));
  EXPECT_THROW(pom::depth_from_height(path), std::invalid_argument);
  std::filesystem::remove_all(dir);
}
TEST(Robust, NulByteInAVectorFileIsShownEscaped) {
  const std::string text = std::string("# texunit-vectors 1\n# block: reciprocal\n# set: golden\n# seed: 1\n"
                                       "# fields: q:in:s24.16\n0a") + '\0' + "b\n";
  try {
    (void)vec::parse(text, "n.vec");
    ADD_FAILURE() << "accepted a NUL byte";
  } catch (const vec::FormatError& e) {
    EXPECT_EQ(std::string(e.what()), "n.vec:6: field 'q': '0a\\x00b' is not hexadecimal");
  }
}
}  // namespace
