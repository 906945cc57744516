// POM set-up, refinement and per-pixel unit co-simulation (docs/blocks/relief.md §8):
// 0 mismatches with 30 % stalls on golden / stiff / random; set-up and refinement have a fixed
// latency and II 1; the unit's cycles over a scene's pixel stream match pom::unit_cycles.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "complexity/complexity.hpp"
#include "cosim_checks.hpp"
#include "pom/pom_layers.hpp"
#include "pom/pom_march.hpp"
#include "pom/relief_quality.hpp"

namespace {
using namespace tu;

class PomStageCosim : public ::testing::TestWithParam<std::string> {};

TEST_P(PomStageCosim, GoldenStiffRandomWithStalls) {
  const auto& b = blocks::find(GetParam());
  if (GetParam() == "pom_unit") {  // data-dependent latency; error vs march_ref: §8 of relief.md
    cosim::checks::for_each_set_with_stalls(b, [](const vec::VectorFile&, const cosim::Report&) {});
    return;
  }
  cosim::checks::for_each_set_with_stalls(b, [&](const vec::VectorFile&, const cosim::Report& rep) {
    EXPECT_EQ(rep.latency_cycles, static_cast<uint64_t>(b.latency_cycles));
    EXPECT_DOUBLE_EQ(rep.ii_cycles, 1.0);
    // set-up: dT rounded twice (P, then P/N); refinement: w and w*dT rounded (+ |dT| / 2^17
    // from w's 16 bits), stiff dT up to 2^22 -> 32 LSB
    EXPECT_LE(rep.max_abs_err, GetParam() == "pom_setup" ? 1.0 : 34.0);
  });
}

TEST_P(PomStageCosim, DetectsACorruptedExpectedValue) {
  cosim::checks::expect_corruption_detected(GetParam());
}

INSTANTIATE_TEST_SUITE_P(Pom, PomStageCosim, ::testing::Values("pom_setup", "pom_refine", "pom_unit"));

// A 64x64-pixel tile of the bricks map (the engine's ROM), S = 0.05, azimuth 30 degrees: fixed N
// and adaptive N (pom::layers of the map's complexity), no stalls.
TEST(PomUnitCosim, CyclesPerPixelMatchTheEstimator) {
  const auto& b = blocks::find("pom_unit");
  const img::Gray8 depth = pom::map_bricks(64);
  const img::Gray8 cmap = complexity::complexity_map(depth);
  for (double ang : {45.0, 80.0})
    for (int n_fixed : {8, 32, 0}) {  // 0: adaptive
      pom::View vw;
      const double th = ang * M_PI / 180, ph = M_PI / 6;
      vw.vx = static_cast<int32_t>(std::lround(std::sin(th) * std::cos(ph) * 16384));
      vw.vy = static_cast<int32_t>(std::lround(std::sin(th) * std::sin(ph) * 16384));
      vw.vz = static_cast<int32_t>(std::lround(std::cos(th) * 16384));
      vw.scale = 3277;
      vec::VectorFile vf;
      vf.block = b.name;
      vf.set = "scene";
      vf.fields = b.fields;
      std::vector<uint32_t> steps;
      for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
          const int64_t u = (2 * x + 1) << 9, v = (2 * y + 1) << 9;
          const uint32_t n = n_fixed ? uint32_t(n_fixed) : pom::layers(vw.vz, pom::tex_nearest(cmap, u, v)).n;
          blocks::Row row = {uint64_t(u), uint64_t(v), uint64_t(vw.vx) & 0xffff, uint64_t(vw.vy) & 0xffff,
                             uint64_t(vw.vz) & 0xffff, vw.scale, n, 1};
          const auto out = b.model(row);
          const auto ref = b.ref(row);
          steps.push_back(static_cast<uint32_t>(out[2]));
          row.insert(row.end(), out.begin(), out.end());
          row.insert(row.end(), ref.begin(), ref.end());
          vf.rows.push_back(row);
        }
      cosim::Options opt;
      opt.run.stall_prob = 0;
      const auto rep = cosim::run(vf, opt);
      EXPECT_EQ(rep.mismatches, 0u) << rep.first_mismatch;
      const double np = double(vf.rows.size()), measured = double(rep.sim_cycles);
      const double predicted = double(pom::unit_cycles(steps));
      double k = 0;
      for (uint32_t s : steps) k += s;
      std::printf("pom_unit scene %g deg N=%s: steps/px %.3f, cycles/px measured %.3f predicted "
                  "%.3f (%.2f %%)\n", ang, n_fixed ? std::to_string(n_fixed).c_str() : "adaptive",
                  k / np, measured / np, predicted / np, 100 * (measured / predicted - 1));
      EXPECT_NEAR(measured / predicted, 1.0, 0.05);
    }
}
}  // namespace
