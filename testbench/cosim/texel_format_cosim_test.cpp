// Texel formats through the texture-unit top (docs/blocks/texture.md "Texel formats"):
// docs/scenes/texel_formats.json (every packed format, sRGB on rgba8 and rgb565, border colours,
// adjacent quads of one engine with different formats) rendered by the Verilated unit with its
// texel decode stage (tu_texel_decode) equals the C model on every pixel, cycles = predicted.
#include <gtest/gtest.h>

#include <cstdio>
#include <set>

#include "texture/texel_format.hpp"
#include "texture_unit_rtl.hpp"
#include "texunit/render.hpp"
#include "texunit/scene.hpp"

namespace {
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
  const render::Frame a = render::render_cmodel(s);
  const render::Frame b = render::render_cmodel(plain);
  size_t differ = 0;
  for (size_t i = 0; i < a.pixels.size() && i < b.pixels.size(); ++i) differ += !(a.pixels[i].color == b.pixels[i].color);
  EXPECT_GT(differ, a.pixels.size() / 2);
  std::printf("texel formats: %zu of %zu px differ from the scene stored as rgba8\n", differ, a.pixels.size());
}

}  // namespace
