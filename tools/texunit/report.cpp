// `texunit report`: one row per block variant with error, cycles, area, C-model speed and RTL
// simulation speed: the project-wide "error against run time" table (docs/report.md).
// Gaussian rows use exhaustive C-model statistics; every other block's rows come from the block
// registry (random + stiff vectors) and its Verilated RTL.
#include "report.hpp"
#include "report_filters.hpp"
#include "report_relief.hpp"

#include "planner/pareto.hpp"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include "block.hpp"
#include "cosim.hpp"
#include "brdf/brdf_error.hpp"
#include "gauss/clip.hpp"
#include "gauss/schemes.hpp"
#include "gauss/weight.hpp"
#include "texunit/rtl_manifest.hpp"

namespace fs = std::filesystem;

namespace tu::cosim {
RtlBlock rtl_persp_direct();  // persp_rtl.cpp (same vectors as persp, not in the registry)
RtlBlock rtl_persp_texel_depth();  // persp_rtl.cpp (tu_texel_depth on persp_texel_depth rows)
}

namespace tu::report {

namespace {
using json = nlohmann::json;

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

// Latency / II measured on the Verilated RTL (stall-free prefix) and its simulation throughput
// with 30% random stalls, checked bit for bit against the C model: a report row never carries the
// speed of an RTL that disagrees with the model.
void measure_rtl(Row& r, const cosim::RtlBlock& rtl, const blocks::Block& b, const std::vector<blocks::Row>& in) {
  const std::vector<blocks::Row> prefix(in.begin(), in.begin() + static_cast<long>(std::min<size_t>(in.size(), 256)));
  const auto [lat, ii] = rtl.timing(prefix);
  r.latency_cycles = static_cast<int64_t>(lat);
  r.ii_cycles = ii;
  r.cycles_source = "measured (Verilator " + r.rtl_top + ")";
  cosim::RunOptions ro;
  ro.stall_prob = 0.3;
  const auto t0 = std::chrono::steady_clock::now();
  const auto rr = rtl.run(in, ro);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  for (size_t i = 0; i < in.size(); ++i)
    if (rr.hung || i >= rr.outputs.size() || rr.outputs[i] != b.model(in[i]))
      throw std::runtime_error("report: " + r.rtl_top + " differs from the C model of block '" + b.name +
                               "' at vector " + std::to_string(i) + " (run `texunit cosim`)");
  r.rtl_sim_items_per_s = static_cast<double>(in.size()) / s;
  r.rtl_sim_source = "measured (Verilator, " + std::to_string(in.size()) + " vectors, 30% stalls)";
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
    const auto& rtl = cosim::find_rtl(graph);
    const auto& b = blocks::find(graph);
    r.rtl_top = "tu_" + graph;
    measure_rtl(r, rtl, b, b.inputs("random", 4096, 3));
  } catch (const std::invalid_argument&) {
  }
}

// A row whose variant has no RTL of its own (the structure's RTL was timed): keep the timing as
// an estimate, drop the RTL speed and area.
void no_rtl(Row& r, const std::string& cycles_source) {
  r.rtl_top.clear();
  r.cycles_source = cycles_source;
  r.rtl_sim_items_per_s = -1;
  r.rtl_sim_source = "not measured: no RTL for this variant";
}

// ---- area: Yosys on the RTL top and exactly the files it instantiates, cached by content hash ----
std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

uint64_t fnv1a(const std::string& s, uint64_t h) {
  for (unsigned char c : s) h = (h ^ c) * 1099511628211ull;
  return h;
}

std::vector<std::string> rtl_files(const std::string& root, const std::string& top) {
  return rtl::Manifest::load(root).top_sources(top);
}

namespace {
// A package (`*_pkg.sv`) enters a top's key with its lines outside localparams and typedefs, and
// with only the localparams and typedef blocks the top's other files name (`pkg::Name`, for a
// typedef its type or one of its enum members): a constant or enum added for another block does
// not make every cached synthesis stale, a changed width of this one does.
bool names(const std::string& users, const std::string& id) {
  const std::string name = "::" + id;
  for (auto at = users.find(name); at != std::string::npos; at = users.find(name, at + 1)) {
    const char next = at + name.size() < users.size() ? users[at + name.size()] : ' ';
    if (!std::isalnum(static_cast<unsigned char>(next)) && next != '_') return true;
  }
  return false;
}
// The identifier ending just before position `end` (exclusive) of `line`.
std::string word_before(const std::string& line, size_t end) {
  const auto last = line.find_last_not_of(" \t", end - 1);
  if (last == std::string::npos) return "";
  size_t first = last + 1;
  while (first > 0 && (std::isalnum(static_cast<unsigned char>(line[first - 1])) || line[first - 1] == '_')) --first;
  return line.substr(first, last + 1 - first);
}
std::string package_part(const std::string& pkg, const std::string& users) {
  std::istringstream in(pkg);
  std::string line, out;
  while (std::getline(in, line)) {
    const auto lp = line.find("localparam");
    const auto eq = line.find('=');
    if (line.find("typedef") != std::string::npos) {
      // A typedef block up to `} name;`: kept if its type or any member (`Member = ...`) is named.
      std::string block = line + "\n";
      std::vector<std::string> ids;
      auto member = [&](const std::string& l) {
        const auto e = l.find('=');
        if (e != std::string::npos) ids.push_back(word_before(l, e));
      };
      member(line);
      const bool braced = line.find('{') != std::string::npos;
      while (braced && line.find('}') == std::string::npos && std::getline(in, line)) {
        block += line + "\n";
        member(line);
      }
      const auto close = line.find('}');
      const auto semi = line.find(';', close == std::string::npos ? 0 : close);
      if (semi != std::string::npos) ids.push_back(word_before(line, semi));
      for (const auto& id : ids)
        if (!id.empty() && names(users, id)) {
          out += block;
          break;
        }
      continue;
    }
    if (lp == std::string::npos || eq == std::string::npos || eq < lp) {
      // Comment-only lines are not design: a comment added with another block's constant or enum
      // keeps every other top's key.
      const auto first = line.find_first_not_of(" \t");
      if (first == std::string::npos || line.compare(first, 2, "//") == 0) continue;
      out += line + "\n";
      continue;
    }
    if (names(users, word_before(line, eq))) out += line + "\n";
  }
  return out;
}
bool is_package(const std::string& f) {
  const std::string name = fs::path(f).filename().string();
  return name.size() > 7 && name.compare(name.size() - 7, 7, "_pkg.sv") == 0;
}
}  // namespace

std::string rtl_hash(const std::string& root, const std::string& top, const std::string& script) {
  uint64_t h = fnv1a(slurp(fs::path(root) / script));
  const auto manifest = rtl::Manifest::load(root);
  const auto sources = manifest.top_sources(top);
  std::string users;
  for (const auto& f : sources)
    if (!is_package(f)) users += slurp(f);
  // Only the headers the top's files `include` (a record added to tu_records.svh for the top
  // does not make the reciprocal's synthesis stale).
  std::vector<std::string> headers;
  for (const auto& f : manifest.headers())
    if (users.find("\"" + fs::path(f).filename().string() + "\"") != std::string::npos) headers.push_back(f);
  for (const auto& f : headers) users += slurp(f);
  for (const auto& f : sources)
    h = fnv1a(fs::path(f).filename().string() + (is_package(f) ? package_part(slurp(f), users) : slurp(f)), h);
  for (const auto& f : headers) h = fnv1a(fs::path(f).filename().string() + slurp(f), h);
  char key[17];
  std::snprintf(key, sizeof key, "%016llx", static_cast<unsigned long long>(h));
  return key;
}

namespace {

struct AreaCache {
  std::string path;
  json j = json::object();
  explicit AreaCache(std::string p) : path(std::move(p)) {
    if (path.empty() || !fs::exists(path)) return;
    try {
      j = json::parse(slurp(path));
    } catch (const json::exception& e) {
      throw std::runtime_error(path + ": not a Yosys cache (" + e.what() + "); delete it to rebuild");
    }
  }
  // Writes entry `top` to the file: under an exclusive lock (PATH.lock), re-reads the file and
  // replaces only that entry, so two runs at once (two background `texunit stdcell` jobs, or
  // stdcell beside `report --yosys-cache`) keep each other's results; saving the whole in-memory
  // cache would drop what the other run measured since this one started.
  void save_entry(const std::string& top) const {
    if (path.empty()) return;
    if (fs::path(path).has_parent_path()) fs::create_directories(fs::path(path).parent_path());
    const std::string lock = path + ".lock";
    const int fd = ::open(lock.c_str(), O_CREAT | O_RDWR | O_CLOEXEC, 0644);
    if (fd < 0 || ::flock(fd, LOCK_EX) != 0) {
      if (fd >= 0) ::close(fd);
      throw std::runtime_error(lock + ": cannot lock the cache");
    }
    struct Held {  // unlocks and closes on every way out, a throw included
      int fd;
      ~Held() {
        ::flock(fd, LOCK_UN);
        ::close(fd);
      }
    } held{fd};
    json disk = AreaCache(path).j;
    disk[top] = j.at(top);
    out::write_atomic(path, disk.dump(1) + "\n");
  }
};

// Standard-cell area and timing from the committed cache (never synthesised here: large tops take
// tens of minutes; `texunit stdcell` / scripts/stdcell.sh fill the cache).
void stdcell_area(Row& r, const Options& opt) {
  static std::map<std::string, json> caches;
  if (opt.stdcell_cache.empty()) {
    r.stdcell_source = "not measured: no --stdcell-cache";
    return;
  }
  if (!caches.count(opt.stdcell_cache)) caches[opt.stdcell_cache] = AreaCache(opt.stdcell_cache).j;
  const json& c = caches.at(opt.stdcell_cache);
  const std::string hint = " (run scripts/stdcell.sh " + r.rtl_top + ")";
  if (!c.contains(r.rtl_top)) {
    r.stdcell_source = "not measured: " + r.rtl_top + " not in " + opt.stdcell_cache + hint;
    return;
  }
  const json& e = c.at(r.rtl_top);
  if (e.value("hash", "") != rtl_hash(opt.root, r.rtl_top, "scripts/stdcell_flow.sh")) {
    r.stdcell_source = "not measured: RTL or flow changed since the cached run" + hint;
    return;
  }
  const auto field = [&](const char* k, bool number) -> const json& {  // a broken entry names the file and field
    if (!e.contains(k) || (number ? !e.at(k).is_number() : !e.at(k).is_string()))
      throw std::invalid_argument(opt.stdcell_cache + ": /" + r.rtl_top + "/" + k + ": " +
                                  (e.contains(k) ? "expected a " + std::string(number ? "number" : "string") + ", not " + e.at(k).dump()
                                                 : std::string("missing")));
    return e.at(k);
  };
  r.area_um2 = field("area_um2", true).get<double>();
  r.period_ns = field("period_ns", true).get<double>();
  r.fmax_mhz = field("fmax_mhz", true).get<double>();
  r.stdcell_cells = field("cells", true).get<int64_t>();
  r.critical_path = field("path_from", false).get<std::string>() + " -> " + field("path_to", false).get<std::string>();
  r.stdcell_source = "osu018 (scripts/stdcell_flow.sh)";
}

// The Debian package of a tool a flow script reports missing (scripts print {"error": "..."}).
std::string with_package(const std::string& why) {
  if (why.find("Debian package") != std::string::npos) return why;
  if (const auto at = why.find("(package "); at != std::string::npos)  // the flattened flow's Liberty message
    return why.substr(0, at) + "(Debian package " + why.substr(at + 9);
  if (why.rfind("yosys not installed", 0) == 0) return why + " (Debian package yosys)";
  if (why.find("(sta) not installed") != std::string::npos) return why + " (Debian package opensta)";
  return why;
}

// Runs a flow script (prints one JSON object) and parses its output; `cmd` is the whole command.
// A script that cannot run (a tool or the Liberty file missing) prints {"error": WHY}: the
// message gives WHY and the package to install.
json run_flow(const std::string& cmd, const std::string& what) {
  // A child of its own process group: SIGINT / SIGTERM kill it (and Yosys / OpenSTA under it).
  std::string out;
  if (out::run_capture(cmd + " 2>/dev/null", out) != 0) {
    const json e = json::parse(out, nullptr, false);
    if (e.is_object() && e.contains("error") && e.at("error").is_string())
      throw std::runtime_error(what + ": " + with_package(e.at("error").get<std::string>()));
    throw std::runtime_error("report: " + what + " failed (run " + cmd + ")");
  }
  return json::parse(out);
}

std::string file_list(const std::vector<std::string>& files) {
  std::string list;
  for (const auto& f : files) list += f + " ";
  return list;
}

void area(Row& r, const Options& opt, AreaCache& cache) {
  if (r.rtl_top.empty()) {
    r.area_source = "not measured: no RTL";
    r.stdcell_source = "not measured: no RTL";
    return;
  }
  stdcell_area(r, opt);
  if (!opt.yosys) {
    r.area_source = "not measured: " + opt.no_yosys_why;
    return;
  }
  const std::string key = rtl_hash(opt.root, r.rtl_top, "scripts/yosys_area.sh");
  const auto hit = cache.j.find(r.rtl_top);
  if (opt.yosys_cached_only && (hit == cache.j.end() || !hit->is_object() || hit->value("hash", "") != key)) {
    r.area_source = "not measured: no Yosys cache entry for this RTL (scripts/report.sh or texunit report --update-cache synthesises it)";
    return;  // a stale entry is not a measurement of this RTL
  }
  json& e = cache.j[r.rtl_top];
  if (!e.is_object() || e.value("hash", "") != key) {
    const auto files = rtl_files(opt.root, r.rtl_top);
    std::cerr << "yosys: synthesising " << r.rtl_top << " (" << files.size() << " files)\n";
    e = run_flow(opt.root + "/scripts/yosys_area.sh " + r.rtl_top + " " + file_list(files), "Yosys on " + r.rtl_top);
    e["hash"] = key;
    cache.save_entry(r.rtl_top);
  }
  r.cells = e.at("cells").get<int64_t>();
  r.flip_flops = e.at("flip_flops").get<int64_t>();
  r.multipliers = e.at("multipliers").get<int64_t>();
  r.area_source = "yosys synth";
}

// Registry-backed groups: (group, variant, registry block, RTL binding or null, RTL top).
struct Spec {
  std::string group, variant, block;
  const cosim::RtlBlock* rtl;
  std::string top, err_unit;  // err_unit: what the registry's error function measures
};

// Rows of a registry block: error over its random + stiff vectors, C-model speed, RTL timing and
// simulation speed, area.
Row registry_row(const Spec& spec, const Options& opt, AreaCache& cache) {
  const auto& b = blocks::find(spec.block);
  auto in = b.inputs("random", opt.count, 7);
  if (std::find(b.sets.begin(), b.sets.end(), "stiff") != b.sets.end())
    for (auto& x : b.inputs("stiff", 0, 0)) in.push_back(std::move(x));
  Row r;
  r.block = spec.group;
  r.variant = spec.variant;
  r.scheme = spec.block;
  r.err_unit = spec.err_unit;
  double sum_sq = 0;
  uint64_t n = 0, flagged = 0;
  for (const auto& x : in) {
    const auto e = b.error(x, b.model(x), b.ref(x));
    if (!e.valid) {
      ++flagged;
      continue;
    }
    r.max_abs_err = std::max(r.max_abs_err, e.abs);
    r.max_ulp_err = std::max(r.max_ulp_err, e.ulp);
    sum_sq += e.abs * e.abs;
    ++n;
  }
  r.rms_err = n ? std::sqrt(sum_sq / static_cast<double>(n)) : 0;
  const size_t timed = std::min<size_t>(in.size(), 4096);
  r.cmodel_ns_per_item = ns_per_item([&] {
    uint64_t s = 0;
    for (size_t i = 0; i < timed; ++i) s += b.model(in[i])[0];
    return s;
  }, timed);
  r.latency_cycles = b.latency_cycles;
  r.ii_cycles = b.ii_cycles;
  r.cycles_source = "declared (block registry)";
  if (spec.rtl) {
    r.rtl_top = spec.top;
    measure_rtl(r, *spec.rtl, b, in);
  }
  area(r, opt, cache);
  std::ostringstream no;
  no << opt.count << " random + " << (in.size() - opt.count) << " stiff vectors, " << flagged << " flagged (excluded)";
  r.notes = no.str();
  return r;
}
std::vector<Row> clip_rows(const Options& opt, AreaCache& cache) {
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
      r.err_unit = "volume (0..1)";
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
        no_rtl(r, "estimated (" + g + "; RTL has the mm coefficients)");
      }
      area(r, opt, cache);
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

std::vector<Row> weight_rows(const Options& opt, AreaCache& cache) {
  const auto st = gauss::weight_exhaustive();
  Row r;
  r.block = "gauss_weight";
  r.err_unit = "weight (0..1)";
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
  area(r, opt, cache);
  r.notes = st.monotonic ? "exhaustive over 2^16 Q codes, monotonic" : "NOT monotonic";
  return {r};
}

std::vector<Row> table_rows(const Options& opt, AreaCache& cache) {
  std::vector<Row> rows;
  const auto comp = gauss::table_stats(2, 0);
  for (int kind = 0; kind < 2; ++kind)
    for (int l = 4; l <= 10; ++l) {
      const auto st = gauss::table_stats(kind, l);
      Row r;
      r.block = "weight_table";
      r.err_unit = "weight (0..1)";
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
        no_rtl(r, "estimated (" + r.scheme + "; RTL has N = " + std::to_string(1 << rtl_l) + ")");
      }
      area(r, opt, cache);
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

std::string na(int64_t x) { return x < 0 ? std::string("n/a") : std::to_string(x); }

const cosim::RtlBlock* rtl_or_null(const std::string& name) {
  try {
    return &cosim::find_rtl(name);
  } catch (const std::invalid_argument&) {
    return nullptr;
  }
}
std::vector<Spec> registry_specs() {
  static const cosim::RtlBlock direct = cosim::rtl_persp_direct();
  static const cosim::RtlBlock texel_depth = cosim::rtl_persp_texel_depth();  // tu_texel_depth on B1's seeds
  std::vector<Spec> v = {
      {"reciprocal", "faithful_25b", "reciprocal", rtl_or_null("reciprocal"), "tu_reciprocal", "1/M, absolute"},
      {"persp", "incremental", "persp", rtl_or_null("persp"), "tu_persp", "texels"},
      {"persp", "direct", "persp", &direct, "tu_persp_direct", "texels"},
      {"persp", "klane4", "persp_k4", rtl_or_null("persp_k4"), "tu_persp_klane", "texels (item = 4 pixels)"},
      {"persp", "texel_depth", "persp_texel_depth", &texel_depth, "tu_texel_depth", "texels"},
      {"persp_setup", "setup", "persp_setup", rtl_or_null("persp_setup"), "tu_persp_setup", "seed value (0: exact)"},
      {"ellipse", "analytic", "ellipse", rtl_or_null("ellipse"), "tu_ellipse", "LOD (mip levels)"},
      {"ellipse", "recurrence", "ellipse_rec", rtl_or_null("ellipse_rec"), "tu_ellipse_rec",
       "LOD (mip levels) against the analytic float Jacobian"},
      {"pom_layers", "pom_layers", "pom_layers", rtl_or_null("pom_layers"), "tu_pom_layers", "layers"},
      {"pom_march", "pom_march", "pom_march", rtl_or_null("pom_march"), "tu_pom_march", "march steps"},
      {"iter_parallax", "iter_parallax", "iter_parallax", rtl_or_null("iter_parallax"), "tu_iter_parallax",
       "uv in 2^-16 units"}};
  // Perlin noise: both schemes on the same vectors (docs/blocks/noise.md).
  for (const std::string d : {"3d", "2d"}) {
    v.push_back({"perlin" + d, "pipelined", "perlin" + d, rtl_or_null("perlin" + d), "tu_perlin" + d, "fbm value 0..1"});
    v.push_back({"perlin" + d, "octave_serial", "perlin" + d, rtl_or_null("perlin" + d + "_serial"),
                 "tu_perlin" + d + "_serial", "fbm value 0..1"});
  }
  // Any other registry block (e.g. a new one) gets a row of its own; the Gaussian blocks have
  // the exhaustive producers below.
  for (const auto& b : blocks::all()) {
    const bool known = b.name.rfind("clip_", 0) == 0 || b.name.rfind("weight_table", 0) == 0 ||
                       b.name.rfind("brdf_", 0) == 0 ||
                       b.name == "gauss_weight" ||
                       b.name == "texel_depth" ||  // its RTL is row persp/texel_depth (on B1's seeds)
                       b.name == "afvis" ||        // its rows: report_relief.cpp (afvis_rows)
                       std::any_of(v.begin(), v.end(), [&](const Spec& x) { return x.block == b.name; });
    if (!known) v.push_back({b.name, b.name, b.name, rtl_or_null(b.name), "tu_" + b.name, b.err_metric});
  }
  // The BRDF models share one section: one row per model (brdf_rows adds the Blinn measures).
  for (const auto& b : blocks::all())
    if (b.name.rfind("brdf_", 0) == 0)
      v.push_back({"brdf", b.name.substr(5), b.name, rtl_or_null(b.name), "tu_" + b.name,
                   "F (0..1.024, 1 ULP = 2^-8) against the model's own float formula"});
  return v;
}
const std::vector<std::string> kGauss = {"clip_volume", "gauss_weight", "weight_table"};

std::string fmt_g(double x, const char* f = "%.4g") {
  char b[64];
  std::snprintf(b, sizeof b, f, x);
  return b;
}

// brdf rows: the registry row of each model plus its measures against Blinn on the thesis grid
// (deg 0..90 x n 1..1000): MAD, max |F - c^n| and the relative error at the epicentre F_B = 0.3.
std::vector<Row> brdf_rows(const Options& opt, AreaCache& cache) {
  std::vector<Row> out;
  for (const auto& s : registry_specs()) {
    if (s.group != "brdf") continue;
    Row r = registry_row(s, opt, cache);
    const std::string model = s.variant == "msh_seq" ? "msh" : s.variant;
    for (brdf::Model m : brdf::kModels) {
      if (brdf::name(m) != model) continue;
      const auto g = brdf::vs_blinn_fx(m);
      const int n_lo = m == brdf::Model::Dsh ? 9 : 2;  // the thesis's ranges (F_dsh: n >= 9)
      const double ep = brdf::epicentre_rel_fx(m, n_lo);
      r.extra_json = "\"mad_vs_blinn\": " + jnum(g.mad) + ", \"max_err_vs_blinn\": " + jnum(g.max_abs) +
                     ", \"epicentre_rel_err\": " + jnum(ep) + ", \"epicentre_n_from\": " + std::to_string(n_lo);
      r.notes = "MAD vs Blinn " + fmt_g(g.mad) + ", max |F - c^n| " + fmt_g(g.max_abs) +
                ", epicentre rel. err " + fmt_g(100 * ep, "%.2f") + " % (n " + std::to_string(n_lo) +
                "..1000); " + r.notes;
    }
    out.push_back(std::move(r));
  }
  return out;
}

// Text for inside a gnuplot single-quoted string: a quote is written twice.
std::string gnuplot_quoted(const std::string& t) {
  std::string q;
  for (char c : t) q += c == '\'' ? std::string("''") : std::string(1, c);
  return q;
}

// Per block: error against cycles and against Yosys cells, frontier joined by a line.
void plots(const std::vector<Row>& rs, const std::string& dir, out::Outputs& outs) {
  outs.make_dir(dir);
  const std::string gp = dir + "/report.gp";
  std::vector<std::string> pngs;
  std::ostringstream g;
  g << "set terminal pngcairo size 900,600 noenhanced\nset logscale y\nset grid\nset key bottom left\n"
    << "set offsets graph 0.05, graph 0.3, graph 0.1, graph 0.1\n";  // room for the labels
  for (const auto& grp : groups()) {
    for (const auto& m : kMeasures) {
      // Error 0 (bit-exact blocks) has no place on the log scale: frontier only, not drawn.
      Points p = points(rs, grp, m);
      for (size_t i = p.rows.size(); i-- > 0;)
        if (p.xy[i].second <= 0) p.rows.erase(p.rows.begin() + static_cast<long>(i)), p.xy.erase(p.xy.begin() + static_cast<long>(i));
      if (p.rows.empty()) continue;
      const std::string stem = dir + "/" + grp + "_error_vs_" + m.stem;
      std::ostringstream d, fr;
      for (size_t i = 0; i < p.rows.size(); ++i)
        d << p.xy[i].first << " " << p.xy[i].second << " " << p.rows[i]->variant << "/" << p.rows[i]->scheme << "\n";
      for (size_t i : frontier(p.xy)) fr << p.xy[i].first << " " << p.xy[i].second << "\n";
      outs.write(stem + ".dat", d.str());
      outs.write(stem + "_frontier.dat", fr.str());
      pngs.push_back(stem + ".png");
      g << "set output '" << stem << ".png'\nset title '" << grp << ": max abs error ("
        << gnuplot_quoted(p.rows[0]->err_unit) << ") against " << m.stem << "'\n"
        << "set xlabel '" << m.label << "'\n"
        << "set ylabel 'max abs error'\n"
        << "plot '" << stem << ".dat' using 1:2 with points pt 7 ps 1.2 title 'variant', '"
        << stem << "_frontier.dat' using 1:2 with linespoints lw 2 pt 6 ps 2 title 'Pareto frontier', '"
        << stem << ".dat' using 1:2:3 with labels rotate by 25 left font ',8' offset 0.5,0.5 notitle\n";
    }
  }
  outs.write(gp, g.str());
  // gnuplot warns about the zero-width range of one-variant blocks: its messages matter on failure only.
  if (const std::string why = out::gnuplot(outs, gp, pngs); !why.empty()) throw std::runtime_error("report: " + why);
}

void markdown(const std::vector<Row>& rs, const Options& opt, out::Outputs& outs) {
  std::ostringstream o;
  o << "# Error against run time: every block and variant\n\n"
    << "Generated by " << (opt.provenance.empty() ? "`scripts/report.sh` (`texunit report --count " + std::to_string(opt.count) + "`)" : opt.provenance)
    << "; do not edit by hand. Column meanings: [reading the report](reading-the-report.md).\n"
    << "Error is against the block's float reference, in the unit named per block; cycles are latency + II "
       "from Verilator where an RTL exists (else the estimator, column *cycles from*); cells / multipliers from "
       "Yosys `synth` (generic gates) on the RTL top; area um2 / period / fmax from the OSU 0.18 um standard-cell "
       "flow (`scripts/stdcell_flow.sh`, cache `docs/report/stdcell_cache.json`; assumptions in "
       "[area-timing.md](area-timing.md)), latency ns = latency x period, ns/item = II x period (II: mean measured "
       "cycles per item for data-dependent blocks); C-model ns per item timed on this machine; RTL items/s is "
       "the Verilator co-simulation throughput with 30% random stalls (outputs checked against the C model).\n";
  for (const auto& grp : groups()) {
    bool any = false;
    for (const auto& r : rs) any = any || r.block == grp;
    if (!any) continue;
    std::string unit;
    for (const auto& r : rs)
      if (r.block == grp) unit = r.err_unit;
    if (grp == "filters") {
      const bool plot = !opt.plots.empty() && fs::exists(opt.plots + "/filters_psnr_vs_clocks.png");
      o << "\n## filters: quality against clocks per pixel\n\n"
        << filters_markdown(rs, plot ? fs::relative(fs::absolute(opt.plots), fs::absolute(opt.markdown).parent_path()).string() : "");
      continue;
    }
    o << "\n## " << grp << "\n\nerror unit: " << unit << "\n\n";
    if (!opt.plots.empty() && fs::exists(opt.plots + "/" + grp + "_error_vs_cycles.png")) {
      const auto rel = fs::relative(fs::absolute(opt.plots), fs::absolute(opt.markdown).parent_path()).string();
      for (const auto& m : kMeasures)
        if (fs::exists(opt.plots + "/" + grp + "_error_vs_" + m.stem + ".png"))
          o << "![" << grp << " error vs " << m.stem << "](" << rel << "/" << grp << "_error_vs_" << m.stem << ".png) ";
      o << "\n\n";
    }
    o << "| variant | scheme | max abs err | rms err | max ULP | latency | II | cycles from | cells | mul | "
         "area um2 | period ns | fmax MHz | latency ns | ns/item | critical path | "
         "C model ns/item | RTL sim items/s | Pareto | notes |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    std::vector<Points> pm;
    for (const auto& m : kMeasures) pm.push_back(points(rs, grp, m));
    for (const auto& r : rs) {
      if (r.block != grp) continue;
      std::string pareto;
      for (size_t i = 0; i < kMeasures.size(); ++i)
        if (pm[i].front.count(&r)) pareto += std::string(pareto.empty() ? "" : " ") + kMeasures[i].stem;
      const bool sc = r.area_um2 >= 0;
      const auto std_or = [&](double x, const char* f) { return sc && x >= 0 ? fmt_g(x, f) : std::string("—"); };
      o << "| " << r.variant << " | " << r.scheme << " | " << fmt_g(r.max_abs_err) << " | " << fmt_g(r.rms_err)
        << " | " << fmt_g(r.max_ulp_err, "%.3g") << " | " << na(r.latency_cycles) << " | " << fmt_g(r.ii_cycles, "%.3g")
        << " | " << r.cycles_source << " | " << (r.cells < 0 ? r.area_source : std::to_string(r.cells)) << " | "
        << na(r.multipliers) << " | " << (sc ? fmt_g(r.area_um2, "%.0f") : r.stdcell_source) << " | "
        << std_or(r.period_ns, "%.2f") << " | " << std_or(r.fmax_mhz, "%.1f") << " | " << std_or(r.latency_ns(), "%.1f")
        << " | " << std_or(r.ns_per_item(), "%.2f") << " | " << (sc ? r.critical_path : "—") << " | "
        << fmt_g(r.cmodel_ns_per_item, "%.1f") << " | "
        << (r.rtl_sim_items_per_s < 0 ? r.rtl_sim_source : fmt_g(r.rtl_sim_items_per_s, "%.0f")) << " | "
        << pareto << " | " << r.notes << " |\n";
    }
  }
  outs.write(opt.markdown, o.str());
}
}  // namespace

std::vector<std::string> groups() {
  std::vector<std::string> g;
  for (const auto& s : registry_specs())
    if (std::find(g.begin(), g.end(), s.group) == g.end() && s.group != "pom_setup" && s.group != "pom_refine")
      g.push_back(s.group);  // pom_setup, pom_refine: rows of pom_unit (report_relief.cpp)
  g.insert(g.begin() + 3, kGauss.begin(), kGauss.end());  // after reciprocal, persp, ellipse: B1 .. B5 order
  g.push_back("distance_map");  // C model only (report_relief.cpp)
  g.push_back("afvis");         // report_relief.cpp
  g.push_back("filters");       // report_filters.cpp: quality against clocks per filter and scene
  return g;
}

std::vector<Row> rows(const Options& in) {
  Options opt = in;
  opt.root = repo_root(opt.root);
  const auto known = groups();
  for (const auto& b : opt.blocks)
    if (std::find(known.begin(), known.end(), b) == known.end()) {
      std::string k;
      for (const auto& n : known) k += (k.empty() ? "" : ", ") + n;
      throw std::invalid_argument("report: unknown block '" + b + "' (known: " + k + ")");
    }
  AreaCache cache(opt.yosys ? opt.yosys_cache : "");
  std::vector<Row> out;
  for (size_t gi = 0; gi < known.size(); ++gi) {
    const auto& g = known[gi];
    if (!opt.blocks.empty() && std::find(opt.blocks.begin(), opt.blocks.end(), g) == opt.blocks.end()) continue;
    if (!opt.shard.owns_round_robin(gi)) continue;  // groups differ in cost: round-robin balances
    std::vector<Row> r;
    if (g == "clip_volume") r = clip_rows(opt, cache);
    else if (g == "gauss_weight") r = weight_rows(opt, cache);
    else if (g == "weight_table") r = table_rows(opt, cache);
    else if (g == "brdf") r = brdf_rows(opt, cache);
    else if (g == "filters") r = filter_rows(opt.root, [&](Row& x) { area(x, opt, cache); });
    else if (is_relief_block(g)) {
      // report_relief.cpp: the engines' cycles per pixel on the bricks scene stream, pom_unit with
      // its stages pom_setup and pom_refine; area from the same Yosys cache.
      r = relief_rows({g}, opt.root);
      for (auto& x : r) area(x, opt, cache);
    } else
      for (const auto& s : registry_specs())
        if (s.group == g) r.push_back(registry_row(s, opt, cache));
    std::cerr << "report: " << g << " (" << r.size() << " rows)\n";
    out.insert(out.end(), r.begin(), r.end());
  }
  return out;
}

std::vector<Row> rows(const std::vector<std::string>& blocks, const std::string& root, bool yosys) {
  Options o;
  o.blocks = blocks;
  o.root = root;
  o.yosys = yosys;
  return rows(o);
}

std::string repo_root(const std::string& given) {
  if (!given.empty()) return given;
#ifdef TU_SOURCE_DIR
  if (fs::exists(fs::path(TU_SOURCE_DIR) / "rtl" / "manifest.json")) return TU_SOURCE_DIR;
#endif
  return ".";
}

int stdcell(const StdcellOptions& o) {
  const std::string root = repo_root(o.root);
  const std::string script = o.hier ? "scripts/stdcell_hier.py" : "scripts/stdcell_flow.sh";
  const std::string name = o.hier ? "stdcell_hier.json" : "stdcell_cache.json";
  const std::string tracked = root + "/docs/report/" + name, local = root + "/build/stdcell/" + name;
  // The cache written: the one named, the tracked one when asked, else the local one; a current
  // entry of the tracked cache is used in any case (it is the committed measurement).
  const std::string out = !o.cache.empty() ? o.cache : o.update_cache ? tracked : local;
  AreaCache cache(out);
  const AreaCache committed(o.cache.empty() && out != tracked ? tracked : "");
  const std::string netlists = !o.netlists.empty() ? o.netlists : root + (o.hier ? "/build/stdcell_hier" : "/build/stdcell");
  const std::string modules = !o.module_cache.empty() ? o.module_cache : root + "/build/stdcell_modules";
  std::vector<std::string> keys;  // every top checked (it exists, its files hash) before the first synthesis
  for (const auto& top : o.tops) keys.push_back(rtl_hash(root, top, script));
  for (size_t t = 0; t < o.tops.size(); ++t) {
    const std::string& top = o.tops[t];
    const std::string& key = keys[t];
    const std::string net = netlists + "/" + top + ".v";
    json& e = cache.j[top];
    const auto current = [&](const json& x) { return x.is_object() && x.value("hash", "") == key; };
    if (!o.force && !current(e) && committed.j.contains(top) && current(committed.j.at(top))) e = committed.j.at(top);
    // A current entry is kept unless its netlist is wanted and missing (the flow is deterministic:
    // the re-run only writes the netlist again).
    if (!o.force && current(e) && fs::exists(net)) {
      std::cerr << "stdcell: " << top << " current (hash " << key << "), netlist " << net << "\n";
      continue;
    }
    const auto t0 = std::chrono::steady_clock::now();
    std::cerr << "stdcell: synthesising " << top << (o.hier ? " (hierarchical)" : "") << "\n";
    const std::string args = o.hier ? " --cache-dir " + modules + " --jobs " + std::to_string(o.jobs) + " " : " ";
    e = run_flow(root + "/" + script + args + top + " " + net + " " + file_list(rtl_files(root, top)),
                 "the standard-cell flow on " + top);
    e["hash"] = key;
    e["flow_seconds"] = std::round(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    cache.save_entry(top);  // after every top: a long background run keeps what it measured
    std::cerr << "stdcell: " << top << " " << e.at("area_um2") << " um2, " << e.at("period_ns") << " ns, "
              << e.at("path_from").get<std::string>() << " -> " << e.at("path_to").get<std::string>() << " (saved in "
              << out << ")\n";
  }
  return 0;
}

int run(const Options& in) {
  Options opt = in;
  opt.root = repo_root(opt.root);
  // The repository's caches by default; the tracked Yosys cache is written only when asked
  // (without --update-cache a stale entry is "not measured", never a silent re-synthesis).
  if (opt.yosys_cache.empty()) {
    opt.yosys_cache = opt.root + "/docs/report/yosys_cache.json";
    if (!opt.update_cache) opt.yosys_cached_only = true;
  }
  if (opt.stdcell_cache.empty()) opt.stdcell_cache = opt.root + "/docs/report/stdcell_cache.json";
  // The targets checked before the measurements (minutes): a missing or unwritable directory fails now.
  for (const auto* f : {&opt.json, &opt.markdown})
    if (!f->empty()) out::check_target(*f);
  if (opt.yosys && out::run("command -v yosys >/dev/null 2>&1") != 0) {
    opt.yosys = false;
    opt.no_yosys_why = "yosys not installed (Debian package yosys)";
  }
  // Everything is measured before any file is written: a failure leaves no partial output.
  write(rows(opt), opt);
  return 0;
}

std::string shard_identity(const Options& opt) {
  json id = json::object();
  id["report_shard"] = opt.shard.str();
  id["count"] = opt.count;
  id["blocks"] = opt.blocks;  // empty: every group
  id["yosys"] = !opt.yosys ? "off" : opt.yosys_cached_only ? "cached only" : "measured";
  id["yosys_cache"] = opt.yosys_cache;
  id["stdcell_cache"] = opt.stdcell_cache;
  return id.dump();
}

void write(const std::vector<Row>& rs, const Options& opt) {
  std::printf("%-13s %-16s %-20s %10s %10s %9s %4s %5s %6s %4s %8s %10s\n", "block", "variant", "scheme",
              "max_abs", "rms", "max_ulp", "lat", "II", "cells", "mul", "ns/item", "rtl_item/s");
  for (const auto& r : rs)
    std::printf("%-13s %-16s %-20s %10.4g %10.4g %9.3g %4s %5.2f %6s %4s %8.1f %10s\n", r.block.c_str(),
                r.variant.c_str(), r.scheme.c_str(), r.max_abs_err, r.rms_err, r.max_ulp_err,
                na(r.latency_cycles).c_str(), r.ii_cycles, na(r.cells).c_str(), na(r.multipliers).c_str(),
                r.cmodel_ns_per_item, r.rtl_sim_items_per_s < 0 ? "n/a" : fmt_g(r.rtl_sim_items_per_s, "%.0f").c_str());
  if (!opt.yosys) std::printf("(cells: not measured: yosys not installed or --no-yosys)\n");
  // Plots, JSON and Markdown are one set of outputs, all or none: the plots are published first
  // (gnuplot reads their data by name, the Markdown links the PNGs it finds) but removed again if
  // anything after them fails.
  out::Outputs outs;
  bool relief_ok = false;
  if (!opt.plots.empty()) {
    plots(rs, opt.plots, outs);
    if (std::any_of(rs.begin(), rs.end(), [](const Row& r) { return is_relief_block(r.block); })) {
      relief_ok = relief_plot(opt.plots, outs);
      if (!relief_ok) std::cerr << "gnuplot failed (relief plots skipped)\n";
    }
    if (const std::string why = filters_plot(rs, opt.plots, outs); !why.empty()) throw std::runtime_error("report: " + why);
  }
  if (!opt.json.empty())
    outs.write(opt.json, [&](std::ostream& o) {
      o << "[\n";
      if (!opt.shard.whole()) o << "  " << shard_identity(opt) << (rs.empty() ? "\n" : ",\n");  // element 0: merge
      for (size_t i = 0; i < rs.size(); ++i) o << "  " << rs[i].json() << (i + 1 < rs.size() ? ",\n" : "\n");
      o << "]\n";
    });
  if (!opt.markdown.empty()) markdown(rs, opt, outs);
  outs.commit();
  if (!opt.plots.empty()) std::cerr << "wrote plots to " << opt.plots << "\n";
  if (relief_ok) std::cerr << "wrote " + opt.plots + "/relief_psnr_vs_steps.png, relief_psnr_vs_cycles.png\n";
  if (!opt.json.empty()) std::cerr << "wrote " << opt.json << "\n";
  if (!opt.markdown.empty()) std::cerr << "wrote " << opt.markdown << "\n";
}

std::vector<Row> merge_rows(const std::vector<std::vector<Row>>& shards) {
  const auto known = groups();
  const auto rank = [&](const std::string& g) {
    const auto it = std::find(known.begin(), known.end(), g);
    if (it == known.end()) throw std::invalid_argument("merge: unknown report block '" + g + "'");
    return it - known.begin();
  };
  std::vector<Row> out;
  std::map<std::string, size_t> owner;  // group -> shard that measured it
  for (size_t s = 0; s < shards.size(); ++s)
    for (const auto& r : shards[s]) {
      if (const auto [it, fresh] = owner.emplace(r.block, s); !fresh && it->second != s)
        throw std::invalid_argument("merge: block '" + r.block + "' is in shard files " + std::to_string(it->second + 1) +
                                    " and " + std::to_string(s + 1) + " (the same shard twice?)");
      out.push_back(r);
    }
  // Stable: a group's rows keep their order (one shard measured each group).
  std::stable_sort(out.begin(), out.end(), [&](const Row& a, const Row& b) { return rank(a.block) < rank(b.block); });
  return out;
}

}  // namespace tu::report
