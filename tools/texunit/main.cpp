// texunit: command-line front end (one binary, subcommands).
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <iterator>
#include <sstream>

#include <unistd.h>

#include "block.hpp"
#include "cli_checks.hpp"
#include "output.hpp"
#include "complexity/complexity.hpp"
#include "distmap/distance_map.hpp"
#include "pom/relief_quality.hpp"
#include "afvis/afvis_quality.hpp"
#include "cosim.hpp"
#include "demo_jobs.hpp"
#include "merge.hpp"
#include "plan.hpp"
#include "render_cmd.hpp"
#include "sysmodel_cmd.hpp"
#include "filter_cmd.hpp"
#include "objspace_cmd.hpp"
#include "report.hpp"
#include "texunit/parallel.hpp"
#include "texunit/rtl_gen.hpp"
#include "texunit/rtl_manifest.hpp"
#include "vector_file.hpp"

namespace fs = std::filesystem;

namespace {

// Vectors per generated set (`vectors --count`, `demo --count`): a set is held in memory
// (about 200 bytes per vector for the widest block, ewa), so 2^22 vectors stay under 1 GB.
constexpr uint64_t kMaxCount = 1ull << 22;

int cmd_vectors(const std::string& block, const std::string& set, uint64_t count, uint64_t seed,
                const std::string& out, int threads, const tu::Shard& shard) {
  const auto& b = tu::blocks::find(block);
  tu::cli::Outputs outs;
  if (set == "random" && !shard.whole() && shard.range(count).first == shard.range(count).second)
    throw std::invalid_argument("vectors: --shard " + shard.str() + " of " + std::to_string(count) +
                                " vectors is empty (give at most --count shards)");
  const std::string tmp = outs.stage(out);  // the target checked before the work
  const auto vf = tu::blocks::generate(b, set, count, seed, threads, shard);
  if (vf.rows.empty())  // a golden or stiff set smaller than the shard count: cosim would refuse the file
    throw std::invalid_argument("vectors: --shard " + shard.str() + " of the " + set + " set of " + block +
                                " is empty (give fewer shards)");
  tu::out::write_stream(tmp, [&](std::ostream& os) { tu::vec::serialise(vf, os); }, out);
  outs.commit();
  std::cerr << "wrote " << vf.rows.size() << " vectors (" << block << ", " << set
            << (vf.shard.empty() ? "" : ", shard " + vf.shard + " from vector " + std::to_string(vf.first_vector))
            << ") to " << out << "\n";
  return 0;
}

// What the vector format cannot check without the block: the set is one of the block's (the
// identity a shard's result carries; cosim::run checks the fields and the reference values).
void check_set(const tu::vec::VectorFile& vf, const std::string& file) {
  const auto& b = tu::blocks::find(vf.block);
  if (std::find(b.sets.begin(), b.sets.end(), vf.set) != b.sets.end()) return;
  std::string known;
  for (const auto& s : b.sets) known += (known.empty() ? "" : ", ") + s;
  throw std::invalid_argument(file + ": set '" + vf.set + "' is not a set of block '" + b.name + "' (" + known + ")");
}

// Verilator writes the FST itself (stdio, errors not reported), so the file is checked after the
// run: a sequence of blocks (type byte, 8-byte big-endian length counting itself), ending exactly
// at the end of the file, none left unfinished (type 255 or length 0), the header first and the
// geometry and hierarchy blocks written at close present. A full disk cuts it short and fails this.
bool fst_complete(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string s((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  bool geom = false, hier = false;
  size_t pos = 0;
  for (int n = 0; pos < s.size(); ++n) {
    if (s.size() - pos < 9) return false;
    const auto type = static_cast<unsigned char>(s[pos]);
    uint64_t len = 0;
    for (int i = 1; i <= 8; ++i) len = len << 8 | static_cast<unsigned char>(s[pos + static_cast<size_t>(i)]);
    if ((n == 0 && type != 0) || type == 255 || len < 8 || len > s.size() - pos - 1) return false;
    geom |= type == 3;
    hier |= type == 4 || type == 6 || type == 7;
    pos += 1 + len;
  }
  return pos == s.size() && geom && hier;
}

int cmd_cosim(const std::string& block, const std::string& file, double stall, uint64_t seed,
              const std::string& fst, bool json, const std::string& rtl, const tu::Shard& shard) {
  auto vf = tu::vec::read(file);
  if (vf.block != block)
    throw std::invalid_argument(file + ": vectors are for block '" + vf.block + "', not '" +
                                block + "'");
  if (vf.rows.empty())
    throw std::invalid_argument(file + ": no vectors (the file has a header and no data line)");
  check_set(vf, file);
  // A shard's identity (cosim::Report): when this run cuts the file, the whole file's rows and hash.
  const uint64_t file_vectors = vf.rows.size();
  const std::string file_hash = shard.whole() ? "" : [&] {
    char h[17];
    std::snprintf(h, sizeof h, "%016llx", static_cast<unsigned long long>(tu::report::fnv1a(tu::vec::serialise(vf))));
    return std::string(h);
  }();
  if (!shard.whole()) {  // rows [first, last) of the file (a vectors shard file: split it no further)
    if (!vf.shard.empty())
      throw std::invalid_argument(file + ": already shard " + vf.shard + " of a set (run it without --shard)");
    const auto [first, last] = tu::blocks::shard_rows(tu::blocks::find(vf.block), vf.rows, vf.indices(tu::vec::Role::In), shard);
    vf.rows = std::vector<std::vector<uint64_t>>(vf.rows.begin() + static_cast<std::ptrdiff_t>(first),
                                                 vf.rows.begin() + static_cast<std::ptrdiff_t>(last));
    vf.shard = shard.str();
    vf.first_vector = first;
  }
  // The waveform is written by Verilator, which fails silently: check its directory first.
  tu::cli::Outputs outs;
  const std::string fst_tmp = fst.empty() ? "" : outs.stage(fst);
  if (!fst.empty()) outs.adopt(fst_tmp + ".hier");  // the FST writer's own temporary (removed at its close)
  tu::cosim::Options opt;
  opt.run.stall_prob = stall;
  opt.run.seed = seed;
  opt.run.fst_path = fst_tmp;
  opt.rtl = rtl;
  opt.first_vector = vf.first_vector;
  tu::cosim::Report rep;
  try {
    rep = tu::cosim::run(vf, opt);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(file + ": " + e.what());
  }
  rep.shard = vf.shard;
  rep.set = vf.set, rep.seed = vf.seed, rep.first_vector = vf.first_vector, rep.rtl = rtl;
  rep.file_vectors = file_hash.empty() ? 0 : file_vectors, rep.file_hash = file_hash;
  if (json) {
    std::cout << rep.json() << "\n";
  } else {
    std::cout << "block " << rep.block << ": " << rep.vectors << " vectors, " << rep.outputs
              << " outputs, " << rep.mismatches << " mismatches (RTL vs C model), "
              << rep.model_mismatches << " stale expected values, " << rep.extra_outputs
              << " extra outputs\n"
              << "  error vs float reference: max " << rep.max_abs_err << " (" << rep.max_ulp_err
              << " ULP), rms " << rep.rms_err << ", " << rep.flagged << " flagged\n"
              << "  latency " << rep.latency_cycles << " cycles, II " << rep.ii_cycles << ", "
              << rep.sim_cycles << " cycles with " << rep.stall_prob * 100 << "% stalls, "
              << rep.wall_s << " s\n";
  }
  if (!rep.first_mismatch.empty()) std::cerr << "first mismatch: " << rep.first_mismatch << "\n";
  if (!fst.empty() && !fst_complete(fst_tmp))
    throw std::runtime_error(fst + ": cannot write the file (the waveform writer left it incomplete: a full disk?)");
  outs.commit();  // the waveform, also of a run with mismatches (it is how they are debugged)
  return rep.ok() ? 0 : 1;
}

int cmd_gen_rtl(const std::string& root, bool check) {
  int stale = 0;
  // Every out-of-date file is staged and written first, then all are renamed: a failure (a full
  // disk) leaves the tree as it was.
  tu::cli::Outputs outs;
  std::vector<std::string> written;
  for (const auto& [rel, content] : tu::generated_rtl()) {
    const fs::path p = fs::path(root) / rel;
    std::string old;
    if (std::ifstream in(p, std::ios::binary); in) {
      std::ostringstream ss;
      ss << in.rdbuf();
      old = ss.str();
    }
    if (old == content) continue;
    if (check) {
      std::cerr << p.string() << ": out of date (run `texunit gen-rtl`)\n";
      ++stale;
      continue;
    }
    outs.make_dir(p.parent_path().string());
    outs.write(p.string(), content);
    written.push_back(p.string());
  }
  outs.commit();
  for (const auto& p : written) std::cerr << "wrote " << p << "\n";
  return stale ? 1 : 0;
}

// Complexity map (docs/blocks/relief.md): HEIGHT.png (first channel) -> 8-bit level codes.
int cmd_complexity(const std::string& in, const std::string& out, const tu::complexity::Params& p) {
  tu::complexity::validate(p);
  tu::cli::Outputs outs;
  const std::string tmp = outs.stage(out);
  const auto h = tu::img::read_png_channel0(in);
  const auto c = tu::complexity::complexity_map(h, p);
  tu::out::write_file(tmp, tu::img::png_gray(c, out), out);
  outs.commit();
  std::cerr << "wrote " << c.width << "x" << c.height << " complexity map (" << p.levels
            << " levels, gamma " << p.gamma << ", dilate " << p.dilate << ") to " << out << "\n";
  return 0;
}

// Distance map (docs/blocks/relief.md §13): HEIGHT.png -> OUT.raw + OUT.json (+ PNG slices).
int cmd_distance_map(const std::string& in, const std::string& out, const std::string& slices,
                     const tu::dm::Params& p) {
  // OUT names files beside it: "DIR/" or "DIR/." would write the hidden DIR/.raw.
  if (const auto name = fs::path(out).filename(); name.empty() || name == "." || name == "..")
    throw std::invalid_argument("OUT " + out + ": a base name (writes OUT.raw and OUT.json), not a directory");
  tu::cli::Outputs outs;
  const std::string raw = out + ".raw", hdr = out + ".json";
  const std::string raw_tmp = outs.stage(raw), hdr_tmp = outs.stage(hdr);
  std::vector<std::string> slice_tmp, slice_names;
  if (!slices.empty()) {
    outs.make_dir(slices);
    for (int k = 0; k < p.layers; ++k) {
      char name[32];
      std::snprintf(name, sizeof name, "/layer_%03d.png", k);
      slice_names.push_back(slices + name);
      slice_tmp.push_back(outs.stage(slice_names.back()));
    }
  }
  tu::img::Gray8 h = tu::img::read_png_channel0(in);
  for (auto& x : h.px) x = static_cast<uint8_t>(255 - x);  // height 255 = top -> depth 0
  tu::dm::Map m;
  try {
    m = tu::dm::build(h, p);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(in + ": " + e.what());
  }
  tu::out::write_file(raw_tmp, std::string_view(reinterpret_cast<const char*>(m.code.data()), m.code.size()), raw);
  tu::out::write_file(hdr_tmp, tu::dm::header_json(m, fs::path(raw).filename().string()), hdr);
  for (size_t k = 0; k < slice_tmp.size(); ++k)
    tu::out::write_file(slice_tmp[k], tu::img::png_gray(tu::dm::slice(m, static_cast<int>(k)), slice_names[k]), slice_names[k]);
  outs.commit();
  size_t nonzero = 0;
  for (auto c : m.code) nonzero += c != 0;
  std::cout << "distance map " << m.w << "x" << m.h << "x" << m.layers << (m.refined ? " (refined, " : " (classic, ")
            << "depth " << m.depth_texels << " texels, margin " << m.margin << " texel";
  if (m.refined) std::cout << ", " << m.directions << " directions";
  std::cout << "): memory " << m.bytes() << " bytes; " << nonzero << " voxels with a step > 0\n";
  std::cerr << "wrote " << raw << ", " << hdr << (slices.empty() ? "" : " and " + std::to_string(p.layers) + " slices in " + slices)
            << "\n";
  return 0;
}

int cmd_relief_quality(const tu::pom::QualityParams& p) {
  std::cout << tu::pom::quality_markdown(tu::pom::quality(p));
  return 0;
}

// relief-quality --afvis SCENE (docs/blocks/afvis-appendix.md §4): plain EWA and each visibility rule against
// the truth on the scene's relief pixels, per height map and camera height. The height PNGs go to a
// private temporary directory, removed afterwards.
int cmd_afvis_quality(const std::string& scene_arg, tu::afvis::QualityParams p, const std::string& plot_dir) {
  const tu::scene::Scene s = scene_arg == "default" ? tu::scene::default_scene() : tu::scene::load(scene_arg);
  bool relief = false;
  for (const auto& [name, m] : s.materials) relief |= m.relief.has_value();
  if (!relief) throw std::invalid_argument(scene_arg + ": no material has relief (relief-quality --afvis needs one)");
  // The private directory and its height PNGs belong to an Outputs that is never committed: they
  // are removed on every way out, a signal included.
  const fs::path dir = fs::temp_directory_path() / ("texunit_afvis_" + std::to_string(::getpid()));
  tu::cli::Outputs scratch;
  scratch.make_dir(dir.string());
  for (const auto& m : p.maps) scratch.adopt((dir / ("afvis_height_" + m + ".png")).string());
  p.tmp_dir = dir.string();
  const std::vector<tu::afvis::QualityRow> rows = tu::afvis::quality(s, p);
  if (!plot_dir.empty()) tu::afvis::write_quality_plot(rows, plot_dir);
  std::cout << tu::afvis::quality_markdown(rows);
  return 0;
}

// Estimated CPU seconds of a demo co-simulation job (100,000 random vectors; measured once,
// docs/performance.md §6): only the job order depends on it.
double demo_cosim_cost(const std::string& block, const std::string& set) {
  if (set != "random") return 0.1;
  static const std::map<std::string, double> kCost = {{"ewa", 5}};
  const auto it = kCost.find(block);
  return it == kCost.end() ? 1 : it->second;
}

// Main job: every block with RTL co-simulated on its golden, stiff and random sets with 30% stalls
// (one table), then the default scene rendered through the float reference with every filter.
// Then the C-model and the RTL render engines (texture-unit top == C model on every pixel).
// Every co-simulation and render is a job of one pool (tools/texunit/demo_jobs.hpp), the longest
// first, on every thread; the tables are printed afterwards, then the time each section took.
int cmd_demo(uint64_t count, const std::string& out_dir, int threads) {
  const std::string load_before = tu::cli::load_average();
  const auto t0 = std::chrono::steady_clock::now();
  const double cpu0 = tu::cli::process_cpu_s();
  // One job per (block, set) (each run has its own Verilator context), printed in the registry's order.
  struct Job {
    const tu::blocks::Block* block;
    std::string set;  // empty: no RTL co-simulation model
    tu::cosim::Report report;
  };
  std::vector<Job> cs;
  for (const auto& b : tu::blocks::all()) {
    try {
      tu::cosim::find_rtl(b.name);
    } catch (const std::invalid_argument&) {  // C model and vectors ahead of the block's RTL
      cs.push_back({&b, "", {}});
      continue;
    }
    for (const auto& set : b.sets) cs.push_back({&b, set, {}});
  }
  std::vector<tu::cli::DemoJob> jobs;
  for (auto& j : cs) {
    if (j.set.empty()) continue;
    jobs.push_back({"co-simulation", j.block->name + " " + j.set, demo_cosim_cost(j.block->name, j.set), [&j, count] {
                      const auto vf = tu::blocks::generate(*j.block, j.set, count, 2026, 1);
                      tu::cosim::Options opt;
                      opt.run.stall_prob = 0.3;
                      j.report = tu::cosim::run(vf, opt);
                    }});
  }
  const auto print_renders = tu::cli::demo_render_jobs(out_dir, jobs);
  tu::cli::run_demo_jobs(jobs, threads);
  const double jobs_wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const auto t1 = std::chrono::steady_clock::now();
  std::printf("%-12s %-7s %9s %9s %10s %11s %10s %8s %4s %10s\n", "block", "set", "vectors",
              "outputs", "mismatch", "max_ulp", "rms_err", "latency", "II", "cycles");
  bool ok = true;
  for (const auto& j : cs) {
    const auto& r = j.report;
    if (j.set.empty()) {
      std::printf("%-12s (C model only: no RTL co-simulation model yet)\n", j.block->name.c_str());
      continue;
    }
    ok = ok && r.ok();
    std::printf("%-12s %-7s %9llu %9llu %10llu %11.4f %10.3g %8llu %4.0f %10llu\n",
                j.block->name.c_str(), j.set.c_str(), (unsigned long long)r.vectors,
                (unsigned long long)r.outputs, (unsigned long long)r.mismatches, r.max_ulp_err,
                r.rms_err, (unsigned long long)r.latency_cycles, r.ii_cycles,
                (unsigned long long)r.sim_cycles);
  }
  std::printf("%s\n", ok ? "RTL == C model on every vector (30% random stalls, in order, none lost)"
                          : "MISMATCH: RTL and C model disagree (see above)");
  ok = print_renders() && ok;
  const double print_wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
  tu::cli::print_demo_times(jobs, threads, jobs_wall, tu::cli::process_cpu_s() - cpu0, print_wall, load_before);
  return ok ? 0 : 1;
}

// `texunit rtl-files`: the manifest's lists, one path a line.
int cmd_rtl_files(const std::string& root, const std::string& top, const std::string& list, const std::string& key) {
  if (top.empty() == list.empty()) {
    std::cerr << "texunit rtl-files: give a TOP or --list (not both)\n";
    return 2;
  }
  if (!key.empty()) {
    if (top.empty()) {
      std::cerr << "texunit rtl-files: --key needs a TOP\n";
      return 2;
    }
    std::cout << tu::report::rtl_hash(root, top, key == "yosys" ? "scripts/yosys_area.sh" : "scripts/stdcell_flow.sh") << "\n";
    return 0;
  }
  const auto m = tu::rtl::Manifest::load(root);
  std::vector<std::string> out;
  if (!top.empty()) out = m.top_sources(top);
  else if (list == "tops") out = m.tops();
  else if (list == "all") out = m.all_sources();
  else
    for (const auto& f : list == "include-dirs" ? m.include_dirs : m.lint_only) out.push_back(m.rtl_dir + "/" + f);
  for (const auto& f : out) std::cout << f << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  tu::out::install_signal_cleanup();  // SIGINT / SIGTERM: no temporary, created directory or child left
  tu::out::check_stdout_at_exit();     // a failed write to standard output is an error too
  CLI::App app{"texunit: bit-accurate texture-unit models, RTL co-simulation and reports"};
  app.require_subcommand(1);

  std::string block, set = "random", out, file, fst, root = ".";
  uint64_t count = 1000, seed = 1;
  double stall = 0.3;
  bool json = false, check = false;
  int threads = 0;  // <= 0: every core
  const char* threads_help = "threads (default 0: every core); the output is the same for any count";

  auto* vec = app.add_subcommand("vectors", "generate a vector file (inputs, C-model outputs, reference)");
  vec->add_option("--block", block, "block name")->required();
  vec->add_option("--set", set, "golden | stiff | random")
      ->check(CLI::IsMember({"golden", "stiff", "random"}));
  vec->add_option("--count", count, "vectors in a random set")
      ->check(tu::cli::non_negative_integer() & CLI::Range(uint64_t{1}, kMaxCount));
  vec->add_option("--seed", seed, "generator seed")->check(tu::cli::non_negative_integer());
  vec->add_option("--out", out, "output file")->required();
  vec->add_option("--threads", threads, threads_help)->check(CLI::Range(0, 4096));
  std::string shard_text = "0/1";
  const char* shard_help = "run part K of N (0 <= K < N; `texunit merge` combines the parts' JSON)";
  vec->add_option("--shard", shard_text, "write rows [floor(K*T/N), floor((K+1)*T/N)) of the T-row set")
      ->check(tu::cli::shard_spec());

  auto* cos = app.add_subcommand("cosim", "run the RTL against the C model on a vector file");
  cos->add_option("--block", block, "block name")->required();
  cos->add_option("--vectors", file, "vector file")->required()->check(CLI::ExistingFile);
  cos->add_option("--stall-prob", stall, "probability of an input bubble / output stall")
      ->check(tu::cli::finite_in(0.0, 0.95));
  cos->add_option("--seed", seed, "stall pattern seed")->check(tu::cli::non_negative_integer());
  cos->add_option("--fst", fst, "write an FST waveform");
  cos->add_flag("--json", json, "print one JSON object");
  std::string rtl_variant;
  cos->add_option("--rtl", rtl_variant, "RTL variant to run on the block's vectors (e.g. perlin3d_serial)");
  cos->add_option("--shard", shard_text, shard_help)->check(tu::cli::shard_spec());

  auto* gen = app.add_subcommand("gen-rtl", "write rtl/generated/ from the C model's formats and tables");
  gen->add_option("--root", root, "repository root")->check(CLI::ExistingDirectory);
  gen->add_flag("--check", check, "only check that the files are up to date");

  auto* demo = app.add_subcommand("demo", "main job: co-simulate every block and print the table");
  demo->add_option("--count", count, "random vectors per block")
      ->check(tu::cli::non_negative_integer() & CLI::Range(uint64_t{1}, kMaxCount));
  std::string demo_out = "build/demo";
  demo->add_option("--out", demo_out, "directory for the rendered images");
  demo->add_option("--threads", threads, threads_help)->check(CLI::Range(0, 4096));

  std::string cx_in, cx_out;
  tu::complexity::Params cx;
  auto* cpx = app.add_subcommand("complexity", "complexity map of a height map for adaptive POM (docs/methods/relief.md)");
  cpx->add_option("HEIGHT", cx_in, "height map PNG (first channel)")->required();
  cpx->add_option("OUT", cx_out, "output PNG (8-bit grey level codes)")->required();
  cpx->add_option("--levels", cx.levels, "quantisation levels")->check(CLI::Range(2, 256));
  cpx->add_option("--gamma", cx.gamma, "gamma exponent")->check(tu::cli::finite_in(1e-6, 16.0));
  cpx->add_option("--dilate", cx.dilate, "odd max-filter size (1 = none)")->check(tu::cli::odd_in(1, 255));

  std::string dm_in, dm_out, dm_slices;
  tu::dm::Params dmp;
  auto* dmc = app.add_subcommand("distance-map", "3-D distance map of a height map for sphere-traced relief (docs/methods/relief.md)");
  dmc->add_option("HEIGHT", dm_in, "height map PNG (first channel, 255 = top; square, power of two up to 512)")->required();
  dmc->add_option("OUT", dm_out, "output base name: writes OUT.raw (voxels) and OUT.json (header)")->required();
  dmc->add_option("--depth", dmp.layers, "layers D of the map (1..255)")->required()->check(CLI::Range(1, tu::dm::kMaxLayers));
  dmc->add_option("--scale", dmp.scale, "relief depth in texture repeats (the material's scale)")
      ->check(tu::cli::finite_in(1e-6, 0.99));
  auto* refined = dmc->add_flag("--refined", dmp.refined, "the visibility-refined map (docs/methods/relief.md)");
  dmc->add_option("--direction-step", dmp.direction_step_deg, "refined: degrees between view directions")
      ->check(tu::cli::finite_in(1.0, 45.0))->needs(refined);
  dmc->add_option("--slices", dm_slices, "write one PNG per layer here");
  dmc->add_option("--threads", dmp.threads, threads_help)->check(CLI::Range(0, 4096));

  tu::pom::QualityParams rq;
  auto* rqc = app.add_subcommand("relief-quality", "POM / iterative parallax PSNR vs steps (docs/blocks/relief.md)");
  rqc->add_option("--size", rq.side, "texture and image side (power of two)")->check(CLI::IsMember({16, 32, 64, 128, 256, 512}));
  rqc->add_option("--scale", rq.scale, "height scale S")->check(tu::cli::finite_in(0.0, 0.99));
  rqc->add_option("--height", rq.height_png, "a height map PNG of your own (first channel, 255 = top; square, "
                  "power of two, 16..512) instead of the procedural maps; its side replaces --size")
      ->check(CLI::ExistingFile);
  rqc->add_option("--debug-dir", rq.debug_dir, "write layer-count debug PNGs here")->check(CLI::ExistingDirectory);
  rqc->add_flag("--compare", rq.compare, "also linear+binary search and the distance maps (classic, refined), "
                "PSNR against the exact intersection, and the fbm/gravel/bark/stone maps");
  rqc->add_option("--dm-layers", rq.dm_layers, "distance-map layers (--compare)")->check(CLI::Range(1, tu::dm::kMaxLayers));
  rqc->add_option("--dm-step", rq.dm_step_deg, "refined map direction step in degrees (--compare)")
      ->check(tu::cli::finite_in(1.0, 45.0));
  std::string afvis_scene;
  tu::afvis::QualityParams afq;
  rqc->add_option("--afvis", afvis_scene, "AF with parallax visibility on SCENE (JSON or 'default'): PSNR vs the truth, "
                  "sharpness, texels and visibility steps per relief pixel for plain EWA and each visibility rule, "
                  "per height map and camera height (docs/blocks/afvis.md)");
  rqc->add_option("--afvis-maps", afq.maps, "--afvis height maps: bricks, fbm, gravel, bark, stone")
      ->delimiter(',')->check(CLI::IsMember({"bricks", "fbm", "gravel", "bark", "stone"}));
  rqc->add_option("--afvis-heights", afq.heights, "--afvis camera heights (multiples of the scene's)")
      ->delimiter(',')->check(tu::cli::finite_in(0.1, 100.0));
  rqc->add_option("--afvis-ss", afq.ss, "--afvis truth samples per pixel side")->check(CLI::Range(1, 64));
  std::string afvis_plot;
  rqc->add_option("--afvis-plot", afvis_plot, "--afvis: write afvis_gain_vs_clocks.{dat,gp,png} (gnuplot) into this directory")
      ->check(CLI::ExistingDirectory);
  rqc->add_option("--afvis-bias", afq.bias, "--afvis: the trace's bias in depth codes (default " +
                  std::to_string(tu::afvis::kDefaultBias) + ")")->check(CLI::Range(0, 255));
  rqc->add_option("--threads", afq.threads, "--afvis: threads for the C-model renders (0: every core)")->check(CLI::Range(0, 256));

  tu::report::Options ro;
  bool no_yosys = false;
  auto* rep = app.add_subcommand("report", "error / cycles / area / speed of every block variant (docs/report.md)");
  std::string known;
  for (const auto& g : tu::report::groups()) known += (known.empty() ? "" : ",") + g;
  rep->add_option("--blocks", ro.blocks, "comma-separated subset of " + known + " (default: all)")->delimiter(',');
  rep->add_option("--json", ro.json, "write the rows as a JSON array");
  rep->add_option("--plots", ro.plots, "directory for the per-block Pareto plots (gnuplot PNG)");
  rep->add_option("--markdown", ro.markdown, "write a Markdown table grouped per block");
  rep->add_option("--count", ro.count, "random vectors per registry block (plus its stiff set)")
      ->check(tu::cli::non_negative_integer() & CLI::Range(1ull, 1ull << 26));
  rep->add_option("--yosys-cache", ro.yosys_cache, "JSON cache of Yosys results, keyed by the RTL files' hash "
                  "(default: the repository's docs/report/yosys_cache.json, read only without --update-cache)");
  rep->add_flag("--update-cache", ro.update_cache, "synthesise the tops whose default Yosys cache entry is stale and save them there");
  rep->add_flag("--no-yosys", no_yosys, "do not synthesise (cells: not measured)");
  rep->add_flag("--yosys-cached-only", ro.yosys_cached_only,
                "take cells from matching --yosys-cache entries only; never synthesise (stale: not measured)");
  rep->add_option("--stdcell-cache", ro.stdcell_cache, "standard-cell results (texunit stdcell); read only "
                  "(default: the repository's docs/report/stdcell_cache.json)")
      ->check(CLI::ExistingFile);
  rep->add_option("--root", ro.root, "repository root (default: the source directory texunit was built from)")
      ->check(CLI::ExistingDirectory);
  rep->add_option("--shard", shard_text, "measure the block groups i with i % N == K (groups in report order)")
      ->check(tu::cli::shard_spec());

  tu::cli::MergeArgs merge_args;
  auto* mrg = app.add_subcommand("merge", "combine the JSON of `--shard K/N` runs (cosim or report) into one result");
  mrg->add_option("FILES", merge_args.files, "shard JSON files (`cosim --json` output, or `report --json` files)")
      ->required()->check(CLI::ExistingFile);
  mrg->add_option("--json", merge_args.report.json, "write the merged JSON here (cosim: default standard output)");
  mrg->add_option("--markdown", merge_args.report.markdown, "report shards: write the Markdown tables");
  mrg->add_option("--plots", merge_args.report.plots, "report shards: directory for the Pareto plots");

  std::string rtl_top;
  std::string rtl_list;
  auto* rtf = app.add_subcommand("rtl-files", "list the RTL files a top needs (package first), from rtl/manifest.json");
  rtf->add_option("TOP", rtl_top, "module name, e.g. tu_persp");
  rtf->add_option("--list", rtl_list, "instead: every top, every file (packages first), the include dirs or the lint-only files")
      ->check(CLI::IsMember({"tops", "all", "include-dirs", "lint-only"}));
  rtf->add_option("--root", root, "repository root")->check(CLI::ExistingDirectory);
  std::string rtl_key;
  rtf->add_option("--key", rtl_key, "instead: the top's cache key in docs/report/{yosys,stdcell}_cache.json (the hash of its files)")
      ->check(CLI::IsMember({"yosys", "stdcell"}));

  tu::report::StdcellOptions sc;
  auto* stc = app.add_subcommand("stdcell", "OSU 0.18 um area and timing of RTL tops (scripts/stdcell_flow.sh), cached");
  stc->add_option("TOPS", sc.tops, "RTL tops, e.g. tu_reciprocal")->required();
  stc->add_option("--cache", sc.cache, "JSON cache keyed by the hash of the RTL files and the flow script, read and "
                  "written (default: read docs/report/, write build/stdcell/ of the repository)");
  stc->add_flag("--update-cache", sc.update_cache, "write the results into the tracked docs/report/ cache");
  stc->add_option("--netlists", sc.netlists, "directory for the gate-level netlists TOP.v (default: build/stdcell, "
                  "build/stdcell_hier with --hier)");
  stc->add_flag("--hier", sc.hier, "hierarchical flow (scripts/stdcell_hier.py): each module mapped once, cached; "
                "cache docs/report/stdcell_hier.json");
  stc->add_option("--module-cache", sc.module_cache, "--hier: directory of the module netlists (default: build/stdcell_modules)");
  stc->add_option("--jobs", sc.jobs, "--hier: modules mapped at once")->check(CLI::Range(1, 256));
  stc->add_option("--root", sc.root, "repository root (default: the source directory texunit was built from)")
      ->check(CLI::ExistingDirectory);
  stc->add_flag("--force", sc.force, "re-synthesise even when the cache is current");

  tu::plan::Options po;
  auto* pln = app.add_subcommand("plan", "specialise the unit to a scene: blocks, variants, RTL configuration");
  pln->add_option("SCENE", po.scene, "scene JSON file, or 'default'")->required();
  pln->add_option("--report", po.report, "measured report table (scripts/report.sh; default: the copy of docs/report/report.json built into texunit)");
  pln->add_option("--out", po.out_sv, "write the RTL configuration package (tu_unit_cfg_pkg) here");
  pln->add_option("--out-full", po.out_full_sv, "write the full unit's configuration package here");
  pln->add_flag("--json", po.json, "print the plan as JSON");
  pln->add_option("--max-cycles", po.max_cycles,
                  "the frame's cycle budget: the octave-serial noise unit when it meets it (0: none, the pipelined unit)")
      ->check(tu::cli::finite_in(0.0, 1e18));

  tu::cli::RenderArgs render_args;
  auto* rnd = tu::cli::add_render(app, render_args);
  tu::cli::SysmodelArgs sysmodel_args;
  auto* sysm = tu::cli::add_sysmodel(app, sysmodel_args);
  tu::cli::ObjspaceArgs objspace_args;
  auto* objs = tu::cli::add_objspace(app, objspace_args);
  tu::cli::FilterCompareArgs filter_args;
  auto* fcmp = tu::cli::add_filter_compare(app, filter_args);

  tu::cli::check_values(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help prints and succeeds; every usage error exits 2 (CLI11's own codes differ by kind).
    return app.exit(e) == 0 ? 0 : tu::cli::kUsageExit;
  }
  try {
    const tu::Shard shard = tu::Shard::parse(shard_text);
    if (*vec) return cmd_vectors(block, set, count, seed, out, threads, shard);
    if (*mrg) return tu::cli::run_merge(merge_args);
    if (*rnd) return tu::cli::run_render(render_args);
    if (*sysm) return tu::cli::run_sysmodel(sysmodel_args);
    if (*objs) return tu::cli::run_objspace(objspace_args);
    if (*fcmp) return tu::cli::run_filter_compare(filter_args);
    if (*cos) return cmd_cosim(block, file, stall, seed, fst, json, rtl_variant, shard);
    if (*gen) return cmd_gen_rtl(root, check);
    if (*rep) {
      ro.yosys = !no_yosys;
      ro.shard = shard;
      return tu::report::run(ro);
    }
    if (*pln) return tu::plan::run(po);
    if (*stc) return tu::report::stdcell(sc);
    if (*rtf) return cmd_rtl_files(root, rtl_top, rtl_list, rtl_key);
    if (*cpx) return cmd_complexity(cx_in, cx_out, cx);
    if (*rqc) return afvis_scene.empty() ? cmd_relief_quality(rq) : cmd_afvis_quality(afvis_scene, afq, afvis_plot);
    if (*dmc) return cmd_distance_map(dm_in, dm_out, dm_slices, dmp);
    if (*demo) return cmd_demo(*demo->get_option("--count") ? count : 100000, demo_out, threads);
  } catch (const fs::filesystem_error& e) {
    std::cerr << "texunit: error: " << tu::cli::fs_message(e.path1().string(), "access the file", e.code()) << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "texunit: error: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
