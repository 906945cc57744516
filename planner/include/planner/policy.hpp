// The plan's policy as pure functions (no render, no I/O): the footprint gates, the filter order,
// the quantile they use, the measured report table's rows and the cheapest variant meeting a
// budget, and the sum of a unit's blocks. Unit tests: planner/test/policy_test.cpp.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "texunit/scene.hpp"

namespace tu::plan {

// Footprint thresholds: below them a pixel needs neither mip selection nor an anisotropic filter.
constexpr double kMinifyLod = 0.5;  // footprint LOD (log2 texels per pixel) still served by level 0
constexpr double kIsoAniso = 2.0;   // major / minor still served by an isotropic (trilinear) filter
constexpr double kQuantile = 0.99;  // the gates use the 99th percentile (1% of pixels may exceed)

// The element at index floor(q (n - 1)) of the sorted values (no interpolation); 0 when empty.
double quantile(std::vector<double> v, double q);

// The footprint gates on a material's p99 LOD and anisotropy (inclusive thresholds).
inline bool bilinear_gate(double q_lod, double q_aniso) { return q_lod <= kMinifyLod && q_aniso <= kIsoAniso; }
inline bool trilinear_gate(double q_aniso) { return q_aniso <= kIsoAniso; }

// The filters the plan chooses among, cheapest first: bilinear, trilinear, Feline, EWA (the most
// capable). -1 for a filter the plan does not choose (nearest).
int filter_rank(scene::Filter f);
// The most capable of the materials' filters: it names the unit's footprint path and weights
// (bilinear when there is none).
scene::Filter unit_filter(const std::map<std::string, scene::Filter>& per_material);

// One material's filter, cheapest first: bilinear when its footprint gate passes and its render
// meets min_psnr_db, else trilinear likewise, else Feline when `feline` finds a probe cap (> 0),
// else EWA. The measurements are callbacks, called only when the cascade reaches them (the
// renders are expensive); `why` gives the numbers behind the choice.
struct FelineProbe {
  int cap = 0;  // the chosen probe cap; 0: Feline not chosen
  std::string why;
};
struct MaterialFilter {
  scene::Filter filter = scene::Filter::Ewa;
  int feline_cap = 0;
  std::string why;
};
MaterialFilter choose_filter(const std::string& material, double q_lod, double q_aniso, double min_psnr_db,
                             const std::function<double()>& bilinear_psnr, const std::function<double()>& trilinear_psnr,
                             const std::function<FelineProbe()>& feline);

// A row of the measured report table (docs/report/report.json) as the plan reads it.
struct TRow {
  std::string block, variant, scheme, rtl_top;
  double max_abs = 0, rms = 0, ii = 0, cells = -1;  // cells -1: not measured
  double area_um2 = -1, fmax_mhz = -1;               // osu018 standard cells; -1: not measured
  int64_t latency = 0, mul = 0;
  std::string name() const { return block + "/" + variant + (scheme == variant ? "" : " (" + scheme + ")"); }
};

// The rows of the JSON text of a report table; `path` names it in the errors (malformed JSON, not
// an array, a missing or mistyped field: "PATH: /I/FIELD: ...").
std::vector<TRow> parse_table(const std::string& text, const std::string& path);

// Thrown when no variant meets the budget; the message names the budget field.
struct BudgetError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// What "cheapest" means: least osu018 area when every candidate meeting the budget has one; else
// fewest Yosys cells, rows without cells after every row with cells, by fewest multipliers.
constexpr const char* kCostByArea = "osu018 area (um2)";
double cost(const TRow& r, bool by_area);

// The cheapest row among `cands` meeting `ok`. Throws BudgetError "FIELD: no WHAT variant reaches
// it (best: NAME at VALUE)" when none does (VALUE: |score| of the best-scoring row in `unit`'s
// printf format), std::runtime_error when `cands` is empty. When a row meeting `ok` has no area
// the choice is by cells and *cost_basis says so (else it is left as it is).
const TRow* cheapest(const std::vector<const TRow*>& cands, const std::function<bool(const TRow&)>& ok,
                     const std::function<double(const TRow&)>& score, const std::string& field, const std::string& what,
                     const char* unit, std::string* cost_basis);

// Weight-table rows the EWA engine does not implement: 20 log10(1 / rms) with the value range
// [0, 1] as the peak (infinite for rms 0).
double weight_db(const TRow& r);
// The EWA engine's weight source of a weight row, if the engine implements it (formula, the RTL's
// 1-D and 2-D tables).
std::optional<scene::WeightSource> engine_source(const TRow& r);

// A unit as blocks of the report table: stages in sequence, each stage alternatives in parallel,
// each alternative a sequence of blocks; area_only blocks add area but no latency.
struct Unit {
  std::vector<std::vector<std::vector<const TRow*>>> stages;  // stage -> alternatives -> sequence
  std::vector<const TRow*> area_only;                        // e.g. per-scanline set-up
  double texels_per_pixel = 1;
  std::vector<const TRow*> all() const;
  int64_t latency() const;  // sum over stages of the slowest alternative's summed latency
  double ii() const;        // the largest block II (at least 1)
  double cells() const;     // sum of the measured cells
  double area_um2() const;  // sum of the measured areas
  bool area_measured() const;
  bool cells_measured() const;
  // The unit's clock: its slowest block's fmax (blocks synthesised alone); -1 when an area is missing.
  double fmax_mhz() const;
};

// printf of one double (the plan's numbers in its reasons).
std::string fmt(const char* f, double x);

}  // namespace tu::plan
