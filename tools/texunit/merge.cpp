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

// json::parse keeps the last of a repeated key: a shard edited by hand (or two results pasted into
// one object) would merge silently. The parser's callback sees every key; one set per open object.
json parse_unique_keys(const std::string& text, const std::string& file) {
  std::vector<std::set<std::string>> keys;
  return json::parse(text, [&](int, json::parse_event_t ev, json& v) {
    if (ev == json::parse_event_t::object_start) keys.emplace_back();
    if (ev == json::parse_event_t::object_end) keys.pop_back();
    if (ev == json::parse_event_t::key && !keys.back().insert(v.get<std::string>()).second)
      throw std::invalid_argument(file + ": key \"" + v.get<std::string>() + "\" appears twice in one object");
    return true;
  });
}

// The typed fields of one shard's JSON object: a missing key, a value of another type, a negative
// or fractional count are errors naming the file and the field.
struct Fields {
  const json& j;
  const std::string& file;
  [[noreturn]] void bad(const std::string& k, const std::string& why) const {
    throw std::invalid_argument(file + ": \"" + k + "\": " + why);
  }
  const json& need(const std::string& k) const {
    if (!j.contains(k)) throw std::invalid_argument(file + ": no \"" + k + "\"");
    return j.at(k);
  }
  uint64_t count(const std::string& k) const {
    const auto& v = need(k);
    if (!v.is_number_unsigned()) bad(k, "expected a non-negative integer, not " + v.dump());
    return v.get<uint64_t>();
  }
  double number(const std::string& k) const {  // null: the writer's non-finite value
    const auto& v = need(k);
    if (!v.is_number() && !v.is_null()) bad(k, "expected a number, not " + v.dump());
    return v.is_null() ? INFINITY : v.get<double>();
  }
  bool flag(const std::string& k) const {
    const auto& v = need(k);
    if (!v.is_boolean()) bad(k, "expected true or false, not " + v.dump());
    return v.get<bool>();
  }
  std::string text(const std::string& k) const {
    const auto& v = need(k);
    if (!v.is_string()) bad(k, "expected a string, not " + v.dump());
    return v.get<std::string>();
  }
  Shard shard(const std::string& k) const {
    const std::string t = text(k);
    try {
      return Shard::parse(t);
    } catch (const std::invalid_argument& e) {
      bad(k, e.what());
    }
  }
};

// A `cosim --json` object, read back (the keys Report::json writes).
cosim::Report cosim_report(const json& j, const std::string& file) {
  if (!j.is_object()) throw std::invalid_argument(file + ": not a JSON object");
  const Fields f{j, file};
  cosim::Report r;
  r.block = f.text("block");
  r.vectors = f.count("vectors");
  r.outputs = f.count("outputs");
  r.mismatches = f.count("mismatches");
  r.model_mismatches = f.count("model_mismatches");
  r.extra_outputs = f.count("extra_outputs");
  r.in_order = f.flag("in_order");
  r.hung = f.flag("hung");
  r.max_abs_err = f.number("max_abs_err");
  r.max_ulp_err = f.number("max_ulp_err");
  r.rms_err = f.number("rms_err");
  r.err_points = f.count("err_points");
  r.err_sum_sq = f.number("err_sum_sq");
  r.flagged = f.count("flagged");
  r.latency_cycles = f.count("latency_cycles");
  r.ii_cycles = f.number("ii_cycles");
  r.sim_cycles = f.count("sim_cycles");
  r.stall_prob = f.number("stall_prob");
  r.wall_s = f.number("wall_s");
  if (!j.contains("shard")) throw std::invalid_argument(file + ": not a shard (run `texunit cosim --shard K/N --json`)");
  r.shard = f.shard("shard").str();
  r.set = f.text("set");
  r.seed = f.count("seed");
  r.first_vector = f.count("first_vector");
  r.rtl = f.text("rtl");
  if (j.contains("file_hash")) r.file_hash = f.text("file_hash"), r.file_vectors = f.count("file_vectors");
  // The keys Report::json writes for a shard: any other number is the error metric.
  static const auto known = [] {
    cosim::Report id;
    id.shard = "0/1", id.file_hash = "0";
    std::set<std::string> k;
    const auto j0 = json::parse(id.json());  // named: items() does not extend its life
    for (const auto& [key, v] : j0.items()) k.insert(key);
    return k;
  }();
  for (const auto& [k, v] : j.items())
    if (!known.count(k) && v.is_number()) r.err_metric = k;  // the block's name for max_abs_err
  if (j.contains("first_mismatch")) r.first_mismatch = f.text("first_mismatch");
  return r;
}

int merge_cosim(const std::vector<json>& docs, const MergeArgs& a) {
  std::map<uint64_t, cosim::Report> by_k;
  std::map<uint64_t, std::string> file_of;
  uint64_t n = 0;
  for (size_t i = 0; i < docs.size(); ++i) {
    const auto& f = a.files[i];
    auto r = cosim_report(docs[i], f);
    const Shard s = Shard::parse(r.shard);
    if (n && s.n != n) throw std::invalid_argument(f + ": shard " + r.shard + " of another split (N = " + std::to_string(n) + ")");
    n = s.n;
    if (!by_k.emplace(s.k, r).second) throw std::invalid_argument(f + ": shard " + r.shard + " given twice");
    file_of[s.k] = f;
  }
  std::string missing;
  for (uint64_t k = 0; k < n; ++k)
    if (!by_k.count(k)) missing += (missing.empty() ? "" : ", ") + std::to_string(k);
  if (!missing.empty()) throw std::invalid_argument("merge: shards " + missing + " of " + std::to_string(n) + " are missing");
  cosim::Report m = by_k.at(0);  // block, latency, II, stall probability, error metric name
  // Every shard of one run: the same vector set (block, set, seed; the same file's content when
  // cosim cut it), RTL and stalls, and rows that tile the set in K order from row 0.
  uint64_t next = 0;
  for (const auto& [k, r] : by_k) {
    const std::string& f = file_of.at(k);
    const auto differs = [&](const std::string& what, const std::string& x, const std::string& x0) {
      if (x != x0)
        throw std::invalid_argument(f + ": shard " + r.shard + " is of another run: " + what + " " + x + ", shard 0 (" +
                                    file_of.at(0) + ") has " + x0);
    };
    differs("block", r.block, m.block);
    differs("set", r.set, m.set);
    differs("seed", std::to_string(r.seed), std::to_string(m.seed));
    differs("rtl", "'" + r.rtl + "'", "'" + m.rtl + "'");
    differs("stall_prob", json(r.stall_prob).dump(), json(m.stall_prob).dump());
    differs("file_hash", "'" + r.file_hash + "'", "'" + m.file_hash + "'");
    differs("file_vectors", std::to_string(r.file_vectors), std::to_string(m.file_vectors));
    if (r.first_vector != next)
      throw std::invalid_argument(f + ": shard " + r.shard + " starts at vector " + std::to_string(r.first_vector) +
                                  ", the shards before it end at " + std::to_string(next) + " (a gap or an overlap)");
    next += r.vectors;
  }
  if (!m.file_hash.empty() && next != m.file_vectors)
    throw std::invalid_argument("merge: the shards hold " + std::to_string(next) + " vectors, the file " +
                                std::to_string(m.file_vectors));
  m.shard.clear();
  for (const auto& [k, r] : by_k) {
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
  // Element 0 of each file: the shard's identity (report::shard_identity); the rest are rows.
  std::vector<std::vector<report::Row>> shards;
  std::map<uint64_t, std::string> file_of;
  json id0;
  uint64_t n = 0;
  for (size_t i = 0; i < docs.size(); ++i) {
    const auto& f = a.files[i];
    if (docs[i].empty() || !docs[i][0].is_object() || !docs[i][0].contains("report_shard"))
      throw std::invalid_argument(f + ": not a report shard (run `texunit report --shard K/N --json`)");
    json id = docs[i][0];
    const Shard s = Fields{id, f}.shard("report_shard");
    id.erase("report_shard");
    if (i == 0) id0 = id, n = s.n;
    if (s.n != n) throw std::invalid_argument(f + ": shard " + s.str() + " of another split (N = " + std::to_string(n) + ")");
    if (id != id0)
      throw std::invalid_argument(f + ": shard " + s.str() + " is of another run: " + id.dump() + ", " + a.files[0] +
                                  " has " + id0.dump());
    if (!file_of.emplace(s.k, f).second) throw std::invalid_argument(f + ": shard " + s.str() + " given twice");
    std::vector<report::Row> rows;
    for (size_t e = 1; e < docs[i].size(); ++e) {
      try {
        rows.push_back(report::Row::from_json(docs[i][e].dump()));
      } catch (const std::exception& ex) {
        throw std::invalid_argument(f + ": row " + std::to_string(e) + ": " + ex.what());
      }
    }
    shards.push_back(std::move(rows));
  }
  std::string missing;
  for (uint64_t k = 0; k < n; ++k)
    if (!file_of.count(k)) missing += (missing.empty() ? "" : ", ") + std::to_string(k);
  if (!missing.empty()) throw std::invalid_argument("merge: report shards " + missing + " of " + std::to_string(n) + " are missing");
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
      docs.push_back(parse_unique_keys(slurp(f), f));
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
