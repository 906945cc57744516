// Texel cache of the system model (tlm/include/texunit/texel_cache.hpp): LRU replacement and set
// mapping on hand-made address streams, the C model's texel trace (tex::TexelTrace) against each
// filter's texel count, and a scene's hit rate with its effect on the SystemC model's cycles.
#include <gtest/gtest.h>

#include <numeric>

#include "texunit/texel_cache.hpp"
#include "texunit/texture_unit_model.hpp"

namespace {
using namespace tu;
using sysmodel::CacheConfig;
using sysmodel::TexelCache;

// The default scene's texture path at 64 x 48, and the C-model options that trace texel reads.
const scene::Scene& quarter_default() {
  static const auto s = [] {
    auto d = scene::without_relief(scene::default_scene());
    d.camera.width /= 4;
    d.camera.height /= 4;
    return d;
  }();
  return s;
}
render::CmodelOptions traced() {
  auto o = render::texture_path_only();
  o.trace_texels = true;
  return o;
}

TEST(TexelCache, LruAndSetMapping) {
  // 2 sets x 2 ways of 16-texel (64 B) lines: lines 0, 2, 4 map to set 0.
  TexelCache c(CacheConfig{256, 64, 2, 0});
  EXPECT_FALSE(c.read(0));
  EXPECT_TRUE(c.read(15));        // the same line
  EXPECT_FALSE(c.read(16));       // line 1: set 1
  EXPECT_FALSE(c.read(2 * 16));   // line 2: set 0, second way
  EXPECT_TRUE(c.read(0));         // line 0 still there; now the most recent
  EXPECT_FALSE(c.read(4 * 16));   // line 4 evicts line 2 (least recent)
  EXPECT_TRUE(c.read(0));
  EXPECT_FALSE(c.read(2 * 16));
  EXPECT_TRUE(c.read(16));        // set 1 untouched
  EXPECT_THROW(TexelCache(CacheConfig{1000, 64, 2, 0}), std::invalid_argument);
  EXPECT_THROW(TexelCache(CacheConfig{64, 64, 2, 0}), std::invalid_argument);
}

TEST(TexelCache, TraceCountsEachFiltersReads) {
  const auto& s = quarter_default();
  const auto opt = traced();
  for (auto f : {scene::Filter::Nearest, scene::Filter::Bilinear, scene::Filter::Trilinear, scene::Filter::Feline,
                 scene::Filter::Ewa}) {
    const auto fr = render::render_cmodel(s, f, opt);
    for (const auto& p : fr.pixels) {
      if (p.b2_flags & ellipse::fx::kHorizon) continue;  // B1 guard: the texture mean, not traced
      // EWA fetches the texels with a weight (texels_inside) of its box (texels).
      const size_t want = static_cast<size_t>(f == scene::Filter::Ewa ? p.texels_inside : p.texels);
      // Trilinear records 8 (as the RTL reports) and reads 4 when its LOD is the top level.
      if (f == scene::Filter::Trilinear && p.texel_addrs.size() == 4) continue;
      ASSERT_EQ(p.texel_addrs.size(), want) << scene::to_string(f) << " at " << p.x << "," << p.y;
    }
  }
}

TEST(TexelCache, SceneHitRateAndStallCycles) {
  const auto& s = quarter_default();
  const auto opt = traced();
  const auto fr = render::render_cmodel(s, scene::Filter::Ewa, opt);
  const auto small = sysmodel::run_cache(fr, CacheConfig{1024, 64, 1, 0});
  const auto big = sysmodel::run_cache(fr, CacheConfig{64 * 1024, 64, 8, 0});
  EXPECT_GT(small.reads, 0u);
  EXPECT_EQ(small.reads, big.reads);
  EXPECT_EQ(std::accumulate(big.misses_per_pixel.begin(), big.misses_per_pixel.end(), uint64_t(0)), big.misses);
  EXPECT_GT(big.hit_rate(), small.hit_rate());
  EXPECT_GT(big.hit_rate(), 0.5);
  EXPECT_EQ(big.memory_bytes, big.misses * 64);
  // The misses stall the walker: cycles grow by at most misses x penalty, and do grow.
  auto wl = sysmodel::scene_workload(s, fr);
  sysmodel::UnitConfig uc;
  uc.relief_stage = false;
  const auto base = sysmodel::simulate(sysmodel::texture_unit(uc), wl).total_cycles;
  for (size_t i = 0; i < wl.pixels.size(); ++i) wl.pixels[i].misses = small.misses_per_pixel[i];
  uc.miss_penalty = 10;
  const auto slow = sysmodel::simulate(sysmodel::texture_unit(uc), wl).total_cycles;
  EXPECT_GT(slow, base);
  EXPECT_LE(slow, base + 10 * small.misses);
  std::printf("default scene at 64x48, EWA: %llu texel reads; 1 KiB direct-mapped hit rate %.2f %%, 64 KiB 8-way %.2f %%; "
              "cycles %llu -> %llu with a 10-clock miss penalty (1 KiB)\n",
              (unsigned long long)small.reads, 100 * small.hit_rate(), 100 * big.hit_rate(), (unsigned long long)base,
              (unsigned long long)slow);
}

}  // namespace
