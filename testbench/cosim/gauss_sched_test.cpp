// Cycle estimator vs Verilator: for every Gaussian-model scheme with RTL, the list scheduler's
// predicted latency and II equal the measured ones exactly (docs/blocks/gaussian.md).
#include <gtest/gtest.h>

#include "cosim.hpp"
#include "gauss/schemes.hpp"

namespace {
using namespace tu;

TEST(GaussSched, PredictionEqualsVerilatorMeasurement) {
  int checked = 0;
  for (const auto& g : gauss::schemes()) {
    if (g.name.rfind("est_", 0) == 0) continue;
    const auto pred = sched::schedule(g);
    const auto& b = blocks::find(g.name);
    std::vector<cosim::Row> in;
    for (const auto& r : b.inputs("random", 64, 3)) in.push_back(r);
    const auto [lat, ii] = cosim::find_rtl(g.name).timing(in);
    EXPECT_EQ(static_cast<uint64_t>(pred.latency), lat) << g.name;
    EXPECT_DOUBLE_EQ(static_cast<double>(pred.ii), ii) << g.name;
    std::printf("%-14s predicted latency %d II %d, measured latency %llu II %.2f\n", g.name.c_str(),
                pred.latency, pred.ii, static_cast<unsigned long long>(lat), ii);
    ++checked;
  }
  EXPECT_EQ(checked, 7);
}
}  // namespace
