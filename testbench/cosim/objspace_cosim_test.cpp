// Object-space per-sample datapath (rtl/objspace/tu_objspace_sample.sv, docs/blocks/objspace.md):
// the cycle estimator's latency and II against Verilator, and the object-space render through the
// RTL datapath equal to the C-model render on every pixel, with 30 % stalls and without (then the
// simulated cycles equal the estimate exactly). The vector sets run in Cosim.* (cosim_test.cpp).
#include <gtest/gtest.h>

#include "cosim.hpp"
#include "objspace/schemes.hpp"
#include "objspace_rtl.hpp"

namespace {
using namespace tu;

TEST(ObjspaceSched, PredictionEqualsVerilatorMeasurement) {
  const auto pred = sched::schedule(objspace::sample_scheme());
  const auto& b = blocks::find("objspace_sample");
  const auto [lat, ii] = cosim::find_rtl("objspace_sample").timing(b.inputs("random", 64, 3));
  EXPECT_EQ(static_cast<uint64_t>(pred.latency), lat);
  EXPECT_EQ(pred.latency, b.latency_cycles);
  EXPECT_DOUBLE_EQ(static_cast<double>(pred.ii), ii);
  EXPECT_DOUBLE_EQ(ii, 1.0);
  EXPECT_EQ(pred.units_used.at("mul"), 6 + 4 + 4);  // map, reciprocal + p * R, weights
}

TEST(ObjspaceRtl, RenderEqualsTheCModelOnEveryPixel) {
  // A fronto-parallel quad (one sample per pixel) and a grazing floor (overlaps), 64 x 48.
  for (const std::string& v : {std::string("[[-2, -1.5, -2], [2, -1.5, -2], [2, 1.5, -2], [-2, 1.5, -2]]"),
                              objspace::stiff_quad_vertices()[0]}) {
    const auto s = objspace::quad_scene(v);
    for (const double stall : {0.3, 0.0}) {
      cosim::ObjspaceRtlOptions ro;
      ro.stall_prob = stall;
      const auto r = cosim::render_objspace_rtl(s, {}, ro);
      EXPECT_TRUE(r.ok()) << r.first_mismatch;
      EXPECT_EQ(r.mismatches, 0u);
      EXPECT_EQ(r.differing_pixels, 0u);
      EXPECT_GT(r.samples, 3000u);
      EXPECT_EQ(r.samples, r.result.stats.samples);
      EXPECT_GT(r.result.stats.covered, 0u);
      if (stall == 0) {
        EXPECT_EQ(r.sim_cycles, r.predicted_cycles);
      } else {
        EXPECT_GT(r.sim_cycles, r.predicted_cycles * 13 / 10);  // the stalls did happen
      }
    }
  }
}
}  // namespace
