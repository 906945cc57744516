// POM set-up, refinement and per-pixel unit co-simulation (docs/blocks/relief-appendix.md §8):
// 0 mismatches with 30 % stalls on golden / stiff / random; set-up and refinement have a fixed
// latency and II 1; the unit's cycles over a scene's pixel stream match pom::unit_cycles.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "cosim_checks.hpp"
#include "pom/pom_march.hpp"
#include "pom_vec_common.hpp"

namespace {
using namespace tu;

class PomStageCosim : public ::testing::TestWithParam<std::string> {};

TEST_P(PomStageCosim, GoldenStiffRandomWithStalls) {
  const auto& b = blocks::find(GetParam());
  if (GetParam() == "pom_unit") {  // data-dependent latency; error vs march_ref: §8 of docs/blocks/relief-appendix.md
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

// The scene stream (pomvec::scene_vectors: 64x64 pixels of the bricks map, S = 0.05, azimuth 30
// degrees), fixed N and adaptive N, no stalls.
TEST(PomUnitCosim, CyclesPerPixelMatchTheEstimator) {
  for (double ang : {45.0, 80.0})
    for (int n : {8, 32, 0}) {  // 0: adaptive
      const auto vf = blocks::pomvec::scene_vectors("pom_unit", ang, n);
      cosim::Options opt;
      opt.run.stall_prob = 0;
      const auto rep = cosim::run(vf, opt);
      EXPECT_EQ(rep.mismatches, 0u) << rep.first_mismatch;
      const int steps_col = vf.indices(vec::Role::Out)[2];
      std::vector<uint32_t> steps;
      double k = 0;
      for (const auto& r : vf.rows) {
        steps.push_back(static_cast<uint32_t>(r[static_cast<size_t>(steps_col)]));
        k += steps.back();
      }
      const double np = double(vf.rows.size()), measured = double(rep.sim_cycles);
      const double predicted = double(pom::unit_cycles(steps));
      std::printf("pom_unit scene %g deg N=%s: steps/px %.3f, cycles/px measured %.3f predicted "
                  "%.3f (%.2f %%)\n", ang, n ? std::to_string(n).c_str() : "adaptive", k / np,
                  measured / np, predicted / np, 100 * (measured / predicted - 1));
      EXPECT_NEAR(measured / predicted, 1.0, 0.05);
    }
}
}  // namespace
