// AF with parallax visibility (cmodel/blocks/afvis, docs/blocks/afvis.md): the per-texel trace
// against the same trace in exact arithmetic (exhaustive grid), against the ideal unquantised trace
// and the bilinear field, the row rule, the renormalisation and its fallback, the stiff cases
// (grazing 85-89 deg, flat map = the plain walk bit for bit, cliff, a pixel with no visible texel)
// and the declared widths.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <random>

#include "afvis/afvis.hpp"
#include "afvis/afvis_quality.hpp"
#include "afvis/afvis_ref.hpp"
#include "afvis_block.hpp"
#include "ewa/ewa_fx.hpp"
#include "ewa_walk_checks.hpp"
#include "gauss/clip.hpp"
#include "pom/pom_march.hpp"
#include "pom/relief_quality.hpp"
#include "texunit/render.hpp"
#include "texunit/scene.hpp"

namespace {
using namespace tu;
namespace efx = ewa::fx;

const tex::Texture& bricks() { return test::bricks_texture(); }

// The unit's view (s16.14, S u0.16) at `angle` degrees from the normal, azimuth `az` degrees.
pom::View view_at(double angle, double az, double scale) {
  const double th = angle * M_PI / 180, ph = az * M_PI / 180;
  pom::View v;
  v.vx = static_cast<int32_t>(std::lround(std::sin(th) * std::cos(ph) * (1 << fmt::kPomVzF)));
  v.vy = static_cast<int32_t>(std::lround(std::sin(th) * std::sin(ph) * (1 << fmt::kPomVzF)));
  v.vz = static_cast<int32_t>(std::lround(std::cos(th) * (1 << fmt::kPomVzF)));
  v.scale = static_cast<uint32_t>(std::lround(scale * (1 << fmt::kPomSF)));
  return v;
}

afvis::Relief relief_of(const img::Gray8& depth, const pom::View& v) {
  const pom::Parallax p = pom::parallax(v);
  afvis::Relief r;
  r.depth = &depth;
  r.dmin = afvis::min_depth(depth);
  r.pu = p.pu, r.pv = p.pv;
  r.lw = 8, r.lh = 8;  // bricks(): 256 x 256
  return r;
}

double code_to_uv(int64_t c) { return std::ldexp(double(c), -fmt::kPomUvF); }

// A curated pixel: major semi-axis `major` level-0 texels, anisotropy, angle, centre (texels).
efx::In pixel(double major, double aniso, double theta, double u, double v) {
  return efx::in_from_local(efx::footprint_local(major, aniso, theta, u, v));
}

void expect_same(const efx::Out& a, const efx::Out& b) { test::expect_same_walk(a, b); }

// Exhaustive on a grid: every surface point at 1/8 cell on three 8 x 8 maps (a cliff, random
// codes, steps) x 32 directions x 4 lengths of P: the integer trace equals the same DDA in double
// on the same codes (visibility and steps), except where the double trace has a tie within 1e-6
// depth codes (the integer test is exact there; double rounding is not).
TEST(AfvisFx, TraceEqualsTheDoubleTraceOnTheSameCodes) {
  std::vector<img::Gray8> maps;
  img::Gray8 cliff(8, 8, 255);
  for (int y = 0; y < 8; ++y)
    for (int x = 4; x < 8; ++x) cliff.at(x, y) = 0;
  maps.push_back(cliff);
  std::mt19937_64 rng(16);
  img::Gray8 rnd(8, 8);
  for (auto& c : rnd.px) c = static_cast<uint8_t>(rng() % 256);
  maps.push_back(rnd);
  img::Gray8 steps(8, 8);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) steps.at(x, y) = static_cast<uint8_t>(((x + 2 * y) % 5) * 60);
  maps.push_back(steps);
  uint64_t n = 0, ties = 0, occluded = 0, capped = 0;
  for (const auto& m : maps) {
    const uint8_t dmin = afvis::min_depth(m);
    for (int py = 0; py < 64; ++py)
      for (int px = 0; px < 64; ++px) {
        const int64_t u = int64_t(px) << (fmt::kPomUvF - 6), v = int64_t(py) << (fmt::kPomUvF - 6);
        const uint8_t d0 = pom::tex_nearest(m, u, v);
        for (int dir = 0; dir < 32; ++dir)
          for (int len = 0; len < 4; ++len) {
            const double r = std::ldexp(0.03, 2 * len), a = dir * 2 * M_PI / 32;  // incl. the axes (Pu or Pv = 0) and the diagonals (corner ties)
            const int64_t pu = std::llround(std::cos(a) * r * 65536), pv = std::llround(std::sin(a) * r * 65536);
            const afvis::Trace f = afvis::trace(m, dmin, d0, u, v, pu, pv);
            const afvis::Trace d = afvis::trace_ref(m, dmin, d0, code_to_uv(u), code_to_uv(v), code_to_uv(pu), code_to_uv(pv));
            ++n;
            occluded += f.visible ? 0 : 1;
            if (f.capped) {
              ++capped;
              EXPECT_GT(d.steps, uint32_t(fmt::kAfvStepMax));
              continue;
            }
            if (f.visible != d.visible || f.steps != d.steps) {
              const double mg = afvis::trace_margin_ref(m, dmin, d0, code_to_uv(u), code_to_uv(v), code_to_uv(pu), code_to_uv(pv));
              ++ties;
              EXPECT_LT(std::fabs(mg), 1e-6) << "u " << u << " v " << v << " P " << pu << "," << pv;
            }
          }
      }
  }
  std::printf("%llu traces: %llu occluded, %llu capped, %llu differ from double (all ties)\n",
              (unsigned long long)n, (unsigned long long)occluded, (unsigned long long)capped, (unsigned long long)ties);
  EXPECT_GT(occluded, n / 10);
}

// The cliff: depth 255 left of u = 1/2, 0 right of it; the eye towards +u. A deep point at
// distance x from the cliff rises 1 relief depth per |P| of travel: occluded iff x < |P|
// (exactly, on codes: 255 x < 255 |P|).
TEST(AfvisFx, CliffIsExact) {
  img::Gray8 m(64, 1, 255);
  for (int x = 32; x < 64; ++x) m.at(x, 0) = 0;
  for (int64_t pu : {int64_t(1000), int64_t(5000), int64_t(20000), int64_t(65536)})
    for (int64_t u = 0; u < 32768; u += 37) {
      const afvis::Trace t = afvis::trace(m, 0, 255, u, 100, pu, 0);
      const int64_t x = 32768 - u;
      if (t.capped) continue;
      EXPECT_EQ(t.visible, x >= pu) << u << " " << pu;
    }
}

// Flat and constant maps occlude nothing: the visibility walk is the plain walk bit for bit
// (colour, level, texels visited and inside, flags) on random pixels, each weight source, border
// weights off and on, each rule, at 0 .. 89 degrees.
TEST(AfvisFx, FlatMapIsThePlainWalk) {
  std::mt19937_64 rng(5);
  for (uint8_t level : {uint8_t(0), uint8_t(200)}) {
    const img::Gray8 flat(64, 64, level);
    for (int i = 0; i < 1500; ++i) {
      const efx::In in = efx::random_in(rng);
      const efx::Config cfg{static_cast<efx::Weights>(i % 3), 1024, i % 4 == 0 ? &clip::variant("mm_p1") : nullptr};
      const auto r = relief_of(flat, view_at(double(i % 90), double(i * 7 % 360), 0.2));
      const afvis::Out a = afvis::filter(in, bricks(), {cfg, static_cast<afvis::Rule>(i % 2)}, r);
      SCOPED_TRACE(i);
      expect_same(a.ewa, efx::filter(in, bricks(), cfg));
      EXPECT_EQ(a.visible, a.ewa.texels_inside);
      EXPECT_EQ(a.steps, a.traced);  // d0 <= dmin: one read each
      EXPECT_FALSE(a.no_visible);
    }
  }
}

// On the bricks depth map: the row rule keeps a subset of the visible texels (those it traced
// visible) and traces at most the inside texels; Every traces each inside texel. Prints the
// occluded fraction and the cost of both.
TEST(AfvisFx, RowRuleKeepsASubsetOfTheVisible) {
  const img::Gray8 depth = pom::map_bricks(64);
  std::mt19937_64 rng(9);
  uint64_t inside = 0, vis_every = 0, vis_row = 0, tr_every = 0, tr_row = 0, st_every = 0, st_row = 0, nov = 0;
  for (int i = 0; i < 2000; ++i) {
    const double major = std::ldexp(1.0, static_cast<int>(rng() % 5)), aniso = 1 + double(rng() % 8);
    const efx::In in = pixel(major, aniso, double(rng() % 360) * M_PI / 180, double(rng() % 256), double(rng() % 256));
    const auto r = relief_of(depth, view_at(60 + double(rng() % 29), double(rng() % 360), 0.1));
    const efx::Config cfg;
    const afvis::Out e = afvis::filter(in, bricks(), {cfg, afvis::Rule::Every}, r);
    const afvis::Out w = afvis::filter(in, bricks(), {cfg, afvis::Rule::Row}, r);
    SCOPED_TRACE(i);
    EXPECT_EQ(e.traced, e.ewa.texels_inside);
    EXPECT_LE(w.traced, w.ewa.texels_inside);
    EXPECT_LE(w.visible, e.visible);
    EXPECT_EQ(e.ewa.texels_inside, w.ewa.texels_inside);
    inside += e.ewa.texels_inside, vis_every += e.visible, vis_row += w.visible;
    tr_every += e.traced, tr_row += w.traced, st_every += e.steps, st_row += w.steps;
    nov += w.no_visible ? 1 : 0;
  }
  std::printf("bricks 64, 60-88 deg: inside %llu, visible every %.4f row %.4f; traced every %.2f row %.2f"
              " /px; steps every %.2f row %.2f /px; row: %llu px with no visible texel\n",
              (unsigned long long)inside, double(vis_every) / double(inside), double(vis_row) / double(inside),
              double(tr_every) / 2000, double(tr_row) / 2000, double(st_every) / 2000, double(st_row) / 2000,
              (unsigned long long)nov);
  EXPECT_LT(vis_every, inside);  // the map occludes something
}

// The row mask of the float EWA with trace_ref against the fixed-point walk on the same pixels:
// same level; colour within the plain walk's bound (3 LSB, EwaFx.WeightSourcesMatchFloat) plus the
// texels whose visibility the quantised P and centre flip (printed).
TEST(AfvisFx, MatchesTheFloatReference) {
  const img::Gray8 depth = pom::map_bricks(64);
  std::mt19937_64 rng(11);
  int max_diff = 0, n = 0;
  uint64_t sum_diff = 0, tr_fx = 0, tr_ref = 0;
  for (int i = 0; i < 1000; ++i) {
    const efx::In in = pixel(std::ldexp(1.0, static_cast<int>(rng() % 4)), 1 + double(rng() % 6),
                             double(rng() % 360) * M_PI / 180, double(rng() % 256), double(rng() % 256));
    const pom::View vw = view_at(45 + double(rng() % 44), double(rng() % 360), 0.1);
    const auto r = relief_of(depth, vw);
    const afvis::Out f = afvis::filter(in, bricks(), {{}, afvis::Rule::Row}, r);
    uint32_t traced = 0;
    afvis::RefRelief rr{&depth, nullptr, r.dmin, code_to_uv(r.pu), code_to_uv(r.pv), 8, 8, afvis::Rule::Row, &traced, nullptr};
    const ewa::Result g = efx::filter_ref_b2(in, bricks(), afvis::with_visibility(ewa::Params{}, rr));
    EXPECT_EQ(f.ewa.level, g.level);
    EXPECT_EQ(f.no_visible, g.no_weight);
    const int d = std::max({std::abs(f.ewa.color.r - int(std::lround(g.color.r))), std::abs(f.ewa.color.g - int(std::lround(g.color.g))),
                            std::abs(f.ewa.color.b - int(std::lround(g.color.b)))});
    max_diff = std::max(max_diff, d);
    sum_diff += uint64_t(d), ++n;
    tr_fx += f.traced, tr_ref += traced;
  }
  std::printf("1000 px (bricks 64, 45-88 deg, row rule): max %d LSB, mean %.3f LSB; traces fx %llu ref %llu\n",
              max_diff, double(sum_diff) / n, (unsigned long long)tr_fx, (unsigned long long)tr_ref);
  EXPECT_LE(max_diff, 8);
}

// The step rule's error: on texel centres of random pixels, the integer trace against the ideal
// one (exact P of the float view, exact centre; box field) and against the exact visibility on the
// bilinear field of the truth renderer (relief::exact_hit). Prints both disagreement rates.
TEST(AfvisFx, StepRuleErrorAgainstIdealAndBilinear) {
  std::mt19937_64 rng(3);
  for (const auto& [name, depth] : std::vector<std::pair<const char*, img::Gray8>>{
           {"bricks", pom::map_bricks(64)}, {"smooth", pom::map_smooth(64)}, {"noisy", pom::map_noisy(64)}}) {
    const uint8_t dmin = afvis::min_depth(depth);
    uint64_t n = 0, ideal = 0, bil = 0, occ = 0;
    for (int i = 0; i < 20000; ++i) {
      const double th = (45 + double(rng() % 440) / 10) * M_PI / 180, ph = double(rng() % 3600) / 10 * M_PI / 180;
      const double vx = std::sin(th) * std::cos(ph), vy = std::sin(th) * std::sin(ph), vz = std::cos(th), s = 0.1;
      const pom::View vw = view_at(th * 180 / M_PI, ph * 180 / M_PI, s);
      const pom::Parallax p = pom::parallax(vw);
      const int64_t u = int64_t(rng() % 65536), v = int64_t(rng() % 65536);
      const afvis::Trace f = afvis::trace(depth, dmin, pom::tex_nearest(depth, u, v), u, v, p.pu, p.pv);
      const afvis::ParallaxRef pr = afvis::parallax_ref(vx, vy, vz, std::ldexp(double(vw.scale), -fmt::kPomSF));
      const double uf = code_to_uv(u), vf = code_to_uv(v);
      const afvis::Trace d = afvis::trace_ref(depth, dmin, pom::tex_nearest_f(depth, uf, vf), uf, vf, pr.pu, pr.pv);
      const bool b = afvis::visible_bilinear(depth, uf, vf, vx, vy, vz, std::ldexp(double(vw.scale), -fmt::kPomSF));
      ++n;
      occ += f.visible ? 0 : 1;
      ideal += f.visible != d.visible ? 1 : 0;
      bil += f.visible != b ? 1 : 0;
    }
    std::printf("%s: %llu points, occluded %.4f; differ from the ideal box trace %.5f, from bilinear exact %.4f\n",
                name, (unsigned long long)n, double(occ) / double(n), double(ideal) / double(n), double(bil) / double(n));
    EXPECT_LT(double(ideal) / double(n), 0.01);
  }
}

// Grazing views 85 .. 89 deg (|Vz| down to the 88.2 deg guard) at S = 0.05 .. 0.5 on the bricks map
// and a noisy map: traces end (cap at AfvStepMax cells, flagged), steps <= AfvStepMax + 1, and the
// largest view (|Vxy| = 1 at the guard, S -> 1, the largest P) keeps every intermediate inside the
// declared widths (AfvDistW, AfvCrossW, AfvTestW, AfvPW).
TEST(AfvisFx, GrazingAndWidths) {
  afvis::TraceStats st;
  int64_t max_p = 0;
  uint64_t traces = 0, capped = 0;
  for (const auto& depth : {pom::map_bricks(64), pom::map_noisy(128), pom::map_bricks(512)}) {
    for (double angle : {85.0, 87.0, 88.0, 89.0, 90.0})
      for (double scale : {0.05, 0.2, 0.5, 65535.0 / 65536})
        for (double az : {0.0, 33.0, 45.0, 90.0, 200.0}) {
          const pom::View vw = view_at(angle, az, scale);
          const auto r = relief_of(depth, vw);
          max_p = std::max({max_p, std::abs(r.pu), std::abs(r.pv)});
          for (int k = 0; k < 64; ++k) {
            const efx::In in = pixel(4, 8, az * M_PI / 180, 13.7 * k, 7.3 * k);
            afvis::TraceStats s1;
            const afvis::Out o = afvis::walk(efx::setup(in, bricks(), {}), bricks(), {{}, afvis::Rule::Every}, r, &s1);
            EXPECT_LE(o.steps, o.traced * uint32_t(fmt::kAfvStepMax + 1));
            traces += o.traced, capped += o.capped;
            st.max_n = std::max(st.max_n, s1.max_n);
            st.max_cross = std::max(st.max_cross, s1.max_cross);
            st.max_abs_test = std::max(st.max_abs_test, s1.max_abs_test);
          }
        }
  }
  std::printf("grazing: %llu traces, %llu capped; max |P| %lld, n %lld, n|P| %lld, test %lld\n",
              (unsigned long long)traces, (unsigned long long)capped, (long long)max_p, (long long)st.max_n,
              (long long)st.max_cross, (long long)st.max_abs_test);
  EXPECT_LT(max_p, int64_t(1) << fmt::kAfvPW);
  EXPECT_LT(st.max_n, int64_t(1) << fmt::kAfvDistW);
  EXPECT_LT(st.max_cross, int64_t(1) << fmt::kAfvCrossW);
  EXPECT_LT(st.max_abs_test, int64_t(1) << (fmt::kAfvTestW - 1));
  EXPECT_GT(capped, 0u);
}

// The RTL walker's row buffer (tu_afvis_walk, 2^AfvRowLog2 entries) holds every row's texels with
// w > 0: the widest rows come from the largest semi-axes at the walk level (2^EwaAxisMaxLog2 texels,
// the box's half extent plus its margin): over the block's stiff set (incl. a 2000-texel 1:1
// footprint with the largest cap) and 3,000 random vectors the widest row stays below it. The
// walker's clock count afvis::Out::clocks is the sum of its parts (box + AfvRowCycles per row +
// the trace clocks + the finish), checked against Verilator in AfvisCosim.CyclesMatchPrediction.
TEST(AfvisFx, RowBufferHoldsTheWidestRow) {
  const auto& b = blocks::find("afvis");
  uint32_t widest = 0;
  for (const std::string set : {"stiff", "random"}) {
    const auto vf = blocks::generate(b, set, 3000, 11);
    const auto in_idx = vf.indices(vec::Role::In);
    for (const auto& row : vf.rows) {
      const afvis::Out o = blocks::afvis_block_model(blocks::pick(row, in_idx));
      widest = std::max(widest, o.max_row);
      const uint64_t rows_min = o.ewa.texels_visited > 0 ? 1 : 0;
      EXPECT_GE(o.clocks, o.ewa.texels_visited + rows_min * fmt::kAfvRowCycles + uint64_t(o.traced) + o.steps);
    }
  }
  std::printf("afvis: widest row %u texels with w > 0 (row buffer %d)\n", widest, 1 << fmt::kAfvRowLog2);
  EXPECT_LE(widest, uint32_t(2 * ((1 << fmt::kEwaAxisMaxLog2) + 2) + 1));
  EXPECT_LT(widest, uint32_t(1) << fmt::kAfvRowLog2);
  EXPECT_GT(widest, 200u);  // the stiff set reaches the axis clamp
}

// A pixel with no visible texel: a deep plain (255) with a ridge (0) between it and the eye at a
// distance below |P|: every footprint texel is occluded; the colour is the level's texel nearest
// the centre (kNoWeight, no_visible), in the fixed-point walk and the float reference.
TEST(AfvisFx, NoVisibleTexelFallsBackToTheNearestTexel) {
  img::Gray8 m(64, 64, 255);
  for (int y = 0; y < 64; ++y)
    for (int x = 48; x < 52; ++x) m.at(x, y) = 0;
  pom::View vw = view_at(80, 0, 0.1);  // towards +u
  const auto r = relief_of(m, vw);
  ASSERT_GT(code_to_uv(r.pu), 0.2);
  const efx::In in = pixel(3, 1, 0, 0.6 * 256, 100);
  for (auto rule : {afvis::Rule::Every, afvis::Rule::Row}) {
    const afvis::Out o = afvis::filter(in, bricks(), {{}, rule}, r);
    EXPECT_TRUE(o.no_visible);
    EXPECT_EQ(o.visible, 0u);
    EXPECT_TRUE(o.ewa.flags & efx::kNoWeight);
    const efx::PixelSetup su = efx::setup(in, bricks(), {});
    EXPECT_EQ(o.ewa.color, bricks().fetch(su.level, (su.cu + 32) >> 6, (su.cv + 32) >> 6));
    afvis::RefRelief rr{&m, nullptr, r.dmin, code_to_uv(r.pu), code_to_uv(r.pv), 8, 8, rule, nullptr, nullptr};
    EXPECT_TRUE(efx::filter_ref_b2(in, bricks(), afvis::with_visibility(ewa::Params{}, rr)).no_weight);
  }
}

// The min-depth pyramid: a block is one cell holding its minimum; level 0 is the map itself.
TEST(AfvisFx, MinDepthPyramid) {
  const img::Gray8 d = pom::map_noisy(64);
  const img::Gray8 p0 = afvis::min_depth_pyramid(d, 0), p2 = afvis::min_depth_pyramid(d, 2);
  EXPECT_EQ(p0.px, d.px);
  ASSERT_EQ(p2.width, 16);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      uint8_t m = 255;
      for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) m = std::min(m, d.at(4 * x + i, 4 * y + j));
      EXPECT_EQ(p2.at(x, y), m);
    }
  EXPECT_EQ(afvis::min_depth_pyramid(d, 8).width, 1);
  EXPECT_EQ(afvis::min_depth_pyramid(d, 8).at(0, 0), afvis::min_depth(d));
}

// The scene flag: relief.af_visibility is a boolean (default false); anything else is refused
// naming the field.
TEST(AfvisScene, FlagParsesAndBadValuesAreRefused) {
  const std::string path = std::string(TU_SOURCE_DIR) + "/docs/scenes/af_visibility.json";
  const auto s = scene::load(path);
  for (const auto& [name, m] : s.materials) EXPECT_TRUE(m.relief && m.relief->af_visibility) << name;
  EXPECT_FALSE(scene::default_scene().materials.at("wall").relief->af_visibility);
  std::ifstream in(path, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto at = text.find("\"af_visibility\": true");
  ASSERT_NE(at, std::string::npos);
  for (const char* bad : {"\"af_visibility\": 1", "\"af_visibility\": \"yes\"", "\"af_visibility\": null"}) {
    std::string t = text;
    t.replace(at, std::strlen("\"af_visibility\": true"), bad);
    try {
      scene::parse(t, "afv.json", std::string(TU_SOURCE_DIR) + "/docs/scenes");
      ADD_FAILURE() << bad << " accepted";
    } catch (const scene::SceneError& e) {
      EXPECT_NE(std::string(e.what()).find("afv.json: /materials/floor/relief/af_visibility: expected true or false"), std::string::npos) << e.what();
    }
  }
}

// The docs scene at 64 x 48 through the C-model and float engines: visibility changes relief pixels
// only where a texel is occluded (Off = the scene without the flag, bit for bit), and the C model
// stays close to the float reference with the same flag.
TEST(AfvisScene, RenderEnginesUseTheFlag) {
  auto s = scene::load(std::string(TU_SOURCE_DIR) + "/docs/scenes/af_visibility.json");
  s.camera.width = 64, s.camera.height = 48;
  render::CmodelOptions off;
  off.afvis = render::AfvisMode::Off;
  const render::Frame on = render::render_cmodel(s), plain = render::render_cmodel(s, {}, off);
  auto s_noflag = s;
  for (auto& [n, m] : s_noflag.materials) m.relief->af_visibility = false;
  const render::Frame noflag = render::render_cmodel(s_noflag);
  ASSERT_EQ(plain.pixels.size(), noflag.pixels.size());
  size_t differ = 0, traced = 0, steps = 0;
  for (size_t i = 0; i < on.pixels.size(); ++i) {
    EXPECT_EQ(plain.pixels[i].color, noflag.pixels[i].color);
    EXPECT_EQ(noflag.pixels[i].afv_traced, 0);
    differ += on.pixels[i].color == plain.pixels[i].color ? 0 : 1;
    const auto& a = on.pixels[i];
    if (a.afv_traced == 0 || a.afv_visible == a.texels_inside) {
      EXPECT_EQ(a.color, plain.pixels[i].color);  // nothing occluded: the plain walk
    }
    traced += size_t(on.pixels[i].afv_traced), steps += size_t(on.pixels[i].afv_steps);
  }
  const render::Frame ref = render::render_ref(s);
  const double psnr = render::psnr_covered(on, ref, render::relief_pixels(s));
  std::printf("%zu covered px, %zu changed by visibility; %.2f traces, %.2f steps per px; C model vs float ref (both with visibility): %.2f dB\n",
              on.pixels.size(), differ, double(traced) / double(on.pixels.size()), double(steps) / double(on.pixels.size()), psnr);
  EXPECT_GT(differ, on.pixels.size() / 50);
  EXPECT_GT(psnr, 25);
}

// The quality table on a small version of the docs scene: one row per variant, plain traces nothing,
// every rule keeps at most the inside texels, the figures are finite.
TEST(AfvisQuality, SmallTable) {
  auto s = scene::load(std::string(TU_SOURCE_DIR) + "/docs/scenes/af_visibility.json");
  s.camera.width = 48, s.camera.height = 36;
  afvis::QualityParams p;
  p.maps = {"bricks"};
  p.heights = {1};
  p.ss = 4;
  const auto rows = afvis::quality(s, p);
  ASSERT_EQ(rows.size(), 5u);
  EXPECT_EQ(rows[0].variant, "plain");
  EXPECT_EQ(rows[0].traced, 0);
  for (const auto& r : rows) {
    EXPECT_GT(r.pixels, 100u);
    EXPECT_TRUE(std::isfinite(r.psnr));
    EXPECT_LE(r.visible, r.inside + 1e-9);
    EXPECT_GT(r.view_deg, 60);
  }
  EXPECT_LT(rows[1].visible, rows[0].visible);  // every: something is occluded
  std::printf("%s", afvis::quality_markdown(rows).c_str());
}

}  // namespace
