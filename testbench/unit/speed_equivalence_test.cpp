// The faster forms give the same bits as the forms they replace (docs/performance.md):
// visibility with per-triangle screen bounds and a prepared RayCaster against the plain
// every-triangle-every-pixel ray cast, and renders and vector files on several threads against
// one thread.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>

#include "block.hpp"
#include "ellipse/ellipse_fx.hpp"
#include "ewa/ewa_fx.hpp"
#include "gauss/clip.hpp"
#include "persp/persp.hpp"
#include "reciprocal/reciprocal.hpp"
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

// B1's 64-bit rounding and saturation (persp::Model::scale) against the 128-bit form it replaces,
// for every shift an unguarded q gives and products up to the bound |p R| < 2^(PW - 1 + RecipOutF).
TEST(SpeedEquivalence, PerspScaleFastEqualsWide) {
  using U = persp::Unit;
  static_assert(U::kScale64, "the production B1 takes the 64-bit path");
  constexpr int kBits = U::kPW - 1 + fmt::kRecipOutF;
  const i128 lim = i128(1) << kBits;
  std::mt19937_64 rng(20);
  for (int sh = U::kMinSh; sh <= U::kMaxSh; ++sh) {
    std::vector<i128> ps = {0, 1, -1, lim - 1, -lim + 1, -lim};
    for (const i128 c : {i128(persp::Uv::kMaxRaw), i128(persp::Uv::kMinRaw), i128(0)})  // saturation edges, ties
      for (int d = -2; d <= 2; ++d) {
        const i128 at = (c << sh) + (i128(d) << (sh - 1));
        for (int e = -1; e <= 1; ++e) ps.push_back(at + e);
      }
    for (int t = 0; t < 20000; ++t) {
      const i128 r = static_cast<i128>((u128(rng()) << 64 | rng()) >> (128 - 1 - kBits + rng() % kBits));
      ps.push_back(rng() & 1 ? -r : r);
    }
    for (const i128 p : ps) {
      if (p >= lim || p < -lim) continue;
      ASSERT_EQ(U::scale(p, sh), U::scale_wide(p, sh)) << "sh " << sh << " p " << static_cast<double>(p);
    }
  }
}

// B2's analytic unit written directly from its definition (ellipse_fx.hpp) in 128-bit arithmetic
// with the hardware's serial log2 and square root: the reference of the 64-bit per-pixel path.
int msb128(u128 x) {
  int p = -1;
  while (x) x >>= 1, ++p;
  return p;
}
u128 top128(u128 x, int w) {
  const int p = msb128(x);
  return p >= w - 1 ? x >> (p - (w - 1)) : x << ((w - 1) - p);
}
int64_t clamp_w(i128 v, int w) {
  return static_cast<int64_t>(std::clamp(v, -(i128(1) << (w - 1)), (i128(1) << (w - 1)) - 1));
}
ellipse::fx::Out analytic_wide(const ellipse::fx::In& in) {
  namespace efx = ellipse::fx;
  constexpr int kL1 = fmt::kEllLogF + 1, kNF = fmt::kEllNumF, kPF = fmt::kPerspF;
  efx::Out o;
  if (in.q < (int64_t(1) << (kPF - fmt::kPerspGuardLog2))) {
    o.flags = efx::kHorizon;
    return o;
  }
  const i128 ux = in.nux, vx = in.nvx, uy = in.nuy, vy = in.nvy;
  const i128 a = vx * vx + vy * vy, c = ux * ux + uy * uy, b = -2 * (ux * vx + uy * vy);
  const u128 s = static_cast<u128>(a + c), px = static_cast<u128>(ux * ux + vx * vx),
             py = static_cast<u128>(uy * uy + vy * vy);
  const int ke = s == 0 ? 0 : std::max(0, msb128(s) - (fmt::kEllCoefW - 3));
  o.ae = static_cast<uint64_t>(a >> ke), o.ce = static_cast<uint64_t>(c >> ke), o.be = static_cast<int64_t>(b >> ke);
  o.eexp = static_cast<uint32_t>(ke);
  const int e = msb128(static_cast<u128>(in.q));
  const u128 mq = top128(static_cast<u128>(in.q), fmt::kRecipMantW);
  const i128 r = recip::core(recip::Mant::from_raw(static_cast<i128>(mq))).raw();
  const i128 p = i128(in.dm) * r;
  const int off = in.dexp - (fmt::kEllDetW - 2) - fmt::kRecipOutF + kPF - e;
  const u128 ap = static_cast<u128>(p < 0 ? -p : p);
  int64_t lf = 0;
  if (ap != 0) {
    o.fm = static_cast<uint32_t>(top128(ap, fmt::kEllFmW));
    o.fexp = std::clamp(msb128(ap) + off, -(1 << (fmt::kEllFexpW - 1)), (1 << (fmt::kEllFexpW - 1)) - 1);
    lf = efx::log2_fx_serial(ap) + int64_t(off) * (1 << kL1);
  }
  const int64_t lq = efx::log2_fx_serial(mq) + int64_t(e - (fmt::kRecipMantW - 1) - kPF) * (1 << kL1);
  const u128 pm = std::max(px, py);
  o.lrho = pm == 0 ? efx::kLogNegInf
                   : static_cast<int32_t>(clamp_w((efx::log2_fx_serial(pm) - int64_t(2 * kNF) * (1 << kL1) - 4 * lq) >> 2,
                                                  fmt::kEllLogW));
  if (s == 0) {
    o.flags |= efx::kDegenerate | efx::kMagnify;
    o.lmaj = o.lmin = efx::kLogNegInf;
    return o;
  }
  const int k = std::max(0, msb128(s) - (fmt::kEllNrmW - 1));
  const i128 dn = (a - c) >> k, bn = b >> k;
  const u128 lam = (s >> k) + efx::isqrt_serial(static_cast<u128>(dn * dn + bn * bn));
  const int64_t ll = efx::log2_fx_serial(lam) + int64_t(k - 2 * kNF - 1) * (1 << kL1);
  const int32_t lmaj = static_cast<int32_t>(clamp_w((ll - 4 * lq) >> 2, fmt::kEllLogW));
  const int32_t cap = static_cast<int32_t>(clamp_w(int64_t(lmaj) - in.laniso, fmt::kEllLogW));
  int32_t lmin = cap;
  if (ap == 0) {
    o.flags |= efx::kDegenerate | efx::kAnisoClamp;
  } else {
    lmin = static_cast<int32_t>(clamp_w((2 * lf - ll) >> 2, fmt::kEllLogW));
    if (cap > lmin) o.flags |= efx::kAnisoClamp, lmin = cap;
  }
  o.lmaj = lmaj, o.lmin = lmin;
  const int32_t lod = lmin >> (fmt::kEllLogF - fmt::kEllLodF), top = static_cast<int32_t>(in.max_lod) << fmt::kEllLodF;
  if (lod < 0) o.flags |= efx::kMagnify;
  else if (lod > top) o.flags |= efx::kLodSat, o.lod = static_cast<uint32_t>(top);
  else o.lod = static_cast<uint32_t>(lod);
  return o;
}

// The per-pixel B2 (64-bit where the ranges allow: |dm R| <= 2^63, the LOD unit's radicand
// < 2^52) equals the 128-bit definition: the vector set's random footprints, raw codes anywhere in
// their formats (s48 numerators, s44 q, s40 dm incl. -2^39, s8 dexp) and their extremes.
TEST(SpeedEquivalence, AnalyticEqualsWideDefinition) {
  namespace efx = ellipse::fx;
  uint32_t rmax = 0;  // R <= 2^RecipOutF on every mantissa (the |dm R| bound)
  for (uint64_t m = uint64_t(1) << (fmt::kRecipMantW - 1); m < (uint64_t(1) << fmt::kRecipMantW); m += 1)
    rmax = std::max(rmax, static_cast<uint32_t>(recip::core(recip::Mant::from_raw(static_cast<i128>(m))).raw()));
  ASSERT_LE(rmax, uint32_t(1) << fmt::kRecipOutF);
  std::mt19937_64 rng(21);
  std::vector<efx::In> ins;
  for (int t = 0; t < 20000; ++t) ins.push_back(efx::in_from_map(efx::local_map(efx::random_local(rng))));
  auto field = [&](int w) {  // a signed w-bit code, its magnitude of a random length
    const int64_t v = static_cast<int64_t>(rng() >> (64 - w + 1)) >> (rng() % w);
    return rng() & 1 ? -v - 1 : v;
  };
  const int64_t kNmax = (int64_t(1) << (fmt::kEllNumW - 1)) - 1, kQmax = (int64_t(1) << (fmt::kPerspQW - 1)) - 1,
                kDmax = (int64_t(1) << (fmt::kEllDetW - 1)) - 1;
  for (int t = 0; t < 30000; ++t) {
    efx::In in;
    in.nux = field(fmt::kEllNumW), in.nvx = field(fmt::kEllNumW), in.nuy = field(fmt::kEllNumW), in.nvy = field(fmt::kEllNumW);
    in.q = std::max<int64_t>(1, field(fmt::kPerspQW) & kQmax);
    in.dm = field(fmt::kEllDetW);
    in.dexp = static_cast<int32_t>(field(fmt::kEllDetExpW));
    in.laniso = static_cast<uint32_t>(rng() % (1u << fmt::kEllAnisoW));
    in.max_lod = static_cast<uint32_t>(rng() % 16);
    ins.push_back(in);
  }
  for (const int64_t n : {kNmax, -kNmax - 1, int64_t(0), int64_t(1)})
    for (const int64_t dm : {kDmax, -kDmax - 1, int64_t(0), int64_t(-1)})
      for (const int64_t q : {kQmax, int64_t(1) << fmt::kPerspF, int64_t(1) << (fmt::kPerspF - fmt::kPerspGuardLog2)}) {
        efx::In in;
        in.nux = n, in.nvx = -n, in.nuy = n, in.nvy = n;
        in.q = q, in.dm = dm, in.dexp = 127;
        ins.push_back(in);
        in.nvx = 0, in.nuy = 0, in.dexp = -128;
        ins.push_back(in);
      }
  for (const auto& in : ins) {
    const efx::Out a = efx::analytic(in), b = analytic_wide(in);
    ASSERT_TRUE(a == b) << "nux " << in.nux << " nvx " << in.nvx << " nuy " << in.nuy << " nvy " << in.nvy << " q "
                        << in.q << " dm " << in.dm << " dexp " << in.dexp;
  }
}

// The EWA walk of the renders (ewa::fx::filter without statistics: one loop per weight source,
// sums in locals, the level's columns and rows wrapped once) against the generic loop (taken when
// statistics are recorded) and against reads through Texture::fetch (taken while a TexelTrace
// records, which must see the same reads): every weight source, border weights on and off, every
// wrap mode, the vector set's random pixels.
TEST(SpeedEquivalence, EwaWalkFastEqualsGeneric) {
  namespace efx = ewa::fx;
  std::mt19937_64 rng(22);
  std::vector<efx::In> ins;
  for (int t = 0; t < 600; ++t) ins.push_back(efx::random_in(rng));
  const auto base = tex::bricks(64).color;
  for (const tex::Wrap wu : {tex::Wrap::Repeat, tex::Wrap::Mirror, tex::Wrap::Clamp, tex::Wrap::Border, tex::Wrap::MirrorOnce}) {
    const auto tx = tex::Texture::build("t", base, tex::Addressing{wu, wu == tex::Wrap::Border ? tex::Wrap::Clamp : tex::Wrap::Border,
                                                                   {10, 20, 30, 40}});
    for (const auto w : {efx::Weights::Formula, efx::Weights::Table1d, efx::Weights::Table2d})
      for (const clip::Variant* cv : {static_cast<const clip::Variant*>(nullptr), &clip::variants().front()}) {
        const efx::Config cfg{w, 1024, cv};
        for (const auto& in : ins) {
          const efx::Out fast = efx::filter(in, tx, cfg);
          efx::WalkStats st;
          const efx::Out generic = efx::walk(efx::setup(in, tx, cfg), tx, cfg, false, &st);
          std::vector<uint64_t> addrs;
          efx::Out traced;
          {
            const tex::TexelTrace trace(&addrs, 0);
            traced = efx::filter(in, tx, cfg);
          }
          for (const efx::Out* o : std::initializer_list<const efx::Out*>{&generic, &traced}) {
            ASSERT_TRUE(fast.color.r == o->color.r && fast.color.g == o->color.g && fast.color.b == o->color.b &&
                        fast.color.a == o->color.a && fast.level == o->level && fast.texels_visited == o->texels_visited &&
                        fast.texels_inside == o->texels_inside && fast.capped == o->capped && fast.flags == o->flags)
                << "u " << in.u << " v " << in.v << " weights " << int(w) << " clip " << (cv != nullptr);
          }
          ASSERT_EQ(addrs.size(), fast.texels_inside + ((fast.flags & efx::kNoWeight) ? 1u : 0u));
        }
      }
  }
}

}  // namespace
