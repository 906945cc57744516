// Iterative parallax engine co-simulation (docs/blocks/relief-appendix.md §7): data-dependent cycles,
// so not in the generic fixed-latency Cosim suite. 0 mismatches with 30 % stalls; cycles per
// pixel = iterations + 3 (measured vs predicted within 5 %); non-convergence rate of a scene.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "cosim_checks.hpp"
#include "pom/pom_march.hpp"

namespace {
using namespace tu;

TEST(IterParallaxCosim, GoldenStiffRandomWithStalls) {
  cosim::checks::for_each_set_with_stalls(blocks::find("iter_parallax"),
                                          [](const vec::VectorFile&, const cosim::Report&) {});
}

TEST(IterParallaxCosim, DetectsACorruptedExpectedValue) {
  cosim::checks::expect_corruption_detected("iter_parallax");
}

TEST(IterParallaxCosim, CyclesPerPixelMatchPredictionAndNonConvergenceRate) {
  const auto& b = blocks::find("iter_parallax");
  for (double ang : {45.0, 80.0})
    for (int kind = 0; kind < 2; ++kind) {
      pom::View vw;
      const double th = ang * M_PI / 180, ph = M_PI / 6;
      vw.vx = static_cast<int32_t>(std::lround(std::sin(th) * std::cos(ph) * 16384));
      vw.vy = static_cast<int32_t>(std::lround(std::sin(th) * std::sin(ph) * 16384));
      vw.vz = static_cast<int32_t>(std::lround(std::cos(th) * 16384));
      vw.scale = 3277;
      const auto d = kind ? pom::ipx_dir_normalised(vw) : pom::ipx_dir_seed(vw);
      vec::VectorFile vf;
      vf.block = b.name;
      vf.set = "scene";
      vf.fields = b.fields;
      double predicted = 0, iters = 0, nonconv = 0;
      for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
          blocks::Row row = {uint64_t((2 * x + 1) << 9), uint64_t((2 * y + 1) << 9),
                             uint64_t(d.su) & 0xffffffffu, uint64_t(d.sv) & 0xffffffffu,
                             uint64_t(d.sh) & 0xffffffffu};
          const auto out = b.model(row);
          const auto ref = b.ref(row);
          const auto o = cosim::glue::out_iter_parallax(out);
          predicted += double(o.iters) + 3;
          iters += double(o.iters);
          nonconv += double(o.nonconv);
          row.insert(row.end(), out.begin(), out.end());
          row.insert(row.end(), ref.begin(), ref.end());
          vf.rows.push_back(row);
        }
      cosim::Options opt;
      opt.run.stall_prob = 0;
      const auto rep = cosim::run(vf, opt);
      EXPECT_EQ(rep.mismatches, 0u) << rep.first_mismatch;
      const double np = double(vf.rows.size()), measured = double(rep.sim_cycles);
      std::printf("iter_parallax scene %g deg %s: iters/px %.3f, non-converged %.1f %%, cycles/px "
                  "measured %.3f predicted %.3f (%.2f %%)\n", ang, kind ? "norm" : "seed",
                  iters / np, 100 * nonconv / np, measured / np, predicted / np,
                  100 * (measured / predicted - 1));
      EXPECT_NEAR(measured / predicted, 1.0, 0.05);
    }
}
}  // namespace
