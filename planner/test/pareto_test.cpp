// The report's Pareto selection (planner/pareto.hpp) on small hand-made tables.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "planner/pareto.hpp"

namespace tu::report {
namespace {

TEST(PlanPareto, FrontierDropsDominatedPoints) {
  const std::vector<std::pair<double, double>> pts = {
      {10, 5},   // 0: front
      {20, 1},   // 1: front
      {15, 5},   // 2: same error as 0 at a higher cost: dominated
      {10, 7},   // 3: same cost as 0 with a larger error: dominated
      {30, 1},   // 4: same error as 1 at a higher cost: dominated
      {5, 9},    // 5: front (cheapest)
      {25, 0.5}  // 6: front (most accurate)
  };
  EXPECT_EQ(frontier(pts), (std::vector<size_t>{5, 0, 1, 6}));  // sorted by cost
  EXPECT_TRUE(frontier({}).empty());
  EXPECT_EQ(frontier({{3, 3}}), (std::vector<size_t>{0}));
}

TEST(PlanPareto, EqualPointsKeepOne) {
  const auto f = frontier({{2, 4}, {1, 8}, {2, 4}});
  ASSERT_EQ(f.size(), 2u);
  EXPECT_EQ(f[0], 1u);
  EXPECT_TRUE(f[1] == 0u || f[1] == 2u);
}

Row row(const std::string& block, const std::string& variant, int64_t latency, double ii, double err, int64_t cells) {
  Row r;
  r.block = block, r.variant = variant, r.scheme = variant;
  r.latency_cycles = latency, r.ii_cycles = ii, r.max_abs_err = err, r.cells = cells;
  return r;
}

TEST(PlanPareto, PointsPerBlockAndMeasure) {
  const std::vector<Row> rs = {
      row("b", "r0", 2, 1, 0.5, 100),   // cycles 3
      row("b", "r1", 4, 1, 0.1, -1),    // cycles 5; no cells
      row("b", "r2", 6, 1, 0.3, 50),    // cycles 7: dominated by r1 on cycles; the cheapest in cells
      row("b", "r3", -1, 1, 0.01, 10),  // no latency: on no axis
      row("other", "o", 1, 1, 0.0, 1),  // another block
      row("b", "r5", 1, 1, NAN, 5),     // no error
      row("b", "r6", 3, 0, 0.5, 200),   // cycles 3 as r0, the same error: one of the two
  };
  ASSERT_EQ(kMeasures.size(), 4u);
  EXPECT_STREQ(kMeasures[0].stem, "cycles");
  EXPECT_STREQ(kMeasures[1].stem, "cells");
  EXPECT_STREQ(kMeasures[2].stem, "ns_per_item");
  EXPECT_STREQ(kMeasures[3].stem, "area_um2");

  const Points cyc = points(rs, "b", kMeasures[0]);
  ASSERT_EQ(cyc.rows.size(), 4u);  // r0 r1 r2 r6
  EXPECT_EQ(cyc.xy[0], (std::pair<double, double>{3, 0.5}));
  EXPECT_EQ(cyc.xy[2], (std::pair<double, double>{7, 0.3}));
  EXPECT_EQ(cyc.front.size(), 2u);
  EXPECT_TRUE(cyc.front.count(&rs[1]));
  EXPECT_EQ(cyc.front.count(&rs[0]) + cyc.front.count(&rs[6]), 1u);
  EXPECT_FALSE(cyc.front.count(&rs[2]));

  const Points cells = points(rs, "b", kMeasures[1]);
  ASSERT_EQ(cells.rows.size(), 3u);  // r0 r2 r6: r1 has no cells
  EXPECT_EQ(cells.front, (std::set<const Row*>{&rs[2]}));  // 50 cells at 0.3 beats 100 and 200 at 0.5

  // No standard-cell result: nothing on the ns-per-item and area axes.
  EXPECT_TRUE(points(rs, "b", kMeasures[2]).rows.empty());
  EXPECT_TRUE(points(rs, "b", kMeasures[3]).rows.empty());
}

TEST(PlanPareto, NsPerItemAndAreaFromTheStandardCells) {
  Row a = row("b", "a", 2, 2, 0.5, 10), c = row("b", "c", 2, 1, 0.7, 10);
  a.period_ns = 5, a.area_um2 = 1000;  // 2 x 5 = 10 ns per item
  c.period_ns = 4, c.area_um2 = 900;   // 1 x 4 = 4 ns per item
  const std::vector<Row> rs = {a, c};
  const Points ns = points(rs, "b", kMeasures[2]);
  ASSERT_EQ(ns.rows.size(), 2u);
  EXPECT_EQ(ns.xy[0].first, 10);
  EXPECT_EQ(ns.xy[1].first, 4);
  EXPECT_EQ(ns.front.size(), 2u);  // c faster, a more accurate
  EXPECT_EQ(cycles_x(a), 4);
}

TEST(PlanReportRow, JsonRoundTrip) {
  Row r = row("persp", "klane4", 9, 1.25, 0.0625, 1234);
  r.err_unit = "texels", r.notes = "n", r.area_um2 = 5000.5, r.period_ns = 6.25, r.stdcell_source = "measured";
  r.extra_json = "\"mad_vs_blinn\": 0.125";
  const Row b = Row::from_json(r.json());
  EXPECT_EQ(b.json(), r.json());
  EXPECT_EQ(b.latency_cycles, 9);
  EXPECT_EQ(b.cells, 1234);
  EXPECT_EQ(b.flip_flops, -1);
  EXPECT_EQ(b.area_um2, 5000.5);
  EXPECT_EQ(b.ns_per_item(), 1.25 * 6.25);
  EXPECT_EQ(b.extra_json, "\"mad_vs_blinn\": 0.125");
  EXPECT_EQ(jnum(0.1), "0.1");
  EXPECT_EQ(jnum(INFINITY), "null");
  EXPECT_THROW(Row::from_json("{\"block\": \"b\"}"), std::invalid_argument);
}

}  // namespace
}  // namespace tu::report
