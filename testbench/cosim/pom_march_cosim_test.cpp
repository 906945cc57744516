// POM march engine co-simulation (docs/blocks/relief-appendix.md §6). Cycles per pixel depend on the
// number of march steps k, so this block is not in the generic fixed-latency Cosim suite:
// 0 mismatches with 30 % stalls on golden/stiff/random, and the cycle prediction
// pom::march_cycles = sum(k + 1) + 2 agrees with the measured cycles of a rendered scene within 5 %.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "cosim_checks.hpp"
#include "pom/pom_march.hpp"
#include "pom/relief_quality.hpp"

namespace {
using namespace tu;

TEST(PomMarchCosim, GoldenStiffRandomWithStalls) {
  cosim::checks::for_each_set_with_stalls(
      blocks::find("pom_march"),
      [](const vec::VectorFile&, const cosim::Report& rep) { EXPECT_EQ(rep.max_abs_err, 0.0); });
}

TEST(PomMarchCosim, DetectsACorruptedExpectedValue) {
  cosim::checks::expect_corruption_detected("pom_march");
}

TEST(PomMarchCosim, CyclesPerPixelMatchPrediction) {
  // A 64x64-pixel tile of the bricks map seen at 60 and 80 degrees (S = 0.05, azimuth 30),
  // fixed N = 16 and N = 32; no stalls. Prediction: pom::march_cycles (k + 1 cycles per pixel).
  const auto& b = blocks::find("pom_march");
  for (double ang : {60.0, 80.0})
    for (uint32_t n : {16u, 32u}) {
      pom::View vw;
      const double th = ang * M_PI / 180, ph = M_PI / 6;
      vw.vx = static_cast<int32_t>(std::lround(std::sin(th) * std::cos(ph) * 16384));
      vw.vy = static_cast<int32_t>(std::lround(std::sin(th) * std::sin(ph) * 16384));
      vw.vz = static_cast<int32_t>(std::lround(std::cos(th) * 16384));
      vw.scale = 3277;
      const auto p = pom::parallax(vw);
      const int64_t du = std::llround(double(p.pu) / n), dv = std::llround(double(p.pv) / n);
      vec::VectorFile vf;
      vf.block = b.name;
      vf.set = "scene";
      vf.fields = b.fields;
      std::vector<blocks::Row> in;
      for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x)
          in.push_back({uint64_t((2 * x + 1) << 9), uint64_t((2 * y + 1) << 9),
                        uint64_t(du) & 0xffffffffu, uint64_t(dv) & 0xffffffffu, n});
      double steps = 0;
      std::vector<uint32_t> ks;
      for (const auto& r : in) {
        blocks::Row row = r;
        const auto out = b.model(r);
        const auto ref = b.ref(r);
        row.insert(row.end(), out.begin(), out.end());
        row.insert(row.end(), ref.begin(), ref.end());
        vf.rows.push_back(row);
        ks.push_back(static_cast<uint32_t>(cosim::glue::out_pom_march(out).steps));
        steps += double(cosim::glue::out_pom_march(out).steps);
      }
      cosim::Options opt;
      opt.run.stall_prob = 0;
      const auto rep = cosim::run(vf, opt);
      EXPECT_EQ(rep.mismatches, 0u) << rep.first_mismatch;
      const double measured = static_cast<double>(rep.sim_cycles);
      const double predicted = static_cast<double>(pom::march_cycles(ks));
      std::printf("pom_march scene %g deg N=%u: %zu px, steps/px %.3f, cycles/px measured %.3f "
                  "predicted %.3f (%.2f %%)\n", ang, n, in.size(), steps / in.size(),
                  measured / in.size(), predicted / in.size(), 100 * (measured / predicted - 1));
      EXPECT_NEAR(measured / predicted, 1.0, 0.05);
    }
}
}  // namespace
