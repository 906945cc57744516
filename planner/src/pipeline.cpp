// `texunit plan`: the pipeline per material (pipeline.hpp).
#include "planner/pipeline.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>

#include "objspace/objspace.hpp"
#include "planner/plan.hpp"
#include "texunit/render.hpp"

namespace tu::plan {

double engine_clocks(ewa::Engine e) {
  ewa::PixelCost c;
  c.engine = e;
  return double(ewa::stream_cycles(std::vector<ewa::PixelCost>(2000, c)) -
                ewa::stream_cycles(std::vector<ewa::PixelCost>(1000, c))) / 1000.0;
}

namespace {
std::string num(const char* f, double x) {
  char b[64];
  std::snprintf(b, sizeof b, f, x);
  return b;
}
}  // namespace

PipelineChoice choose_pipeline(const scene::Scene& s, const std::string& material, scene::Filter filter, bool procedural) {
  PipelineChoice c;
  c.material = material;
  c.screen_filter = filter;
  const scene::Material& m = s.materials.at(material);
  if (m.relief || procedural) {
    c.why = material + ": screen space (object space has no " + std::string(m.relief ? "relief step" : "noise unit") + ")";
    return c;
  }
  // The material alone, texture path only: both pipelines see the same pixels.
  scene::Scene t = scene::without_relief(s);
  t.lights.clear();
  t.objects.clear();
  for (const auto& o : s.objects)
    if (o.material == material) t.objects.push_back(o);
  for (auto& [name, mat] : t.materials) mat.filter = filter;
  size_t covered = 0;
  const uint64_t screen =
      scene_stream_cycles(t, [filter](const scene::Material&) { return filter; }, false, std::nullopt, false, 0, {}, &covered);
  c.covered = covered;
  if (c.covered == 0) {
    c.why = material + ": screen space (no pixel)";
    return c;
  }
  const double n = static_cast<double>(c.covered);
  std::optional<render::Frame> ewa;  // the float EWA reference, once an object-space render completes
  c.screen_clocks_per_px = static_cast<double>(screen) / n;
  // Object space: one lookup per sample on the unit's trilinear engine, one divide per pixel.
  c.sample_clocks = engine_clocks(ewa::Engine::Trilinear);
  const double cap_d = std::floor((static_cast<double>(screen) - n) / c.sample_clocks);
  const ObjectSpaceTry* best = nullptr;
  for (double sp : kObjectSpaceSpacings) {
    ObjectSpaceTry k;
    k.spacing = sp;
    k.samples = static_cast<uint64_t>(std::max(0.0, cap_d));
    if (k.samples == 0) {
      c.tries.push_back(k);
      continue;
    }
    objspace::Options o;
    o.spacing = sp;
    o.max_samples = k.samples;  // more samples than this cost at least the screen clocks
    try {
      const auto r = objspace::render_cmodel(t, o);
      k.rendered = true;
      k.samples = r.stats.samples;
      k.holes = r.stats.holes;
      k.overlaps = r.stats.overlaps;
      if (!ewa) ewa = render::render_ref(t, scene::Filter::Ewa);
      k.psnr_db = render::psnr_covered(r.frame, *ewa);
      k.clocks_per_px = (c.sample_clocks * static_cast<double>(k.samples) + n) / n;
    } catch (const std::runtime_error& e) {
      // The sample cap (objspace: "exceed(s) ... --max-samples", counted samples or a triangle's
      // grid over 4x the cap) or a set-up error: not a candidate at this spacing.
      const std::string what = e.what();
      if (what.find("--max-samples") == std::string::npos) k.error = what;
    }
    c.tries.push_back(k);
    const ObjectSpaceTry& b = c.tries.back();
    if (b.rendered && b.holes == 0 && b.psnr_db >= s.budget.min_psnr_db && b.clocks_per_px < c.screen_clocks_per_px &&
        (!best || b.clocks_per_px < best->clocks_per_px))
      best = &b;
  }
  c.object_space = best != nullptr;
  std::string tries;
  for (const auto& k : c.tries) {
    tries += (tries.empty() ? "" : "; ") + std::string("spacing ") + num("%.2g", k.spacing) + ": ";
    if (!k.error.empty())
      tries += k.error;
    else if (!k.rendered)
      tries += "> " + std::to_string(k.samples) + " samples (" + num("%.2f", double(k.samples) / n) +
               "/px), >= the screen clocks";
    else
      tries += num("%.2f", double(k.samples) / n) + " samples/px, " + num("%.2f", k.clocks_per_px) + " clk/px, " +
               num("%.2f", k.psnr_db) + " dB, " + std::to_string(k.holes) + " holes";
  }
  c.why = material + ": " + (c.object_space ? "object space (spacing " + num("%.2g", best->spacing) + ")" : "screen space") +
          "; screen " + std::string(scene::to_string(c.screen_filter)) + " " + num("%.2f", c.screen_clocks_per_px) + " clk/px; object space (" +
          num("%.0f", c.sample_clocks) + " clk/sample + 1 divide/px, budget " + num("%g", s.budget.min_psnr_db) +
          " dB, no holes): " + tries;
  return c;
}

}  // namespace tu::plan
