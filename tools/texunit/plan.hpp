// `texunit plan SCENE.json [--json] [--out FILE.sv]`: a texture unit specialised to a scene.
// Reads the scene's footprints (float reference), relief and error budget and the measured report
// table (docs/report/report.json), picks the blocks and the cheapest variant of each that meets
// the budget, writes the RTL configuration package tu_unit_cfg_pkg and prints the cycles and area
// of the specialised unit against the full unit.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "ewa/ewa_cycles.hpp"
#include "texunit/scene.hpp"

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
  // it meets the budget, docs/blocks/noise.md §5 "Plan").
  double max_cycles = 0;
};

// Thrown when no variant meets the budget; the message names the budget field.
struct BudgetError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

int run(const Options& opt);

// Clocks of the RTL texture unit (texture path) for a scene with `filter_of` choosing each
// material's filter: ewa::stream_cycles on the C-model render's per-pixel work (exact against
// Verilator, TextureUnitRtl.CyclesMatchPrediction); clip_variant: the unit's EwaClipVariant (the
// border pipeline's latency for materials with border weights); noise_objects[o]: object o's pixels
// go to the noise unit (a procedural material; TextureUnitRtl.ProceduralSceneEqualsCModelCyclesPredicted);
// covered (if given): the render's covered pixels.
uint64_t scene_stream_cycles(const scene::Scene& s, const std::function<scene::Filter(const scene::Material&)>& filter_of,
                             bool relief_stage, std::optional<scene::WeightSource> weights = std::nullopt,
                             bool ell_recurrence = false, int clip_variant = 0,
                             const std::vector<bool>& noise_objects = {}, size_t* covered = nullptr,
                             const std::vector<bool>& water_objects = {}, int noise_slots = 1,
                             const ewa::EngineParams& engine = {});

}  // namespace tu::plan
