// Cycle estimator vs Verilator for the ellipse/LOD units (B2): the list scheduler's latency and II
// of the analytic scheme (cmodel/blocks/ellipse/ellipse_scheme.hpp) equal the measurement of
// rtl/ellipse/tu_ellipse.sv.
#include <gtest/gtest.h>

#include "cosim.hpp"
#include "ellipse/ellipse_scheme.hpp"
#include "texunit/formats.hpp"

namespace {
using namespace tu;

TEST(EllipseSched, PredictionEqualsVerilatorMeasurement) {
  const auto g = ellipse::scheme();
  const auto pred = sched::schedule(g);
  const auto& b = blocks::find("ellipse");
  std::vector<cosim::Row> in;
  for (const auto& r : b.inputs("random", 64, 3)) in.push_back(r);
  const auto [lat, ii] = cosim::find_rtl("ellipse").timing(in);
  EXPECT_EQ(static_cast<uint64_t>(pred.latency), lat);
  EXPECT_DOUBLE_EQ(static_cast<double>(pred.ii), ii);
  EXPECT_EQ(pred.latency, fmt::kEllLatency);
  std::printf("ellipse predicted latency %d II %d (mul %d), measured latency %llu II %.2f\n",
              pred.latency, pred.ii, pred.units_used.at("mul"), static_cast<unsigned long long>(lat), ii);
  auto longer = g;  // the estimator sees a structural change
  longer.add("extra", "reg", 1, {static_cast<int>(longer.ops.size()) - 1});
  EXPECT_EQ(sched::schedule(longer).latency, pred.latency + 1);
}
}  // namespace

namespace {
// The recurrence variant (rtl/ellipse/tu_ellipse_rec.sv): front (two reciprocals, J, det J) +
// the analytic unit on J.
TEST(EllipseSched, RecurrencePredictionEqualsVerilatorMeasurement) {
  const auto pred = sched::schedule(ellipse::scheme_rec());
  std::vector<cosim::Row> in;
  for (const auto& r : blocks::find("ellipse_rec").inputs("random", 64, 3)) in.push_back(r);
  const auto [lat, ii] = cosim::find_rtl("ellipse_rec").timing(in);
  EXPECT_EQ(static_cast<uint64_t>(pred.latency), lat);
  EXPECT_DOUBLE_EQ(static_cast<double>(pred.ii), ii);
  EXPECT_EQ(pred.latency, fmt::kEllRecLatency);
  std::printf("ellipse_rec predicted latency %d II %d (mul %d), measured latency %llu II %.2f\n", pred.latency,
              pred.ii, pred.units_used.at("mul"), static_cast<unsigned long long>(lat), ii);
}
}  // namespace
