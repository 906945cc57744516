// report::Row's JSON form (report_row.hpp); moved from tools/texunit/report.cpp.
#include "planner/report_row.hpp"

#include <charconv>
#include <cmath>
#include <set>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace tu::report {

namespace {
using json = nlohmann::json;
std::string jstr(const std::string& s) { return json(s).dump(); }
// A measured count, or the reason it is missing.
std::string jint(int64_t x, const std::string& why) { return x < 0 ? jstr(why) : std::to_string(x); }

// A measured value (>= 0), or the reason it is missing.
std::string jmeasured(double x, const std::string& why) { return x < 0 ? jstr(why) : jnum(x); }
}  // namespace

std::string jnum(double x) {
  if (!std::isfinite(x)) return "null";
  char buf[32];
  const auto res = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, res.ptr);
}

std::string Row::json() const {
  return "{\"block\": " + jstr(block) + ", \"variant\": " + jstr(variant) + ", \"scheme\": " +
         jstr(scheme) + ", \"err_unit\": " + jstr(err_unit) + ", \"max_abs_err\": " + jnum(max_abs_err) +
         ", \"rms_err\": " + jnum(rms_err) + ", \"max_ulp_err\": " + jnum(max_ulp_err) +
         ", \"latency_cycles\": " + jint(latency_cycles, "n/a") + ", \"ii_cycles\": " + jnum(ii_cycles) +
         ", \"cycles_source\": " + jstr(cycles_source) + ", \"cells\": " + jint(cells, area_source) +
         ", \"flip_flops\": " + jint(flip_flops, area_source) + ", \"multipliers\": " +
         jint(multipliers, area_source) + ", \"area_source\": " + jstr(area_source) + ", \"rtl_top\": " +
         jstr(rtl_top) + ", \"memory_bits\": " + jint(memory_bits, "n/a") + ", \"cmodel_ns_per_item\": " +
         jnum(cmodel_ns_per_item) + ", \"rtl_sim_items_per_s\": " +
         (rtl_sim_items_per_s < 0 ? jstr(rtl_sim_source) : jnum(rtl_sim_items_per_s)) +
         ", \"rtl_sim_source\": " + jstr(rtl_sim_source) + ", \"area_um2\": " + jmeasured(area_um2, stdcell_source) +
         ", \"period_ns\": " + jmeasured(period_ns, stdcell_source) + ", \"fmax_mhz\": " +
         jmeasured(fmax_mhz, stdcell_source) + ", \"latency_ns\": " + jmeasured(latency_ns(), stdcell_source) +
         ", \"ns_per_item\": " + jmeasured(ns_per_item(), stdcell_source) + ", \"stdcell_cells\": " +
         jint(stdcell_cells, stdcell_source) + ", \"critical_path\": " + jstr(critical_path) +
         ", \"stdcell_source\": " + jstr(stdcell_source) + ", \"notes\": " + jstr(notes) + (extra_json.empty() ? "" : ", " + extra_json) + "}";
}

Row Row::from_json(const std::string& text) {
  const auto j = nlohmann::ordered_json::parse(text);  // ordered: extra keys keep their order
  const auto need = [&](const char* k) -> const nlohmann::ordered_json& {
    if (!j.contains(k)) throw std::invalid_argument(std::string("report row without \"") + k + "\"");
    return j.at(k);
  };
  // Each key as json() writes it; any other type names the key (nlohmann's own message does not).
  const auto bad = [&](const char* k, const char* want) {
    throw std::invalid_argument(std::string("\"") + k + "\": expected " + want + ", not " + j.at(k).dump());
  };
  const auto num = [&](const char* k) {  // jnum: a number, null when not finite
    const auto& v = need(k);
    if (!v.is_number() && !v.is_null()) bad(k, "a number");
    return v.is_null() ? INFINITY : v.get<double>();
  };
  // jmeasured: a number >= 0, or the string naming why it was not measured (-1).
  const auto measured = [&](const char* k) {
    const auto& v = need(k);
    if (v.is_string()) return -1.0;
    if (!v.is_null() && !(v.is_number() && v.get<double>() >= 0)) bad(k, "a number >= 0 or the reason it is missing");
    return v.is_null() ? INFINITY : v.get<double>();
  };
  const auto cnt = [&](const char* k) {  // jint: an integer >= 0, or the reason it is missing (-1)
    const auto& v = need(k);
    if (v.is_string()) return int64_t{-1};
    if (!v.is_number_unsigned() || v.get<uint64_t>() > uint64_t(INT64_MAX)) bad(k, "an integer >= 0 or the reason it is missing");
    return v.get<int64_t>();
  };
  const auto str = [&](const char* k) {
    if (!need(k).is_string()) bad(k, "a string");
    return j.at(k).get<std::string>();
  };
  Row r;
  r.block = str("block"), r.variant = str("variant"), r.scheme = str("scheme"), r.err_unit = str("err_unit");
  r.max_abs_err = num("max_abs_err"), r.rms_err = num("rms_err"), r.max_ulp_err = num("max_ulp_err");
  r.latency_cycles = cnt("latency_cycles"), r.ii_cycles = num("ii_cycles"), r.cycles_source = str("cycles_source");
  r.cells = cnt("cells"), r.flip_flops = cnt("flip_flops"), r.multipliers = cnt("multipliers");
  r.area_source = str("area_source"), r.rtl_top = str("rtl_top"), r.memory_bits = cnt("memory_bits");
  r.cmodel_ns_per_item = num("cmodel_ns_per_item"), r.rtl_sim_items_per_s = measured("rtl_sim_items_per_s");
  r.rtl_sim_source = str("rtl_sim_source");
  r.area_um2 = measured("area_um2"), r.period_ns = measured("period_ns"), r.fmax_mhz = measured("fmax_mhz");
  r.stdcell_cells = cnt("stdcell_cells"), r.critical_path = str("critical_path"), r.stdcell_source = str("stdcell_source");
  r.notes = str("notes");
  // The keys json() always writes (a default row has no extra keys): the rest are the extras.
  static const auto known = [] {
    std::set<std::string> k;
    const auto j0 = nlohmann::json::parse(Row{}.json());  // named: items() does not extend its life
    for (const auto& [key, v] : j0.items()) k.insert(key);
    return k;
  }();
  for (const auto& [k, v] : j.items()) {
    if (known.count(k)) continue;
    const std::string val = v.is_number_float() ? jnum(v.get<double>()) : v.is_null() ? "null" : v.dump();
    r.extra_json += (r.extra_json.empty() ? "" : ", ") + jstr(k) + ": " + val;
  }
  return r;
}

}  // namespace tu::report
