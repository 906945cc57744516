#include "report_relief.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <map>
#include <stdexcept>

#include "afvis/afvis_quality.hpp"
#include "block.hpp"
#include "cosim.hpp"
#include "distmap/dm_trace.hpp"
#include "pom/relief.hpp"
#include "pom/relief_quality.hpp"
#include "pom_vec_common.hpp"
#include "texunit/render.hpp"
#include "texunit/scene.hpp"

namespace tu::report {

namespace {
// One row from a Verilator run of vf (no stalls): errors vs the block's float reference, cycles,
// RTL simulation speed, C-model speed.
Row measured_row(const std::string& variant, const vec::VectorFile& vf, bool per_pixel_cycles) {
  const auto& b = blocks::find(vf.block);
  cosim::Options opt;
  opt.run.stall_prob = 0;
  const auto rep = cosim::run(vf, opt);
  if (!rep.ok()) throw std::runtime_error("report: " + b.name + " " + variant + ": RTL != C model: " + rep.json());
  Row r;
  r.block = b.name;
  r.variant = variant;
  r.scheme = "tu_" + b.name;
  r.rtl_top = r.scheme;
  r.max_abs_err = rep.max_abs_err;
  r.rms_err = rep.rms_err;
  r.max_ulp_err = rep.max_ulp_err;
  r.err_unit = b.name == "pom_layers" ? "layers" : b.name == "pom_march" ? "march steps" : "uv LSB (2^-16)";
  r.latency_cycles = per_pixel_cycles ? b.latency_cycles : static_cast<int64_t>(rep.latency_cycles);
  r.ii_cycles = per_pixel_cycles ? double(rep.sim_cycles) / double(rep.vectors) : rep.ii_cycles;
  r.cycles_source = per_pixel_cycles ? "measured (Verilator, mean cycles per pixel of the stream)"
                                     : "measured (Verilator)";
  r.rtl_sim_items_per_s = double(rep.vectors) / rep.wall_s;
  r.rtl_sim_source = "measured (Verilator, " + std::to_string(rep.vectors) + " items)";
  const auto in_idx = vf.indices(vec::Role::In);
  const auto t0 = std::chrono::steady_clock::now();
  uint64_t items = 0, sink = 0;
  do {
    for (const auto& row : vf.rows) sink += b.model(blocks::pick(row, in_idx))[0];
    items += vf.rows.size();
  } while (std::chrono::steady_clock::now() - t0 < std::chrono::milliseconds(50));
  r.cmodel_ns_per_item =
      std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count() / double(items);
  if (sink == 0xdeadbeef) std::fputs("", stderr);  // keep the work
  return r;
}

// Distance-map tracer (docs/blocks/relief.md §13): the bricks 64x64 tile at 60 deg, S = 0.125, 16
// layers, with the finish; error = |uv - float reference| in uv LSB; cycles per pixel of the tile's
// stream through the relief stage's tracer tu_dm_trace (relief::stage_cycles, equal to Verilator:
// ReliefStageCosim.DistanceMap*).
Row dm_row(bool refined) {
  constexpr int kSide = 64;
  const img::Gray8 depth = pom::map_bricks(kSide);
  dm::Params p;
  p.layers = 16;
  p.scale = 0.125;
  p.refined = refined;
  const dm::Map m = dm::build(depth, p);
  const double th = 60 * M_PI / 180, ph = 30 * M_PI / 180;
  pom::View v;
  v.vx = static_cast<int32_t>(std::lround(std::sin(th) * std::cos(ph) * (1 << fmt::kPomVzF)));
  v.vy = static_cast<int32_t>(std::lround(std::sin(th) * std::sin(ph) * (1 << fmt::kPomVzF)));
  v.vz = static_cast<int32_t>(std::lround(std::cos(th) * (1 << fmt::kPomVzF)));
  v.scale = m.scale_code;
  double max_e = 0, se = 0, steps = 0;
  std::vector<relief::StagePixel> stream;
  const auto t0 = std::chrono::steady_clock::now();
  for (int y = 0; y < kSide; ++y)
    for (int x = 0; x < kSide; ++x) {
      const int64_t u = (int64_t(2 * x + 1) << fmt::kPomUvF) / (2 * kSide), w = (int64_t(2 * y + 1) << fmt::kPomUvF) / (2 * kSide);
      const auto o = dm::trace(m, depth, u, w, v, fmt::kDmCap, fmt::kDmFinish);
      const auto r = dm::trace_ref(m, depth, std::ldexp(double(u), -fmt::kPomUvF), std::ldexp(double(w), -fmt::kPomUvF),
                                   std::ldexp(v.vx, -fmt::kPomVzF), std::ldexp(v.vy, -fmt::kPomVzF),
                                   std::ldexp(v.vz, -fmt::kPomVzF), m.scale, fmt::kDmCap, fmt::kDmFinish);
      for (double e : {double(o.u) - r.u * 65536, double(o.v) - r.v * 65536}) {
        max_e = std::max(max_e, std::abs(e));
        se += e * e;
      }
      steps += o.steps + o.finish_steps;
      stream.push_back(relief::stage_pixel(true, o.steps + o.finish_steps, scene::ReliefMethod::DistanceMap));
    }
  const double trace_ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count();
  const double n = double(kSide) * kSide;
  Row row;
  row.block = "distance_map";
  row.variant = refined ? "refined_60deg" : "classic_60deg";
  row.scheme = refined ? "sphere trace, visibility-refined map + linear/binary finish" : "sphere trace, classic map + linear/binary finish";
  row.max_abs_err = max_e;
  row.rms_err = std::sqrt(se / (2 * n));
  row.err_unit = "uv LSB (2^-16) vs the float tracer";
  row.latency_cycles = -1;
  row.ii_cycles = static_cast<double>(relief::stage_cycles(stream)) / n;
  row.cycles_source = "relief::stage_cycles of the tile's stream through tu_dm_trace (= Verilator, ReliefStageCosim)";
  row.memory_bits = static_cast<int64_t>(m.bytes()) * 8;
  row.cmodel_ns_per_item = trace_ns / n / 2;  // 2 tracers
  char b[160];
  std::snprintf(b, sizeof b, "bricks 64x64, S 0.125, 16 layers (%zu bytes): %.3f reads/px", m.bytes(), steps / n);
  row.notes = b;
  return row;
}

// AF with parallax visibility (docs/blocks/afvis.md): the engine tu_afvis on the block's random
// vectors (Verilator, mean clocks per pixel) and on the docs scene's relief pixels with the row rule
// (the walker's clocks afvis::Out::clocks = Verilator, TextureUnitRtl.AfVisibility*), with the
// quality against the truth of the bricks map at the scene's camera (afvis::quality, 4x4 samples).
std::vector<Row> afvis_rows(const std::string& root) {
  std::vector<Row> rows;
  rows.push_back(measured_row("random_vectors", blocks::generate(blocks::find("afvis"), "random", 2000, 3), true));
  rows.back().err_unit = "8-bit colour levels vs the float EWA with the float visibility";
  rows.back().notes = "2,000 random vectors (bricks 256 colour, bricks 64 depth, views 0-90 deg, both rules)";
  const scene::Scene s = scene::load(root + "/docs/scenes/af_visibility.json");
  const auto t0 = std::chrono::steady_clock::now();
  const render::Frame on = render::render_cmodel(s);
  const double ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count();
  render::CmodelOptions off;
  off.afvis = render::AfvisMode::Off;
  const render::Frame plain = render::render_cmodel(s, {}, off);
  double n = 0, clocks = 0, box = 0, steps = 0, traced = 0;
  for (size_t i = 0; i < on.pixels.size() && i < plain.pixels.size(); ++i)
    if (on.pixels[i].afv_clocks) {
      ++n;
      clocks += double(on.pixels[i].afv_clocks);
      box += plain.pixels[i].texels;
      steps += on.pixels[i].afv_steps;
      traced += on.pixels[i].afv_traced;
    }
  n = std::max(n, 1.0);
  afvis::QualityParams qp;
  qp.maps = {"bricks"};
  qp.heights = {1};
  qp.ss = 4;
  const auto q = afvis::quality(s, qp);
  auto db = [&](const std::string& v) {
    for (const auto& r : q)
      if (r.variant == v) return r.psnr;
    return 0.0;
  };
  Row r;
  r.block = "afvis";
  r.variant = "docs_scene_row_rule";
  r.scheme = "tu_afvis: row scan, row rule, box-field DDA one depth read per clock";
  r.rtl_top = "tu_afvis";
  r.err_unit = "dB vs the truth (relief pixels)";
  r.max_abs_err = db("row");
  r.latency_cycles = -1;
  r.ii_cycles = clocks / n;
  r.cycles_source = "afvis::Out::clocks per visibility pixel of the docs scene (walker, hand-over to output; = Verilator)";
  r.cmodel_ns_per_item = ns / double(std::max<size_t>(1, on.pixels.size()));
  char b[400];
  std::snprintf(b, sizeof b,
                "docs/scenes/af_visibility.json 128x96, %.0f visibility px: box %.1f texels, %.1f traces, %.1f depth reads per px; "
                "walker %.1f clocks/px vs tu_ewa %.1f (+%.0f %%); bricks x1 vs truth (4x4): plain %.2f dB, row %.2f dB, every %.2f dB",
                n, box / n, traced / n, steps / n, clocks / n, box / n + 12, 100 * (clocks / (box + 12 * n) - 1), db("plain"),
                db("row"), db("every"));
  r.notes = b;
  rows.push_back(r);
  return rows;
}

std::string mean_steps(const vec::VectorFile& vf, int out_col) {
  const int c = vf.indices(vec::Role::Out)[static_cast<size_t>(out_col)];
  double k = 0;
  for (const auto& row : vf.rows) k += double(row[static_cast<size_t>(c)]);
  char b[96];
  std::snprintf(b, sizeof b, "bricks 64x64 scene, S 0.05: %.3f steps/px", k / double(vf.rows.size()));
  return b;
}
}  // namespace

bool is_relief_block(const std::string& b) {
  return b == "pom_layers" || b == "pom_march" || b == "iter_parallax" || b == "pom_unit" || b == "distance_map" ||
         b == "afvis";
}

std::vector<Row> relief_rows(const std::vector<std::string>& blocks_, const std::string& root) {
  std::vector<Row> rows;
  auto fixed = [&](const std::string& block, const std::string& variant) {
    rows.push_back(measured_row(variant, blocks::generate(blocks::find(block), "random", 20000, 3), false));
    rows.back().notes = "20,000 random vectors";
  };
  auto scene = [&](const std::string& block, const std::string& variant, double deg, int n, int steps_col) {
    const auto vf = blocks::pomvec::scene_vectors(block, deg, n);
    rows.push_back(measured_row(variant, vf, true));
    rows.back().notes = mean_steps(vf, steps_col);
  };
  for (const auto& b : blocks_) {
    if (b == "pom_layers") {
      fixed("pom_layers", "adaptive_4_32");
    } else if (b == "pom_march") {
      for (int n : {8, 16, 32}) scene("pom_march", "60deg_N" + std::to_string(n), 60, n, 2);
    } else if (b == "iter_parallax") {
      scene("iter_parallax", "60deg_seed", 60, 0, 2);
      scene("iter_parallax", "60deg_norm", 60, 1, 2);
    } else if (b == "pom_unit") {
      fixed("pom_setup", "P_dT");
      fixed("pom_refine", "w_T");
      for (double deg : {45.0, 80.0})
        for (int n : {4, 8, 16, 24, 32, 0})
          scene("pom_unit", std::to_string(int(deg)) + "deg_" + (n ? "N" + std::to_string(n) : "adaptive"), deg, n, 2);
    } else if (b == "afvis") {
      for (auto& r : afvis_rows(root)) rows.push_back(r);
    } else if (b == "distance_map") {
      rows.push_back(dm_row(false));
      rows.push_back(dm_row(true));
    } else {
      throw std::invalid_argument("report: '" + b + "' is not a relief block");
    }
  }
  return rows;
}

bool relief_plot(const std::string& dir, out::Outputs& outs) {
  out::Outputs own;  // a failed relief plot is skipped alone: its files are removed, the others kept
  own.make_dir(dir);
  pom::QualityParams p;
  p.angles = {45, 60, 80, 85};  // 0 degrees: every method is exact (PSNR inf)
  const auto q = pom::quality(p);
  const std::string dat = dir + "/relief_quality.dat", gp = dir + "/relief_quality.gp";
  {
    // One block per (map, angle), rows in method order N=4..32, adaptive, iter-seed, iter-norm.
    std::ostringstream d;
    d << "# texunit relief-quality --size 128 --scale 0.05 (azimuth 30): method steps/px cycles/px PSNR\n"
         "# cycles/px: POM k + 1 (tu_pom_unit stream), iterative k + 3 (tu_iter_parallax)\n";
    std::string key;
    for (const auto& r : q) {
      char k[64];
      std::snprintf(k, sizeof k, "%s %g", r.map.c_str(), r.angle);
      if (key != k) d << (key.empty() ? "" : "\n\n") << "# " << k << "\n";
      key = k;
      const double overhead = r.method.rfind("iter", 0) == 0 ? 3 : 1;  // tu_iter_parallax / tu_pom_unit
      d << r.method << " " << r.steps << " " << r.steps + overhead << " " << (std::isinf(r.psnr) ? 99.0 : r.psnr) << "\n";
    }
    own.write(dat, d.str());
  }
  {
    std::ostringstream g;
    g << "set terminal pngcairo size 1500,480 noenhanced\nset grid\nset key top left font ',8'\n"
         "set ylabel 'PSNR dB (vs 256-layer exact march)'\nangles = '45 60 80 85'\n"
         "maps = 'smooth bricks noisy'\n";
    for (const char* x : {"steps", "cycles"}) {
      const int col = std::string(x) == "steps" ? 2 : 3;
      g << "set output '" << dir << "/relief_psnr_vs_" << x << ".png'\n"
        << "set xlabel '" << (col == 2 ? "march steps (iterations) per pixel" : "cycles per pixel (POM k + 1, iterative k + 3)")
        << "'\nset multiplot layout 1,3\n"
        << "do for [m=1:3] {\n  set title word(maps, m)\n"
        << "  plot for [a=1:4] '" << dat << "' index ((m-1)*4+a-1) every ::0::4 using " << col
        << ":4 with linespoints lc a pt 7 title 'N=4..32 '.word(angles, a).' deg', \\\n"
        << "       for [a=1:4] '' index ((m-1)*4+a-1) every ::5::5 using " << col
        << ":4 with points lc a pt 9 ps 2 title (a == 1 ? 'adaptive' : ''), \\\n"
        << "       for [a=1:4] '' index ((m-1)*4+a-1) every ::6::6 using " << col
        << ":4 with points lc a pt 4 ps 1.5 title (a == 1 ? 'iter-seed' : ''), \\\n"
        << "       for [a=1:4] '' index ((m-1)*4+a-1) every ::7::7 using " << col
        << ":4 with points lc a pt 12 ps 1.5 title (a == 1 ? 'iter-norm' : '')\n}\nunset multiplot\n";
    }
    own.write(gp, g.str());
  }
  if (!out::gnuplot(own, gp, {dir + "/relief_psnr_vs_steps.png", dir + "/relief_psnr_vs_cycles.png"}).empty()) return false;
  outs.absorb(own);
  return true;
}

}  // namespace tu::report
