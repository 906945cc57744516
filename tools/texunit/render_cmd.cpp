// `texunit render SCENE.json --out DIR [--dump FILE.csv] [--engine ref] [--filter F]`.
#include "render_cmd.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "texunit/render.hpp"
#include "texunit/scene.hpp"

namespace tu::cli {

CLI::App* add_render(CLI::App& app, RenderArgs& a) {
  auto* r = app.add_subcommand("render", "render a scene to PNG images (docs/scene-format.md)");
  r->add_option("SCENE", a.scene, "scene JSON file, or 'default' for the embedded scene")->required();
  r->add_option("--out", a.out_dir, "output directory (created if missing)")->required();
  r->add_option("--dump", a.dump, "CSV: one row per covered pixel (x,y,u,v,lod,texels,r,g,b,a)");
  r->add_option("--engine", a.engine, "rendering engine")->check(CLI::IsMember({"ref", "cmodel"}));
  r->add_option("--filter", a.filter, "override every material's filter")
      ->check(CLI::IsMember({"nearest", "bilinear", "trilinear", "ewa"}));
  return r;
}

int run_render(const RenderArgs& a) {
  const scene::Scene s = a.scene == "default" ? scene::default_scene() : scene::load(a.scene);
  std::optional<scene::Filter> f;
  if (a.filter == "nearest") f = scene::Filter::Nearest;
  if (a.filter == "bilinear") f = scene::Filter::Bilinear;
  if (a.filter == "trilinear") f = scene::Filter::Trilinear;
  if (a.filter == "ewa") f = scene::Filter::Ewa;
  // Everything is computed before any file is written: a failure leaves no partial output.
  render::CmodelOptions opt;
  opt.progress = true;
  const render::Frame frame = a.engine == "cmodel" ? render::render_cmodel(s, f, opt) : render::render_ref(s, f);
  std::filesystem::create_directories(a.out_dir);
  const std::string png = (std::filesystem::path(a.out_dir) / (a.engine + ".png")).string();
  img::write_png_rgba(png, frame.image);
  std::cerr << "wrote " << png << " (" << frame.pixels.size() << " covered pixels)\n";
  if (!a.dump.empty()) {
    render::write_dump_csv(a.dump, frame);
    std::cerr << "wrote " << a.dump << "\n";
  }
  return 0;
}

namespace {
// The demo's C-model rows: every filter (EWA with each weight source) against the float EWA frame.
void demo_render_cmodel(const scene::Scene& s, const render::Frame& ewa_ref, const std::string& out_dir);
}  // namespace

void demo_render(const std::string& out_dir) {
  const scene::Scene s = scene::default_scene();
  const scene::Filter filters[] = {scene::Filter::Nearest, scene::Filter::Bilinear,
                                   scene::Filter::Trilinear, scene::Filter::Ewa};
  std::vector<render::Frame> frames;
  std::vector<double> seconds;
  for (auto f : filters) {
    const auto t0 = std::chrono::steady_clock::now();
    frames.push_back(render::render_ref(s, f));
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  std::filesystem::create_directories(out_dir);
  const auto& ewa = frames.back();
  std::printf("\ndefault scene (%dx%d, %zu covered pixels), float reference engine:\n",
              s.camera.width, s.camera.height, ewa.pixels.size());
  std::printf("%-10s %14s %14s %10s  %s\n", "filter", "PSNR vs EWA", "texels/pixel", "seconds",
              "image");
  for (size_t i = 0; i < frames.size(); ++i) {
    const auto name = std::string(scene::to_string(filters[i]));
    const auto png = (std::filesystem::path(out_dir) / ("ref_" + name + ".png")).string();
    img::write_png_rgba(png, frames[i].image);
    if (i + 1 < frames.size())
      img::write_png_rgba((std::filesystem::path(out_dir) / ("heat_" + name + "_vs_ewa.png")).string(),
                          render::error_heatmap(frames[i].image, ewa.image, 64));
    double texels = 0;
    for (const auto& p : frames[i].pixels) texels += p.texels;
    const double ps = tex::psnr(frames[i].image, ewa.image);
    char psnr_txt[32];
    std::snprintf(psnr_txt, sizeof psnr_txt, std::isinf(ps) ? "reference" : "%.2f dB", ps);
    std::printf("%-10s %14s %14.2f %10.3f  %s\n", name.c_str(), psnr_txt,
                texels / static_cast<double>(std::max<size_t>(1, frames[i].pixels.size())),
                seconds[i], png.c_str());
  }
  demo_render_cmodel(s, ewa, out_dir);
}

namespace {
void demo_render_cmodel(const scene::Scene& s, const render::Frame& ewa_ref, const std::string& out_dir) {
  struct Row {
    const char* name;
    scene::Filter filter;
    scene::WeightSource weights;
  };
  const Row rows[] = {{"nearest", scene::Filter::Nearest, scene::WeightSource::Formula},
                      {"bilinear", scene::Filter::Bilinear, scene::WeightSource::Formula},
                      {"trilinear", scene::Filter::Trilinear, scene::WeightSource::Formula},
                      {"ewa_formula", scene::Filter::Ewa, scene::WeightSource::Formula},
                      {"ewa_table1d", scene::Filter::Ewa, scene::WeightSource::Table1d},
                      {"ewa_table2d", scene::Filter::Ewa, scene::WeightSource::Table2d}};
  std::printf("\ndefault scene, bit-accurate C-model engine (B1 persp -> B2 ellipse -> filter), "
              "against the float EWA reference:\n");
  std::printf("%-12s %12s %13s %13s %12s  %s\n", "filter", "PSNR vs EWA", "texels/pixel",
              "inside/pixel", "pixels/s", "image");
  for (const auto& r : rows) {
    render::CmodelOptions opt;
    opt.weights = r.weights;  // each render takes ~0.5 s: no progress bar
    const auto t0 = std::chrono::steady_clock::now();
    const auto fr = render::render_cmodel(s, r.filter, opt);
    const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const auto dir = std::filesystem::path(out_dir);
    const auto png = (dir / (std::string("cmodel_") + r.name + ".png")).string();
    img::write_png_rgba(png, fr.image);
    img::write_png_rgba((dir / (std::string("heat_cmodel_") + r.name + "_vs_ewa.png")).string(),
                        render::error_heatmap(fr.image, ewa_ref.image, 64));
    double texels = 0, inside = 0;
    for (const auto& p : fr.pixels) texels += p.texels, inside += p.texels_inside;
    const double n = static_cast<double>(std::max<size_t>(1, fr.pixels.size()));
    char inside_txt[32] = "-";
    if (r.filter == scene::Filter::Ewa) std::snprintf(inside_txt, sizeof inside_txt, "%.2f", inside / n);
    std::printf("%-12s %9.2f dB %13.2f %13s %12.0f  %s\n", r.name, tex::psnr(fr.image, ewa_ref.image),
                texels / n, inside_txt, n / sec, png.c_str());
  }
}
}  // namespace

}  // namespace tu::cli
