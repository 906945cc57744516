// C-model render engine (B1 persp fixed -> B2 ellipse fixed -> fixed filters / EWA fx) against the
// float reference render on the default scene, and the per-pixel uv-shift hook.
#include <gtest/gtest.h>

#include "ellipse/ellipse_fx.hpp"
#include "texunit/render.hpp"

namespace {
using namespace tu;

// The default scene at half resolution (the same view): a quarter of the pixels keeps the
// sanitizer build fast.
scene::Scene half_default() {
  auto d = scene::default_scene();
  d.camera.width /= 2;
  d.camera.height /= 2;
  return d;
}
// Without relief: the filter tests measure the texture path (the float reference's relief is the
// 256-layer ideal march, the C model's the material's method; ReliefFollowsTheMaterial covers it).
const scene::Scene& scn() {
  static const auto s = scene::without_relief(half_default());
  return s;
}

TEST(RenderCmodel, EwaIsCloseToTheFloatEwa) {
  const auto ref = render::render_ref(scn(), scene::Filter::Ewa);
  for (auto w : {scene::WeightSource::Formula, scene::WeightSource::Table2d}) {
    render::CmodelOptions opt;
    opt.weights = w;
    const auto fx = render::render_cmodel(scn(), scene::Filter::Ewa, opt);
    ASSERT_EQ(fx.pixels.size(), ref.pixels.size());  // same visibility
    EXPECT_GT(tex::psnr(fx.image, ref.image), 50);
    size_t same_level = 0;
    for (size_t i = 0; i < fx.pixels.size(); ++i) {
      same_level += fx.pixels[i].lod == ref.pixels[i].lod;
      EXPECT_GE(fx.pixels[i].texels, fx.pixels[i].texels_inside);
      if (!(fx.pixels[i].b2_flags & ellipse::fx::kHorizon)) {
        EXPECT_GT(fx.pixels[i].texels_inside, 0);
      }
    }
    EXPECT_GT(same_level, fx.pixels.size() * 99 / 100);
  }
}

TEST(RenderCmodel, BaselineFiltersTrackTheReference) {
  for (auto f : {scene::Filter::Nearest, scene::Filter::Bilinear, scene::Filter::Trilinear}) {
    const auto ref = render::render_ref(scn(), f);
    const auto fx = render::render_cmodel(scn(), f);
    ASSERT_EQ(fx.pixels.size(), ref.pixels.size());
    size_t close = 0, horizon = 0;  // B1 rounds u, v to 1/256 texel: a nearest texel may flip
    for (size_t i = 0; i < fx.pixels.size(); ++i) {
      const auto a = fx.pixels[i].color, b = ref.pixels[i].color;
      close += std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)}) <= 2;
      if (fx.pixels[i].b2_flags & ellipse::fx::kHorizon) {  // B1 guard: the texture's mean
        ++horizon;
        continue;
      }
      EXPECT_NEAR(fx.pixels[i].u, ref.pixels[i].u, 1.0 / 256);
    }
    EXPECT_LT(horizon, fx.pixels.size() / 100);
    EXPECT_GT(close, fx.pixels.size() * 98 / 100) << scene::to_string(f);
  }
}

TEST(RenderCmodel, UvShiftHookMovesTheSample) {
  const auto base = render::render_cmodel(scn(), scene::Filter::Nearest);
  render::CmodelOptions opt;
  int calls = 0;
  opt.uv_shift = [&](int, int, int, int64_t* u, int64_t*) {
    ++calls;
    *u += int64_t(3) << fmt::kTexUvF;  // three texels
  };
  const auto moved = render::render_cmodel(scn(), scene::Filter::Nearest, opt);
  EXPECT_EQ(static_cast<size_t>(calls), base.pixels.size());
  for (size_t i = 0; i < base.pixels.size(); ++i) ASSERT_EQ(moved.pixels[i].u, base.pixels[i].u + 3);
  EXPECT_LT(tex::psnr(moved.image, base.image), 40);
}

}  // namespace

// Relief in the C-model engine: only the relief material's pixels move (against the texture path
// alone), and the method (adaptive POM, fixed point) stays close to the float reference's
// 256-layer march with exact refinement (38.3 dB measured on this half-size default scene).
TEST(RenderCmodel, ReliefFollowsTheMaterial) {
  const auto s = half_default();
  const auto with = render::render_cmodel(s, scene::Filter::Ewa);
  const auto without = render::render_cmodel(s, scene::Filter::Ewa, render::texture_path_only());
  ASSERT_EQ(with.pixels.size(), without.pixels.size());
  size_t moved = 0, relief_pixels = 0;
  for (size_t i = 0; i < with.pixels.size(); ++i) {
    const auto& p = with.pixels[i];
    const bool has = s.materials.at(s.objects[static_cast<size_t>(p.object)].material).relief.has_value();
    relief_pixels += has;
    const bool same = p.u == without.pixels[i].u && p.v == without.pixels[i].v;
    if (!has) {
      EXPECT_TRUE(same) << p.x << "," << p.y;
      EXPECT_EQ(p.relief_n, 0);
    } else {
      moved += !same;
      EXPECT_GE(p.relief_n, 4);  // adaptive POM: N in [Nmin = 4, Nmax]
    }
  }
  ASSERT_GT(relief_pixels, 0u);
  EXPECT_GT(moved, relief_pixels / 2);
  EXPECT_GT(tex::psnr(with.image, render::render_ref(s, scene::Filter::Ewa).image), 35);
}

// The guard flags and relief counts the --dump columns and `render` show (issue 13, item 4).
namespace {
TEST(RenderCmodel, FlagCountsAndReliefColumns) {
  using namespace tu;
  const auto s = scene::default_scene();
  const auto f = render::render_cmodel(s, scene::Filter::Ewa);
  const auto& flags = render::pixel_flags();
  const auto n = render::flag_counts(f);
  auto count = [&](const std::string& name) {
    for (size_t i = 0; i < flags.size(); ++i)
      if (name == flags[i].name) return n[i];
    ADD_FAILURE() << name;
    return size_t(0);
  };
  size_t relief = 0, steps = 0;
  for (const auto& p : f.pixels) relief += p.relief_n > 0, steps += static_cast<size_t>(p.relief_steps);
  std::printf("%zu pixels: b1_guard %zu, b2_aniso_clamp %zu, b2_magnify %zu, ewa_texel_cap %zu, relief %zu px, "
              "%.2f steps / relief px\n", f.pixels.size(), count("b1_guard"), count("b2_aniso_clamp"),
              count("b2_magnify"), count("ewa_texel_cap"), relief, double(steps) / double(std::max<size_t>(1, relief)));
  EXPECT_GT(count("b1_guard"), 0u);        // the horizon rows
  EXPECT_GT(count("b2_aniso_clamp"), 0u);  // grazing ground and wall
  EXPECT_GT(count("b2_magnify"), 0u);      // the near ground
  EXPECT_GT(relief, 1000u);
  EXPECT_GT(steps, relief);
  const auto tri = render::render_cmodel(s, scene::Filter::Trilinear);
  const auto nt = render::flag_counts(tri);
  size_t mag = 0;
  for (size_t i = 0; i < flags.size(); ++i)
    if (std::string(flags[i].name) == "tri_magnify") mag = nt[i];
  EXPECT_GT(mag, 0u);
}
}  // namespace
