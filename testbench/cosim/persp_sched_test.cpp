// Cycle estimator vs Verilator for the perspective divide unit (B1): the shared list scheduler
// (texunit/sched.hpp) predicts latency and II of the incremental, direct and 4-lane graphs, of
// the per-scanline set-up and of the texel-depth variant (cmodel/blocks/persp/schemes.cpp); the
// Verilator runs of tu_persp, tu_persp_direct, tu_persp_klane, tu_persp_setup and tu_texel_depth
// measure them; they must agree exactly (docs/blocks/persp.md).
#include <gtest/gtest.h>

#include "cosim.hpp"
#include "persp/schemes.hpp"

namespace tu::cosim {
RtlBlock rtl_persp_direct();  // persp_rtl.cpp
}

namespace {
using namespace tu;

TEST(PerspSched, PredictionEqualsVerilatorMeasurement) {
  int checked = 0;
  for (const auto& g : persp::schemes()) {
    const auto pred = sched::schedule(g);
    const bool direct = g.name == "persp_direct";
    const auto& b = blocks::find(direct ? "persp" : g.name);
    const auto rtl = direct ? cosim::rtl_persp_direct() : cosim::find_rtl(g.name);
    std::vector<cosim::Row> in;
    for (const auto& r : b.inputs("random", 64, 3)) in.push_back(r);
    const auto [lat, ii] = rtl.timing(in);
    EXPECT_EQ(static_cast<uint64_t>(pred.latency), lat) << g.name;
    EXPECT_DOUBLE_EQ(static_cast<double>(pred.ii), ii) << g.name;
    std::printf("%-13s predicted latency %d II %d (mul %d), measured latency %llu II %.2f\n",
                g.name.c_str(), pred.latency, pred.ii, pred.units_used.at("mul"),
                static_cast<unsigned long long>(lat), ii);
    ++checked;
  }
  EXPECT_EQ(checked, 5);
}

// The estimator is not a constant: a graph with one more registered stage, or with the two output
// multiplies on one shared multiplier, predicts different figures from the RTL's.
TEST(PerspSched, EstimatorSeesStructuralChanges) {
  auto g = persp::scheme("persp");
  const auto base = sched::schedule(g);
  EXPECT_EQ(base.latency, 8);
  EXPECT_EQ(base.ii, 1);
  auto longer = g;
  longer.add("extra_stage", "reg", 1, {static_cast<int>(longer.ops.size()) - 1});
  EXPECT_EQ(sched::schedule(longer).latency, 9);
  auto shared = g;
  shared.limits["mul"] = 1;
  const auto s = sched::schedule(shared);
  EXPECT_GT(s.ii, 1);
  EXPECT_GT(s.latency, 8);
}
}  // namespace
