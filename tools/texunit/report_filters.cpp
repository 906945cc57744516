#include "report_filters.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "filter_cmd.hpp"

namespace tu::report {

namespace {
using json = nlohmann::json;

// The scenes of feline.md's table: the default scene and the docs scenes with a textured surface.
const std::vector<std::string> kScenes = {"default", "docs/scenes/ui_quad.json", "docs/scenes/hud_floor.json",
                                          "docs/scenes/corridor.json", "docs/scenes/shaded_sphere.json"};

// The engine that runs a filter in tu_texture_unit and its own synthesis top (empty: the K = 4
// engine, synthesised by scripts/yosys_ewa_k4.sh, not a manifest top).
std::pair<std::string, std::string> engine(const std::string& filter) {
  if (filter == "nearest") return {"tu_nearest (texel address + one read)", "tu_nearest"};
  if (filter == "bilinear") return {"tu_bilinear (one texel per clock)", "tu_bilinear"};
  if (filter == "trilinear") return {"tu_trilinear (one texel per clock)", "tu_trilinear"};
  if (filter.rfind("feline", 0) == 0) return {"tu_feline (probes through one tu_trilinear)", "tu_feline"};
  if (filter == "ewa") return {"tu_ewa Lanes 1 (one texel per clock)", "tu_ewa"};
  return {"tu_ewa Lanes 4, Setups 3 (2x2 block per clock)", ""};
}

json extra(const Row& r) { return json::parse("{" + r.extra_json + "}"); }

std::string f2(double x, const char* f = "%.2f") {
  char b[32];
  std::snprintf(b, sizeof b, f, x);
  return b;
}
}  // namespace

std::vector<Row> filter_rows(const std::string& root, const std::function<void(Row&)>& area) {
  std::vector<Row> out;
  for (const auto& name : kScenes) {
    const auto sc = name == "default" ? scene::default_scene() : scene::load(root + "/" + name);
    const auto c = cli::compare_filters(sc, 16);
    for (const auto& f : c.rows) {
      Row r;
      r.block = "filters";
      r.variant = f.name;
      r.scheme = name == "default" ? "default" : name.substr(name.rfind('/') + 1, name.size() - name.rfind('/') - 6);
      r.err_unit = "PSNR dB over the covered pixels vs the 16x16 box truth (higher is better)";
      r.max_abs_err = 0;
      r.latency_cycles = -1;
      r.ii_cycles = f.clocks;
      r.cycles_source = "ewa::stream_cycles: the RTL unit's exact cycle model (= Verilator)";
      const auto [scheme, top] = engine(f.name);
      r.notes = scheme;
      r.rtl_top = top;
      if (top.empty()) {
        r.area_source = "scripts/yosys_ewa_k4.sh (docs/blocks/ewa.md)";
        r.stdcell_source = r.area_source;
      } else {
        area(r);
      }
      json e = {{"scene", r.scheme},           {"covered_px", c.covered},     {"psnr_truth_db", f.psnr_truth},
                {"psnr_float_ewa_db", f.psnr_ewa}, {"probes_per_px", f.probes}, {"texels_per_px", f.texels},
                {"clocks_per_px", f.clocks}};
      r.extra_json = e.dump().substr(1, e.dump().size() - 2);
      out.push_back(r);
    }
  }
  return out;
}

std::string filters_markdown(const std::vector<Row>& rs, const std::string& plot_rel) {
  std::ostringstream o;
  o << "Every filter through the bit-accurate C model on each scene's texture path (relief off), "
       "`texunit filter-compare SCENE` per scene; the discussion is in "
       "[feline.md](blocks/feline.md#quality-against-clocks-the-architects-table). "
       "Clocks per pixel: the RTL texture unit's exact cycle model (equal to Verilator; the Feline and K = 4 "
       "engines co-simulated on the default scene). 2x2 bound: texels / 4, a datapath reading one 2 x 2 block "
       "per clock. Engine cells: Yosys generic cells of the engine's own top (this report's cache).\n\n";
  if (!plot_rel.empty()) o << "![filters: PSNR vs clocks per pixel](" << plot_rel << "/filters_psnr_vs_clocks.png)\n\n";
  o << "| scene | filter | PSNR vs truth | vs float EWA | probes / px | texels / px | clocks / px | texels / clock | "
       "2x2 bound | engine | engine cells |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& r : rs) {
    if (r.block != "filters") continue;
    const json e = extra(r);
    const double clocks = e.at("clocks_per_px").get<double>(), texels = e.at("texels_per_px").get<double>();
    const double probes = e.at("probes_per_px").get<double>();
    o << "| " << r.scheme << " (" << e.at("covered_px").get<size_t>() << " px) | " << r.variant << " | "
      << f2(e.at("psnr_truth_db").get<double>()) << " dB | " << f2(e.at("psnr_float_ewa_db").get<double>()) << " dB | "
      << (probes > 0 ? f2(probes) : "–") << " | " << f2(texels) << " | " << f2(clocks) << " | "
      << f2(texels / clocks, "%.3f") << " | " << f2(std::max(1.0, texels / 4)) << " | " << r.notes << " | "
      << (r.cells >= 0 ? std::to_string(r.cells)
          : r.area_source.rfind("not measured", 0) == 0 ? std::string("not measured (no current Yosys cache entry)")
                                                         : r.area_source)
      << " |\n";
  }
  return o.str();
}

std::string filters_plot(const std::vector<Row>& rs, const std::string& dir, out::Outputs& outs) {
  std::map<std::string, std::vector<const Row*>> by_scene;
  std::vector<std::string> order;
  for (const auto& r : rs)
    if (r.block == "filters") {
      if (!by_scene.count(r.scheme)) order.push_back(r.scheme);
      by_scene[r.scheme].push_back(&r);
    }
  if (order.empty()) return "";
  const std::string stem = dir + "/filters_psnr_vs_clocks";
  std::ostringstream g;
  g << "set terminal pngcairo size 1000,650 noenhanced\nset output '" << stem << ".png'\n"
    << "set title 'filters: PSNR vs the box truth against clocks per pixel (RTL cycle model)'\n"
    << "set xlabel 'clocks per pixel'\nset ylabel 'PSNR (dB, covered pixels)'\nset logscale x\nset grid\n"
    << "set key outside right\nplot ";
  for (size_t i = 0; i < order.size(); ++i) {
    const std::string dat = stem + "_" + order[i] + ".dat";
    std::ostringstream d;
    for (const Row* r : by_scene[order[i]]) {
      const json e = extra(*r);
      d << e.at("clocks_per_px").get<double>() << " " << e.at("psnr_truth_db").get<double>() << " \""
        << r->variant << "\"\n";
    }
    outs.write(dat, d.str());
    g << (i ? ", " : "") << "'" << dat << "' using 1:2 with points pt " << 5 + i << " ps 1.4 title '" << order[i] << "'";
    if (i == 0) g << ", '" << dat << "' using 1:2:3 with labels left offset 0.7,0.3 font ',8' notitle";
  }
  g << "\n";
  outs.write(stem + ".gp", g.str());
  return out::gnuplot(outs, stem + ".gp", {stem + ".png"});
}

}  // namespace tu::report
