// A row of `texunit report` (one block variant: error, cycles, area, speed) and its JSON form, the
// format of docs/report/report.json (the measuring is tools/texunit/report*.cpp's).
#pragma once

#include <cstdint>
#include <string>

namespace tu::report {

struct Row {
  std::string block, variant, scheme;
  double max_abs_err = 0, rms_err = 0, max_ulp_err = 0;
  int64_t latency_cycles = -1;  // -1: n/a
  double ii_cycles = 0;
  std::string cycles_source;    // "measured (Verilator ...)" or "estimated (graph)"
  int64_t cells = -1, flip_flops = -1, multipliers = -1, memory_bits = -1;
  std::string area_source = "n/a", rtl_top, notes;
  double cmodel_ns_per_item = 0;
  double rtl_sim_items_per_s = -1;  // -1: not measured (rtl_sim_source says why)
  std::string rtl_sim_source = "not measured: no RTL";
  std::string err_unit;             // what max_abs_err is measured in
  // Standard cells (scripts/stdcell_flow.sh, OSU 0.18 um): -1 = not measured, stdcell_source says why.
  double area_um2 = -1, period_ns = -1, fmax_mhz = -1;
  int64_t stdcell_cells = -1;
  std::string stdcell_source = "not measured: no RTL", critical_path;
  double latency_ns() const { return period_ns < 0 || latency_cycles < 0 ? -1 : static_cast<double>(latency_cycles) * period_ns; }
  double ns_per_item() const { return period_ns < 0 || latency_cycles < 0 ? -1 : ii_cycles * period_ns; }
  std::string extra_json;           // block-specific keys, `"k": v, ...` (e.g. brdf: mad_vs_blinn)
  std::string json() const;
  // The inverse of json() (texunit merge); throws std::invalid_argument naming the missing key.
  static Row from_json(const std::string& text);
};

// Shortest text that reads back as the same double ("null" when not finite): `texunit merge`
// re-derives latency_ns, ns_per_item and the Pareto sets from the shards' JSON exactly as the
// unsharded run does.
std::string jnum(double x);

}  // namespace tu::report
