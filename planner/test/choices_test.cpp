// The plan's selections that need no render (planner/plan.hpp): relief method among measured
// candidates, noise scheme against a cycle budget.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "planner/plan.hpp"
#include "texture/texel_format.hpp"
#include "texture/texture.hpp"

namespace tu::plan {
namespace {

using M = scene::ReliefMethod;

ReliefChoice candidates() {
  ReliefChoice c{M::PomAdaptive, M::PomAdaptive, false, 32, {}};
  c.cands = {{M::PomFixed, 30, 2, 8, 0}, {M::PomAdaptive, 41, 5, 12, 0}, {M::Iterative, 45, 4, 6, 0},
             {M::DistanceMap, 50, 9, 3, 4096}};
  return c;
}

TEST(PlanRelief, CheapestMeetingTheBudget) {
  ReliefChoice c = candidates();
  pick_relief(c, 40);  // adaptive (5 cycles/px), iterative (4) and the distance map (9) meet 40 dB
  EXPECT_EQ(c.chosen, M::Iterative);
  EXPECT_TRUE(c.meets);
  pick_relief(c, 30);  // inclusive: fixed POM at 30 dB and 2 cycles/px
  EXPECT_EQ(c.chosen, M::PomFixed);
  EXPECT_TRUE(c.meets);
}

TEST(PlanRelief, BestPsnrWhenNoneMeetsIt) {
  ReliefChoice c = candidates();
  pick_relief(c, 60);
  EXPECT_EQ(c.chosen, M::DistanceMap);
  EXPECT_FALSE(c.meets);
}

TEST(PlanRelief, FirstOfEqualCosts) {
  ReliefChoice c = candidates();
  c.cands[3].cycles_per_px = 4;  // the distance map as cheap as iterative: the earlier one stays
  pick_relief(c, 40);
  EXPECT_EQ(c.chosen, M::Iterative);
  ReliefChoice none{M::Iterative, M::Iterative, false, 8, {}};
  pick_relief(none, 40);
  EXPECT_EQ(none.chosen, M::Iterative);
  EXPECT_FALSE(none.meets);
}

TEST(PlanNoiseScheme, OctaveSerialOnlyWhenItMeetsTheBudget) {
  // pipelined 1000 clocks, octave-serial 1500, 4 octave cores.
  NoiseScheme n = choose_noise_scheme(0, 1000, 1500, 4);
  EXPECT_FALSE(n.octave_serial);
  EXPECT_EQ(n.why, "no cycle budget: the fastest");
  EXPECT_EQ(n.max_cycles, 0);
  n = choose_noise_scheme(-5, 1000, 1500, 4);
  EXPECT_FALSE(n.octave_serial);
  EXPECT_EQ(n.max_cycles, 0);
  n = choose_noise_scheme(1500, 1000, 1500, 4);  // the budget is inclusive
  EXPECT_TRUE(n.octave_serial);
  EXPECT_EQ(n.why, "the octave-serial unit meets max_cycles with one core");
  EXPECT_EQ(n.max_cycles, 1500);
  EXPECT_EQ(n.pipelined_cycles, 1000u);
  EXPECT_EQ(n.octave_serial_cycles, 1500u);
  n = choose_noise_scheme(1499, 1000, 1500, 4);
  EXPECT_FALSE(n.octave_serial);
  EXPECT_EQ(n.why, "only the pipelined unit meets max_cycles");
  n = choose_noise_scheme(999, 1000, 1500, 4);
  EXPECT_FALSE(n.octave_serial);
  EXPECT_EQ(n.why, "no scheme meets max_cycles: the fastest");
  n = choose_noise_scheme(5000, 1000, 1500, 1);  // one octave core: nothing to save
  EXPECT_FALSE(n.octave_serial);
  EXPECT_EQ(n.why, "only the pipelined unit meets max_cycles");
}

}  // namespace
}  // namespace tu::plan

namespace tu::plan {
namespace {

// Two objects on two textures, and a texture no object samples (it must not count).
scene::Scene two_textures() {
  scene::Scene s;
  s.textures["a"].name = "a", s.textures["b"].name = "b", s.textures["unused"].name = "unused";
  s.textures["unused"].addressing.u = tex::Wrap::Border;
  s.textures["unused"].format = static_cast<int>(tex::TexelFormat::La8);
  s.textures["unused"].srgb = true;
  s.materials["ma"].texture = "a", s.materials["mb"].texture = "b", s.materials["mu"].texture = "unused";
  scene::Object o1, o2;
  o1.material = "ma", o2.material = "mb";
  s.objects = {o1, o2};
  return s;
}

TEST(PlanTextures, WrapModesOfTheSampledTextures) {
  scene::Scene s = two_textures();
  TextureNeeds n = texture_needs(s);
  EXPECT_EQ(n.wrap_modes, 1);  // repeat only
  EXPECT_EQ(n.wrap_names, (std::vector<std::string>{"repeat"}));
  s.textures["b"].addressing.u = tex::Wrap::Clamp, s.textures["b"].addressing.v = tex::Wrap::Mirror;
  n = texture_needs(s);
  EXPECT_EQ(n.wrap_modes, 0b111);
  EXPECT_EQ(n.wrap_names, (std::vector<std::string>{"repeat", "mirror", "clamp"}));
  s.textures["a"].addressing.u = s.textures["a"].addressing.v = tex::Wrap::MirrorOnce;  // repeat stays
  EXPECT_EQ(texture_needs(s).wrap_modes, 0b10111);
}

TEST(PlanTextures, FormatsSrgbAndPortWidth) {
  scene::Scene s = two_textures();
  TextureNeeds n = texture_needs(s);  // both rgba8
  EXPECT_EQ(n.tex_formats, 1);
  EXPECT_EQ(n.texel_w, 32);
  EXPECT_FALSE(n.srgb);
  EXPECT_FALSE(n.bc1);
  EXPECT_EQ(n.format_names, (std::vector<std::string>{"rgba8"}));
  s.textures["a"].format = static_cast<int>(tex::TexelFormat::L8), s.textures["a"].srgb = true;
  s.textures["b"].format = static_cast<int>(tex::TexelFormat::Rgb565);
  n = texture_needs(s);
  EXPECT_EQ(n.tex_formats, 1 | 2 | 16);  // rgba8 always, rgb565 (1), l8 (4)
  EXPECT_EQ(n.texel_w, 16);              // the widest stored format
  EXPECT_TRUE(n.srgb);
  EXPECT_EQ(n.format_names, (std::vector<std::string>{"rgba8", "rgb565", "l8"}));
  s.textures["b"].format = static_cast<int>(tex::TexelFormat::A8);
  EXPECT_EQ(texture_needs(s).texel_w, 8);
}

TEST(PlanTextures, Bc1IsTheBlockFetchNotADecodeFormat) {
  scene::Scene s = two_textures();
  s.textures["a"].format = s.textures["b"].format = static_cast<int>(tex::TexelFormat::Bc1);
  s.textures["b"].srgb = true;
  const TextureNeeds n = texture_needs(s);
  EXPECT_TRUE(n.bc1);
  EXPECT_TRUE(n.srgb);
  EXPECT_EQ(n.tex_formats, 1);
  EXPECT_EQ(n.texel_w, 32);  // no decoded format: the default port
  EXPECT_EQ(n.format_names, (std::vector<std::string>{"rgba8", "bc1"}));
}

}  // namespace
}  // namespace tu::plan

namespace tu::plan {
namespace {

TEST(PlanFootprint, Histograms) {
  EXPECT_EQ(lod_histogram({-0.5, 0.0, 0.49, 1.0, 2.7}),
            (std::map<std::string, int>{{"-1", 1}, {"0", 2}, {"1", 1}, {"2", 1}}));
  EXPECT_EQ(aniso_histogram({1.0, 1.99, 2.0, 3.9, 4, 8, 15.9, 16, 100}),
            (std::map<std::string, int>{{"1-2", 2}, {"2-4", 2}, {"4-8", 1}, {"8-16", 2}, {"16+", 2}}));
  EXPECT_TRUE(lod_histogram({}).empty());
}

TEST(PlanFootprint, PixelsPerMaterialAndReliefEngines) {
  scene::Scene s;
  s.materials["flat"].name = "flat", s.materials["bumpy"].name = "bumpy", s.materials["dm"].name = "dm";
  s.materials["bumpy"].relief.emplace(), s.materials["dm"].relief.emplace();
  s.materials["bumpy"].relief->method = scene::ReliefMethod::Iterative, s.materials["bumpy"].relief->layers = 16;
  s.materials["dm"].relief->method = scene::ReliefMethod::DistanceMapRefined, s.materials["dm"].relief->layers = 64;
  scene::Object a, b, c;
  a.material = "flat", b.material = "bumpy", c.material = "dm";
  s.objects = {a, b, c};
  render::Frame f;
  auto px = [&](int object, double lod, double aniso) {
    render::PixelRecord p;
    p.object = object, p.footprint_lod = lod, p.aniso = aniso;
    f.pixels.push_back(p);
  };
  px(0, 0.25, 1.5), px(0, 1.5, 3), px(1, -1, 1);  // no pixel of the distance-map object
  Footprints fp = footprints(s, f);
  EXPECT_EQ(fp.material_pixels, (std::map<std::string, size_t>{{"bumpy", 1}, {"flat", 2}}));
  EXPECT_EQ(fp.lod, (std::vector<double>{0.25, 1.5, -1}));
  EXPECT_EQ(fp.aniso, (std::vector<double>{1.5, 3, 1}));
  EXPECT_TRUE(fp.relief);
  EXPECT_TRUE(fp.iterative);
  EXPECT_FALSE(fp.pom);
  EXPECT_FALSE(fp.distance_map);  // authored, but covers no pixel
  EXPECT_EQ(fp.max_layers, 16);
  px(2, 0, 1);
  fp = footprints(s, f);
  EXPECT_TRUE(fp.distance_map);
  EXPECT_EQ(fp.max_layers, 64);
  s.materials["bumpy"].relief->method = scene::ReliefMethod::PomFixed;
  EXPECT_TRUE(footprints(s, f).pom);
  EXPECT_FALSE(footprints(s, f).iterative);
}

}  // namespace
}  // namespace tu::plan
