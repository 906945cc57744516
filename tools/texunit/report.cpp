// `texunit report`: one row per block variant with error, cycles, area and C-model speed; the
// first piece of the project-wide "error against run time" report. Generic rows: a block adds a
// row producer to `producers()`.
#include "report.hpp"
#include "report_relief.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <sstream>

#include "block.hpp"
#include "cosim.hpp"
#include "gauss/clip.hpp"
#include "gauss/schemes.hpp"
#include "gauss/weight.hpp"

namespace fs = std::filesystem;

namespace tu::report {

namespace {
template <class F>
double ns_per_item(F&& f, uint64_t items) {
  const auto t0 = std::chrono::steady_clock::now();
  uint64_t sink = 0;
  int reps = 0;
  do {
    sink += f();
    ++reps;
  } while (std::chrono::steady_clock::now() - t0 < std::chrono::milliseconds(50));
  const double ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count();
  if (sink == 0xdeadbeefcafe) std::fputs("", stderr);  // keep the work
  return ns / static_cast<double>(items * static_cast<uint64_t>(reps));
}

// Verilator timing (measured) or the scheduler's estimate.
void cycles(Row& r, const std::string& graph) {
  const auto pred = sched::schedule(gauss::scheme(graph));
  r.latency_cycles = pred.latency;
  r.ii_cycles = pred.ii;
  r.cycles_source = "estimated (" + graph + ")";
  r.multipliers = pred.units_used.count("mul") ? pred.units_used.at("mul") : 0;
  const auto& lim = gauss::scheme(graph).limits;
  if (lim.count("mul")) r.multipliers = std::min<int64_t>(r.multipliers, lim.at("mul"));
  try {
    const auto& b = blocks::find(graph);
    std::vector<cosim::Row> in = b.inputs("random", 64, 3);
    const auto [lat, ii] = cosim::find_rtl(graph).timing(in);
    r.latency_cycles = static_cast<int>(lat);
    r.ii_cycles = ii;
    r.cycles_source = "measured (Verilator " + graph + ")";
    r.rtl_top = "tu_" + graph;
  } catch (const std::invalid_argument&) {
  }
}

void area(Row& r, const std::string& root) {
  if (r.rtl_top.empty()) return;
  const std::string rtl = root + "/rtl/";
  std::string files = rtl + "0_pkg/tu_formats_pkg.sv " + rtl + "common/tu_pipe_valid.sv ";
  for (const char* f : {"generated/tu_clip_coef_mm3.sv", "generated/tu_clip_seg_mm1.sv", "generated/tu_wtab1d_rom.sv",
                        "generated/tu_wtab2d_rom.sv",
                        "gauss/tu_clip_abs.sv", "gauss/tu_clip_fold.sv", "gauss/tu_clip_mulfloor.sv"})
    files += rtl + f + " ";
  files += rtl + "gauss/" + r.rtl_top + ".sv";
  const std::string cmd = root + "/scripts/yosys_area.sh " + r.rtl_top + " " + files + " 2>/dev/null";
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return;
  char buf[512];
  std::string out;
  while (fgets(buf, sizeof buf, p)) out += buf;
  if (pclose(p) != 0) return;
  auto num = [&](const std::string& key) {
    const auto k = out.find("\"" + key + "\": ");
    return k == std::string::npos ? -1 : std::atoi(out.c_str() + k + key.size() + 4);
  };
  r.cells = num("cells");
  r.flip_flops = num("flip_flops");
  r.multipliers = num("multipliers");
  r.area_source = "yosys synth";
}

std::vector<Row> clip_rows(const std::string& root, bool yosys) {
  // variant -> schemes (graph names); RTL exists for the graphs that are block names.
  const std::map<std::string, std::vector<std::string>> schemes = {
      {"seed_p1", {"clip_p1"}},        {"seed_p2", {"est_clip_horner_deg2", "est_clip_seq_deg2"}},
      {"seed_p3", {"clip_horner"}},    {"mm_p1", {"clip_p1"}},
      {"mm_p2", {"est_clip_horner_deg2", "est_clip_seq_deg2"}},
      {"mm_p3", {"clip_horner", "clip_seq"}}, {"mm_p3_estrin", {"clip_estrin"}},
      {"mm_p4", {"est_clip_horner_deg4"}},    {"tab16", {"est_clip_tab16"}}};
  std::vector<Row> rows;
  for (const auto& v : clip::variants()) {
    const auto st = clip::exhaustive(v);
    const double ns = ns_per_item([&] {
      uint64_t s = 0;
      for (int32_t d = -(1 << 12); d < (1 << 12); ++d) s += clip::eval(v, d);
      return s;
    }, 1 << 13);
    for (const auto& g : schemes.at(v.name)) {
      Row r;
      r.block = "clip_volume";
      r.variant = v.name;
      r.scheme = g;
      r.max_abs_err = st.max_abs;
      r.rms_err = st.rms;
      r.max_ulp_err = st.max_ulp;
      r.cmodel_ns_per_item = ns;
      cycles(r, g);
      // The RTL implements the minimax coefficients; seed coefficients on the same structure are
      // estimates (same operators, different constants).
      if ((v.name == "seed_p1" || v.name == "seed_p3") && !r.rtl_top.empty()) {
        r.rtl_top.clear();
        r.cycles_source = "estimated (" + g + "; RTL has the mm coefficients)";
      }
      if (yosys) area(r, root);
      std::ostringstream n;
      n << "approx " << st.max_approx << " + round " << st.max_round
        << (st.monotonic_half ? ", monotonic on [0,0.5]" : ", NOT monotonic on [0,0.5]")
        << (st.symmetric ? ", symmetric" : "");
      r.notes = n.str();
      rows.push_back(r);
    }
  }
  return rows;
}

std::vector<Row> weight_rows(const std::string& root, bool yosys) {
  const auto st = gauss::weight_exhaustive();
  Row r;
  r.block = "gauss_weight";
  r.variant = "three_squarings";
  r.scheme = "gauss_weight";
  r.max_abs_err = st.max_abs;
  r.rms_err = st.rms;
  r.max_ulp_err = st.max_ulp;
  r.cmodel_ns_per_item = ns_per_item([] {
    uint64_t s = 0;
    for (uint32_t q = 0; q < (1u << 16); ++q) s += gauss::weight(q);
    return s;
  }, 1 << 16);
  cycles(r, "gauss_weight");
  if (yosys) area(r, root);
  r.notes = st.monotonic ? "exhaustive over 2^16 Q codes, monotonic" : "NOT monotonic";
  return {r};
}

std::vector<Row> table_rows(const std::string& root, bool yosys) {
  std::vector<Row> rows;
  const auto comp = gauss::table_stats(2, 0);
  for (int kind = 0; kind < 2; ++kind)
    for (int l = 4; l <= 10; ++l) {
      const auto st = gauss::table_stats(kind, l);
      Row r;
      r.block = "weight_table";
      r.variant = std::string(kind ? "2d_" : "1d_") + std::to_string(1 << l);
      r.scheme = kind ? "weight_table_2d" : "weight_table_1d";
      r.max_abs_err = st.max_abs;
      r.rms_err = st.rms;
      r.max_ulp_err = st.max_abs / std::ldexp(1.0, -fmt::kWtabEntryW);
      cycles(r, r.scheme);
      // The RTL (tu_weight_table_1d / _2d) is built at N = 2^kWtabRtlLog2N / 2^kWtab2dRtlLog2N
      // only; other sizes have the same structure (estimate; the ROM depth differs).
      const int rtl_l = kind ? gauss::kWtab2dRtlLog2N : gauss::kWtabRtlLog2N;
      if (!r.rtl_top.empty() && l != rtl_l) {
        r.rtl_top.clear();
        r.cycles_source = "estimated (" + r.scheme + "; RTL has N = " + std::to_string(1 << rtl_l) + ")";
      }
      if (yosys) area(r, root);
      const gauss::Table1D t1(kind ? 4 : l);
      const gauss::Table2D t2(kind ? l : 4);
      r.cmodel_ns_per_item = ns_per_item([&] {
        uint64_t s = 0;
        for (int32_t i = 0; i < 4096; ++i)
          s += kind ? t2.lookup(i * 5 - 10000, 7000 - i * 3) : t1.lookup(static_cast<uint32_t>(i * 4));
        return s;
      }, 4096);
      r.memory_bits = static_cast<int64_t>(st.memory_bits);
      std::ostringstream n;
      n << "nmse " << st.nmse << " (seed 0.000708; computed weight " << comp.nmse << "), max |err| at Q<=0.9 "
        << st.max_abs_inner << ", " << st.samples << " samples";
      r.notes = n.str();
      rows.push_back(r);
    }
  return rows;
}

std::string jnum(double x) {
  if (!std::isfinite(x)) return "null";
  std::ostringstream os;
  os.precision(6);
  os << x;
  return os.str();
}
std::string jint(int64_t x) { return x < 0 ? "\"n/a\"" : std::to_string(x); }
std::string jstr(const std::string& s) {
  std::string o = "\"";
  for (char c : s) o += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
  return o + "\"";
}
}  // namespace

std::string Row::json() const {
  return "{\"block\": " + jstr(block) + ", \"variant\": " + jstr(variant) + ", \"scheme\": " +
         jstr(scheme) + ", \"max_abs_err\": " + jnum(max_abs_err) + ", \"rms_err\": " +
         jnum(rms_err) + ", \"max_ulp_err\": " + jnum(max_ulp_err) + ", \"latency_cycles\": " +
         jint(latency_cycles) + ", \"ii_cycles\": " + jnum(ii_cycles) + ", \"cycles_source\": " +
         jstr(cycles_source) + ", \"cells\": " + jint(cells) + ", \"flip_flops\": " +
         jint(flip_flops) + ", \"multipliers\": " + jint(multipliers) + ", \"area_source\": " +
         jstr(area_source) + ", \"memory_bits\": " + jint(memory_bits) +
         ", \"cmodel_ns_per_item\": " + jnum(cmodel_ns_per_item) + ", \"rtl_sim_items_per_s\": " +
         jnum(rtl_sim_items_per_s) + ", \"err_unit\": " + jstr(err_unit) + ", \"notes\": " + jstr(notes) + "}";
}

std::vector<Row> rows(const std::vector<std::string>& blocks, const std::string& root, bool yosys) {
  std::vector<Row> out;
  for (const auto& b : blocks) {
    std::vector<Row> r;
    if (b == "clip_volume") r = clip_rows(root, yosys);
    else if (b == "gauss_weight") r = weight_rows(root, yosys);
    else if (b == "weight_table") r = table_rows(root, yosys);
    else if (is_relief_block(b)) r = relief_rows({b}, root, yosys);  // report_relief.cpp
    else throw std::invalid_argument("report: unknown block '" + b + "' (known: clip_volume, gauss_weight, weight_table, pom_layers, pom_march, iter_parallax, pom_unit)");
    out.insert(out.end(), r.begin(), r.end());
  }
  return out;
}

int run(const std::vector<std::string>& blocks, const std::string& json, const std::string& plots,
        const std::string& root) {
  const bool yosys = std::system("command -v yosys >/dev/null 2>&1") == 0;
  const auto rs = rows(blocks, root, yosys);
  std::printf("%-12s %-16s %-22s %10s %10s %9s %4s %5s %6s %4s %9s %8s\n", "block", "variant", "scheme",
              "max_abs", "rms", "max_ulp", "lat", "II", "cells", "mul", "mem_bits", "ns/item");
  auto na = [](int64_t x) { return x < 0 ? std::string("n/a") : std::to_string(x); };
  for (const auto& r : rs)
    std::printf("%-12s %-16s %-22s %10.4g %10.4g %9.2f %4s %5.2f %6s %4s %9s %8.2f\n", r.block.c_str(),
                r.variant.c_str(), r.scheme.c_str(), r.max_abs_err, r.rms_err, r.max_ulp_err,
                na(r.latency_cycles).c_str(), r.ii_cycles, na(r.cells).c_str(),
                na(r.multipliers).c_str(), na(r.memory_bits).c_str(), r.cmodel_ns_per_item);
  if (!yosys) std::printf("(yosys not installed: cells n/a)\n");
  if (!json.empty()) {
    std::ofstream o(json);
    o << "[\n";
    for (size_t i = 0; i < rs.size(); ++i) o << "  " << rs[i].json() << (i + 1 < rs.size() ? ",\n" : "\n");
    o << "]\n";
    std::cerr << "wrote " << json << "\n";
  }
  if (!plots.empty()) {
    fs::create_directories(plots);
    const std::string dat = plots + "/report.dat";
    {
      std::ofstream d(dat);
      d << "# block variant scheme max_abs_err latency ii cells\n";
      for (const auto& r : rs)
        if (r.latency_cycles >= 0)
          d << r.block << "/" << r.variant << "/" << r.scheme << " " << r.max_abs_err << " "
            << r.latency_cycles << " " << r.ii_cycles << " " << r.cells << "\n";
    }
    const std::string gp = plots + "/report.gp";
    {
      std::ofstream g(gp);
      g << "set terminal pngcairo size 1200,800 noenhanced\nset logscale y\nset grid\nset key off\n"
        << "set ylabel 'max abs error'\n"
        << "set output '" << plots << "/error_vs_cycles.png'\n"
        << "set xlabel 'cycles per item (latency + II; estimated where no RTL)'\n"
        << "plot '" << dat << "' using ($3+$4):2 with points pt 7, '' using ($3+$4):2:1 with labels font ',7' offset 0,0.7\n"
        << "set output '" << plots << "/error_vs_cells.png'\n"
        << "set xlabel 'Yosys cells (synth, generic)'\n"
        << "plot '" << dat << "' using ($5 > 0 ? $5 : 1/0):2 with points pt 7, '' using ($5 > 0 ? $5 : 1/0):2:1 with labels font ',7' offset 0,0.7\n";
    }
    for (const auto& b : blocks)
      if (is_relief_block(b)) {
        std::cerr << (relief_plot(plots) ? "wrote " + plots + "/relief_psnr_vs_steps.png, relief_psnr_vs_cycles.png\n"
                                         : std::string("gnuplot failed (relief plots skipped)\n"));
        break;
      }
    if (std::system(("gnuplot " + gp).c_str()) != 0) std::cerr << "gnuplot failed (plots skipped)\n";
    else std::cerr << "wrote " << plots << "/error_vs_cycles.png, error_vs_cells.png\n";
  }
  return 0;
}

}  // namespace tu::report
