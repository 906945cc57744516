// Relief in the render path (docs/blocks/relief-appendix.md §9): tangent frame, the bit-accurate per-pixel
// shift, and the float reference render with relief per material.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "ewa/ewa_cycles.hpp"
#include "pom/relief.hpp"
#include "pom/relief_quality.hpp"
#include "texunit/render.hpp"

namespace {
using namespace tu;

// The default scene with one substitution applied (must match exactly once).
std::string edited(std::string s, const std::string& from, const std::string& to) {
  const auto at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? s : s.replace(at, from.size(), to);
}
const std::string kRelief =
    R"(,
             "relief": {"height": "bricks", "scale": 0.04, "method": "pom_adaptive", "layers": 32})";

persp::Triangle xy_quad_half(double vsign) {  // z = 0 plane, uv = (x, vsign * y)
  persp::Triangle t;
  const double p[3][2] = {{0, 0}, {1, 0}, {0, 1}};
  for (int i = 0; i < 3; ++i) {
    t.v[i].p[0] = p[i][0], t.v[i].p[1] = p[i][1], t.v[i].p[2] = 0;
    t.v[i].uv[0] = p[i][0], t.v[i].uv[1] = vsign * p[i][1];
  }
  return t;
}

TEST(Relief, TangentViewFromTheUvMapping) {
  relief::TangentView tv;
  const double above[3] = {0.25, 0.25, 5}, slant[3] = {5.25, 0.25, 5};
  ASSERT_TRUE(relief::tangent_view(xy_quad_half(1), above, 0.25, 0.25, &tv));
  EXPECT_NEAR(tv.x, 0, 1e-12);
  EXPECT_NEAR(tv.y, 0, 1e-12);
  EXPECT_NEAR(tv.z, 1, 1e-12);
  ASSERT_TRUE(relief::tangent_view(xy_quad_half(1), slant, 0.25, 0.25, &tv));
  EXPECT_NEAR(tv.x, std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(tv.z, std::sqrt(0.5), 1e-12);
  // v running against y flips the tangent-space y; the eye below the plane flips the normal
  const double side[3] = {0.25, 5.25, 5}, below[3] = {0.25, 0.25, -5};
  ASSERT_TRUE(relief::tangent_view(xy_quad_half(-1), side, 0.25, 0.25, &tv));
  EXPECT_NEAR(tv.y, -std::sqrt(0.5), 1e-12);
  ASSERT_TRUE(relief::tangent_view(xy_quad_half(1), below, 0.25, 0.25, &tv));
  EXPECT_NEAR(tv.z, 1, 1e-12);
  auto flat = xy_quad_half(1);
  flat.v[2].uv[0] = 2, flat.v[2].uv[1] = 0;  // degenerate mapping
  EXPECT_FALSE(relief::tangent_view(flat, above, 0.25, 0.25, &tv));
}

TEST(Relief, FlatHeightMapDoesNotShiftAndConstantDepthShiftsUniformly) {
  const relief::TangentView view{std::sin(1.2) * 0.6, std::sin(1.2) * 0.8, std::cos(1.2)};
  const auto q = relief::quantise(view, 0.05);
  for (int h : {255, 128, 0}) {
    const auto maps = relief::make_maps(img::Gray8(64, 64, static_cast<uint8_t>(h)));
    const double d = (255 - h) / 255.0;
    for (auto m : {relief::Method::PomFixed, relief::Method::PomAdaptive, relief::Method::Iterative})
      for (int64_t u : {int64_t(1234), int64_t(3 * 65536 + 40000)}) {
        const auto r = relief::shift_uv_fx(maps, u, 777, q, m, 32);
        const auto ref = relief::shift_uv_ref(maps, u / 65536.0, 777 / 65536.0, view, 0.05);
        if (h == 255) {  // top surface everywhere: no shift in any method
          EXPECT_EQ(r.u, u);
          EXPECT_EQ(r.v, 777);
          EXPECT_EQ(r.steps, 0u);
          EXPECT_DOUBLE_EQ(ref.u, u / 65536.0);
        }
        // shift = -d * P (in repeats); the integer part of u is kept
        const double P = view.x / view.z * 0.05;
        EXPECT_NEAR(ref.u, u / 65536.0 - d * P, 1e-9);
        double du = r.u / 65536.0 - (u / 65536.0 - d * P);
        du -= std::round(du);
        EXPECT_LT(std::fabs(du), 40.0 / 65536) << h << " " << scene::to_string(m);
        EXPECT_EQ(r.u >> 16, u >> 16);
      }
  }
}

TEST(Relief, FixedPointShiftFollowsTheReferenceOnBricks) {
  const auto maps = relief::make_maps(tex::bricks(64).height);
  for (double ang : {30.0, 60.0}) {
    const double th = ang * M_PI / 180;
    const relief::TangentView view{std::sin(th), 0, std::cos(th)};
    const auto q = relief::quantise(view, 0.04);
    int close = 0, n = 0;
    for (int y = 0; y < 64; y += 3)
      for (int x = 0; x < 64; x += 3, ++n) {
        const int64_t u = (2 * x + 1) << 9, v = (2 * y + 1) << 9;
        const auto r = relief::shift_uv_fx(maps, u, v, q, relief::Method::PomFixed, 63);
        const auto ref = relief::shift_uv_ref(maps, u / 65536.0, v / 65536.0, view, 0.04);
        double e = r.u / 65536.0 - ref.u;
        e -= std::round(e);
        close += std::fabs(e) < 1.0 / 64;  // within one depth texel
      }
    EXPECT_GT(close, n * 9 / 10) << ang;
  }
}

TEST(Relief, OnlyReliefMaterialsChangeTheRender) {
  const auto with = scene::default_scene();
  const auto without = scene::parse(edited(scene::default_scene_json(), kRelief, ""), "no-relief", ".");
  const auto a = render::render_ref(with, scene::Filter::Bilinear);
  const auto b = render::render_ref(without, scene::Filter::Bilinear);
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  size_t wall = 0, wall_changed = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    const auto &p = a.pixels[i], &q = b.pixels[i];
    ASSERT_EQ(p.object, q.object);
    if (p.object == 0) {  // ground: no relief, bit-identical
      EXPECT_EQ(p.color, q.color);
      EXPECT_EQ(p.u, q.u);
      EXPECT_EQ(p.relief_n, 0);
    } else {
      ++wall;
      wall_changed += p.u != q.u || p.v != q.v;
      EXPECT_GE(p.relief_n, 4);
      EXPECT_LE(p.relief_n, 32);
    }
  }
  EXPECT_GT(wall, 1000u);
  // The wall is seen at an angle: every pixel whose depth is not 0 (brick tops) moves.
  EXPECT_GT(wall_changed, wall / 2);
  std::printf("default scene: %zu wall pixels, %zu moved by the relief\n", wall, wall_changed);
  const auto layers = render::layers_image(with, a);
  ASSERT_TRUE(layers.has_value());
  EXPECT_FALSE(render::layers_image(without, b).has_value());
}

TEST(Relief, FlatHeightTextureRendersLikeNoRelief) {
  const auto dir = std::filesystem::temp_directory_path() / "tu_relief_test";
  std::filesystem::create_directories(dir);
  img::write_png_gray((dir / "flat.png").string(), img::Gray8(64, 64, 255));
  img::write_png_gray((dir / "odd.png").string(), img::Gray8(48, 64, 255));
  std::string js = edited(scene::default_scene_json(), R"("height": "bricks")", R"("height": "flat")");
  js = edited(js, R"("bricks": {"builtin")", R"("flat": {"png": "flat.png"}, "odd": {"png": "odd.png"},
    "bricks": {"builtin")");
  const auto flat = scene::parse(js, "flat.json", dir.string());
  const auto none = scene::parse(edited(scene::default_scene_json(), kRelief, ""), "none", ".");
  const auto a = render::render_ref(flat, scene::Filter::Bilinear);
  const auto b = render::render_ref(none, scene::Filter::Bilinear);
  EXPECT_EQ(a.image.px, b.image.px);
  const auto odd = scene::parse(edited(js, R"("height": "flat")", R"("height": "odd")"), "odd.json", dir.string());
  try {
    render::render_ref(odd, scene::Filter::Nearest);
    ADD_FAILURE() << "non-power-of-two height map accepted";
  } catch (const scene::SceneError& e) {
    // the texture loader rejects it first, naming the file and the texture
    EXPECT_NE(std::string(e.what()).find("odd.json: /textures/odd"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
  EXPECT_THROW(relief::make_maps(img::Gray8(48, 64, 255)), std::invalid_argument);
}
}  // namespace

// The relief stage's stream-cycle estimator (its equality with Verilator: relief_stage_cosim_test).
TEST(ReliefStageCycles, PlainPixelsOnePerClockAndStepsAddOneEach) {
  std::vector<relief::StagePixel> plain(300);
  EXPECT_EQ(relief::stage_cycles(plain), 301u);
  EXPECT_EQ(relief::stage_cycles({}), 0u);
  // A lone shifted pixel: every march step is one more cycle; pixels behind it wait (order).
  auto with = [&](uint32_t k) {
    auto p = plain;
    p[0] = {true, k};
    return relief::stage_cycles(p);
  };
  const uint64_t base = with(0);
  EXPECT_GT(base, 301u);
  for (uint32_t k : {1u, 7u, 63u}) EXPECT_EQ(with(k), base + k);
  // Back-to-back shifted pixels overlap set-up and refinement: k + 1 cycles each.
  std::vector<relief::StagePixel> pom(200, {true, 5});
  std::vector<relief::StagePixel> pom2(201, {true, 5});
  EXPECT_EQ(relief::stage_cycles(pom2) - relief::stage_cycles(pom), 6u);
}

// Iterative pixels: k + 3 cycles each in a stream (the engine's Idle and Done); a lone one leaves
// when a POM pixel with the same k does (both engines output k + 2 cycles after acceptance).
TEST(ReliefStageCycles, IterativePixelsAndTheEngineHandOver) {
  std::vector<relief::StagePixel> ipx(200, {true, 5, true}), ipx2(201, {true, 5, true});
  EXPECT_EQ(relief::stage_cycles(ipx2) - relief::stage_cycles(ipx), 8u);
  const std::vector<relief::StagePixel> one_pom = {{true, 4, false}}, one_ipx = {{true, 4, true}};
  EXPECT_EQ(relief::stage_cycles(one_ipx), relief::stage_cycles(one_pom));
  // Alternating methods cost more than either method alone (no overlap across the hand-over).
  std::vector<relief::StagePixel> alt;
  for (int i = 0; i < 200; ++i) alt.push_back({true, 5, i % 2 == 1});
  std::vector<relief::StagePixel> pom(200, {true, 5, false});
  EXPECT_GT(relief::stage_cycles(alt), (relief::stage_cycles(pom) + relief::stage_cycles(ipx)) / 2);
}

// The whole unit's model without shifted pixels is the filter's recurrence from the front latency.
TEST(TextureUnitCycles, WithoutShiftedPixelsEqualsTheFilterStream) {
  std::vector<ewa::PixelCost> px;
  for (int i = 0; i < 300; ++i) {
    ewa::PixelCost c;
    c.engine = i % 50 < 25 ? ewa::Engine::Ewa : i % 50 < 40 ? ewa::Engine::Bilinear : ewa::Engine::Nearest;
    c.box = 20 + static_cast<uint64_t>(i % 7);
    c.guard = i % 31 == 0;
    px.push_back(c);
  }
  const std::vector<relief::StagePixel> plain(px.size());
  EXPECT_EQ(ewa::texture_unit_cycles(px, plain),
            ewa::stream_cycles(px, static_cast<uint64_t>(ewa::texture_unit_front_latency(true))));
  // Marches under EWA pixels hide; under nearest pixels (4 clocks each) they show.
  std::vector<relief::StagePixel> marching(px.size(), {true, 30, true});
  EXPECT_GE(ewa::texture_unit_cycles(px, marching), ewa::texture_unit_cycles(px, plain));
  std::vector<ewa::PixelCost> nearest(300);
  for (auto& c : nearest) c.engine = ewa::Engine::Nearest;
  EXPECT_GT(ewa::texture_unit_cycles(nearest, marching), 300u * 33);
}
