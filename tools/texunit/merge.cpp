#include "merge.hpp"

#include "output.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "cosim.hpp"
#include "texunit/shard.hpp"

namespace tu::cli {
namespace {

using json = nlohmann::json;

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::invalid_argument(path + ": cannot open the file");
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// A `cosim --json` object, read back (the keys Report::json writes).
cosim::Report cosim_report(const json& j, const std::string& file) {
  const auto need = [&](const char* k) -> const json& {
    if (!j.contains(k)) throw std::invalid_argument(file + ": cosim result without \"" + k + "\"");
    return j.at(k);
  };
  const auto num = [&](const char* k) { const auto& v = need(k); return v.is_null() ? INFINITY : v.get<double>(); };
  cosim::Report r;
  r.block = need("block").get<std::string>();
  r.vectors = need("vectors").get<uint64_t>();
  r.outputs = need("outputs").get<uint64_t>();
  r.mismatches = need("mismatches").get<uint64_t>();
  r.model_mismatches = need("model_mismatches").get<uint64_t>();
  r.extra_outputs = need("extra_outputs").get<uint64_t>();
  r.in_order = need("in_order").get<bool>();
  r.hung = need("hung").get<bool>();
  r.max_abs_err = num("max_abs_err");
  r.max_ulp_err = num("max_ulp_err");
  r.rms_err = num("rms_err");
  r.err_points = need("err_points").get<uint64_t>();
  r.err_sum_sq = num("err_sum_sq");
  r.flagged = need("flagged").get<uint64_t>();
  r.latency_cycles = need("latency_cycles").get<uint64_t>();
  r.ii_cycles = num("ii_cycles");
  r.sim_cycles = need("sim_cycles").get<uint64_t>();
  r.stall_prob = num("stall_prob");
  r.wall_s = num("wall_s");
  r.shard = j.value("shard", "");
  // The keys Report::json always writes, and "shard": any other number is the error metric.
  static const auto known = [] {
    std::set<std::string> k = {"shard"};
    const auto j0 = json::parse(cosim::Report{}.json());  // named: items() does not extend its life
    for (const auto& [key, v] : j0.items()) k.insert(key);
    return k;
  }();
  for (const auto& [k, v] : j.items())
    if (!known.count(k) && v.is_number()) r.err_metric = k;  // the block's name for max_abs_err
  r.first_mismatch = j.value("first_mismatch", "");
  return r;
}

int merge_cosim(const std::vector<json>& docs, const MergeArgs& a) {
  std::map<uint64_t, cosim::Report> by_k;
  uint64_t n = 0;
  for (size_t i = 0; i < docs.size(); ++i) {
    const auto& f = a.files[i];
    auto r = cosim_report(docs[i], f);
    if (r.shard.empty()) throw std::invalid_argument(f + ": not a shard (run `texunit cosim --shard K/N --json`)");
    const Shard s = Shard::parse(r.shard);
    if (n && s.n != n) throw std::invalid_argument(f + ": shard " + r.shard + " of another split (N = " + std::to_string(n) + ")");
    n = s.n;
    if (!by_k.emplace(s.k, r).second) throw std::invalid_argument(f + ": shard " + r.shard + " given twice");
  }
  std::string missing;
  for (uint64_t k = 0; k < n; ++k)
    if (!by_k.count(k)) missing += (missing.empty() ? "" : ", ") + std::to_string(k);
  if (!missing.empty()) throw std::invalid_argument("merge: shards " + missing + " of " + std::to_string(n) + " are missing");
  cosim::Report m = by_k.at(0);  // block, latency, II, stall probability, error metric name
  m.shard.clear();
  for (const auto& [k, r] : by_k) {
    if (r.block != m.block) throw std::invalid_argument("merge: shards of blocks '" + m.block + "' and '" + r.block + "'");
    if (r.stall_prob != m.stall_prob) throw std::invalid_argument("merge: shards with different --stall-prob");
    if (k == 0) continue;
    m.vectors += r.vectors, m.outputs += r.outputs, m.mismatches += r.mismatches;
    m.model_mismatches += r.model_mismatches, m.extra_outputs += r.extra_outputs, m.flagged += r.flagged;
    m.in_order = m.in_order && r.in_order, m.hung = m.hung || r.hung;
    m.max_abs_err = std::max(m.max_abs_err, r.max_abs_err), m.max_ulp_err = std::max(m.max_ulp_err, r.max_ulp_err);
    m.err_points += r.err_points, m.err_sum_sq += r.err_sum_sq;
    m.sim_cycles += r.sim_cycles;  // each shard fills and drains the pipeline once
    m.wall_s += r.wall_s;          // summed: CPU time of the whole run
    if (m.first_mismatch.empty()) m.first_mismatch = r.first_mismatch;
  }
  m.rms_err = m.err_points ? std::sqrt(m.err_sum_sq / static_cast<double>(m.err_points)) : 0;
  const std::string out = m.json();
  if (a.report.json.empty()) std::cout << out << "\n";
  else tu::out::write_atomic(a.report.json, out + "\n");
  if (!m.first_mismatch.empty()) std::cerr << "first mismatch: " << m.first_mismatch << "\n";
  return m.ok() ? 0 : 1;
}

int merge_report(const std::vector<json>& docs, const MergeArgs& a) {
  std::vector<std::vector<report::Row>> shards;
  for (size_t i = 0; i < docs.size(); ++i) {
    std::vector<report::Row> rows;
    for (const auto& e : docs[i]) {
      try {
        rows.push_back(report::Row::from_json(e.dump()));
      } catch (const std::exception& ex) {
        throw std::invalid_argument(a.files[i] + ": row " + std::to_string(rows.size() + 1) + ": " + ex.what());
      }
    }
    shards.push_back(std::move(rows));
  }
  report::Options o = a.report;
  o.provenance = "`texunit merge` of " + std::to_string(docs.size()) + " `texunit report --shard K/N` runs";
  report::write(report::merge_rows(shards), o);
  return 0;
}

}  // namespace

int run_merge(const MergeArgs& a) {
  for (const auto* f : {&a.report.json, &a.report.markdown})  // the targets checked before the work
    if (!f->empty()) tu::out::check_target(*f);
  std::vector<json> docs;
  for (const auto& f : a.files) {
    try {
      docs.push_back(json::parse(slurp(f)));
    } catch (const json::parse_error& e) {
      throw std::invalid_argument(f + ": not JSON (" + e.what() + ")");
    }
  }
  const bool arrays = std::all_of(docs.begin(), docs.end(), [](const json& d) { return d.is_array(); });
  const bool objects = std::all_of(docs.begin(), docs.end(), [](const json& d) { return d.is_object(); });
  if (arrays) return merge_report(docs, a);
  if (objects) {
    if (!a.report.markdown.empty() || !a.report.plots.empty())
      throw std::invalid_argument("merge: --markdown and --plots are for report shards, these are cosim results");
    return merge_cosim(docs, a);
  }
  throw std::invalid_argument("merge: give either report shards (JSON arrays) or cosim shards (JSON objects), not a mix");
}

}  // namespace tu::cli
