// `texunit objspace-compare SCENE|default [--ss N]`: the object-space pipeline (docs/methods/objspace.md)
// against the screen-space pipeline (B1 -> B2 -> trilinear / EWA) on one scene, texture path
// (relief off: the object-space pipeline has no relief step): PSNR against the ground truth,
// samples and texels per pixel, holes, overlaps and clocks per pixel (docs/blocks/objspace.md).
#include "objspace_cmd.hpp"

#include <chrono>
#include <cstdio>
#include <tuple>

#include "ewa/ewa_cycles.hpp"
#include "objspace/objspace.hpp"
#include "objspace/schemes.hpp"
#include "plan.hpp"
#include "planner/pipeline.hpp"
#include "texunit/objspace_accum.hpp"
#include "texunit/render.hpp"

namespace tu::cli {

CLI::App* add_objspace(CLI::App& app, ObjspaceArgs& a) {
  auto* c = app.add_subcommand("objspace-compare",
                               "object-space pipeline (docs/methods/objspace.md) vs the screen-space pipeline on a scene: PSNR vs truth, "
                               "samples, holes, clocks per pixel (docs/blocks/objspace.md)");
  c->add_option("SCENE", a.scene, "scene JSON file, or 'default'")->required();
  c->add_option("--ss", a.ss, "ground truth: stratified samples per pixel side")->check(CLI::Range(1, 64));
  c->add_option("--os-spacing", a.spacing, "object-space sample spacing, pixels at the plane's distance")
      ->check(CLI::Range(0.05, 64.0));
  c->add_option("--max-samples", a.max_samples, "object-space: cap on the render's samples (more: exit 2)")
      ->check(CLI::Range(uint64_t(1), uint64_t(1) << 40));
  return c;
}

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

int run_objspace(const ObjspaceArgs& a) {
  const scene::Scene s = scene::without_relief(a.scene == "default" ? scene::default_scene() : scene::load(a.scene));
  render::TruthOptions to;
  to.ss = a.ss;
  const auto truth = render::render_truth(s, to);
  const double n = static_cast<double>(std::max<size_t>(1, truth.pixels.size()));
  std::printf("%s: %dx%d, %zu covered pixels, texture path (relief off); truth %d x %d samples per pixel, box\n",
              s.source.c_str(), s.camera.width, s.camera.height, truth.pixels.size(), a.ss, a.ss);
  std::printf("%-22s %10s %12s %12s %8s %9s %14s %14s %9s\n", "pipeline", "PSNR", "samples/px", "texels/px", "holes",
              "overlaps", "clocks/px unit", "clocks/px 1/clk", "seconds");
  // Screen space: the C-model render; clocks of the RTL texture unit from the exact cycle model.
  for (const scene::Filter f : {scene::Filter::Trilinear, scene::Filter::Ewa}) {
    const auto t0 = std::chrono::steady_clock::now();
    const auto fr = render::render_cmodel(s, f, render::texture_path_only());
    const double sec = seconds_since(t0);
    double texels = 0;
    for (const auto& p : fr.pixels) texels += p.texels;
    const uint64_t cyc = plan::scene_stream_cycles(s, [f](const scene::Material&) { return f; }, false);
    std::printf("%-22s %10.2f %12.2f %12.2f %8s %9s %14.2f %14s %9.2f\n",
                (std::string("screen ") + scene::to_string(f)).c_str(), render::psnr_covered(fr, truth), 1.0,
                texels / n, "-", "-", double(cyc) / n, "-", sec);
  }
  // Object space: per sample one trilinear lookup; clocks as the unit's tu_trilinear engine
  // (one sample per its steady-state interval) and as a scheme taking one sample per clock (the
  // per-sample datapath is II = 1), plus one normalising divide per covered pixel.
  const objspace::Options oo{a.spacing, a.max_samples};
  const double tri_clk = plan::engine_clocks(ewa::Engine::Trilinear);
  objspace::Result ref_r;
  // The C model's sample stream as the accumulation model needs it (bank bits, guard).
  std::vector<sysmodel::AccumSample> stream;
  auto record = [&](const std::vector<objspace::SampleIn>& in, std::vector<objspace::Splat>& out) {
    for (size_t k = 0; k < in.size(); ++k) {
      out[k] = objspace::splat_fx(*in[k].k, in[k].i, in[k].j);
      stream.push_back(sysmodel::AccumSample::of(out[k].x, out[k].y, out[k].guard));
    }
  };
  for (const bool fx : {false, true}) {
    const auto t0 = std::chrono::steady_clock::now();
    auto r = fx ? objspace::render_cmodel(s, oo, record) : objspace::render_ref(s, oo);
    const double sec = seconds_since(t0);
    const auto& st = r.stats;
    const double spp = double(st.samples) / n;
    std::printf("%-22s %10.2f %12.2f %12.2f %8llu %9llu %14.2f %14.2f %9.2f\n",
                fx ? "object-space cmodel" : "object-space ref", render::psnr_covered(r.frame, truth), spp, 8 * spp,
                (unsigned long long)st.holes, (unsigned long long)st.overlaps, tri_clk * spp + 1, spp + 1, sec);
    if (fx) {
      std::printf("object-space cmodel vs ref: %.2f dB; samples %llu, off screen %llu, guarded %llu, foreign splats "
                  "%llu, max sum s %.1f, accumulator saturations %llu\n",
                  render::psnr_covered(r.frame, ref_r.frame), (unsigned long long)st.samples,
                  (unsigned long long)st.off_screen, (unsigned long long)st.guarded, (unsigned long long)st.foreign,
                  st.max_weight, (unsigned long long)st.acc_saturated);
    } else {
      ref_r = std::move(r);
    }
  }
  std::printf("clocks/px unit: object space with the unit's trilinear engine (%.0f clocks per sample); 1/clk: one "
              "sample per clock; screen space: the RTL texture unit (ewa::stream_cycles)\n", tri_clk);
  // The sample stream through S datapath lanes into the banked pixel buffer (SystemC, timing of
  // the structure; the texture lookups are not in it: an S-sample-per-clock texture engine is
  // assumed), against the structural estimate.
  std::printf("object-space accumulation (SystemC, tlm/src/objspace_accum.cpp), %zu samples, %zu covered pixels, "
              "1 divider:\n%-22s %14s %12s %12s %10s %9s\n", stream.size(), truth.pixels.size(), "scheme", "clocks",
              "clocks/px", "conflict %", "= est.", "seconds");
  for (const auto& [lanes, bx, by] : std::vector<std::tuple<int, int, int>>{{1, 2, 2}, {2, 4, 2}, {4, 8, 2}, {4, 4, 4}}) {
    sysmodel::AccumScheme sc;
    sc.lanes = lanes, sc.bank_x = bx, sc.bank_y = by;
    sc.datapath_latency = sched::schedule(objspace::sample_scheme()).latency;
    const auto r = sysmodel::simulate_accumulation(sc, stream, truth.pixels.size());
    const auto e = sysmodel::estimate_accumulation(sc, stream, truth.pixels.size());
    std::printf("%-22s %14llu %12.2f %12.2f %10s %9.2f\n", sc.name().c_str(), (unsigned long long)r.total_cycles,
                double(r.total_cycles) / n, 100.0 * double(r.conflict_clocks) / double(std::max<uint64_t>(1, r.issue_clocks)),
                r.total_cycles == e.total_cycles ? "yes" : "NO", r.sim_seconds);
  }
  return 0;
}

}  // namespace tu::cli
