// `texunit sysmodel`: the scene's pixel stream through the SystemC system model (tlm/).
#include "sysmodel_cmd.hpp"

#include <chrono>
#include <cstdio>
#include <iostream>

#include "texunit/render.hpp"
#include "texunit/scene.hpp"
#include "texunit/texture_unit_model.hpp"

namespace tu::cli {

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

CLI::App* add_sysmodel(CLI::App& app, SysmodelArgs& a) {
  auto* c = app.add_subcommand(
      "sysmodel", "cycle-approximate SystemC model of the unit on a scene: total cycles, per-block utilisation");
  c->add_option("SCENE", a.scene, "scene JSON file, or 'default' for the embedded scene")->required();
  c->add_option("--fifo-depth", a.fifo_depth, "pixels buffered between B2 and the filter")
      ->check(CLI::Range(1, 1024));
  c->add_flag("--json", a.json, "print one JSON object");
  return c;
}

int run_sysmodel(const SysmodelArgs& a) {
  const scene::Scene s = a.scene == "default" ? scene::default_scene() : scene::load(a.scene);
  const auto t0 = std::chrono::steady_clock::now();
  // Per-pixel work (texels walked) from the C-model render of the scene.
  const render::Frame frame = render::render_cmodel(s);
  const sysmodel::Workload wl = sysmodel::scene_workload(s, frame);
  const double work_s = seconds_since(t0);
  sysmodel::UnitConfig cfg;
  cfg.pixel_fifo = a.fifo_depth;
  const auto r = sysmodel::simulate(sysmodel::texture_unit(cfg), wl);
  if (a.json) {
    auto j = sysmodel::to_json(r);
    j["scene"] = s.source;
    j["spans"] = wl.spans.size();
    j["workload_seconds"] = work_s;
    std::cout << j.dump() << "\n";
  } else {
    std::printf("scene %s: %zu spans, %zu covered pixels (per-pixel work from the C model: %.3f s)\n",
                s.source.c_str(), wl.spans.size(), wl.pixels.size(), work_s);
    std::cout << sysmodel::table(r);
  }
  return 0;
}

}  // namespace tu::cli
