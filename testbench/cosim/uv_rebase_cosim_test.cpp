// uv rebase through the texture-unit top (docs/blocks/persp.md "uv rebase"): camera-facing quads
// whose uv lie far from 0 (B1's coefficient C overflowed s54.40 before the rebase) rendered by the
// Verilated unit from the same rebased span records as the C model: every pixel equal to the C
// model, and for a shift by whole periods the unshifted quad's image.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "../unit/uv_rebase_scene.hpp"
#include "texture_unit_rtl.hpp"
#include "texunit/render.hpp"
#include "texunit/scene.hpp"

namespace {
using namespace tu;

TEST(TextureUnitRtl, RebasedUvQuadsEqualTheCModel) {
  struct Case {
    int size;
    const char* wrap;
    const char* filter;
    double du, dv;
    bool whole;  // a whole-period shift: the unshifted image
  };
  const Case cases[] = {{256, "repeat", "ewa", 32.5, -40, false},
                        {64, "mirror", "trilinear", 1000, 65534, true},
                        {64, "repeat", "bilinear", -65536, 65535, true}};
  for (const Case& c : cases) {
    SCOPED_TRACE(std::to_string(c.size) + " " + c.wrap + " " + c.filter + " shift " + test::num(c.du) + ", " + test::num(c.dv));
    const auto s = scene::parse(test::quad_scene(c.size, c.wrap, c.filter, c.du, c.dv), "q.json", ".");
    cosim::RtlRenderOptions o;
    o.stall_prob = 0.3;
    const auto r = cosim::render_rtl(s, o);
    EXPECT_TRUE(r.ok()) << r.first_mismatch;
    EXPECT_GT(r.frame.pixels.size(), 500u);
    if (c.whole) {
      const auto plain = render::render_cmodel(scene::parse(test::quad_scene(c.size, c.wrap, c.filter, 0, 0), "q.json", "."));
      EXPECT_TRUE(plain.image.px == r.frame.image.px);
    }
    std::printf("%d %s %s shift (%g, %g): %zu px, %llu mismatches\n", c.size, c.wrap, c.filter, c.du, c.dv,
                r.frame.pixels.size(), (unsigned long long)r.mismatches);
  }
}

}  // namespace
