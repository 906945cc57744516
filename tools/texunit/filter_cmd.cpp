// `texunit filter-compare SCENE|default [--ss N] [--plot DIR]`: the architect's table of
// docs/blocks/feline.md. Every filter of the unit (nearest, bilinear, trilinear, EWA) and Feline at
// probe caps 2, 4, 8, 16 through the bit-accurate C model on the scene's texture path (relief
// off): PSNR against the box ground truth and the float EWA, probes, texels and clocks per pixel,
// texels per clock. Clocks: the RTL texture unit's exact cycle model (ewa::stream_cycles, equal to
// Verilator) for every engine, Feline's tu_feline included.
#include "filter_cmd.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "ewa/ewa_cycles.hpp"
#include "output.hpp"
#include "plan.hpp"
#include "texunit/render.hpp"

namespace tu::cli {

CLI::App* add_filter_compare(CLI::App& app, FilterCompareArgs& a) {
  auto* c = app.add_subcommand("filter-compare",
                               "every filter and Feline (probe caps 2..16) on a scene: PSNR vs truth and the float "
                               "EWA, probes, texels and clocks per pixel (docs/blocks/feline.md)");
  c->add_option("SCENE", a.scene, "scene JSON file, or 'default'")->required();
  c->add_option("--ss", a.ss, "ground truth: stratified samples per pixel side")->check(CLI::Range(1, 64));
  c->add_option("--plot", a.plot, "write psnr_vs_clocks.{dat,gp,png} (gnuplot) into this directory");
  c->add_option("--mip-filter", a.mip_filters,
                "build every texture's mip pyramid with this filter (box, box_linear, lanczos2; a comma-separated "
                "list or 'all': one table per pyramid and PSNR vs truth side by side; docs/blocks/texture.md)")
      ->delimiter(',')
      ->check(CLI::IsMember({"box", "box_linear", "lanczos2", "all"}));
  return c;
}

namespace {
using Row = FilterRow;

// The plot's files belong to `outs` (the command's outputs: all or none).
void write_plot(const std::vector<Row>& rows, const std::string& dir, const std::string& title, Outputs& outs) {
  const std::string dat = dir + "/psnr_vs_clocks.dat", gp = dir + "/psnr_vs_clocks.gp";
  {
    std::ostringstream d;
    d << "# filter clocks_per_pixel psnr_vs_truth_db texels_per_pixel\n";
    for (const auto& r : rows) d << '"' << r.name << "\" " << r.clocks << ' ' << r.psnr_truth << ' ' << r.texels << '\n';
    outs.write(dat, d.str());
  }
  std::ostringstream g;
  g << "set terminal pngcairo size 900,600\nset output '" << dir << "/psnr_vs_clocks.png'\n"
    << "set title \"" << title << "\"\nset xlabel 'clocks per pixel (RTL cycle model; Feline: N tu\\_trilinear passes)'\n"
    << "set ylabel 'PSNR vs box truth (dB)'\nset logscale x\nset grid\nset key off\n"
    << "plot '" << dat << "' using 2:3 with points pt 7 ps 1.5, '' using 2:3:1 with labels offset 0,1 font ',9'\n";
  outs.write(gp, g.str());
  if (const std::string why = out::gnuplot(outs, gp, {dir + "/psnr_vs_clocks.png"}); !why.empty())
    throw std::runtime_error("filter-compare: " + why);
}
}  // namespace

FilterComparison compare_filters(const scene::Scene& scene_in, int ss, std::optional<tex::MipFilter> mip) {
  scene::Scene s = scene::without_relief(scene_in);
  if (mip)
    for (auto& [name, t] : s.textures) t.mip_filter = static_cast<int>(*mip);
  render::TruthOptions to;
  to.ss = ss;
  to.relief = false;
  const auto truth = render::render_truth(s, to);
  const auto ewa_ref = render::render_ref(s, scene::Filter::Ewa);
  const double n = static_cast<double>(std::max<size_t>(1, truth.pixels.size()));
  FilterComparison out;
  out.source = s.source;
  out.width = s.camera.width;
  out.height = s.camera.height;
  out.ss = ss;
  out.covered = truth.pixels.size();
  if (mip) out.mip_filter = tex::kMipFilterNames[static_cast<int>(*mip)];
  out.truth_hash = 1469598103934665603ull;  // FNV-1a over the truth image's bytes
  for (const auto& p : truth.image.px)
    for (const uint8_t b : {p.r, p.g, p.b, p.a}) out.truth_hash = (out.truth_hash ^ b) * 1099511628211ull;
  std::vector<Row>& rows = out.rows;
  auto measure = [&](const std::string& name, const scene::Scene& si, scene::Filter f, const ewa::EngineParams& ep = {}) {
    const auto fr = render::render_cmodel(si, f, render::texture_path_only());
    Row r{name, render::psnr_covered(fr, truth), render::psnr_covered(fr, ewa_ref)};
    for (const auto& p : fr.pixels) r.probes += p.probes, r.texels += p.texels;
    r.probes /= n;
    r.texels /= n;
    r.clocks = double(plan::scene_stream_cycles(si, [f](const scene::Material&) { return f; }, false, std::nullopt,
                                                false, 0, {}, nullptr, {}, 1, ep)) /
               n;
    rows.push_back(r);
  };
  for (const scene::Filter f : {scene::Filter::Nearest, scene::Filter::Bilinear, scene::Filter::Trilinear})
    measure(scene::to_string(f), s, f);
  for (const int cap : {2, 4, 8, 16}) {
    scene::Scene si = s;
    for (auto& [name, m] : si.materials) m.feline_max_probes = cap;
    measure("feline N<=" + std::to_string(cap), si, scene::Filter::Feline);
  }
  measure("ewa", s, scene::Filter::Ewa);
  // The multi-texel engine (tu_ewa Lanes = 4: a 2 x 2 block per clock, three set-up units; the
  // corridor unit model's, co-simulated = this cycle model): the same pixels, fewer clocks.
  measure("ewa K=4", s, scene::Filter::Ewa, ewa::four_lane_engine());
  return out;
}

namespace {
void print_table(const FilterComparison& c, int ss) {
  const auto& s = c;
  const auto& rows = c.rows;
  std::printf("%s: %dx%d, %zu covered pixels, texture path (relief off), C model; truth %d x %d samples per pixel, box",
              s.source.c_str(), s.width, s.height, s.covered, ss, ss);
  if (!c.mip_filter.empty()) std::printf("; mip filter %s (every texture)", c.mip_filter.c_str());
  std::printf("\n");
  std::printf("%-14s %12s %14s %11s %11s %11s %12s %12s\n", "filter", "PSNR truth", "PSNR float EWA", "probes/px",
              "texels/px", "clocks/px", "texels/clock", "4/clk bound");
  for (const auto& r : rows)
    std::printf("%-14s %9.2f dB %11.2f dB %11.2f %11.2f %11.2f %12.3f %12.2f\n", r.name.c_str(), r.psnr_truth,
                r.psnr_ewa, r.probes, r.texels, r.clocks, r.texels / r.clocks,
                std::max(1.0, r.texels / 4));
  std::printf("clocks/px: the RTL texture unit's exact cycle model (ewa::stream_cycles, = Verilator; Feline: "
              "tu_feline, its probes through one tu_trilinear; ewa K=4: tu_ewa_walk_lanes, 2x2 blocks, 3 set-up units); 4/clk bound: texels / 4, the clocks of a datapath "
              "reading a 2x2 texel block per clock (a GPU's bilinear probe)\n");
}
}  // namespace

int run_filter_compare(const FilterCompareArgs& a) {
  const scene::Scene scene = a.scene == "default" ? scene::default_scene() : scene::load(a.scene);
  Outputs outs;
  if (!a.plot.empty()) outs.make_dir(a.plot);  // after the scene is read, before the renders
  // The pyramids asked for, in kMipFilterNames order, each once ('all': every one).
  std::vector<tex::MipFilter> mips;
  for (int i = 0; i < 3; ++i)
    for (const auto& m : a.mip_filters)
      if (m == "all" || m == tex::kMipFilterNames[i]) {
        mips.push_back(static_cast<tex::MipFilter>(i));
        break;
      }
  if (mips.empty()) {
    const auto c = compare_filters(scene, a.ss);
    print_table(c, a.ss);
    if (!a.plot.empty()) write_plot(c.rows, a.plot, c.source + ": PSNR vs clocks per pixel", outs);
    outs.commit();
    if (!a.plot.empty()) std::fprintf(stderr, "wrote %s/psnr_vs_clocks.png\n", a.plot.c_str());
    return 0;
  }
  std::vector<FilterComparison> cs;
  for (const auto m : mips) {
    cs.push_back(compare_filters(scene, a.ss, m));
    print_table(cs.back(), a.ss);
    std::printf("\n");
    if (!a.plot.empty()) {
      const std::string dir = a.plot + "/" + cs.back().mip_filter;
      outs.make_dir(dir);
      write_plot(cs.back().rows, dir, cs.back().source + ": PSNR vs clocks per pixel, mip filter " + cs.back().mip_filter, outs);
    }
  }
  outs.commit();
  for (const auto& c : cs)
    if (!a.plot.empty()) std::fprintf(stderr, "wrote %s/%s/psnr_vs_clocks.png\n", a.plot.c_str(), c.mip_filter.c_str());
  if (cs.size() < 2) return 0;
  // PSNR vs truth per filter (rows) and pyramid (columns), and whether the truth moved.
  std::printf("PSNR vs truth (dB) per mip filter: %s\n%-14s", cs[0].source.c_str(), "filter");
  for (const auto& c : cs) std::printf(" %11s", c.mip_filter.c_str());
  std::printf("\n");
  for (size_t r = 0; r < cs[0].rows.size(); ++r) {
    std::printf("%-14s", cs[0].rows[r].name.c_str());
    for (const auto& c : cs) std::printf(" %8.2f dB", c.rows[r].psnr_truth);
    std::printf("\n");
  }
  bool same = true;
  for (const auto& c : cs) same = same && c.truth_hash == cs[0].truth_hash;
  std::printf("truth image: %s with every pyramid (FNV-1a %016llx%s)\n", same ? "identical" : "DIFFERENT",
              static_cast<unsigned long long>(cs[0].truth_hash), same ? "; it samples level 0 alone" : "");
  return 0;
}

}  // namespace tu::cli
