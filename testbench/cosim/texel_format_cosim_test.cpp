// Texel formats through the texture-unit top (docs/blocks/texture.md "Texel formats"):
// docs/scenes/texel_formats.json (every packed format, sRGB on rgba8 and rgb565, border colours,
// adjacent quads of one engine with different formats) rendered by the Verilated unit with its
// texel decode stage (tu_texel_decode) equals the C model on every pixel, cycles = predicted.
#include <gtest/gtest.h>

#include <cstdio>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>

#include "texture/texel_format.hpp"
#include "texture_unit_rtl.hpp"
#include "texunit/render.hpp"
#include "texunit/scene.hpp"

namespace {

// Pixels of the C-model frame of `s` whose colour differs from the frame of `plain` (the same
// scene stored otherwise): a format test is meaningful only if the decode changes the picture.
size_t differing_pixels(const tu::scene::Scene& s, const tu::scene::Scene& plain, size_t* total) {
  const tu::render::Frame a = tu::render::render_cmodel(s);
  const tu::render::Frame b = tu::render::render_cmodel(plain);
  size_t differ = 0;
  for (size_t i = 0; i < a.pixels.size() && i < b.pixels.size(); ++i) differ += !(a.pixels[i].color == b.pixels[i].color);
  *total = a.pixels.size();
  return differ;
}
using namespace tu;

TEST(TextureUnitRtl, TexelFormatsSceneEqualsCModelCyclesPredicted) {
  const auto s = scene::load(std::string(TU_SOURCE_DIR) + "/docs/scenes/texel_formats.json");
  std::set<int> formats;
  bool srgb = false;
  for (const auto& [name, t] : s.textures) formats.insert(t.format), srgb = srgb || t.srgb;
  EXPECT_EQ(formats.size(), std::size(tex::kTexelFormatNames) - 1);  // every format but bc1, and sRGB
  EXPECT_TRUE(srgb);
  for (double stall : {0.0, 0.3}) {
    cosim::RtlRenderOptions o;
    o.stall_prob = stall;
    const auto r = cosim::render_rtl(s, o);
    EXPECT_TRUE(r.ok()) << r.first_mismatch;
    EXPECT_GT(r.frame.pixels.size(), 2000u);
    if (stall == 0) {
      EXPECT_EQ(r.cycles, r.predicted_cycles);
    }
    std::printf("texel formats, stalls %.1f: %zu px, %llu mismatches, cycles %llu (predicted %llu)\n", stall,
                r.frame.pixels.size(), (unsigned long long)r.mismatches, (unsigned long long)r.cycles,
                (unsigned long long)r.predicted_cycles);
  }
  // The decode matters: the same scene stored as rgba8 (no sRGB) differs on most pixels.
  auto plain = s;
  for (auto& [name, t] : plain.textures) t.format = 0, t.srgb = false;
  size_t total = 0;
  const size_t differ = differing_pixels(s, plain, &total);
  EXPECT_GT(differ, total / 2);
  std::printf("texel formats: %zu of %zu px differ from the scene stored as rgba8\n", differ, total);
}

// BC1 in the unit (docs/blocks/texture.md "BC1 in the unit"): docs/scenes/bc1.json (six BC1
// textures: every wrap mode, a transparent border block, sRGB, sides 16..64, deep minification to
// the 2 x 2 and 1 x 1 levels) through the full unit's 64-bit texel RAM, tu_bc1_addr and
// tu_bc1_decode: every pixel equal to the C model, cycles = ewa::texture_unit_cycles, as authored
// (EWA, bilinear, trilinear, nearest, Feline) and with every material on each engine.
TEST(TextureUnitRtl, Bc1SceneEqualsCModelCyclesPredicted) {
  const auto s = scene::load(std::string(TU_SOURCE_DIR) + "/docs/scenes/bc1.json");
  for (const auto& [name, t] : s.textures) EXPECT_EQ(t.format, static_cast<int>(tex::TexelFormat::Bc1)) << name;
  struct Run {
    const char* what;
    std::optional<scene::Filter> filter;
    double stall;
  };
  const Run runs[] = {{"as authored", std::nullopt, 0.0},      {"as authored", std::nullopt, 0.3},
                      {"ewa", scene::Filter::Ewa, 0.0},         {"trilinear", scene::Filter::Trilinear, 0.0},
                      {"bilinear", scene::Filter::Bilinear, 0.0}, {"nearest", scene::Filter::Nearest, 0.0},
                      {"feline", scene::Filter::Feline, 0.0}};
  for (const Run& run : runs) {
    SCOPED_TRACE(std::string(run.what) + (run.stall > 0 ? ", 30 % stalls" : ""));
    cosim::RtlRenderOptions o;
    o.stall_prob = run.stall;
    o.filter = run.filter;
    const auto r = cosim::render_rtl(s, o);
    EXPECT_TRUE(r.ok()) << r.first_mismatch;
    EXPECT_EQ(r.mismatches, 0u);
    EXPECT_GT(r.frame.pixels.size(), 2000u);
    if (run.stall == 0) {
      EXPECT_EQ(r.cycles, r.predicted_cycles);
    }
    std::printf("bc1 %s, stalls %.1f: %zu px, %llu mismatches, cycles %llu (predicted %llu)\n", run.what, run.stall,
                r.frame.pixels.size(), (unsigned long long)r.mismatches, (unsigned long long)r.cycles,
                (unsigned long long)r.predicted_cycles);
  }
  // Memory: texel RAM words of the scene's textures as BC1 blocks (one 64-bit word per block, the
  // border a block) and in the texel layout (one word per texel, the border a word); bits per texel.
  uint64_t block_words = 0, texel_words = 0, texels = 0;
  for (const auto& [name, t] : s.textures) {
    const tex::Texture x = scene::build_texture(s, name);
    block_words += x.words.size() / 2;
    for (const auto& lv : x.levels) texel_words += lv.px.size(), texels += lv.px.size();
    ++texel_words;
  }
  EXPECT_LT(block_words * 64, texel_words * 32 / 7);  // about 4 bits per texel against 32
  std::printf("bc1: %llu RAM words of 64 bits for %llu texels (%.3f bits per texel with the border blocks); "
              "the texel layout: %llu words\n",
              (unsigned long long)block_words, (unsigned long long)texels, 64.0 * double(block_words) / double(texels),
              (unsigned long long)texel_words);
  // The block decode matters: the same scene stored as rgba8 differs on most pixels.
  auto plain = s;
  for (auto& [name, t] : plain.textures) t.format = 0;
  size_t total = 0;
  const size_t differ = differing_pixels(s, plain, &total);
  EXPECT_GT(differ, total / 2);
  std::printf("bc1: %zu of %zu px differ from the scene stored as rgba8\n", differ, total);
  // The K = 4 unit model (the corridor unit's plan: rgba8 only, HasBc1 = 0) refuses BC1, naming the field.
  cosim::RtlRenderOptions k4;
  k4.corridor_unit = true;
  k4.filter = scene::Filter::Ewa;
  k4.weights = scene::WeightSource::Table1d;
  try {
    (void)cosim::render_rtl(s, k4);
    ADD_FAILURE() << "the corridor unit accepted a bc1 texture";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("/format: the corridor unit decodes rgba8 texels only"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("HasBc1 = 0"), std::string::npos) << e.what();
  }
}

// BC1 on the K = 4 EWA engine's four bank ports (a tu_texel_port each): the full unit verilated
// with EwaLanes 4, EwaSetups 3 (-DTU_COSIM_K4_UNIT=ON; skipped without it), bc1.json with every
// material on EWA: every pixel equal to the C model, with and without stalls; without stalls the
// cycles equal ewa::texture_unit_cycles with the full unit's engine (full_unit_k4_ewa_params: the
// four-lane engine with HasEwaClip = 1, so every pixel, plain or not, leaves the border pipeline's
// latency after its last block and each drain between textures costs it). The same scene stored as
// rgba8 and the default scene (every material on EWA) on the same unit, cycles = predicted too
// (docs/blocks/texture.md "BC1 in the unit").
TEST(TextureUnitRtl, Bc1OnTheFourLaneEwaEqualsCModel) {
#if !TU_COSIM_K4_UNIT
  GTEST_SKIP() << "the K = 4 full unit is verilated only with -DTU_COSIM_K4_UNIT=ON";
#else
  const auto s = scene::load(std::string(TU_SOURCE_DIR) + "/docs/scenes/bc1.json");
  auto plain = s;  // the same scene stored as rgba8 (the sRGB texture keeps its flag: one format change)
  for (auto& [name, t] : plain.textures) t.format = 0;
  const auto def = scene::default_scene();
  struct Run {
    const char* what;
    const scene::Scene* scene;
    double stall;
  };
  for (const Run& run : {Run{"bc1", &s, 0.0}, Run{"bc1", &s, 0.3}, Run{"rgba8", &plain, 0.0},
                         Run{"default scene", &def, 0.0}}) {
    SCOPED_TRACE(std::string(run.what) + (run.stall > 0 ? ", 30 % stalls" : ""));
    cosim::RtlRenderOptions o;
    o.ewa_lanes = 4;
    o.filter = scene::Filter::Ewa;
    o.stall_prob = run.stall;
    const auto r = cosim::render_rtl(*run.scene, o);
    EXPECT_TRUE(r.ok()) << run.what << ": " << r.first_mismatch;
    EXPECT_EQ(r.mismatches, 0u);
    EXPECT_GT(r.frame.pixels.size(), 2000u);
    if (run.stall == 0) {
      EXPECT_EQ(r.cycles, r.predicted_cycles);
    }
    std::printf("%s on the K = 4 EWA, stalls %.1f: %zu px, %llu mismatches, cycles %llu (predicted %llu), %.2f clocks/px\n",
                run.what, run.stall, r.frame.pixels.size(), (unsigned long long)r.mismatches,
                (unsigned long long)r.cycles, (unsigned long long)r.predicted_cycles,
                double(r.cycles) / double(r.frame.pixels.size()));
  }
#endif
}

}  // namespace
