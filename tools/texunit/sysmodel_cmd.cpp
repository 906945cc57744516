// `texunit sysmodel`: the scene's pixel stream through the SystemC system model (tlm/).
#include "sysmodel_cmd.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <stdexcept>

#include "cli_checks.hpp"
#include "ewa/ewa_cycles.hpp"
#include "texunit/formats.hpp"
#include "texunit/render.hpp"
#include "texunit/scene.hpp"
#include "texunit/texel_cache.hpp"
#include "texunit/texture_unit_model.hpp"
#include "texture_unit_rtl.hpp"

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
  c->add_option("--cord-unroll", a.cord_unroll, "EWA set-up: CORDIC iterations per clock (divides EwaCordIter)")
      ->check(divisor_of(tu::fmt::kEwaCordIter, "EwaCordIter"));
  c->add_option("--sqrt-step", a.sqrt_step, "EWA set-up: square-root bits per clock (divides the root width)")
      ->check(divisor_of(tu::ewa::EngineParams{}.root_w, "the root width"));
  c->add_option("--engine-compare", a.compare,
                 "also render the scene through the RTL (Verilator) in this process: both cycle totals, ratios")
      ->check(CLI::IsMember({"rtl"}));
  c->add_flag("--relief", a.relief,
              "apply each material's relief: shifted pixels' march steps (C model) drive the relief stage "
              "(default: the texture path, relief pixels pass the stage like any other)");
  c->add_option("--cache-size", a.cache_size, "texel cache in front of the texel memory: bytes (power of two; "
                "0: none, the RTL's single-cycle RAM); prints reads, hit rate and memory bandwidth")
      ->check(CLI::Range(0u, 1u << 30));
  c->add_option("--cache-line", a.cache_line, "texel cache line, bytes (power of two, >= 4)")->check(CLI::Range(4u, 1u << 20));
  c->add_option("--cache-ways", a.cache_ways, "texel cache associativity (power of two)")->check(CLI::Range(1u, 1u << 16));
  c->add_option("--miss-penalty", a.miss_penalty, "clocks the EWA walker stalls per texel-cache miss (blocking cache)")
      ->check(CLI::Range(0u, 10000u));
  c->add_flag("--json", a.json, "print one JSON object");
  return c;
}

int run_sysmodel(const SysmodelArgs& a) {
  const scene::Scene s = a.scene == "default" ? scene::default_scene() : scene::load(a.scene);
  const auto t0 = std::chrono::steady_clock::now();
  // Per-pixel work (texels walked, levels tried) from the bit-accurate C-model render.
  render::CmodelOptions copt = render::texture_path_only();
  copt.relief = a.relief;  // relief pixels' march steps drive the relief stage
  copt.trace_texels = a.cache_size > 0;
  const sysmodel::CacheConfig cc{a.cache_size, a.cache_line, a.cache_ways, a.miss_penalty};
  if (a.cache_size > 0) sysmodel::TexelCache{cc};  // a bad geometry fails before the render
  const render::Frame frame = render::render_cmodel(s, tu::scene::Filter::Ewa, copt);
  sysmodel::Workload wl = sysmodel::scene_workload(s, frame);
  sysmodel::CacheStats cs;
  if (a.cache_size > 0) {
    cs = sysmodel::run_cache(frame, cc);
    for (size_t i = 0; i < wl.pixels.size(); ++i) wl.pixels[i].misses = cs.misses_per_pixel[i];
  }
  const double work_s = seconds_since(t0);
  sysmodel::UnitConfig cfg;
  cfg.pixel_fifo = a.fifo_depth;
  cfg.ewa.cord_unroll = a.cord_unroll;
  cfg.ewa.sqrt_step = a.sqrt_step;
  cfg.miss_penalty = static_cast<int>(a.miss_penalty);
  auto r = sysmodel::simulate(sysmodel::texture_unit(cfg), wl);
  const double model_s = seconds_since(t0);
  // Speed: the fastest of three identical runs (a short run is easily disturbed by other load).
  if (a.compare == "rtl")
    for (int i = 0; i < 2; ++i)
      r.sim_seconds = std::min(r.sim_seconds, sysmodel::simulate(sysmodel::texture_unit(cfg), wl).sim_seconds);
  // The RTL render of the same scene in this process: the Verilated tu_texture_unit, no stalls.
  // Its cycle count runs to the cycle after the last output, the model's to the last output.
  cosim::RtlRender rtl;
  double rtl_s = 0;
  if (a.compare == "rtl") {
    const ewa::EngineParams rtl_ewa;
    if (a.fifo_depth != 4 || a.cord_unroll != rtl_ewa.cord_unroll || a.sqrt_step != rtl_ewa.sqrt_step ||
        a.miss_penalty != 0)
      throw std::invalid_argument("--engine-compare rtl: the RTL top is built with FifoDepth 4, CordUnroll " +
                                  std::to_string(rtl_ewa.cord_unroll) + ", SqrtStep " +
                                  std::to_string(rtl_ewa.sqrt_step) + "; drop the what-if options");
    const auto t1 = std::chrono::steady_clock::now();
    cosim::RtlRenderOptions ro;
    ro.filter = scene::Filter::Ewa;
    ro.relief = a.relief;
    rtl = cosim::render_rtl(s, ro);
    rtl_s = seconds_since(t1);
  }
  const uint64_t model_cycles = r.total_cycles + 1;
  const double cycle_ratio = rtl.cycles ? static_cast<double>(model_cycles) / static_cast<double>(rtl.cycles) : 0;
  const double speed_sim = r.sim_seconds > 0 ? rtl.sim_wall_s / r.sim_seconds : 0;
  const double speed_all = model_s > 0 ? rtl_s / model_s : 0;
  if (a.json) {
    auto j = sysmodel::to_json(r);
    j["scene"] = s.source;
    j["spans"] = wl.spans.size();
    j["workload_seconds"] = work_s;
    j["model_seconds"] = model_s;
    if (a.cache_size > 0)
      j["texel_cache"] = {{"size_bytes", cc.size_bytes}, {"line_bytes", cc.line_bytes}, {"ways", cc.ways},
                          {"miss_penalty", cc.miss_penalty}, {"reads", cs.reads}, {"hits", cs.hits},
                          {"misses", cs.misses}, {"hit_rate", cs.hit_rate()}, {"memory_bytes", cs.memory_bytes}};
    if (a.compare == "rtl") {
      j["rtl"] = {{"cycles", rtl.cycles}, {"sim_seconds", rtl.sim_wall_s}, {"seconds", rtl_s},
                  {"mismatches", rtl.mismatches}, {"ok", rtl.ok()}};
      j["model_cycles"] = model_cycles;  // total_cycles + 1: counted like the RTL
      j["cycle_ratio"] = cycle_ratio;
      j["speed_ratio_sim"] = speed_sim;
      j["speed_ratio_total"] = speed_all;
    }
    std::cout << j.dump() << "\n";
  } else {
    std::printf("scene %s: %zu spans, %zu covered pixels (per-pixel work from the C model: %.3f s)\n",
                s.source.c_str(), wl.spans.size(), wl.pixels.size(), work_s);
    std::cout << sysmodel::table(r);
    if (a.cache_size > 0) {
      const double px = double(std::max<size_t>(1, wl.pixels.size())), clk = double(r.total_cycles + 1);
      std::printf("texel cache %u B, %u B lines, %u ways: %llu texel reads (%.2f per pixel, %.3f per clock), hit rate "
                  "%.2f %%, memory %llu B (%.2f B per pixel, %.3f B per clock); miss penalty %u clocks\n",
                  cc.size_bytes, cc.line_bytes, cc.ways, static_cast<unsigned long long>(cs.reads), double(cs.reads) / px,
                  double(cs.reads) / clk, 100 * cs.hit_rate(), static_cast<unsigned long long>(cs.memory_bytes),
                  double(cs.memory_bytes) / px, double(cs.memory_bytes) / clk, cc.miss_penalty);
    }
    if (a.compare == "rtl") {
      std::printf("RTL (Verilator tu_texture_unit): %llu cycles, %llu mismatches vs C model, simulation %.3f s, "
                  "render %.3f s\n",
                  static_cast<unsigned long long>(rtl.cycles), static_cast<unsigned long long>(rtl.mismatches),
                  rtl.sim_wall_s, rtl_s);
      std::printf("SystemC model: %llu cycles (to the cycle after the last output), simulation %.3f s, "
                  "with the C-model work %.3f s\n",
                  static_cast<unsigned long long>(model_cycles), r.sim_seconds, model_s);
      std::printf("cycles model / RTL = %.5f (%+.3f%%); speed: simulation %.1fx, end to end %.1fx\n",
                  cycle_ratio, 100 * (cycle_ratio - 1), speed_sim, speed_all);
    }
  }
  return rtl.ok() || a.compare.empty() ? 0 : 1;
}

}  // namespace tu::cli
