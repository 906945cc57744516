// `texunit plan SCENE.json [--json] [--out FILE.sv]`: a texture unit specialised to a scene.
// Reads the scene's footprints (float reference), relief and error budget and the measured report
// table (docs/report/report.json), picks the blocks and the cheapest variant of each that meets
// the budget, writes the RTL configuration package tu_unit_cfg_pkg and prints the cycles and area
// of the specialised unit against the full unit.
#pragma once

#include <stdexcept>
#include <string>

namespace tu::plan {

struct Options {
  std::string scene;                             // file, or "default"
  // Measured table (`scripts/report.sh`); empty: the copy of docs/report/report.json built into
  // the binary (so that plan works from any directory).
  std::string report;
  std::string out_sv;                            // SystemVerilog package; empty: none
  std::string out_full_sv;                       // the same for the full unit (area comparison)
  bool json = false;
};

// Thrown when no variant meets the budget; the message names the budget field.
struct BudgetError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

int run(const Options& opt);

}  // namespace tu::plan
