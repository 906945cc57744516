// Relief stage of the texture unit (rtl/pom/tu_relief_stage.sv) against the C model's per-pixel
// step relief::shift_texel_uv_fx: 0 mismatches (u, v, layers, steps, flags) with 30 % stalls and
// view bubbles on (a) every covered pixel of the default scene (wall: relief, ground: none) with
// pom_fixed / pom_adaptive / iterative and 8 / 32 layers, (b) seeded random pixels with extremes,
// POM and iterative mixed; stream cycles without stalls equal relief::stage_cycles; non-relief
// pixels stream at 1 pixel / clock; (c) distance-map pixels (tu_dm_trace): the default scene's
// wall and seeded random pixels with extremes, mixed with POM and iterative ones.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <tuple>

#include "distmap/distance_map.hpp"
#include "pom/relief.hpp"
#include "relief_stage_rtl.hpp"
#include "texture/texture.hpp"
#include "texunit/render.hpp"
#include "texunit/scene.hpp"

namespace {
using namespace tu;
using cosim::ReliefPixel;

// Depth maps in the RAM model, one after another, each followed by its distance map if it has one.
struct Bank {
  std::vector<relief::Maps> maps;
  std::vector<uint32_t> base, dbase;
  std::vector<uint32_t> ram;
  int add(const img::Gray8& height) { return add(relief::make_maps(height)); }
  // With the distance map of `height` (classic or refined) for relief scale `scale`.
  int add_dm(const img::Gray8& height, int layers, double scale, bool refined) {
    relief::Maps m = relief::make_maps(height);
    dm::Params p;
    p.layers = layers;
    p.scale = scale;
    p.refined = refined;
    m.dist = std::make_shared<const dm::Map>(dm::build(m.depth, p));
    return add(std::move(m));
  }
  int add(relief::Maps m) {
    maps.push_back(std::move(m));
    base.push_back(static_cast<uint32_t>(ram.size()));
    for (uint8_t d : maps.back().depth.px) ram.push_back(d);
    dbase.push_back(static_cast<uint32_t>(ram.size()));
    if (maps.back().dist)
      for (uint8_t c : maps.back().dist->code) ram.push_back(c);
    return static_cast<int>(maps.size()) - 1;
  }
  void place(ReliefPixel* p, int m) const {
    const auto& mm = maps[static_cast<size_t>(m)];
    p->hbase = base[static_cast<size_t>(m)];
    p->hlw = std::countr_zero(static_cast<unsigned>(mm.depth.width));
    p->hlh = std::countr_zero(static_cast<unsigned>(mm.depth.height));
    p->dbase = dbase[static_cast<size_t>(m)];
    p->dlayers = mm.dist ? mm.dist->layers : 0;
  }
};

img::Gray8 noise(int w, int h, std::mt19937_64& rng) {
  img::Gray8 g(w, h);
  for (auto& p : g.px) p = static_cast<uint8_t>(rng());
  return g;
}

// The C model's answer for one pixel (and its march steps, for the cycle estimator).
struct Expect {
  int64_t u, v;
  uint32_t n, steps, flags;
  bool shift;
};
relief::Method method_of(const ReliefPixel& p) {
  return p.dm     ? relief::Method::DistanceMap
         : p.iter ? relief::Method::Iterative
         : p.adaptive ? relief::Method::PomAdaptive
                      : relief::Method::PomFixed;
}
Expect expect(const Bank& b, int map, const ReliefPixel& p) {
  if (!(p.rel && !p.guard && p.ok)) return {p.u, p.v, 0, 0, 0, false};
  pom::View w = p.view;
  w.scale = p.scale;
  const auto r = relief::shift_texel_uv_fx(b.maps[static_cast<size_t>(map)], p.u, p.v, p.lw, p.lh, w, method_of(p),
                                           p.layers);
  return {r.u, r.v, r.n, r.steps, r.flags, true};
}
relief::StagePixel stage_pixel(const Expect& e, const ReliefPixel& p) {
  return relief::stage_pixel(e.shift, e.steps, method_of(p));
}
const char* method_name(relief::Method m) { return scene::to_string(m); }

// The complexity texel the shader samples at the unshifted uv (relief::layers_at).
uint32_t complexity_at(const relief::Maps& m, const ReliefPixel& p) {
  const int du = fmt::kPomUvF - fmt::kTexUvF;
  return pom::tex_nearest(m.complexity, relief::shift_code(p.u, du - p.lw), relief::shift_code(p.v, du - p.lh));
}

// A random view: a unit vector, grazing (|vz| tiny), behind (vz < 0), straight on, or any.
pom::View random_view(std::mt19937_64& rng, std::uniform_real_distribution<double>& uni,
                      std::uniform_int_distribution<int>& pct) {
  double x = uni(rng), y = uni(rng), z = uni(rng);
  const int vk = pct(rng);
  if (vk < 15) z = uni(rng) * 0.02;  // grazing, either side
  else if (vk < 25) z = -std::fabs(z);
  else if (vk < 30) x = y = 0, z = 1;
  else z = std::fabs(z);
  relief::TangentView tv;
  const double l = std::sqrt(x * x + y * y + z * z);
  if (l > 1e-9) tv = {x / l, y / l, z / l};
  return relief::quantise(tv, 0);
}

struct Checked {
  uint64_t mismatches = 0;
  std::string first;
  cosim::ReliefRun run;
};
Checked check(const Bank& b, const std::vector<int>& maps, const std::vector<ReliefPixel>& px,
              double stall, uint64_t seed) {
  Checked c;
  c.run = cosim::run_relief_stage(px, b.ram, stall, stall, seed);
  EXPECT_FALSE(c.run.hung);
  EXPECT_EQ(c.run.extra_outputs, 0u);
  EXPECT_EQ(c.run.out.size(), px.size());
  for (size_t i = 0; i < c.run.out.size() && i < px.size(); ++i) {
    const auto e = expect(b, maps[i], px[i]);
    const auto& o = c.run.out[i];
    EXPECT_TRUE(e.u == static_cast<int32_t>(e.u) && e.v == static_cast<int32_t>(e.v))
        << "C-model result outside PerspUvW, pixel " << i;
    if (o.u != e.u || o.v != e.v || o.n != e.n || o.steps != e.steps || o.flags != e.flags ||
        o.index != (i & 0xfffff)) {
      if (!c.mismatches++) {
        char buf[320];
        std::snprintf(buf, sizeof buf,
                      "pixel %zu (%s): rtl (%lld, %lld, n %u, steps %u, flags %u, #%u) c-model (%lld, %lld, n %u, "
                      "steps %u, flags %u)",
                      i, method_name(method_of(px[i])), static_cast<long long>(o.u), static_cast<long long>(o.v), o.n,
                      o.steps, o.flags, o.index, static_cast<long long>(e.u), static_cast<long long>(e.v), e.n, e.steps,
                      e.flags);
        c.first = buf;
      }
    }
  }
  return c;
}

// (a) The default scene: every covered pixel in raster order, B1 codes as render_cmodel computes
// them (its uv_shift hook with relief off sees the unshifted codes), the wall with relief.
struct ScenePixels {
  std::vector<ReliefPixel> px;
  std::vector<int> maps;
};
ScenePixels scene_pixels(Bank& b, relief::Method method, int layers) {
  auto s = scene::default_scene();
  const auto cov = render::visibility(s);
  int wall = -1;
  for (size_t o = 0; o < s.objects.size(); ++o)
    if (s.materials.at(s.objects[o].material).relief) wall = static_cast<int>(o);
  const auto& wall_mat = s.objects[static_cast<size_t>(wall)].material;
  auto& mat = s.materials.at(wall_mat);
  mat.relief->method = method;  // distance maps: make_maps builds the map
  const int map = b.add(relief::make_maps(s, wall_mat));  // as render_cmodel
  std::vector<std::pair<int, int>> log2s;  // colour texture level 0 per object
  for (const auto& ob : s.objects) {
    const auto tx = scene::build_texture(s, s.materials.at(ob.material).texture);
    log2s.emplace_back(std::countr_zero(static_cast<unsigned>(tx.levels[0].width)),
                       std::countr_zero(static_cast<unsigned>(tx.levels[0].height)));
  }
  ScenePixels sp;
  render::CmodelOptions opt = render::texture_path_only();
  opt.uv_shift = [&](int x, int y, int object, int64_t* u, int64_t* v) {
    ReliefPixel p;
    p.u = *u;
    p.v = *v;
    std::tie(p.lw, p.lh) = log2s[static_cast<size_t>(object)];
    p.rel = object == wall;
    if (p.rel) {
      const auto c = cov[static_cast<size_t>(y) * static_cast<size_t>(s.camera.width) + static_cast<size_t>(x)];
      relief::TangentView tv;
      p.ok = relief::pixel_view(s, c.object, c.triangle, x, y, &tv);
      const auto q = relief::quantise(tv, mat.relief->scale);
      p.view = q;
      p.scale = q.scale;
      p.adaptive = method == relief::Method::PomAdaptive;
      p.iter = method == relief::Method::Iterative;
      p.dm = method == relief::Method::DistanceMap;
      p.layers = p.dm ? static_cast<int>(relief::dm_cap(layers)) : layers;
      b.place(&p, map);
      p.vc = complexity_at(b.maps[static_cast<size_t>(map)], p);
    }
    sp.px.push_back(p);
    sp.maps.push_back(map);
  };
  render::render_cmodel(s, scene::Filter::Nearest, opt);
  return sp;
}

TEST(ReliefStageCosim, DefaultSceneEveryPixelWithStalls) {
  for (auto method : {relief::Method::PomFixed, relief::Method::PomAdaptive, relief::Method::Iterative})
    for (int layers : {8, 32}) {
      Bank b;
      const auto sp = scene_pixels(b, method, layers);
      size_t shifted = 0, wall = 0, moved = 0, nonconv = 0;
      for (size_t i = 0; i < sp.px.size(); ++i) {
        const auto e = expect(b, sp.maps[i], sp.px[i]);
        wall += sp.px[i].rel;
        shifted += e.shift;
        moved += e.u != sp.px[i].u || e.v != sp.px[i].v;
        nonconv += (e.flags & relief::kReliefNonConv) != 0;
      }
      const auto c = check(b, sp.maps, sp.px, 0.3, 11);
      std::printf("scene %s %d layers: %zu pixels, %zu wall, %zu shifted, %zu moved, %zu non-converged, %llu cycles "
                  "(30%% stalls)\n",
                  method_name(method), layers, sp.px.size(), wall, shifted, moved, nonconv,
                  static_cast<unsigned long long>(c.run.cycles));
      if (method == relief::Method::Iterative) EXPECT_GT(nonconv, 0u);  // the flag is exercised
      EXPECT_GT(moved, 5000u);
      EXPECT_EQ(c.mismatches, 0u) << c.first;
    }
}

// (b) Seeded random pixels and extremes.
TEST(ReliefStageCosim, RandomAndExtremesWithStalls) {
  std::mt19937_64 rng(2026);
  Bank b;
  const int flat0 = b.add(img::Gray8(4, 4, 255));  // height 255: depth 0 everywhere
  const int flat255 = b.add(img::Gray8(8, 2, 0));  // height 0: depth 255 everywhere
  const int br64 = b.add(tex::bricks(64).height);
  const int br256 = b.add(tex::bricks(256).height);
  const int noise1 = b.add(noise(32, 16, rng));
  const int noise2 = b.add(noise(1, 64, rng));
  const int all[] = {flat0, flat255, br64, br256, noise1, noise2};
  std::uniform_int_distribution<int> pick(0, 5), lw(0, 10), pct(0, 99), layers(1, 63);
  std::uniform_real_distribution<double> uni(-1, 1);
  std::vector<ReliefPixel> px;
  std::vector<int> maps;
  const int64_t ext[] = {std::numeric_limits<int32_t>::min(), std::numeric_limits<int32_t>::max(), 0, -1, 1,
                         255, 256, -256, 65535, -65536};
  auto code = [&]() -> int64_t {
    const int k = pct(rng);
    if (k < 10) return ext[static_cast<size_t>(pct(rng)) % std::size(ext)];
    if (k < 40) return static_cast<int32_t>(rng());                     // any, negative and large
    return static_cast<int64_t>(uni(rng) * 4096 * 256);                 // within +-16 repeats of 256
  };
  for (int i = 0; i < 4000; ++i) {
    ReliefPixel p;
    const int m = all[pick(rng)];
    p.u = code();
    p.v = code();
    p.lw = pct(rng) < 4 ? 15 : lw(rng);  // 15: the widest the 4-bit port takes
    p.lh = pct(rng) < 20 ? p.lw : lw(rng);
    p.rel = pct(rng) < 75;
    p.guard = pct(rng) < 8;
    p.ok = pct(rng) < 90;
    p.adaptive = pct(rng) < 50;
    p.iter = pct(rng) < 35;  // POM and iterative pixels mixed: the engines hand the depth port over
    const int lk = pct(rng);
    p.layers = lk < 10 ? 1 : lk < 20 ? 63 : layers(rng);
    const int sk = pct(rng);
    p.scale = sk < 5 ? 0 : sk < 10 ? 65535 : static_cast<uint32_t>(pct(rng) * 655);
    p.view = random_view(rng, uni, pct);
    b.place(&p, m);
    p.vc = complexity_at(b.maps[static_cast<size_t>(m)], p);
    px.push_back(p);
    maps.push_back(m);
  }
  size_t shifted = 0, moved = 0, iter = 0, nonconv = 0;
  std::vector<relief::StagePixel> sched;
  for (size_t i = 0; i < px.size(); ++i) {
    const auto e = expect(b, maps[i], px[i]);
    shifted += e.shift;
    iter += e.shift && px[i].iter;
    nonconv += (e.flags & relief::kReliefNonConv) != 0;
    moved += e.u != px[i].u || e.v != px[i].v;
    sched.push_back(stage_pixel(e, px[i]));
  }
  const auto c = check(b, maps, px, 0.3, 5);
  std::printf("random: %zu pixels, %zu shifted (%zu iterative, %zu non-converged), %zu moved, %llu cycles (30%% "
              "stalls, 30%% view bubbles)\n",
              px.size(), shifted, iter, nonconv, moved, static_cast<unsigned long long>(c.run.cycles));
  EXPECT_GT(moved, px.size() / 4);
  EXPECT_GT(nonconv, 0u);
  EXPECT_EQ(c.mismatches, 0u) << c.first;
  // The same mixed stream without stalls: cycles = the estimator (method switches included).
  const auto c0 = check(b, maps, px, 0, 5);
  EXPECT_EQ(c0.mismatches, 0u) << c0.first;
  EXPECT_EQ(c0.run.cycles, relief::stage_cycles(sched));
  std::printf("random, no stalls: %llu cycles measured, %llu predicted\n", static_cast<unsigned long long>(c0.run.cycles),
              static_cast<unsigned long long>(relief::stage_cycles(sched)));
}

// Stream cycles without stalls = relief::stage_cycles, on the scene stream and a mixed stream.
TEST(ReliefStageCosim, StreamCyclesMatchTheEstimator) {
  for (auto method : {relief::Method::PomFixed, relief::Method::PomAdaptive, relief::Method::Iterative}) {
    Bank b;
    const auto sp = scene_pixels(b, method, method == relief::Method::PomAdaptive ? 32 : 8);
    std::vector<relief::StagePixel> sched;
    uint64_t shifted = 0, steps = 0;
    for (size_t i = 0; i < sp.px.size(); ++i) {
      const auto e = expect(b, sp.maps[i], sp.px[i]);
      sched.push_back(stage_pixel(e, sp.px[i]));
      shifted += e.shift;
      steps += e.steps;
    }
    const auto c = check(b, sp.maps, sp.px, 0, 1);
    EXPECT_EQ(c.mismatches, 0u) << c.first;
    const uint64_t predicted = relief::stage_cycles(sched);
    std::printf("scene stream %s: %zu pixels (%llu shifted, %.3f steps each), cycles measured %llu, "
                "predicted %llu, sum(k + 1) over shifted %llu\n",
                method_name(method), sp.px.size(),
                static_cast<unsigned long long>(shifted), double(steps) / double(shifted),
                static_cast<unsigned long long>(c.run.cycles), static_cast<unsigned long long>(predicted),
                static_cast<unsigned long long>(steps + shifted));
    EXPECT_EQ(c.run.cycles, predicted);
  }
}

// Non-relief pixels stream at 1 pixel / clock; a relief pixel between them delays only the ones
// behind it (order), and the estimator follows both.
TEST(ReliefStageCosim, NonReliefPixelsAtOnePerClock) {
  Bank b;
  const int m = b.add(tex::bricks(64).height);
  std::vector<ReliefPixel> px(500);
  std::vector<int> maps(px.size(), m);
  for (size_t i = 0; i < px.size(); ++i) {
    px[i].u = static_cast<int64_t>(i) * 77;
    px[i].lw = px[i].lh = 8;
    b.place(&px[i], m);
  }
  auto cycles = [&](const std::vector<ReliefPixel>& p) {
    const auto c = check(b, maps, p, 0, 3);
    EXPECT_EQ(c.mismatches, 0u) << c.first;
    std::vector<relief::StagePixel> sched;
    for (size_t i = 0; i < p.size(); ++i) {
      const auto e = expect(b, maps[i], p[i]);
      sched.push_back(stage_pixel(e, p[i]));
    }
    EXPECT_EQ(c.run.cycles, relief::stage_cycles(sched));
    return c.run.cycles;
  };
  EXPECT_EQ(cycles(px), px.size() + 1);  // first output one cycle after its input
  px[100].rel = true;
  px[100].layers = 63;
  px[100].scale = 65535;
  px[100].view = relief::quantise({0.7, 0.1, 0.7}, 0);
  px[100].u = 3 << 8;  // mortar column: the march runs
  const auto e = expect(b, m, px[100]);
  ASSERT_GT(e.steps, 0u);
  EXPECT_GT(cycles(px), px.size() + 1);
  // One shifted pixel alone: accepted in cycle 0, out in cycle stage_cycles - 1.
  std::vector<ReliefPixel> one = {px[100]};
  std::printf("one shifted pixel, %u march steps: output in cycle %llu (plain pixel: cycle 1)\n", e.steps,
              static_cast<unsigned long long>(cycles(one) - 1));
}

// (c) Distance maps: the default scene's wall traced through its 256 x 256 x 16 classic map, with
// 30 % stalls and view bubbles, then without stalls: cycles = relief::stage_cycles.
TEST(ReliefStageCosim, DistanceMapSceneWithStallsAndCycles) {
  Bank b;
  const auto sp = scene_pixels(b, relief::Method::DistanceMap, 32);
  size_t shifted = 0, moved = 0;
  uint64_t steps = 0;
  std::vector<relief::StagePixel> sched;
  for (size_t i = 0; i < sp.px.size(); ++i) {
    const auto e = expect(b, sp.maps[i], sp.px[i]);
    shifted += e.shift;
    steps += e.steps;
    moved += e.u != sp.px[i].u || e.v != sp.px[i].v;
    sched.push_back(stage_pixel(e, sp.px[i]));
  }
  const auto c = check(b, sp.maps, sp.px, 0.3, 13);
  EXPECT_EQ(c.mismatches, 0u) << c.first;
  EXPECT_GT(moved, 5000u);
  const auto c0 = check(b, sp.maps, sp.px, 0, 1);
  EXPECT_EQ(c0.mismatches, 0u) << c0.first;
  const uint64_t predicted = relief::stage_cycles(sched);
  EXPECT_EQ(c0.run.cycles, predicted);
  std::printf("scene distance_map cap 32: %zu pixels, %zu shifted (%.3f map steps + finish reads each), %zu moved; "
              "%llu cycles with 30%% stalls; no stalls: %llu measured, %llu predicted\n",
              sp.px.size(), shifted, double(steps) / double(shifted), moved,
              static_cast<unsigned long long>(c.run.cycles), static_cast<unsigned long long>(c0.run.cycles),
              static_cast<unsigned long long>(predicted));
}

// Seeded random distance-map pixels with extremes (grazing, behind, straight and zero views; caps
// 1 and DmCapMax; flat maps that stop at once or reach the bottom; 1 and 255 map layers; a
// refined map), mixed with POM and iterative pixels that share the depth port. TU_DM_RANDOM=N
// runs N pixels instead of 3,000 (the 1,000,000-pixel run of docs/blocks/relief-appendix.md §13.8).
TEST(ReliefStageCosim, DistanceMapRandomAndExtremesWithStalls) {
  const char* count_env = std::getenv("TU_DM_RANDOM");
  const int count = count_env ? std::max(1, std::atoi(count_env)) : 3000;
  std::mt19937_64 rng(2027);
  Bank b;
  struct DmMap {
    int map;
    uint32_t scale;
  };
  std::vector<DmMap> dms;
  auto add = [&](const img::Gray8& h, int layers, double scale, bool refined) {
    dms.push_back({b.add_dm(h, layers, scale, refined), relief::quantise({}, scale).scale});
  };
  add(img::Gray8(4, 4, 255), 4, 0.5, false);         // depth 0: the surface at the top
  add(img::Gray8(8, 8, 0), 3, 0.25, false);          // depth 255: every ray reaches the bottom
  add(tex::bricks(64).height, 16, 0.05, false);
  add(tex::bricks(32).height, 1, 0.125, false);      // one layer
  add(noise(16, 16, rng), 255, 0.25, false);         // 255 layers
  add(tex::bricks(16).height, 8, 0.25, true);        // refined
  add(noise(32, 32, rng), 16, 0.1, false);
  const int pom_map = b.add(tex::bricks(64).height);
  std::uniform_int_distribution<int> pct(0, 99), layers(1, 63);
  std::uniform_real_distribution<double> uni(-1, 1);
  std::vector<ReliefPixel> px;
  std::vector<int> maps;
  for (int i = 0; i < count; ++i) {
    ReliefPixel p;
    p.u = static_cast<int32_t>(rng());
    p.v = pct(rng) < 10 ? std::numeric_limits<int32_t>::min() : static_cast<int32_t>(rng());
    p.lw = pct(rng) % 11;
    p.lh = pct(rng) < 50 ? p.lw : pct(rng) % 11;
    p.rel = pct(rng) < 85;
    p.guard = pct(rng) < 5;
    p.ok = pct(rng) < 95;
    const int kind = pct(rng);
    p.dm = kind < 60;
    p.iter = !p.dm && kind < 75;
    p.adaptive = !p.dm && !p.iter && pct(rng) < 50;
    const int lk = pct(rng);
    p.layers = lk < 10 ? 1 : lk < 20 ? 63 : layers(rng);
    int m = pom_map;
    if (p.dm) {
      const auto& d = dms[static_cast<size_t>(pct(rng)) % dms.size()];
      m = d.map;
      p.scale = d.scale;
      p.layers = static_cast<int>(relief::dm_cap(p.layers));
    } else {
      p.scale = static_cast<uint32_t>(pct(rng) * 655);
    }
    p.view = random_view(rng, uni, pct);
    if (pct(rng) < 2) p.view.vx = p.view.vy = p.view.vz = 0;  // V = 0: clamped, no shift
    b.place(&p, m);
    p.vc = complexity_at(b.maps[static_cast<size_t>(m)], p);
    px.push_back(p);
    maps.push_back(m);
  }
  size_t dm_px = 0, moved = 0, guard = 0, capped = 0;
  std::vector<relief::StagePixel> sched;
  for (size_t i = 0; i < px.size(); ++i) {
    const auto e = expect(b, maps[i], px[i]);
    dm_px += e.shift && px[i].dm;
    moved += e.shift && px[i].dm && (e.u != px[i].u || e.v != px[i].v);
    guard += e.shift && px[i].dm && (e.flags & relief::kReliefVzGuard) != 0;
    capped += e.shift && px[i].dm && px[i].layers == 1;
    sched.push_back(stage_pixel(e, px[i]));
  }
  EXPECT_GT(dm_px, static_cast<size_t>(count) / 3);
  EXPECT_GT(moved, static_cast<size_t>(count) / 10);
  EXPECT_GT(guard, static_cast<size_t>(count) / 60);
  const auto c = check(b, maps, px, 0.3, 7);
  EXPECT_EQ(c.mismatches, 0u) << c.first;
  const auto c0 = check(b, maps, px, 0, 7);
  EXPECT_EQ(c0.mismatches, 0u) << c0.first;
  EXPECT_EQ(c0.run.cycles, relief::stage_cycles(sched));
  std::printf("distance-map random: %zu pixels, %zu traced (%zu moved, %zu Vz guard, %zu cap 1), %llu cycles (30%% "
              "stalls); no stalls %llu measured, %llu predicted\n",
              px.size(), dm_px, moved, guard, capped, static_cast<unsigned long long>(c.run.cycles),
              static_cast<unsigned long long>(c0.run.cycles),
              static_cast<unsigned long long>(relief::stage_cycles(sched)));
}
}  // namespace
