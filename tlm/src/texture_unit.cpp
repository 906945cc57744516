#include <algorithm>
#include <stdexcept>

#include "ellipse/ellipse_scheme.hpp"
#include "ewa/ewa_cycles.hpp"
#include "ewa/ewa_fx.hpp"
#include "persp/schemes.hpp"
#include "texunit/formats.hpp"
#include "texunit/sched.hpp"
#include "texunit/texture_unit_model.hpp"

namespace tu::sysmodel {

ewa::PixelCost cost_of(const PixelWork& w) {
  return {static_cast<int>(w.levels), w.texels, w.no_weight, w.guard};
}

Workload scene_workload(const scene::Scene& s, const render::Frame& frame) {
  const auto cov = render::visibility(s);
  const int w = s.camera.width;
  Workload wl;
  for (int y = 0; y < s.camera.height; ++y) {
    for (int x = 0; x < w; ++x) {
      const auto& c = cov[static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x)];
      if (c.object < 0) continue;
      const bool extend = x > 0 && !wl.spans.empty() && wl.spans.back().y == y &&
                          wl.spans.back().object == c.object &&
                          wl.spans.back().triangle == c.triangle &&
                          wl.spans.back().x0 + static_cast<int>(wl.spans.back().count) == x;
      if (extend) {
        ++wl.spans.back().count;
      } else {
        wl.spans.push_back(Span{c.object, c.triangle, y, x, static_cast<uint32_t>(wl.pixels.size()), 1});
      }
      const size_t i = wl.pixels.size();
      if (i >= frame.pixels.size() || frame.pixels[i].x != x || frame.pixels[i].y != y)
        throw std::invalid_argument("scene_workload: the frame's pixels do not match the coverage at (" +
                                    std::to_string(x) + ", " + std::to_string(y) + ")");
      const auto& rec = frame.pixels[i];
      PixelWork p;
      p.texels = static_cast<uint32_t>(rec.texels);
      // In an EWA render only B1-guard pixels skip the filter (no levels tried).
      p.guard = rec.levels == 0;
      p.levels = static_cast<uint32_t>(std::max(rec.levels, 1));
      p.no_weight = (rec.ewa_flags & ewa::fx::kNoWeight) != 0;
      // Relief renders: a pixel the relief stage shifts (it used n >= 1 layers) and its march.
      p.relief = rec.relief_n > 0;
      p.steps = static_cast<uint32_t>(rec.relief_steps);
      wl.pixels.push_back(p);
    }
  }
  if (wl.pixels.size() != frame.pixels.size())
    throw std::invalid_argument("scene_workload: the frame has more pixels than the coverage");
  return wl;
}

Pipeline texture_unit(const UnitConfig& c) {
  const auto setup = sched::schedule(persp::scheme("persp_setup"));
  const auto ell = sched::schedule(ellipse::scheme());
  Pipeline p;
  p.name = "texture_unit";
  // tu_texture_unit (rtl/top): span -> [tu_persp_setup || tu_num_setup] -> tu_span_expand ->
  // [tu_persp || tu_ellipse || sideband FIFO] -> tu_fifo -> filter.
  // The two span set-ups have the same latency and II (tu_num_setup mirrors tu_persp_setup);
  // fixed pipelines (tu_pipe_valid) hold one item per register stage.
  StageSpec s;
  s.name = "span_setup";
  s.lat0 = setup.latency, s.ii0 = setup.ii, s.capacity = setup.latency, s.fifo_depth = c.span_fifo;
  p.stages.push_back(s);
  // The expander registers the span and emits one pixel per clock from the next cycle; it takes
  // the next span in the cycle its last pixel leaves.
  s = {};
  s.name = "span_expand";
  s.lat0 = 1, s.ii0 = 1, s.capacity = 1, s.expand = true, s.fifo_depth = 1;
  p.stages.push_back(s);
  // B1 and B2 fork from the expander and join at the filter FIFO: the join waits for the longer
  // (B1), and the shorter pipe (B2) stalls as a whole once its last stage holds a pixel the join
  // cannot take yet, so at most its latency's worth of pixels are in flight.
  s = {};
  s.name = "persp_ellipse";
  s.lat0 = std::max(fmt::kPerspLatency, ell.latency), s.ii0 = std::max(1, ell.ii);
  s.capacity = std::min(fmt::kPerspLatency, ell.latency), s.fifo_depth = 1;
  p.stages.push_back(s);
  if (c.relief_stage) {
    // tu_relief_stage: a pixel without a shift enters its sideband FIFO and leaves it the next
    // clock, one per clock; a shifted one (k march steps) leaves after the layer counter, the
    // set-up, the march (k + 1 compares, output register) and the refinement, k + 19 clocks, in
    // order (head-of-line join), and the march engine takes the next one after k + 1 clocks.
    // Approximate (relief::stage_cycles is the exact model of the stage alone): the set-up of the
    // next shifted pixel overlaps the march here only through the in-flight capacity.
    s = {};
    s.name = "relief";
    s.relief_only = true, s.bypass_latency = ewa::kReliefStagePassLatency, s.work = Work::Steps;
    s.lat0 = fmt::kPomLayersLatency + fmt::kPomSetupLatency + 2 + fmt::kPomRefineLatency, s.lat_per_work = 1;
    s.ii0 = 1, s.ii_per_work = 1;
    s.capacity = c.relief_fifo, s.fifo_depth = 1;
    p.stages.push_back(s);
  }
  // tu_fifo in front of the filter: registered storage, a pushed pixel is visible the next cycle.
  // tu_ewa: a set-up FSM (one pixel; its level loop repeats per texel-cap raise) hands a record
  // to the walker (one texel per clock, drain, normalise) over a direct link and accepts again
  // one clock after the hand-over, so pixel i+1's set-up overlaps pixel i's walk. Per-pixel
  // clocks are the RTL cycle model's (ewa_cycles.hpp), applied to the C model's counts.
  const ewa::EngineParams ep = c.ewa;
  s = {};
  s.name = "ewa_setup";
  s.capacity = 1, s.fifo_depth = c.pixel_fifo, s.link_latency = 1, s.release = 1;
  s.work = Work::Levels;
  s.timing = [ep](const PixelWork& w) {
    const int n = ewa::setup_cycles(cost_of(w), ep);
    return Timing{n, n + 1};
  };
  p.stages.push_back(s);
  s = {};
  s.name = "ewa_walk";
  s.capacity = 1, s.direct = true, s.fifo_depth = 1, s.work = Work::Texels;
  const int penalty = c.miss_penalty;
  s.timing = [penalty](const PixelWork& w) {
    const int n = ewa::walk_cycles(cost_of(w)) + penalty * static_cast<int>(w.misses);
    return Timing{n, n + 1};  // output valid and taken in its last clock, free the clock after
  };
  p.stages.push_back(s);
  return p;
}

}  // namespace tu::sysmodel
