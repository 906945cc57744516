// `texunit render SCENE.json --out DIR [--dump FILE.csv] [--engine ref] [--filter F]`.
#include "render_cmd.hpp"

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
  r->add_option("--engine", a.engine, "rendering engine")->check(CLI::IsMember({"ref"}));
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
  const render::Frame frame = render::render_ref(s, f);
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

}  // namespace tu::cli
