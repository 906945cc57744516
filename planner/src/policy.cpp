// The plan's pure policy (policy.hpp).
#include "planner/policy.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <nlohmann/json.hpp>

namespace tu::plan {

using json = nlohmann::json;

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[static_cast<size_t>(q * static_cast<double>(v.size() - 1))];
}

int filter_rank(scene::Filter f) {
  switch (f) {
    case scene::Filter::Bilinear: return 0;
    case scene::Filter::Trilinear: return 1;
    case scene::Filter::Feline: return 2;
    case scene::Filter::Ewa: return 3;
    case scene::Filter::Nearest: break;
  }
  return -1;
}

scene::Filter unit_filter(const std::map<std::string, scene::Filter>& per_material) {
  scene::Filter best = scene::Filter::Bilinear;
  for (const auto& [name, f] : per_material)
    if (filter_rank(f) > filter_rank(best)) best = f;
  return best;
}

std::string fmt(const char* f, double x) {
  char b[64];
  std::snprintf(b, sizeof b, f, x);
  return b;
}

MaterialFilter choose_filter(const std::string& material, double ql, double qa, double min_psnr_db,
                             const std::function<double()>& bilinear_psnr, const std::function<double()>& trilinear_psnr,
                             const std::function<FelineProbe()>& feline) {
  MaterialFilter m;
  m.why = material + ": ";
  bool chosen = false;
  if (bilinear_gate(ql, qa)) {
    const double p = bilinear_psnr();
    m.why += "bilinear: footprint gate passes, PSNR " + fmt("%.2f", p) + " dB";
    if (p >= min_psnr_db) m.filter = scene::Filter::Bilinear, chosen = true;
    else m.why += "; ";
  } else {
    m.why += "bilinear: footprint gate fails (p99 LOD " + fmt("%.2f", ql) + ", p99 anisotropy " + fmt("%.2f", qa) + "); ";
  }
  if (!chosen) {
    if (trilinear_gate(qa)) {
      const double p = trilinear_psnr();
      m.why += "trilinear: footprint gate passes, PSNR " + fmt("%.2f", p) + " dB";
      if (p >= min_psnr_db) m.filter = scene::Filter::Trilinear, chosen = true;
    } else {
      m.why += "trilinear: footprint gate fails (p99 anisotropy " + fmt("%.2f", qa) + ")";
    }
  }
  if (!chosen) {
    const FelineProbe fc = feline();
    m.why += "; " + fc.why;
    if (fc.cap > 0) m.filter = scene::Filter::Feline, m.feline_cap = fc.cap;
  }
  return m;
}

std::vector<TRow> parse_table(const std::string& text, const std::string& path) {
  json j;
  try {
    j = json::parse(text);
  } catch (const json::exception& e) {
    throw std::runtime_error(path + ": malformed JSON (" + e.what() + ")");
  }
  if (!j.is_array()) throw std::runtime_error(path + ": expected a JSON array of report rows");
  std::vector<TRow> rows;
  for (size_t i = 0; i < j.size(); ++i) {
    const auto& r = j[i];
    auto field = [&](const char* k) -> const json& {
      if (!r.is_object() || !r.contains(k))
        throw std::runtime_error(path + ": /" + std::to_string(i) + "/" + k + ": missing");
      return r.at(k);
    };
    auto num = [&](const char* k, bool optional) {
      const json& v = field(k);
      if (v.is_number()) return v.get<double>();
      if (optional && v.is_string()) return -1.0;  // "not measured: ..." or "n/a"
      throw std::runtime_error(path + ": /" + std::to_string(i) + "/" + k + ": expected a number");
    };
    auto str = [&](const char* k) {
      if (!field(k).is_string()) throw std::runtime_error(path + ": /" + std::to_string(i) + "/" + k + ": expected a string");
      return field(k).get<std::string>();
    };
    TRow t;
    t.block = str("block"), t.variant = str("variant"), t.scheme = str("scheme"), t.rtl_top = str("rtl_top");
    t.max_abs = num("max_abs_err", false), t.rms = num("rms_err", false), t.ii = num("ii_cycles", false);
    t.latency = static_cast<int64_t>(num("latency_cycles", true));
    t.cells = num("cells", true);
    t.mul = static_cast<int64_t>(num("multipliers", true));
    // A table written before the standard-cell columns existed: area not measured.
    if (r.contains("area_um2")) t.area_um2 = num("area_um2", true), t.fmax_mhz = num("fmax_mhz", true);
    rows.push_back(t);
  }
  return rows;
}

double cost(const TRow& r, bool by_area) {
  if (by_area) return r.area_um2;
  return r.cells >= 0 ? r.cells : 1e12 + static_cast<double>(r.mul);
}

const TRow* cheapest(const std::vector<const TRow*>& cands, const std::function<bool(const TRow&)>& ok,
                     const std::function<double(const TRow&)>& score, const std::string& field, const std::string& what,
                     const char* unit, std::string* cost_basis) {
  const TRow* best = nullptr;
  const TRow* closest = nullptr;
  const TRow* no_area = nullptr;
  for (const TRow* r : cands)
    if (ok(*r) && r->area_um2 < 0) no_area = r;
  if (no_area && cost_basis)
    *cost_basis = "Yosys cells (" + no_area->name() + " has no osu018 area: run scripts/stdcell.sh)";
  for (const TRow* r : cands) {
    if (!closest || score(*r) > score(*closest)) closest = r;
    if (ok(*r) && (!best || cost(*r, !no_area) < cost(*best, !no_area))) best = r;
  }
  if (!closest) throw std::runtime_error("report table has no " + what + " row with an RTL (run scripts/report.sh)");
  if (!best)
    throw BudgetError(field + ": no " + what + " variant reaches it (best: " + closest->name() + " at " +
                      fmt(unit, std::fabs(score(*closest))) + ")");
  return best;
}

double weight_db(const TRow& r) { return r.rms > 0 ? 20 * std::log10(1 / r.rms) : INFINITY; }

std::optional<scene::WeightSource> engine_source(const TRow& r) {
  if (r.block == "gauss_weight") return scene::WeightSource::Formula;
  if (r.scheme == "weight_table_1d") return scene::WeightSource::Table1d;
  if (r.scheme == "weight_table_2d") return scene::WeightSource::Table2d;
  return std::nullopt;
}

std::vector<const TRow*> Unit::all() const {
  std::vector<const TRow*> v = area_only;
  for (const auto& s : stages)
    for (const auto& a : s) v.insert(v.end(), a.begin(), a.end());
  return v;
}

int64_t Unit::latency() const {
  int64_t l = 0;
  for (const auto& s : stages) {
    int64_t m = 0;
    for (const auto& a : s) {
      int64_t sum = 0;
      for (const TRow* r : a) sum += r->latency;
      m = std::max(m, sum);
    }
    l += m;
  }
  return l;
}

double Unit::ii() const {
  double m = 1;
  for (const TRow* r : all()) m = std::max(m, r->ii);
  return m;
}

double Unit::cells() const {
  double c = 0;
  for (const TRow* r : all()) c += r->cells < 0 ? 0 : r->cells;
  return c;
}

double Unit::area_um2() const {
  double a = 0;
  for (const TRow* r : all()) a += r->area_um2 < 0 ? 0 : r->area_um2;
  return a;
}

bool Unit::area_measured() const {
  const auto v = all();
  return std::all_of(v.begin(), v.end(), [](const TRow* r) { return r->area_um2 >= 0; });
}

double Unit::fmax_mhz() const {
  double f = INFINITY;
  for (const TRow* r : all()) f = r->fmax_mhz < 0 ? f : std::min(f, r->fmax_mhz);
  return area_measured() ? f : -1;
}

bool Unit::cells_measured() const {
  return std::all_of(area_only.begin(), area_only.end(), [](const TRow* r) { return r->cells >= 0; }) &&
         std::all_of(stages.begin(), stages.end(), [](const auto& s) {
           return std::all_of(s.begin(), s.end(), [](const auto& a) {
             return std::all_of(a.begin(), a.end(), [](const TRow* r) { return r->cells >= 0; });
           });
         });
}

}  // namespace tu::plan
