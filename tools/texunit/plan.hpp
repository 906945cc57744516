// `texunit plan SCENE.json [--json] [--out FILE.sv]`: a texture unit specialised to a scene.
// Reads the scene and the measured report table (docs/report/report.json), asks the planner
// library for the plan (planner/plan.hpp: the blocks and the cheapest variant of each that meets
// the budget, the cycles and area of the specialised unit against the full unit), prints it and
// writes the RTL configuration package tu_unit_cfg_pkg.
#pragma once

#include <string>

#include "planner/plan.hpp"  // scene_stream_cycles, BudgetError (filter_cmd, objspace_cmd)

namespace tu::plan {

struct Options {
  std::string scene;                             // file, or "default"
  // Measured table (`scripts/report.sh`); empty: the copy of docs/report/report.json built into
  // the binary (so that plan works from any directory).
  std::string report;
  std::string out_sv;                            // SystemVerilog package; empty: none
  std::string out_full_sv;                       // the same for the full unit (area comparison)
  bool json = false;
  // The frame's cycle budget on the planned unit (0: none): the noise scheme (octave-serial when
  // it meets the budget, docs/blocks/noise-appendix.md §5 "Plan").
  double max_cycles = 0;
};

int run(const Options& opt);

}  // namespace tu::plan
