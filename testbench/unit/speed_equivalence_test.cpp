// The faster forms give the same bits as the forms they replace (docs/performance.md):
// visibility with per-triangle screen bounds and a prepared RayCaster against the plain
// every-triangle-every-pixel ray cast, and renders and vector files on several threads against
// one thread.
#include <gtest/gtest.h>

#include <limits>

#include "block.hpp"
#include "persp/persp.hpp"
#include "texunit/render.hpp"

namespace {
using namespace tu;

scene::Scene scene_file(const std::string& name) {
  return scene::load(std::string(TU_SOURCE_DIR) + "/docs/scenes/" + name);
}

// The visibility pass as it was: ray_hit (camera basis rebuilt per call) for every triangle at
// every pixel.
std::vector<render::Cover> visibility_plain(const scene::Scene& s) {
  const int w = s.camera.width, h = s.camera.height;
  std::vector<render::Cover> cov(static_cast<size_t>(w) * static_cast<size_t>(h));
  std::vector<double> depth(cov.size(), std::numeric_limits<double>::infinity());
  for (size_t o = 0; o < s.objects.size(); ++o)
    for (size_t t = 0; t < s.objects[o].triangles.size(); ++t)
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          persp::Hit hit;
          if (!persp::ray_hit(s.camera, s.objects[o].triangles[t], x, y, &hit)) continue;
          if (hit.s < 0 || hit.r < 0 || hit.s + hit.r > 1) continue;
          const size_t i = static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x);
          if (hit.dist < depth[i]) depth[i] = hit.dist, cov[i] = {static_cast<int>(o), static_cast<int>(t)};
        }
  return cov;
}

void expect_same_cover(const scene::Scene& s, const std::string& what) {
  const auto plain = visibility_plain(s);
  for (int threads : {1, 3}) {
    const auto fast = render::visibility(s, threads);
    ASSERT_EQ(fast.size(), plain.size());
    size_t covered = 0;
    for (size_t i = 0; i < plain.size(); ++i) {
      ASSERT_EQ(fast[i].object, plain[i].object) << what << " pixel " << i;
      ASSERT_EQ(fast[i].triangle, plain[i].triangle) << what << " pixel " << i;
      covered += plain[i].object >= 0;
    }
    EXPECT_GT(covered, 0u) << what;
  }
}

TEST(SpeedEquivalence, VisibilityEqualsPlainRayCast) {
  expect_same_cover(scene::default_scene(), "default");
  for (const char* f : {"corridor.json", "hud_floor.json", "ui_quad.json"}) expect_same_cover(scene_file(f), f);
  // The eye between the ground's vertices (a vertex behind the eye: no bounds, full scan) and a
  // camera looking along a wall (edge-on triangles).
  auto s = scene::default_scene();
  s.camera.pos[2] = -20;
  expect_same_cover(s, "eye inside the ground quad");
  s = scene::default_scene();
  s.camera.pos[0] = 2.5, s.camera.look_at[0] = 3.5, s.camera.look_at[2] = -40;
  expect_same_cover(s, "along the wall");
}

TEST(SpeedEquivalence, RayCasterEqualsRayHit) {
  const auto s = scene::default_scene();
  const persp::RayCaster rays(s.camera);
  for (const auto& o : s.objects)
    for (const auto& t : o.triangles)
      for (int y = 0; y < s.camera.height; y += 7)
        for (int x = 0; x < s.camera.width; x += 5) {
          persp::Hit a, b;
          const bool ha = persp::ray_hit(s.camera, t, x, y, &a), hb = rays.hit(t, x, y, &b);
          ASSERT_EQ(ha, hb);
          if (ha) {
            ASSERT_TRUE(a.s == b.s && a.r == b.r && a.dist == b.dist);
          }
        }
}

void expect_same_frame(const render::Frame& a, const render::Frame& b) {
  ASSERT_EQ(a.image.px.size(), b.image.px.size());
  for (size_t i = 0; i < a.image.px.size(); ++i) {
    const auto &p = a.image.px[i], &q = b.image.px[i];
    ASSERT_TRUE(p.r == q.r && p.g == q.g && p.b == q.b && p.a == q.a) << "image pixel " << i;
  }
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    const auto &p = a.pixels[i], &q = b.pixels[i];
    ASSERT_TRUE(p.x == q.x && p.y == q.y && p.object == q.object && p.u == q.u && p.v == q.v &&
                p.lod == q.lod && p.texels == q.texels && p.texels_inside == q.texels_inside &&
                p.b2_flags == q.b2_flags && p.ewa_flags == q.ewa_flags && p.levels == q.levels &&
                p.relief_n == q.relief_n && p.relief_steps == q.relief_steps &&
                p.tri_flags == q.tri_flags && p.relief_flags == q.relief_flags &&
                p.color.r == q.color.r && p.color.g == q.color.g && p.color.b == q.color.b &&
                p.color.a == q.color.a)
        << "record " << i;
  }
}

// The default scene at half size with its relief (rows of very different cost: the dynamic
// split hands them out unevenly) on 1, 2 and 5 threads.
TEST(SpeedEquivalence, RenderThreadsBitIdentical) {
  auto s = scene::default_scene();
  s.camera.width /= 2, s.camera.height /= 2;
  for (auto filter : {scene::Filter::Ewa, scene::Filter::Trilinear}) {
    render::CmodelOptions one;
    one.threads = 1;
    const auto base = render::render_cmodel(s, filter, one);
    for (int t : {2, 5}) {
      render::CmodelOptions many;
      many.threads = t;
      expect_same_frame(base, render::render_cmodel(s, filter, many));
    }
  }
}

// Vector generation (model and reference rows by chunks on several threads) writes the same file.
TEST(SpeedEquivalence, VectorsThreadsBitIdentical) {
  for (const auto& b : blocks::all())
    for (const auto& set : b.sets) {
      const auto one = blocks::generate(b, set, 1500, 9, 1);
      const auto many = blocks::generate(b, set, 1500, 9, 3);
      ASSERT_EQ(one.rows, many.rows) << b.name << " " << set;
    }
}

}  // namespace
