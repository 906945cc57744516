// The report's Pareto selection (pareto.hpp); moved from tools/texunit/report.cpp.
#include "planner/pareto.hpp"

#include <algorithm>
#include <cmath>

namespace tu::report {

std::vector<size_t> frontier(const std::vector<std::pair<double, double>>& pts) {
  std::vector<size_t> idx(pts.size());
  for (size_t i = 0; i < idx.size(); ++i) idx[i] = i;
  std::sort(idx.begin(), idx.end(), [&](size_t a, size_t b) { return pts[a] < pts[b]; });
  std::vector<size_t> f;
  double best = INFINITY;
  for (size_t i : idx)
    if (pts[i].second < best) {
      best = pts[i].second;
      f.push_back(i);
    }
  return f;
}

double cycles_x(const Row& r) { return static_cast<double>(r.latency_cycles) + r.ii_cycles; }

const std::vector<Measure> kMeasures = {
    {"cycles", "latency + II (cycles)", [](const Row& r) { return r.latency_cycles < 0 ? -1.0 : cycles_x(r); }},
    {"cells", "Yosys cells (synth, generic gates)", [](const Row& r) { return static_cast<double>(r.cells); }},
    {"ns_per_item", "ns per item (II x clock period, osu018)", [](const Row& r) { return r.ns_per_item(); }},
    {"area_um2", "area (um^2, osu018 standard cells)", [](const Row& r) { return r.area_um2; }}};

Points points(const std::vector<Row>& rs, const std::string& grp, const Measure& m) {
  Points p;
  for (const auto& r : rs) {
    const double x = m.x(r);
    if (r.block != grp || x <= 0 || r.latency_cycles < 0 || !(r.max_abs_err >= 0)) continue;
    p.rows.push_back(&r);
    p.xy.emplace_back(x, r.max_abs_err);
  }
  for (size_t i : frontier(p.xy)) p.front.insert(p.rows[i]);
  return p;
}


}  // namespace tu::report
