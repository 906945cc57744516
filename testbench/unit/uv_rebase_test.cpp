// uv rebase of B1's set-up (docs/blocks/persp.md "uv rebase", docs/scene-format.md "B1 set-up
// limits"): camera-facing quads whose uv lie up to 65,536 repeats from 0 on textures of 64, 256 and
// 4096 texels render in the C model (without the rebase, coefficient C overflowed s54.40 from
// |u| >= 8192 texels on), bit-identical to the unshifted quad for a shift by whole periods and as
// close to the float reference as the unshifted quad otherwise; what cannot be rebased (clamp,
// border, mirror_once; a far triangle on a large texture) is refused in every engine with the
// reason.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "persp/persp.hpp"
#include "uv_rebase_scene.hpp"
#include "texunit/render.hpp"
#include "texunit/scene.hpp"

namespace {
using namespace tu;
using tu::test::num;
using tu::test::quad_scene;

scene::Scene parse(const std::string& j) { return scene::parse(j, "q.json", "."); }

bool same_image(const render::Frame& a, const render::Frame& b) {
  return a.image.width == b.image.width && a.image.height == b.image.height && a.image.px == b.image.px;
}

TEST(UvRebase, OffsetIsWholePeriodsNearTheMidRangeAndZeroBelowTheLimit) {
  persp::Triangle t;
  auto set = [&](double u0, double u1, double u2) {
    t.v[0].uv[0] = u0, t.v[1].uv[0] = u1, t.v[2].uv[0] = u2;
    t.v[0].uv[1] = t.v[1].uv[1] = t.v[2].uv[1] = 0;
  };
  set(0, 8191, 100);  // below 2^13 texels: kept as given
  EXPECT_EQ(persp::rebase_offset(t, {64, 64})[0], 0);
  set(8192, 8256, 8200);  // mid 8224 = 128.5 periods of 64: halves down
  EXPECT_EQ(persp::rebase_offset(t, {64, 64})[0], 8192);
  EXPECT_EQ(persp::rebase_offset(t, {0, 64})[0], 0);  // no period: never rebased
  set(-65536 * 4096.0, -65535 * 4096.0, -65536 * 4096.0);
  EXPECT_EQ(persp::rebase_offset(t, {4096, 4096})[0], -65536 * 4096.0);
  EXPECT_EQ(persp::rebased(t, {4096, 4096}).v[1].uv[0], 4096);
  EXPECT_EQ(persp::rebase_offset(t, {8192, 8192})[0], -65536 * 4096.0);  // mirror: 2 sides
  // Shift-invariance: uv + j periods gives the same rebased triangle.
  set(10000.25, 10100.5, 10050);
  const auto a = persp::rebased(t, {256, 256});
  set(10000.25 + 256 * 7, 10100.5 + 256 * 7, 10050 + 256 * 7);
  const auto b = persp::rebased(t, {256, 256});
  for (int i = 0; i < 3; ++i) EXPECT_EQ(a.v[i].uv[0], b.v[i].uv[0]);
}

// Whole-period shifts (repeat: any integer number of repeats; mirror: an even number), u and v,
// positive and negative, up to the validated 65,536 repeats: the C model renders the unshifted
// quad's image bit for bit (the rebased triangle is the unshifted one).
TEST(UvRebase, WholePeriodShiftsRenderTheUnshiftedImageBitForBit) {
  struct Case {
    int size;
    const char* wrap;
    double du, dv;
  };
  const Case cases[] = {{64, "repeat", 128, -128},     {64, "repeat", 65535, -65536}, {64, "mirror", 1000, 65534},
                        {256, "repeat", 32, 33},        {256, "mirror", -65536, 32},   {256, "repeat", -40000, 12345},
                        {4096, "repeat", 2, -3},        {4096, "mirror", 65534, -2},   {4096, "repeat", -65536, 65535}};
  for (const char* filter : {"bilinear", "trilinear", "ewa"})
    for (const Case& c : cases) {
      if (c.size == 4096 && std::string(filter) != "ewa") continue;  // one filter on the large texture (time)
      SCOPED_TRACE(std::to_string(c.size) + " " + c.wrap + " " + filter + " shift " + num(c.du) + ", " + num(c.dv));
      const auto plain = render::render_cmodel(parse(quad_scene(c.size, c.wrap, filter, 0, 0)));
      const auto shifted = render::render_cmodel(parse(quad_scene(c.size, c.wrap, filter, c.du, c.dv)));
      EXPECT_GT(plain.pixels.size(), 500u);
      EXPECT_TRUE(same_image(plain, shifted));
    }
}

// Shifts by a fraction of a period (and odd repeats on mirror): the rebased triangle differs from
// the unshifted one by whole periods, so the C model's error against the float reference (which
// renders uv as given) is the unshifted quad's: PSNR equal within 0.01 dB.
TEST(UvRebase, OtherShiftsKeepThePsnrAgainstTheFloatReference) {
  struct Case {
    int size;
    const char* wrap;
    double base, shift;  // uv [base, base + 1]: the reference quad; + shift whole repeats
  };
  const Case cases[] = {{64, "repeat", 0.25, 1000},   {256, "repeat", 0.375, -50000}, {4096, "repeat", 0.5, 3},
                        {64, "mirror", 0.125, 60001}, {256, "mirror", 0, -33},       {4096, "mirror", 0.75, 1}};
  for (const Case& c : cases) {
    SCOPED_TRACE(std::to_string(c.size) + " " + c.wrap + " base " + num(c.base) + " shift " + num(c.shift));
    const auto s0 = parse(quad_scene(c.size, c.wrap, "ewa", c.base, c.base));
    const auto s1 = parse(quad_scene(c.size, c.wrap, "ewa", c.base + c.shift, c.base + c.shift));
    const double p0 = render::psnr_covered(render::render_cmodel(s0), render::render_ref(s0));
    const double p1 = render::psnr_covered(render::render_cmodel(s1), render::render_ref(s1));
    std::printf("%4d %-6s base %.3f shift %7.0f: PSNR %.4f / %.4f dB\n", c.size, c.wrap, c.base, c.shift, p0, p1);
    EXPECT_GT(p0, 30);
    EXPECT_NEAR(p1, p0, 0.01);
  }
}

// Clamp, border and mirror_once are not periodic: a quad within B1's range renders in every
// engine; one whose |u| reaches 2^13 texels is refused by every engine, naming the object, the
// triangle and the reason.
TEST(UvRebase, NonPeriodicWrapModesBeyondTheRangeAreRefusedInEveryEngine) {
  for (const char* wrap : {"clamp", "border", "mirror_once"})
    for (int size : {64, 256, 4096}) {
      SCOPED_TRACE(std::string(wrap) + " " + std::to_string(size));
      const double ok = 7000.0 / size - 1, bad = 8192.0 / size;  // repeats: u up to 7000 texels; from 8192 texels
      const auto s_ok = parse(quad_scene(size, wrap, "ewa", ok, 0));
      EXPECT_GT(render::render_cmodel(s_ok).pixels.size(), 500u);
      EXPECT_GT(render::render_ref(s_ok).pixels.size(), 500u);
      const auto s_bad = parse(quad_scene(size, wrap, "ewa", bad, 0));
      for (int engine = 0; engine < 3; ++engine) {
        try {
          engine == 0 ? (void)render::render_ref(s_bad) : engine == 1 ? (void)render::render_cmodel(s_bad)
                                                                      : (void)render::render_truth(s_bad, {.ss = 1});
          ADD_FAILURE() << "engine " << engine << " accepted |u| >= 8192 texels on " << wrap;
        } catch (const persp::SetupError& e) {
          const std::string m = e.what();
          EXPECT_EQ(m.rfind("q.json: object 'q' (/objects/0): persp set-up: triangle 'q#", 0), 0u) << m;
          EXPECT_NE(m.find("wrap mode '" + std::string(wrap) + "' is not periodic"), std::string::npos) << m;
          EXPECT_NE(m.find("keep |u| x the texture's size below 8192 texels"), std::string::npos) << m;
        }
      }
    }
}

// A far, small quad on a 4096-texel texture with uv in [0, 1]: B1's map is evaluated from pixel
// (0, 0), so p_u there (coefficient C) is the map extrapolated over the quad's distance from the
// screen origin at thousands of texels per pixel; no rebase helps (the quad's own uv range is
// the problem). Refused in every engine with that reason; the same quad on 256 texels renders.
TEST(UvRebase, FarTriangleOnALargeTextureIsRefusedWithTheReason) {
  // 3 x 3 world units at depth 40, right of and below the screen centre: ~2 px wide at pixel (37, 26).
  auto far = [](int size) { return parse(quad_scene(size, "repeat", "ewa", 0, 0, 40, 18, 21, -16, -13, 1)); };
  for (int engine = 0; engine < 3; ++engine) {
    try {
      const auto s = far(4096);
      engine == 0 ? (void)render::render_ref(s) : engine == 1 ? (void)render::render_cmodel(s) : (void)render::render_truth(s, {.ss = 1});
      ADD_FAILURE() << "engine " << engine << " accepted the far quad";
    } catch (const persp::SetupError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find("coefficient C"), std::string::npos) << m;
      EXPECT_NE(m.find("B1 evaluates the map from pixel (0, 0) of the screen"), std::string::npos) << m;
    }
  }
  EXPECT_GT(render::render_cmodel(far(256)).pixels.size(), 0u);
}

}  // namespace
