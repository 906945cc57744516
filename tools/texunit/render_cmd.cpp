// `texunit render SCENE.json --out DIR [--dump FILE.csv] [--engine ref] [--filter F]`.
#include "render_cmd.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <iostream>
#include <sstream>
#include <unistd.h>

#include "demo_jobs.hpp"
#include "gauss/clip.hpp"
#include "output.hpp"
#include "texture_unit_rtl.hpp"
#include "texunit/parallel.hpp"
#include "texunit/render.hpp"
#include "texunit/scene.hpp"
#include "objspace/objspace.hpp"
#include "objspace_rtl.hpp"

namespace tu::cli {

std::vector<std::string> clip_choices() {
  std::vector<std::string> c{"off"};
  for (const auto& v : clip::variants()) c.push_back(v.name);
  return c;
}

CLI::App* add_render(CLI::App& app, RenderArgs& a) {
  auto* r = app.add_subcommand("render", "render a scene to PNG images (docs/scene-format.md)");
  r->add_option("SCENE", a.scene, "scene JSON file, or 'default' for the embedded scene")->required();
  r->add_option("--out", a.out_dir, "output directory (created if missing)")->required();
  r->add_option("--dump", a.dump,
                "CSV: one row per covered pixel (x,y,u,v,lod,texels,r,g,b,a, relief_n, relief_steps, "
                "one 0/1 column per guard flag)");
  r->add_option("--engine", a.engine,
                 "rendering engine: float reference, bit-accurate C model, or the Verilated "
                 "texture-unit RTL (compared with the C model pixel by pixel), or the ground truth "
                 "(--ss x --ss point samples per pixel at the exact u,v and relief intersection)")
      ->check(CLI::IsMember({"ref", "cmodel", "rtl", "truth"}));
  r->add_option("--ss", a.ss, "--engine truth: stratified samples per pixel side (N x N)")
      ->check(CLI::Range(1, 256));
  r->add_option("--truth-kernel", a.truth_kernel,
                "--engine truth: box over the pixel square, or gauss (the EWA's pixel model over the unit disc)")
      ->check(CLI::IsMember({"box", "gauss"}));
  r->add_option("--rtl-unit", a.rtl_unit,
                 "--engine rtl: the full unit (EWA, trilinear, bilinear and nearest engines, each material's filter per span), "
                 "the bilinear-only unit (HasEwa = 0) or docs/scenes/corridor.json's planned unit (EWA with the "
                 "1-D weight table, iterative parallax: --filter ewa --weights table1d)")
      ->check(CLI::IsMember({"full", "bilinear", "corridor"}));
  r->add_flag("--no-relief", a.no_relief,
              "leave every material's relief out (the texture path alone; every engine); the "
              "bilinear-only RTL unit has no relief stage and always renders without it");
  r->add_option("--weights", a.weights, "override every material's EWA weight source")
      ->check(CLI::IsMember({"formula", "table1d", "table2d"}));
  r->add_option("--clip", a.clip, "override every material's EWA sub-texel border weights: a clip-volume "
                "variant (docs/blocks/gaussian.md) or off (docs/blocks/ewa.md#border-weights)")
      ->check(CLI::IsMember(clip_choices()));
  r->add_option("--filter", a.filter, "override every material's filter")
      ->check(CLI::IsMember({"nearest", "bilinear", "trilinear", "ewa", "feline"}));
  r->add_option("--feline-max-probes", a.feline_max_probes, "override every material's Feline probe cap Nmax")
      ->check(CLI::Range(1, fmt::kFelNMax));
  r->add_flag("--no-footprint-limit", a.no_footprint_limit,
              "procedural materials: keep every octave (footprint_limit false), the aliased field");
  r->add_option("--vs", a.vs, "also render with this engine (same options) and print the PSNR over covered pixels "
                "against it, per object too, and write heat_ENGINE_vs_VS.png (e.g. --engine cmodel --vs truth: the aliasing of "
                "procedural materials)")
      ->check(CLI::IsMember({"ref", "cmodel", "truth"}));
  r->add_option("--frames", a.frames, "an animation of N frames, one PNG each (ENGINE_0000.png, ...): frame i "
                "renders every procedural material at its time + i * --dt")
      ->check(CLI::Range(1, 100000));
  r->add_option("--dt", a.dt, "--frames: time step between frames (the procedural materials' time unit)")
      ->check(CLI::Range(-1e6, 1e6));
  r->add_option("--mip-filter", a.mip_filter,
                "override every texture's mip generation (box, box_linear, lanczos2; docs/blocks/texture.md)")
      ->check(CLI::IsMember({"box", "box_linear", "lanczos2"}));
  r->add_option("--footprint", a.footprint,
                "cmodel / rtl engines: override the scene's B2 variant (analytic tu_ellipse, or the seed's "
                "recurrences tu_ellipse_rec; docs/blocks/ellipse.md)")
      ->check(CLI::IsMember({"analytic", "recurrence"}));
  r->add_option("--threads", a.threads, "cmodel / rtl engines: threads for the C-model render (default 0: "
                "every core); the image is the same for any count")
      ->check(CLI::Range(0, 4096));
  r->add_option("--pipeline", a.pipeline,
                "screen: B1 -> B2 -> filter per pixel; object-space: each triangle rotated parallel to the "
                "screen, textured on a sample grid (one mip level per polygon), samples rotated back, projected "
                "and splatted (docs/blocks/objspace.md; ref, cmodel and rtl engines: rtl = the per-sample "
                "datapath tu_objspace_sample)")
      ->check(CLI::IsMember({"screen", "object-space"}));
  r->add_option("--os-spacing", a.os_spacing, "object-space: sample spacing in pixels at the plane's distance")
      ->check(CLI::Range(0.05, 64.0));
  r->add_option("--max-samples", a.max_samples, "object-space: cap on the render's samples (more: exit 2)")
      ->check(CLI::Range(uint64_t(1), uint64_t(1) << 40));
  r->add_option("--os-stall-prob", a.os_stall_prob,
                "object-space rtl: probability of an input bubble and of output back-pressure per cycle")
      ->check(CLI::Range(0.0, 0.9));
  return r;
}

static void print_objspace_stats(const objspace::Stats& st) {
  std::printf("object space: %llu triangles, %llu tiles, %llu samples (%.2f per covered pixel), %llu off screen, "
              "%llu guarded, %llu splats, %llu foreign-surface splats dropped; %llu covered pixels: %llu holes, "
              "%llu overlaps (sum s > 4), max sum s %.1f, %llu accumulator saturations\n",
              (unsigned long long)st.triangles, (unsigned long long)st.tiles, (unsigned long long)st.samples,
              st.samples_per_pixel(), (unsigned long long)st.off_screen, (unsigned long long)st.guarded,
              (unsigned long long)st.splats, (unsigned long long)st.foreign, (unsigned long long)st.covered,
              (unsigned long long)st.holes, (unsigned long long)st.overlaps, st.max_weight,
              (unsigned long long)st.acc_saturated);
}

// The object-space render with the per-sample datapath in RTL: every sample's splat compared
// with the C model's, the frame with the C-model render's on every pixel, the simulated cycles
// with the estimate (sum over the runs of samples + the scheme's latency, no stalls).
static bool objspace_rtl_render(const scene::Scene& s, const objspace::Options& oo, double stall_prob,
                                render::Frame* frame) {
  cosim::ObjspaceRtlOptions ro;
  ro.stall_prob = stall_prob;
  const auto r = cosim::render_objspace_rtl(s, oo, ro);
  print_objspace_stats(r.result.stats);
  std::printf("rtl per-sample datapath (tu_objspace_sample): %llu samples in %llu runs, %llu mismatches against the "
              "C model%s%s; %llu pixels differ from the C-model render; cycles measured %llu, predicted %llu "
              "(samples + runs x latency, %s); simulated %.0f samples/s (%.2f s)\n",
              (unsigned long long)r.samples, (unsigned long long)r.runs, (unsigned long long)r.mismatches,
              r.first_mismatch.empty() ? "" : "; first: ", r.first_mismatch.c_str(),
              (unsigned long long)r.differing_pixels, (unsigned long long)r.sim_cycles,
              (unsigned long long)r.predicted_cycles, stall_prob > 0 ? "without stalls: here a lower bound" : "exact without stalls",
              double(r.samples) / std::max(1e-9, r.sim_wall_s), r.sim_wall_s);
  *frame = r.result.frame;
  return r.ok() && (stall_prob > 0 || r.sim_cycles == r.predicted_cycles);
}

int run_render(const RenderArgs& a) {
  scene::Scene s = a.scene == "default" ? scene::default_scene() : scene::load(a.scene);
  if (a.no_footprint_limit)
    for (auto& [name, m] : s.materials)
      if (m.procedural) m.procedural->footprint_limit = false;
  if (!a.clip.empty()) s = scene::with_clip(std::move(s), a.clip);
  if (!a.mip_filter.empty())
    for (auto& [name, t] : s.textures)
      t.mip_filter = a.mip_filter == "lanczos2" ? 2 : a.mip_filter == "box_linear" ? 1 : 0;  // tex::MipFilter
  if (!a.footprint.empty())
    s.footprint = a.footprint == "recurrence" ? scene::Footprint::Recurrence : scene::Footprint::Analytic;
  std::optional<scene::Filter> f;
  if (a.filter == "nearest") f = scene::Filter::Nearest;
  if (a.filter == "bilinear") f = scene::Filter::Bilinear;
  if (a.filter == "trilinear") f = scene::Filter::Trilinear;
  if (a.filter == "ewa") f = scene::Filter::Ewa;
  if (a.filter == "feline") f = scene::Filter::Feline;
  if (a.feline_max_probes > 0)
    for (auto& [name, m] : s.materials) m.feline_max_probes = a.feline_max_probes;
  std::optional<scene::WeightSource> w;
  if (a.weights == "formula") w = scene::WeightSource::Formula;
  if (a.weights == "table1d") w = scene::WeightSource::Table1d;
  if (a.weights == "table2d") w = scene::WeightSource::Table2d;
  // Every output is checked before the render and written only when all succeed (Outputs).
  if (a.frames > 1 && !a.dump.empty()) throw std::invalid_argument("--dump writes one frame: leave it out with --frames N > 1");
  // The animation's last frame keeps every procedural time where the scene format bounds it.
  for (const auto& [name, m] : s.materials)
    if (m.procedural && a.frames > 1) {
      const double t = m.procedural->time + (a.frames - 1) * a.dt;
      if (std::fabs(t) <= scene::kMaxTime) continue;
      std::ostringstream os;
      os << "--frames " << a.frames << " --dt " << a.dt << ": material '" << name << "' reaches time " << t
         << " in the last frame, outside the scene format's [" << -scene::kMaxTime << ", " << scene::kMaxTime << "]";
      throw std::invalid_argument(os.str());
    }
  Outputs outs;
  outs.make_dir(a.out_dir);
  auto frame_png = [&](int i) {
    char name[32];
    std::snprintf(name, sizeof name, "_%04d.png", i);
    return (std::filesystem::path(a.out_dir) / ((a.pipeline == "object-space" ? "objspace_" : "") + a.engine + (a.frames > 1 ? name : ".png"))).string();
  };
  const std::string png = frame_png(0);
  const std::string lp = (std::filesystem::path(a.out_dir) / "layers.png").string();
  const std::string heat_png = (std::filesystem::path(a.out_dir) / ("heat_" + a.engine + "_vs_" + a.vs + ".png")).string();
  if (!a.dump.empty()) {  // the CSV written over an image of the same run
    std::vector<std::string> images{lp};
    if (!a.vs.empty()) images.push_back(heat_png);
    for (int i = 0; i < a.frames; ++i) images.push_back(frame_png(i));
    const auto dump = std::filesystem::weakly_canonical(a.dump);
    for (const auto& p : images)
      if (std::filesystem::weakly_canonical(p) == dump)
        throw std::invalid_argument("--dump " + a.dump + ": the render writes its image " + p + " there");
  }
  std::vector<std::string> png_tmps;
  for (int i = 0; i < a.frames; ++i) png_tmps.push_back(outs.stage(frame_png(i)));
  const std::string& png_tmp = png_tmps[0];
  const std::string dump_tmp = a.dump.empty() ? "" : outs.stage(a.dump);
  render::CmodelOptions opt;
  opt.progress = isatty(STDERR_FILENO);  // a bar on a terminal; none in a log
  opt.weights = w;
  opt.relief = !a.no_relief;
  opt.threads = a.threads;
  render::Frame frame;
  bool ok = true;
  cosim::RtlRenderOptions ro;  // --engine rtl
  if (a.pipeline == "object-space") {
    if (a.engine != "ref" && a.engine != "cmodel" && a.engine != "rtl")
      throw std::invalid_argument("render --pipeline object-space: --engine must be ref, cmodel or rtl (not " + a.engine + ")");
    if (a.frames > 1 || !a.vs.empty())
      throw std::invalid_argument("render --pipeline object-space: one frame, without --vs");
    const objspace::Options oo{a.os_spacing, a.max_samples};
    if (a.engine == "rtl") {
      ok = objspace_rtl_render(s, oo, a.os_stall_prob, &frame);
    } else {
      auto r = a.engine == "cmodel" ? objspace::render_cmodel(s, oo) : objspace::render_ref(s, oo);
      frame = std::move(r.frame);
      print_objspace_stats(r.stats);
    }
  } else if (a.engine == "rtl") {
    ro.has_ewa = a.rtl_unit != "bilinear";
    ro.corridor_unit = a.rtl_unit == "corridor";
    ro.filter = f;
    ro.weights = w;
    ro.relief = ro.has_ewa && !a.no_relief;
    ro.threads = a.threads;
    const auto r = cosim::render_rtl(s, ro);
    frame = r.frame;
    ok = r.ok();
    std::printf("rtl %s unit%s%s: %zu pixels in %llu spans, %llu mismatches against the C model%s%s\n",
                a.rtl_unit.c_str(), s.footprint == scene::Footprint::Recurrence ? " (recurrence ellipse)" : "", ro.relief ? " with relief" : " (texture path, no relief)", r.frame.pixels.size(), (unsigned long long)r.spans,
                (unsigned long long)r.mismatches, r.first_mismatch.empty() ? "" : "; first: ",
                r.first_mismatch.c_str());
    const double n = static_cast<double>(std::max<size_t>(1, r.frame.pixels.size()));
    if (r.predicted_cycles)
      std::printf("cycles measured %llu (%.2f/pixel), predicted %llu (%.2f/pixel, %+.2f %%)",
                  (unsigned long long)r.cycles, double(r.cycles) / n, (unsigned long long)r.predicted_cycles,
                  double(r.predicted_cycles) / n,
                  100.0 * (double(r.predicted_cycles) / double(std::max<uint64_t>(1, r.cycles)) - 1));
    else
      std::printf("cycles measured %llu (%.2f/pixel), not predicted (relief pixels in the stream)",
                  (unsigned long long)r.cycles, double(r.cycles) / n);
    std::printf("; simulated %.0f RTL pixels/s (%.2f s)\n", n / r.sim_wall_s, r.sim_wall_s);
  } else if (a.engine == "truth") {
    render::TruthOptions to;
    to.ss = a.ss;
    to.kernel = a.truth_kernel == "gauss" ? render::TruthKernel::Gaussian : render::TruthKernel::Box;
    to.relief = !a.no_relief;
    to.progress = opt.progress;
    frame = render::render_truth(s, to);
  } else {
    frame = a.engine == "cmodel" ? render::render_cmodel(s, f, opt)
                                 : render::render_ref(a.no_relief ? scene::without_relief(s) : s, f);
  }
  render::TruthOptions to;
  to.ss = a.ss;
  to.kernel = a.truth_kernel == "gauss" ? render::TruthKernel::Gaussian : render::TruthKernel::Box;
  to.relief = !a.no_relief;
  to.progress = opt.progress;
  auto render_with = [&](const std::string& engine, const scene::Scene& si) {
    return engine == "truth" ? render::render_truth(si, to)
           : engine == "cmodel" ? render::render_cmodel(si, f, opt)
                                : render::render_ref(a.no_relief ? scene::without_relief(si) : si, f);
  };
  auto render_at = [&](const scene::Scene& si) { return render_with(a.engine, si); };
  if (a.engine != "rtl" && a.pipeline != "object-space") frame = render_at(s);
  std::optional<img::Rgba8Image> heat;  // --vs: |ENGINE - VS| per pixel, 64 levels = red
  if (!a.vs.empty()) {
    const auto other = render_with(a.vs, s);
    heat = render::error_heatmap(frame.image, other.image, 64);
    std::printf("PSNR %s vs %s: %.2f dB over %zu covered pixels;", a.engine.c_str(), a.vs.c_str(),
                render::psnr_covered(frame, other), frame.pixels.size());
    for (size_t o = 0; o < s.objects.size(); ++o)
      std::printf(" %s %.2f dB", s.objects[o].name.c_str(),
                  render::psnr_covered(frame, other, [o](const render::PixelRecord& p) { return p.object == int(o); }));
    std::printf("\n");
  }
  // Frames 1.. of an animation (frame 0 gives the flags and the dump). Time moves only the
  // procedural materials; the RTL unit renders each frame against the C model.
  for (int i = 1; i < a.frames; ++i) {
    const scene::Scene si = scene::at_time(s, i * a.dt);
    render::Frame fi;
    if (a.engine == "rtl") {
      const auto r = cosim::render_rtl(si, ro);
      if (!r.ok()) std::printf("rtl frame %d: %llu mismatches; first: %s\n", i, (unsigned long long)r.mismatches, r.first_mismatch.c_str());
      ok = ok && r.ok();
      fi = r.frame;
    } else {
      fi = render_at(si);
    }
    tu::out::write_file(png_tmps[static_cast<size_t>(i)], img::png_rgba(fi.image, frame_png(i)), frame_png(i));
  }
  {
    const auto& flags = render::pixel_flags();
    const auto counts = render::flag_counts(frame);
    std::printf("guard flags, pixels of %zu:", frame.pixels.size());
    for (size_t i = 0; i < flags.size(); ++i) std::printf(" %s %zu", flags[i].name, counts[i]);
    std::printf("\n");
    double texels = 0, probes = 0, probe_px = 0;
    for (const auto& p : frame.pixels) texels += p.texels, probes += p.probes, probe_px += p.probes > 0;
    std::printf("texels read per covered pixel: %.3f", texels / double(std::max<size_t>(1, frame.pixels.size())));
    if (probe_px > 0) std::printf("; Feline: %.0f pixels, %.3f probes per pixel", probe_px, probes / probe_px);
    std::printf("\n");
  }
  tu::out::write_file(png_tmp, img::png_rgba(frame.image, png), png);
  const auto layers = render::layers_image(s, frame);
  if (layers) outs.write(lp, img::png_gray(*layers, lp));
  if (!a.dump.empty()) tu::out::write_stream(dump_tmp, [&](std::ostream& os) { render::write_dump_csv(os, frame); }, a.dump);
  if (heat) outs.write(heat_png, img::png_rgba(*heat, heat_png));
  outs.commit();
  std::cerr << "wrote " << png << " (" << frame.pixels.size() << " covered pixels)";
  if (a.frames > 1) std::cerr << " and " << a.frames - 1 << " more frames to " << frame_png(a.frames - 1);
  std::cerr << "\n";
  if (layers) std::cerr << "wrote " << lp << " (adaptive relief: N per pixel, (N - 4) / (Nmax - 4) as grey)\n";
  if (!a.dump.empty()) std::cerr << "wrote " << a.dump << "\n";
  if (heat) std::cerr << "wrote " << heat_png << " (|" << a.engine << " - " << a.vs << "|, 64 levels = red)\n";
  return ok ? 0 : 1;
}

namespace {
// The references every demo row is measured against (PSNR over covered pixels): the float EWA and
// the ground truth (render_truth, 16 x 16 samples, box), each of the same path (texture path, or
// with relief: the 256-layer march / the exact intersection).
struct Refs {
  const render::Frame& ewa;
  const render::Frame& truth;
};
std::string db(double v) {
  char b[32];
  std::snprintf(b, sizeof b, std::isinf(v) ? "reference" : "%.2f dB", v);
  return b;
}
// A render timed by the CPU time of the thread that runs it (the demo's jobs run one per thread).
template <class F>
render::Frame timed(double* cpu_s, F&& f) {
  const double c0 = thread_cpu_s();
  render::Frame fr = f();
  *cpu_s = thread_cpu_s() - c0;
  return fr;
}

// The default scene's C-model rows: every filter (EWA with each weight source) against both references.
struct CmodelRow {
  const char* name;
  scene::Filter filter;
  scene::WeightSource weights;
};
constexpr CmodelRow kCmodelRows[] = {{"nearest", scene::Filter::Nearest, scene::WeightSource::Formula},
                                     {"bilinear", scene::Filter::Bilinear, scene::WeightSource::Formula},
                                     {"trilinear", scene::Filter::Trilinear, scene::WeightSource::Formula},
                                     {"ewa_formula", scene::Filter::Ewa, scene::WeightSource::Formula},
                                     {"ewa_table1d", scene::Filter::Ewa, scene::WeightSource::Table1d},
                                     {"ewa_table2d", scene::Filter::Ewa, scene::WeightSource::Table2d}};
constexpr int kCmodelN = sizeof kCmodelRows / sizeof kCmodelRows[0];
// The RTL rows: the full unit with every span on EWA, with ground on bilinear (per-material
// filters: the engines take turns), and the bilinear-only unit.
struct RtlRow {
  const char* name;
  bool has_ewa;  // false: the bilinear-only unit
  std::optional<scene::Filter> filter;
  std::optional<scene::WeightSource> weights;
  bool relief = false;  // each material's relief through the unit's relief stage
  double cost;          // estimated CPU seconds (the job order)
};
const RtlRow kRtlRows[] = {{"ewa_formula", true, scene::Filter::Ewa, scene::WeightSource::Formula, false, 6},
                           {"ewa_table1d", true, scene::Filter::Ewa, scene::WeightSource::Table1d, false, 6},
                           {"ewa_table2d", true, scene::Filter::Ewa, scene::WeightSource::Table2d, false, 6},
                           {"trilinear", true, scene::Filter::Trilinear, std::nullopt, false, 2},
                           {"nearest", true, scene::Filter::Nearest, std::nullopt, false, 2},
                           {"mixed", true, std::nullopt, scene::WeightSource::Formula, false, 4},
                           {"bilinear", false, scene::Filter::Bilinear, scene::WeightSource::Formula, false, 2},
                           {"ewa+relief", true, scene::Filter::Ewa, std::nullopt, true, 7}};
constexpr int kRtlN = sizeof kRtlRows / sizeof kRtlRows[0];
constexpr scene::Filter kRefFilters[] = {scene::Filter::Nearest, scene::Filter::Bilinear, scene::Filter::Trilinear,
                                         scene::Filter::Ewa};
constexpr int kRefN = sizeof kRefFilters / sizeof kRefFilters[0];

// Every render of the demo (each job fills one slot).
struct DemoData {
  std::string out_dir;
  // The demo's images, all or none: written by the printers (one thread), committed after the last.
  mutable Outputs outs;
  scene::Scene s, flat, mixed, proc, proc_all;  // default scene, without relief, ground bilinear; procedural
  std::optional<scene::Scene> shaded;           // docs/scenes/shaded_sphere.json (run from the repository root)
  render::Frame ref[kRefN], truth, ewa_flat, truth_flat;
  double ref_s[kRefN] = {}, truth_s = 0;
  render::Frame cm[kCmodelN], relief;
  double cm_s[kCmodelN] = {}, relief_s = 0;
  render::Frame proc_truth, proc_ref, proc_ref_all, proc_cm, proc_cm_all;
  cosim::RtlRender rtl[kRtlN];
  render::Frame shaded_ref, shaded_fx;
  cosim::RtlRender shaded_rtl;
};

render::CmodelOptions one_thread() {
  render::CmodelOptions o;
  o.threads = 1;  // the jobs already share the cores
  return o;
}
void write_png(const DemoData& d, const std::string& name, const img::Rgba8Image& im) {
  const std::string path = (std::filesystem::path(d.out_dir) / name).string();
  d.outs.write(path, img::png_rgba(im, path));
}
std::string png_path(const DemoData& d, const std::string& name) {
  return (std::filesystem::path(d.out_dir) / name).string();
}

void add_jobs(const std::shared_ptr<DemoData>& dp, std::vector<DemoJob>& jobs) {
  DemoData& d = *dp;
  auto add = [&](const char* section, std::string name, double cost, std::function<void()> f) {
    jobs.push_back({section, std::move(name), cost, std::move(f)});
  };
  for (int i = 0; i < kRefN; ++i)
    add("float reference", std::string("ref ") + std::string(scene::to_string(kRefFilters[i])),
        kRefFilters[i] == scene::Filter::Ewa ? 1.5 : 0.3, [dp, &d, i] {
          d.ref[i] = timed(&d.ref_s[i], [&] { return render::render_ref(d.s, kRefFilters[i]); });
        });
  add("truth", "truth", 3, [dp, &d] { d.truth = timed(&d.truth_s, [&] { return render::render_truth(d.s); }); });
  add("float reference", "ref ewa flat", 1.5, [dp, &d] { d.ewa_flat = render::render_ref(d.flat, scene::Filter::Ewa); });
  add("truth", "truth flat", 3, [dp, &d] { d.truth_flat = render::render_truth(d.flat); });
  for (int i = 0; i < kCmodelN; ++i)
    add("C model", std::string("cmodel ") + kCmodelRows[i].name, kCmodelRows[i].filter == scene::Filter::Ewa ? 0.8 : 0.2,
        [dp, &d, i] {
          render::CmodelOptions opt = one_thread();
          opt.weights = kCmodelRows[i].weights;
          d.cm[i] = timed(&d.cm_s[i], [&] { return render::render_cmodel(d.flat, kCmodelRows[i].filter, opt); });
        });
  add("C model", "cmodel ewa+relief", 1, [dp, &d] {
    d.relief = timed(&d.relief_s, [&] { return render::render_cmodel(d.s, scene::Filter::Ewa, one_thread()); });
  });
  add("procedural", "procedural truth", 2, [dp, &d] { d.proc_truth = render::render_truth(d.proc); });
  add("procedural", "procedural ref", 1, [dp, &d] { d.proc_ref = render::render_ref(d.proc); });
  add("procedural", "procedural ref all octaves", 1, [dp, &d] { d.proc_ref_all = render::render_ref(d.proc_all); });
  add("procedural", "procedural cmodel", 0.5,
      [dp, &d] { d.proc_cm = render::render_cmodel(d.proc, std::nullopt, one_thread()); });
  add("procedural", "procedural cmodel all octaves", 0.5,
      [dp, &d] { d.proc_cm_all = render::render_cmodel(d.proc_all, std::nullopt, one_thread()); });
  for (int i = 0; i < kRtlN; ++i)
    add("RTL renders", std::string("rtl ") + kRtlRows[i].name, kRtlRows[i].cost, [dp, &d, i] {
      const RtlRow& r = kRtlRows[i];
      cosim::RtlRenderOptions o;
      o.has_ewa = r.has_ewa;
      o.filter = r.filter;
      o.weights = r.weights;
      o.relief = r.relief;
      o.threads = 1;
      d.rtl[i] = cosim::render_rtl(r.relief ? d.s : r.filter ? d.flat : d.mixed, o);
    });
  if (d.shaded) {
    add("shaded", "shaded ref", 0.5, [dp, &d] { d.shaded_ref = render::render_ref(*d.shaded); });
    add("shaded", "shaded cmodel", 0.5, [dp, &d] { d.shaded_fx = render::render_cmodel(*d.shaded, std::nullopt, one_thread()); });
    add("shaded", "shaded rtl", 3, [dp, &d] {
      cosim::RtlRenderOptions o;
      o.threads = 1;
      d.shaded_rtl = cosim::render_rtl(*d.shaded, o);
    });
  }
}

void print_reference(const DemoData& d) {
  const auto& ewa = d.ref[kRefN - 1];
  write_png(d, "truth.png", d.truth.image);
  const auto rel = render::relief_pixels(d.s);
  std::printf("\ndefault scene (%dx%d, %zu covered pixels), float reference engine; PSNR over covered pixels "
              "against the float EWA and the ground truth (16 x 16 samples per pixel, box, exact relief "
              "intersection; %.1f s), the wall's relief pixels alone in the last column:\n",
              d.s.camera.width, d.s.camera.height, ewa.pixels.size(), d.truth_s);
  std::printf("%-10s %14s %14s %14s %14s %10s  %s\n", "filter", "PSNR vs EWA", "vs truth", "relief vs truth",
              "texels/pixel", "seconds", "image");
  for (int i = 0; i < kRefN; ++i) {
    const auto name = std::string(scene::to_string(kRefFilters[i]));
    const auto png = png_path(d, "ref_" + name + ".png");
    d.outs.write(png, img::png_rgba(d.ref[i].image, png));
    if (i + 1 < kRefN) write_png(d, "heat_" + name + "_vs_ewa.png", render::error_heatmap(d.ref[i].image, ewa.image, 64));
    double texels = 0;
    for (const auto& p : d.ref[i].pixels) texels += p.texels;
    std::printf("%-10s %14s %14s %14s %14.2f %10.3f  %s\n", name.c_str(), db(render::psnr_covered(d.ref[i], ewa)).c_str(),
                db(render::psnr_covered(d.ref[i], d.truth)).c_str(), db(render::psnr_covered(d.ref[i], d.truth, rel)).c_str(),
                texels / static_cast<double>(std::max<size_t>(1, d.ref[i].pixels.size())), d.ref_s[i], png.c_str());
  }
}

// The filters are measured on the texture path (relief off on both sides); the relief method is
// measured on its own rows (C model and RTL) against the float reference's 256-layer march.
void print_cmodel(const DemoData& d, const Refs& refs) {
  std::printf("\ndefault scene, bit-accurate C-model engine (B1 persp -> B2 ellipse -> filter), "
              "against the float EWA reference, texture path (relief off on both; pixels/s: per core):\n");
  std::printf("%-12s %12s %12s %13s %13s %12s  %s\n", "filter", "PSNR vs EWA", "vs truth", "texels/pixel",
              "inside/pixel", "pixels/s", "image");
  for (int i = 0; i < kCmodelN; ++i) {
    const CmodelRow& r = kCmodelRows[i];
    const render::Frame& fr = d.cm[i];
    const auto png = png_path(d, std::string("cmodel_") + r.name + ".png");
    d.outs.write(png, img::png_rgba(fr.image, png));
    write_png(d, std::string("heat_cmodel_") + r.name + "_vs_ewa.png", render::error_heatmap(fr.image, refs.ewa.image, 64));
    double texels = 0, inside = 0;
    for (const auto& p : fr.pixels) texels += p.texels, inside += p.texels_inside;
    const double n = static_cast<double>(std::max<size_t>(1, fr.pixels.size()));
    char inside_txt[32] = "-";
    if (r.filter == scene::Filter::Ewa) std::snprintf(inside_txt, sizeof inside_txt, "%.2f", inside / n);
    std::printf("%-12s %12s %12s %13.2f %13s %12.0f  %s\n", r.name, db(render::psnr_covered(fr, refs.ewa)).c_str(),
                db(render::psnr_covered(fr, refs.truth)).c_str(), texels / n, inside_txt, n / d.cm_s[i], png.c_str());
  }
}

void print_relief(const DemoData& d, const Refs& refs) {
  const auto png = png_path(d, "cmodel_ewa_relief.png");
  d.outs.write(png, img::png_rgba(d.relief.image, png));
  write_png(d, "heat_cmodel_ewa_relief_vs_ewa.png", render::error_heatmap(d.relief.image, refs.ewa.image, 64));
  const auto rel = render::relief_pixels(d.s);
  std::printf("\nwith relief (each material's method, fixed point) against the float EWA with the 256-layer "
              "relief march and the truth (exact intersection), over covered pixels / the relief pixels alone:\n"
              "%-12s %12s %12s   relief pixels: %s vs EWA, %s vs truth %12.0f px/s  %s\n",
              "ewa+relief", db(render::psnr_covered(d.relief, refs.ewa)).c_str(), db(render::psnr_covered(d.relief, refs.truth)).c_str(),
              db(render::psnr_covered(d.relief, refs.ewa, rel)).c_str(), db(render::psnr_covered(d.relief, refs.truth, rel)).c_str(),
              double(d.relief.pixels.size()) / d.relief_s, png.c_str());
}

void print_procedural(const DemoData& d) {
  std::printf("\nprocedural scene (docs/scenes/procedural.json, %dx%d: fBm ground, smoke wall; noise unit, "
              "docs/blocks/noise-appendix.md §5), PSNR over covered pixels against the float reference with the "
              "footprint limit and the truth (16 x 16 samples of the unfiltered field):\n",
              d.proc.camera.width, d.proc.camera.height);
  std::printf("%-22s %12s %12s  %s\n", "engine", "vs ref", "vs truth", "image");
  const std::pair<const char*, const render::Frame*> rows[] = {{"ref_limited", &d.proc_ref},
                                                               {"ref_all_octaves", &d.proc_ref_all},
                                                               {"cmodel_limited", &d.proc_cm},
                                                               {"cmodel_all_octaves", &d.proc_cm_all},
                                                               {"truth", &d.proc_truth}};
  for (const auto& [name, fr] : rows) {
    const auto png = png_path(d, std::string("procedural_") + name + ".png");
    d.outs.write(png, img::png_rgba(fr->image, png));
    std::printf("%-22s %12s %12s  %s\n", name, db(render::psnr_covered(*fr, d.proc_ref)).c_str(),
                db(render::psnr_covered(*fr, d.proc_truth)).c_str(), png.c_str());
  }
}

// The RTL rows: the texture-unit top == the C-model engine on every pixel.
bool print_rtl(const DemoData& d, const Refs& relief_refs, const Refs& refs) {
  std::printf("\ndefault scene through the Verilated texture unit (rtl/top/tu_texture_unit.sv: spans ->"
              " B1 -> B2 -> relief -> filter), every pixel compared with the C-model engine, no stalls:\n");
  std::printf("%-12s %8s %10s %11s %11s %13s %13s %9s %12s  %s\n", "filter", "pixels", "mismatch",
              "PSNR vs EWA", "vs truth", "cycles/pixel", "predicted", "error", "RTL pixel/s", "image");
  bool ok = true;
  for (int i = 0; i < kRtlN; ++i) {
    const RtlRow& r = kRtlRows[i];
    const auto& res = d.rtl[i];
    ok = ok && res.ok();
    const auto png = png_path(d, std::string("rtl_") + r.name + ".png");
    d.outs.write(png, img::png_rgba(res.frame.image, png));
    const double n = static_cast<double>(std::max<size_t>(1, res.frame.pixels.size()));
    char pred[32] = "-", err[32] = "-";  // relief streams: not predicted
    if (res.predicted_cycles) {
      std::snprintf(pred, sizeof pred, "%.3f", double(res.predicted_cycles) / n);
      std::snprintf(err, sizeof err, "%+.3f %%",
                    100.0 * (double(res.predicted_cycles) / double(std::max<uint64_t>(1, res.cycles)) - 1));
    }
    // PSNR against the float EWA and the truth of the same path (the relief row: with relief).
    const Refs& rf = r.relief ? relief_refs : refs;
    std::printf("%-12s %8zu %10llu %11s %11s %13.3f %13s %9s %12.0f  %s\n", r.name, res.frame.pixels.size(),
                (unsigned long long)res.mismatches, db(render::psnr_covered(res.frame, rf.ewa)).c_str(),
                db(render::psnr_covered(res.frame, rf.truth)).c_str(), double(res.cycles) / n, pred, err,
                n / res.sim_wall_s, png.c_str());
    if (r.relief) {
      const auto rel = render::relief_pixels(d.s);
      std::printf("%-12s relief pixels alone: %s vs EWA, %s vs truth\n", "", db(render::psnr_covered(res.frame, rf.ewa, rel)).c_str(),
                  db(render::psnr_covered(res.frame, rf.truth, rel)).c_str());
    }
    if (!res.ok()) std::printf("  first mismatch: %s\n", res.first_mismatch.c_str());
  }
  std::printf("%s\n", ok ? "RTL texture unit == C model on every pixel"
                          : "MISMATCH: RTL texture unit and C model disagree (see above)");
  return ok;
}

// The shaded scene (docs/scenes/shaded_sphere.json: one point light, diffuse + the unit's F_MSH
// highlight on a checkered sphere with vertex normals) through the three engines.
bool print_shaded(const DemoData& d) {
  const char* path = "docs/scenes/shaded_sphere.json";
  if (!d.shaded) {
    std::printf("\nshaded scene: %s not found (run the demo from the repository root): skipped\n", path);
    return true;
  }
  const auto& rtl = d.shaded_rtl;
  write_png(d, "shaded_ref.png", d.shaded_ref.image);
  write_png(d, "shaded_cmodel.png", d.shaded_fx.image);
  write_png(d, "shaded_rtl.png", rtl.frame.image);
  const double n = static_cast<double>(std::max<size_t>(1, rtl.frame.pixels.size()));
  std::printf("\nshaded scene %s (%zu covered pixels; one light, diffuse + %s highlight after the filter):\n"
              "  C model %s vs the float reference; RTL: %llu mismatches against the C model, %.3f cycles/pixel, "
              "predicted %.3f (%+.3f %%); images %s/shaded_{ref,cmodel,rtl}.png\n",
              path, rtl.frame.pixels.size(), brdf::name(cosim::RtlRenderOptions{}.shade_model).c_str(),
              db(render::psnr_covered(d.shaded_fx, d.shaded_ref)).c_str(), (unsigned long long)rtl.mismatches,
              double(rtl.cycles) / n, double(rtl.predicted_cycles) / n,
              100.0 * (double(rtl.predicted_cycles) / double(std::max<uint64_t>(1, rtl.cycles)) - 1), d.out_dir.c_str());
  if (!rtl.ok()) std::printf("  first mismatch: %s\n", rtl.first_mismatch.c_str());
  return rtl.ok() && rtl.cycles == rtl.predicted_cycles;
}
}  // namespace

std::function<bool()> demo_render_jobs(const std::string& out_dir, std::vector<DemoJob>& jobs) {
  auto dp = std::make_shared<DemoData>();
  DemoData& d = *dp;
  d.out_dir = out_dir;
  d.s = scene::default_scene();
  d.flat = scene::without_relief(d.s);
  d.mixed = d.flat;
  d.mixed.materials.at("ground").filter = scene::Filter::Bilinear;
  d.proc = scene::procedural_scene();
  d.proc_all = d.proc;
  for (auto& [name, m] : d.proc_all.materials) m.procedural->footprint_limit = false;
  if (const char* path = "docs/scenes/shaded_sphere.json"; std::filesystem::exists(path)) d.shaded = scene::load(path);
  d.outs.make_dir(out_dir);
  add_jobs(dp, jobs);
  return [dp] {
    const DemoData& d = *dp;
    const Refs flat_refs{d.ewa_flat, d.truth_flat}, relief_refs{d.ref[kRefN - 1], d.truth};
    print_reference(d);
    print_cmodel(d, flat_refs);
    print_relief(d, relief_refs);
    print_procedural(d);
    const bool rtl_ok = print_rtl(d, relief_refs, flat_refs);
    const bool ok = print_shaded(d) && rtl_ok;
    d.outs.commit();
    return ok;
  };
}

bool demo_render(const std::string& out_dir, int threads) {
  std::vector<DemoJob> jobs;
  const auto print = demo_render_jobs(out_dir, jobs);
  run_demo_jobs(jobs, threads);
  return print();
}

}  // namespace tu::cli
