// Float reference render: visibility and texture coordinates against per-pixel ray casting, EWA
// filter properties, and image quality against a supersampled ground truth.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "ewa/ewa_ref.hpp"
#include "texunit/render.hpp"

namespace {
using namespace tu;

TEST(RenderRef, CoefficientsAgreeWithRayCastingOnEveryCoveredPixel) {
  const auto s = scene::default_scene();
  const auto cov = render::visibility(s);
  int covered = 0;
  double max_err = 0;
  for (int y = 0; y < s.camera.height; ++y) {
    for (int x = 0; x < s.camera.width; ++x) {
      const auto c = cov[static_cast<size_t>(y * s.camera.width + x)];
      if (c.object < 0) continue;
      ++covered;
      const auto tris = scene::in_texels(s.objects[static_cast<size_t>(c.object)], 256, 256);
      const auto& t = tris[static_cast<size_t>(c.triangle)];
      double ru, rv, u, v, q;
      ASSERT_TRUE(persp::ray_uv(s.camera, t, x, y, &ru, &rv));
      persp::eval_ref(persp::coefficients(s.camera, t), x, y, &u, &v, &q);
      EXPECT_GT(q, 0);
      max_err = std::max({max_err, std::fabs(u - ru), std::fabs(v - rv)});
    }
  }
  EXPECT_GT(covered, s.camera.width * s.camera.height / 2);
  EXPECT_LT(max_err, 1e-6);
}

TEST(RenderRef, EwaOfAConstantTextureIsThatConstant) {
  const auto t = tex::Texture::build("flat", img::Rgba8Image(64, 64, {10, 200, 77, 255}), tex::Wrap::Repeat);
  for (const ellipse::Jacobian j : {ellipse::Jacobian{0.2, 0, 0, 0.2}, {3, 1, -2, 5}, {400, 0, 0, 1}}) {
    const auto r = ewa::filter_ref(t, 13.3, 40.7, j, {});
    EXPECT_NEAR(r.color.g, 200, 1e-9);
    EXPECT_NEAR(r.color.b, 77, 1e-9);
    EXPECT_GT(r.texels_inside, 0);
  }
}

TEST(RenderRef, EwaTexelCapRaisesTheLevel) {
  const auto t = tex::Texture::build("c", tex::checkerboard(256, 16), tex::Wrap::Repeat);
  // 16:1 footprint (60 x 3.75 texels): level 1, a box of ~60 x 4 texels.
  const ellipse::Jacobian j{60, 0, 0, 3.75};
  const auto free = ewa::filter_ref(t, 100, 100, j, {16, 1 << 20});
  EXPECT_FALSE(free.capped);
  EXPECT_EQ(free.level, 1);
  const int cap = free.texels_visited - 1;
  const auto capped = ewa::filter_ref(t, 100, 100, j, {16, cap});
  EXPECT_TRUE(capped.capped);
  EXPECT_EQ(capped.level, 2);
  EXPECT_LE(capped.texels_visited, cap);
}

// Ground truth: 8x8 samples per pixel, nearest texel at level 0, box-averaged.
img::Rgba8Image supersampled(const scene::Scene& s, const render::Frame& like) {
  img::Rgba8Image out = like.image;
  const auto tx = scene::build_texture(s, "checker");
  const auto k0 = persp::coefficients(s.camera, scene::in_texels(s.objects[0], 256, 256)[0]);
  for (const auto& p : like.pixels) {
    if (p.object != 0) continue;  // the ground plane (both triangles share one plane map)
    double acc[3] = {0, 0, 0};
    for (int i = 0; i < 8; ++i) {
      for (int j = 0; j < 8; ++j) {
        const double x = p.x + (i + 0.5) / 8 - 0.5, y = p.y + (j + 0.5) / 8 - 0.5;
        const double q = k0.g * x + k0.h * y + k0.i;
        const auto c = tx.fetch(0, static_cast<int64_t>(std::floor((k0.a * x + k0.b * y + k0.c) / q)),
                                static_cast<int64_t>(std::floor((k0.d * x + k0.e * y + k0.f) / q)));
        acc[0] += c.r, acc[1] += c.g, acc[2] += c.b;
      }
    }
    out.at(p.x, p.y) = {static_cast<uint8_t>(std::lround(acc[0] / 64)),
                        static_cast<uint8_t>(std::lround(acc[1] / 64)),
                        static_cast<uint8_t>(std::lround(acc[2] / 64)), 255};
  }
  return out;
}

TEST(RenderRef, EwaIsCloserToTheSupersampledTruthThanNearestAndBilinear) {
  const auto s = scene::default_scene();
  const auto ewa = render::render_ref(s, scene::Filter::Ewa);
  const auto nearest = render::render_ref(s, scene::Filter::Nearest);
  const auto bilinear = render::render_ref(s, scene::Filter::Bilinear);
  const auto truth = supersampled(s, ewa);
  // Compare the ground plane only (the wall keeps its own colours in `truth`).
  auto ground_only = [&](const render::Frame& f) {
    img::Rgba8Image im = truth;
    for (const auto& p : f.pixels)
      if (p.object == 0) im.at(p.x, p.y) = p.color;
    return im;
  };
  const double pe = tex::psnr(ground_only(ewa), truth);
  const double pn = tex::psnr(ground_only(nearest), truth);
  const double pb = tex::psnr(ground_only(bilinear), truth);
  std::printf("ground plane PSNR vs 8x8 supersampled: ewa %.2f dB, bilinear %.2f dB, nearest %.2f dB\n",
              pe, pb, pn);
  EXPECT_GT(pe, pn + 3);
  EXPECT_GT(pe, pb + 3);
}

TEST(RenderRef, DumpAndHeatmap) {
  const auto s = scene::default_scene();
  const auto f = render::render_ref(s, scene::Filter::Bilinear);
  const auto path = std::filesystem::temp_directory_path() / "tu_dump_test.csv";
  render::write_dump_csv(path.string(), f);
  std::ifstream in(path);
  std::string header;
  std::getline(in, header);
  std::string want = "x,y,u,v,lod,texels,r,g,b,a,relief_n,relief_steps";
  for (const auto& fl : render::pixel_flags()) want += std::string(",") + fl.name;
  EXPECT_EQ(header, want);
  EXPECT_NE(header.find(",b1_guard,"), std::string::npos);
  EXPECT_NE(header.find(",ewa_texel_cap,"), std::string::npos);
  EXPECT_NE(header.find(",relief_nonconv"), std::string::npos);
  size_t rows = 0;
  for (std::string l; std::getline(in, l);) ++rows;
  EXPECT_EQ(rows, f.pixels.size());
  std::filesystem::remove(path);
  const auto h = render::error_heatmap(f.image, f.image, 8);
  for (const auto& p : h.px) EXPECT_EQ(p, (img::Rgba8{0, 0, 0, 255}));
}
}  // namespace

// Every scene in docs/scenes/ loads with the scene loader and renders with the float reference
// (`texunit render SCENE --engine ref`), covering pixels of every object.
TEST(RenderRef, EveryDocsSceneLoadsAndRenders) {
  int scenes = 0;
  for (const auto& e : std::filesystem::directory_iterator(std::string(TU_SOURCE_DIR) + "/docs/scenes")) {
    if (e.path().extension() != ".json") continue;
    SCOPED_TRACE(e.path().string());
    const auto s = tu::scene::load(e.path().string());
    // No larger than the default scene (distance_map.json is the default scene with a traced wall).
    EXPECT_LE(s.camera.width * s.camera.height, 256 * 192) << "keep docs scenes small (test time)";
    const auto f = tu::render::render_ref(s);
    std::vector<int> per_object(s.objects.size());
    for (const auto& p : f.pixels) ++per_object[static_cast<size_t>(p.object)];
    for (size_t o = 0; o < per_object.size(); ++o) EXPECT_GT(per_object[o], 0) << s.objects[o].name;
    ++scenes;
  }
  EXPECT_GE(scenes, 2);
}
