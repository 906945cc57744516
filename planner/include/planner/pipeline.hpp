// `texunit plan`: the pipeline per material, screen space (B1 -> B2 -> the material's filter) or
// object space (seed 003 §5, docs/blocks/objspace.md), decided by rendering
// (docs/reading-the-report.md "Pipeline per material").
#pragma once

#include <string>
#include <vector>

#include "ewa/ewa_cycles.hpp"
#include "texunit/scene.hpp"

namespace tu::plan {

// Steady-state clocks per pixel of one texture-unit engine (ewa::stream_cycles, the exact model
// of the RTL's engines).
double engine_clocks(ewa::Engine e);

// Sample spacings tried for object space (pixels at the plane's distance): the seed's 1 and
// coarser grids that still leave no hole (the splat's tent spans two pixels).
inline const std::vector<double> kObjectSpaceSpacings = {1.0, 1.5, 1.9};

struct ObjectSpaceTry {
  double spacing = 1;
  bool rendered = false;      // false: stopped at the sample cap (or a set-up error in `error`)
  uint64_t samples = 0;       // rendered: the samples; else the cap it exceeded
  uint64_t holes = 0, overlaps = 0;
  double psnr_db = 0;         // against the float EWA of the material alone, covered pixels
  double clocks_per_px = 0;   // rendered: trilinear clocks x samples + one divide per pixel
  std::string error;
};
struct PipelineChoice {
  std::string material;
  bool object_space = false;  // the chosen pipeline
  scene::Filter screen_filter = scene::Filter::Ewa;  // the plan's filter of the material (screen space)
  uint64_t covered = 0;       // the material's pixels rendered alone
  double screen_clocks_per_px = 0;  // the RTL texture unit (ewa::stream_cycles) with that filter
  double sample_clocks = 0;         // object space: clocks per sample (the unit's tu_trilinear)
  std::vector<ObjectSpaceTry> tries;
  std::string why;            // the numbers behind the choice, one line
};

// The material alone (its objects, no relief, no lights: the texture path both pipelines share)
// through both pipelines: screen space with `filter`, its clocks from ewa::stream_cycles on the
// C-model render; object space at each of kObjectSpaceSpacings, C-model render
// (objspace::render_cmodel) stopped once its samples cost the screen clocks (then it cannot win).
// Object space is chosen when a try has no hole, meets min_psnr_db against the float EWA of the
// same scene and takes fewer clocks per pixel; the cheapest such try. Relief and procedural
// materials (`procedural`: the plan has already removed the noise description) stay screen space
// (object space has no relief step and no noise unit).
PipelineChoice choose_pipeline(const scene::Scene& s, const std::string& material, scene::Filter filter,
                               bool procedural = false);

}  // namespace tu::plan
