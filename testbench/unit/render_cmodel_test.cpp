// C-model render engine (B1 persp fixed -> B2 ellipse fixed -> fixed filters / EWA fx) against the
// float reference render on the default scene, and the per-pixel uv-shift hook.
#include <gtest/gtest.h>

#include "ellipse/ellipse_fx.hpp"
#include "texunit/render.hpp"

namespace {
using namespace tu;

// The default scene at half resolution (the same view): a quarter of the pixels keeps the
// sanitizer build fast.
const scene::Scene& scn() {
  static const auto s = [] {
    auto d = scene::default_scene();
    d.camera.width /= 2;
    d.camera.height /= 2;
    return d;
  }();
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
