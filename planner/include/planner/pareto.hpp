// The report's Pareto selection: per block, max abs error against a cost (cycles, Yosys cells,
// ns per item, osu018 area), both minimised. Unit tests: planner/test/pareto_test.cpp.
#pragma once

#include <cstddef>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "planner/report_row.hpp"

namespace tu::report {

// Pareto frontier of (x, y) points, both minimised: the indices of the points no other point
// dominates, sorted by x. A point equal to another is dominated by it (one of them is kept), so
// is a point of equal x and larger y, or of equal y and larger x.
std::vector<size_t> frontier(const std::vector<std::pair<double, double>>& pts);

// latency + II: the cycles axis.
double cycles_x(const Row& r);

// The cost axes of the Pareto plots: file suffix, axis label, value (<= 0: not measured).
struct Measure {
  const char* stem;
  const char* label;
  double (*x)(const Row&);
};
extern const std::vector<Measure> kMeasures;  // cycles, cells, ns_per_item, area_um2

// A block's rows that have the measure (> 0) and a latency and an error (>= 0), their points
// (measure, max abs error) and which of them are on the Pareto frontier.
struct Points {
  std::vector<const Row*> rows;
  std::vector<std::pair<double, double>> xy;
  std::set<const Row*> front;
};
Points points(const std::vector<Row>& rs, const std::string& grp, const Measure& m);

}  // namespace tu::report
