// The plan's pure policy (planner/policy.hpp): expected values worked out by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "planner/policy.hpp"

namespace tu::plan {
namespace {

using scene::Filter;

TEST(PlanQuantile, IndexIsFloorOfQTimesNMinusOne) {
  EXPECT_EQ(quantile({}, 0.99), 0.0);
  EXPECT_EQ(quantile({7.5}, 0.99), 7.5);
  // Sorted 1 2 3 4 5; floor(0.99 x 4) = 3: the fourth value, not the maximum.
  EXPECT_EQ(quantile({5, 1, 4, 2, 3}, 0.99), 4.0);
  // 0..10 shuffled: floor(0.99 x 10) = 9.
  EXPECT_EQ(quantile({3, 10, 0, 7, 1, 9, 2, 8, 4, 6, 5}, 0.99), 9.0);
  EXPECT_EQ(quantile({3, 10, 0, 7, 1, 9, 2, 8, 4, 6, 5}, 0.5), 5.0);
  EXPECT_EQ(quantile({2, 2, 9}, 0.99), 2.0);  // floor(1.98) = 1
}

TEST(PlanGates, BilinearAtItsThresholds) {
  EXPECT_EQ(kMinifyLod, 0.5);
  EXPECT_EQ(kIsoAniso, 2.0);
  EXPECT_TRUE(bilinear_gate(0.5, 2.0));   // both thresholds inclusive
  EXPECT_TRUE(bilinear_gate(-3.0, 1.0));  // magnified
  EXPECT_FALSE(bilinear_gate(std::nextafter(0.5, 1.0), 2.0));
  EXPECT_FALSE(bilinear_gate(0.5, std::nextafter(2.0, 3.0)));
  EXPECT_FALSE(bilinear_gate(0.6, 1.0));
}

TEST(PlanGates, TrilinearOnAnisotropyOnly) {
  EXPECT_TRUE(trilinear_gate(2.0));
  EXPECT_TRUE(trilinear_gate(1.0));
  EXPECT_FALSE(trilinear_gate(std::nextafter(2.0, 3.0)));
  EXPECT_FALSE(trilinear_gate(16.0));
}

TEST(PlanFilterOrder, BilinearTrilinearFelineEwa) {
  EXPECT_EQ(filter_rank(Filter::Bilinear), 0);
  EXPECT_EQ(filter_rank(Filter::Trilinear), 1);
  EXPECT_EQ(filter_rank(Filter::Feline), 2);
  EXPECT_EQ(filter_rank(Filter::Ewa), 3);
  EXPECT_EQ(filter_rank(Filter::Nearest), -1);
  EXPECT_EQ(unit_filter({}), Filter::Bilinear);
  EXPECT_EQ(unit_filter({{"a", Filter::Bilinear}}), Filter::Bilinear);
  EXPECT_EQ(unit_filter({{"a", Filter::Bilinear}, {"b", Filter::Trilinear}}), Filter::Trilinear);
  EXPECT_EQ(unit_filter({{"a", Filter::Feline}, {"b", Filter::Trilinear}}), Filter::Feline);
  EXPECT_EQ(unit_filter({{"a", Filter::Bilinear}, {"b", Filter::Ewa}, {"c", Filter::Feline}}), Filter::Ewa);
}

// The cascade with measurements given by the test; counts which ones it asked for.
struct Probe {
  double bil = 0, tri = 0;
  int feline_cap = 0;
  int bil_calls = 0, tri_calls = 0, feline_calls = 0;
  MaterialFilter run(double ql, double qa, double min_db = 35) {
    return choose_filter(
        "m", ql, qa, min_db, [&] { return ++bil_calls, bil; }, [&] { return ++tri_calls, tri; },
        [&] { return ++feline_calls, FelineProbe{feline_cap, "feline: probe"}; });
  }
};

TEST(PlanFilterOrder, BilinearWhenItsGateAndPsnrPass) {
  Probe p{40, 50, 4};
  const auto f = p.run(0.5, 2.0);
  EXPECT_EQ(f.filter, Filter::Bilinear);
  EXPECT_EQ(f.why, "m: bilinear: footprint gate passes, PSNR 40.00 dB");
  EXPECT_EQ(p.tri_calls + p.feline_calls, 0);  // cheaper first: nothing else measured
}

TEST(PlanFilterOrder, TrilinearWhenBilinearMissesThePsnr) {
  Probe p{30, 36, 4};
  const auto f = p.run(0.2, 1.5);
  EXPECT_EQ(f.filter, Filter::Trilinear);
  EXPECT_EQ(f.why, "m: bilinear: footprint gate passes, PSNR 30.00 dB; trilinear: footprint gate passes, PSNR 36.00 dB");
  EXPECT_EQ(p.feline_calls, 0);
  // The PSNR threshold is inclusive.
  Probe q{35, 0, 0};
  EXPECT_EQ(q.run(0.2, 1.5).filter, Filter::Bilinear);
}

TEST(PlanFilterOrder, FelineWhenTrilinearFailsAndACapIsFound) {
  Probe p{50, 20, 8};
  const auto f = p.run(1.0, 1.5);  // LOD over 0.5: bilinear's gate fails, not measured
  EXPECT_EQ(f.filter, Filter::Feline);
  EXPECT_EQ(f.feline_cap, 8);
  EXPECT_EQ(p.bil_calls, 0);
  EXPECT_EQ(f.why,
            "m: bilinear: footprint gate fails (p99 LOD 1.00, p99 anisotropy 1.50); trilinear: footprint gate passes, "
            "PSNR 20.00 dB; feline: probe");
}

TEST(PlanFilterOrder, EwaWhenNoCheaperFilterQualifies) {
  Probe p{50, 50, 0};
  const auto f = p.run(0.0, 3.0);  // anisotropic: neither isotropic gate passes
  EXPECT_EQ(f.filter, Filter::Ewa);
  EXPECT_EQ(f.feline_cap, 0);
  EXPECT_EQ(p.bil_calls + p.tri_calls, 0);
  EXPECT_EQ(p.feline_calls, 1);
  EXPECT_EQ(f.why,
            "m: bilinear: footprint gate fails (p99 LOD 0.00, p99 anisotropy 3.00); trilinear: footprint gate fails "
            "(p99 anisotropy 3.00); feline: probe");
}

TRow row(const std::string& variant, double max_abs, double area, double cells, int64_t mul = 0) {
  TRow r;
  r.block = "persp", r.variant = variant, r.scheme = variant, r.rtl_top = "tu_persp";
  r.max_abs = max_abs, r.area_um2 = area, r.cells = cells, r.mul = mul;
  return r;
}

struct Cheapest {
  std::string basis = kCostByArea;
  const TRow* operator()(const std::vector<const TRow*>& cands, double max_err) {
    return cheapest(
        cands, [&](const TRow& r) { return r.max_abs <= max_err; }, [](const TRow& r) { return -r.max_abs; },
        "scene.json: /error_budget/max_texel_err = " + fmt("%g", max_err), "persp", "%.4g texel", &basis);
  }
};

TEST(PlanCheapest, LeastAreaMeetingTheBudget) {
  const TRow a = row("a", 0.01, 300, 100), b = row("b", 0.05, 200, 120), c = row("c", 0.2, 100, 50);
  Cheapest pick;
  EXPECT_EQ(pick({&a, &b, &c}, 0.06), &b);  // c is smaller but misses the budget
  EXPECT_EQ(pick({&a, &b, &c}, 0.2), &c);   // the budget is inclusive
  EXPECT_EQ(pick({&a, &b, &c}, 0.02), &a);
  EXPECT_EQ(pick.basis, kCostByArea);
}

TEST(PlanCheapest, RowFailingTheBudgetWithoutAreaKeepsTheAreaBasis) {
  const TRow a = row("a", 0.01, 300, 100), b = row("b", 0.05, 200, 120), c = row("c", 0.2, -1, 50);
  Cheapest pick;
  EXPECT_EQ(pick({&a, &b, &c}, 0.06), &b);
  EXPECT_EQ(pick.basis, kCostByArea);
}

TEST(PlanCheapest, CellsWhenACandidateHasNoArea) {
  // b meets the budget without an osu018 area: every candidate by Yosys cells (a: 100 < b: 120).
  const TRow a = row("a", 0.01, 300, 100), b = row("b", 0.05, -1, 120), c = row("c", 0.2, 100, 50);
  Cheapest pick;
  EXPECT_EQ(pick({&a, &b, &c}, 0.06), &a);
  EXPECT_EQ(pick.basis, "Yosys cells (persp/b has no osu018 area: run scripts/stdcell.sh)");
}

TEST(PlanCheapest, MultipliersWhenCellsAreMissing) {
  // No area and no cells: fewest multipliers; a row with cells before every row without.
  const TRow a = row("a", 0.01, -1, -1, 4), b = row("b", 0.02, -1, -1, 2), c = row("c", 0.03, -1, 5000, 9);
  Cheapest pick;
  EXPECT_EQ(pick({&a, &b}, 0.05), &b);
  EXPECT_EQ(pick({&a, &b, &c}, 0.05), &c);
  EXPECT_EQ(cost(a, false), 1e12 + 4);
  EXPECT_EQ(cost(c, false), 5000);
  EXPECT_EQ(cost(c, true), -1);
}

TEST(PlanCheapest, BudgetErrorNamesTheFieldAndTheClosestVariant) {
  const TRow a = row("a", 0.01, 300, 100), b = row("b", 0.05, 200, 120);
  Cheapest pick;
  try {
    pick({&b, &a}, 0.001);
    FAIL() << "no BudgetError";
  } catch (const BudgetError& e) {
    EXPECT_STREQ(e.what(),
                 "scene.json: /error_budget/max_texel_err = 0.001: no persp variant reaches it (best: persp/a at 0.01 texel)");
  }
  // No candidate at all is not a budget problem: the table lacks the block.
  try {
    pick({}, 1);
    FAIL() << "no error";
  } catch (const BudgetError&) {
    FAIL() << "an empty candidate list is not a BudgetError";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "report table has no persp row with an RTL (run scripts/report.sh)");
  }
}

TEST(PlanTable, ParsesRowsAndNamesTheBadField) {
  const auto rows = parse_table(
      R"([{"block": "persp", "variant": "klane4", "scheme": "persp_k4", "rtl_top": "tu_persp_klane",
           "max_abs_err": 0.25, "rms_err": 0.125, "ii_cycles": 1, "latency_cycles": 9, "cells": 1234,
           "multipliers": 3, "area_um2": 5000.5, "fmax_mhz": 150},
          {"block": "ellipse", "variant": "analytic", "scheme": "analytic", "rtl_top": "", "max_abs_err": 0,
           "rms_err": 0, "ii_cycles": 2, "latency_cycles": "n/a", "cells": "not measured: --no-yosys",
           "multipliers": "not measured"}])",
      "t.json");
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].name(), "persp/klane4 (persp_k4)");
  EXPECT_EQ(rows[0].latency, 9);
  EXPECT_EQ(rows[0].cells, 1234);
  EXPECT_EQ(rows[0].area_um2, 5000.5);
  EXPECT_EQ(rows[1].name(), "ellipse/analytic");
  EXPECT_EQ(rows[1].latency, -1);
  EXPECT_EQ(rows[1].cells, -1);
  EXPECT_EQ(rows[1].area_um2, -1);  // a table without the standard-cell columns
  auto error = [](const std::string& text) {
    try {
      parse_table(text, "t.json");
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error(R"([{"block": "persp"}])"), "t.json: /0/variant: missing");
  EXPECT_EQ(error(R"({"block": "persp"})"), "t.json: expected a JSON array of report rows");
  EXPECT_EQ(error(R"([{"block": "b", "variant": "v", "scheme": "s", "rtl_top": "", "max_abs_err": "x"}])"),
            "t.json: /0/max_abs_err: expected a number");
}

TEST(PlanUnit, SumsBlocksAndTakesTheSlowestAlternative) {
  TRow s = row("setup", 0, 1000, 10), p = row("p", 0, 2000, 20), x = row("x", 0, 300, 3), y = row("y", 0, 400, 4),
       z = row("z", 0, 500, 5);
  s.latency = 100, p.latency = 5, x.latency = 7, y.latency = 4, z.latency = 6;
  p.ii = 1, x.ii = 3, y.ii = 0.5;
  s.fmax_mhz = 90, p.fmax_mhz = 200, x.fmax_mhz = 150, y.fmax_mhz = 120, z.fmax_mhz = 300;
  Unit u;
  u.area_only = {&s};
  u.stages = {{{&p}}, {{&x}, {&y, &z}}};  // second stage: x (7) beside y then z (4 + 6 = 10)
  EXPECT_EQ(u.latency(), 5 + 10);        // area-only blocks add no latency
  EXPECT_EQ(u.ii(), 3);
  EXPECT_EQ(u.cells(), 10 + 20 + 3 + 4 + 5);
  EXPECT_EQ(u.area_um2(), 1000 + 2000 + 300 + 400 + 500);
  EXPECT_TRUE(u.area_measured());
  EXPECT_EQ(u.fmax_mhz(), 90);
  z.area_um2 = -1;
  EXPECT_FALSE(u.area_measured());
  EXPECT_EQ(u.fmax_mhz(), -1);
  EXPECT_EQ(u.area_um2(), 1000 + 2000 + 300 + 400);
  z.cells = -1;
  EXPECT_FALSE(u.cells_measured());
}

TEST(PlanWeights, DbOfRmsAndEngineSources) {
  TRow r = row("w", 0, 1, 1);
  r.rms = 0.01;
  EXPECT_DOUBLE_EQ(weight_db(r), 40.0);
  r.rms = 0;
  EXPECT_TRUE(std::isinf(weight_db(r)));
  r.block = "gauss_weight";
  EXPECT_EQ(engine_source(r), scene::WeightSource::Formula);
  r.block = "weight_table", r.scheme = "weight_table_2d";
  EXPECT_EQ(engine_source(r), scene::WeightSource::Table2d);
  r.scheme = "weight_table_1d";
  EXPECT_EQ(engine_source(r), scene::WeightSource::Table1d);
  r.scheme = "weight_table_lerp";
  EXPECT_EQ(engine_source(r), std::nullopt);
}

}  // namespace
}  // namespace tu::plan
