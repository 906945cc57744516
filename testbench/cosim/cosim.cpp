#include "cosim.hpp"

#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace tu::cosim {

RtlBlock rtl_reciprocal();  // reciprocal_rtl.cpp
std::vector<RtlBlock> rtl_gauss();  // gauss_rtl.cpp
RtlBlock rtl_persp();       // persp_rtl.cpp
RtlBlock rtl_persp_k4();    // persp_rtl.cpp
RtlBlock rtl_persp_setup(); // persp_rtl.cpp
RtlBlock rtl_texel_depth(); // persp_rtl.cpp
RtlBlock rtl_pom_layers();  // pom_layers_rtl.cpp
RtlBlock rtl_pom_march();   // pom_march_rtl.cpp
RtlBlock rtl_iter_parallax();  // iter_parallax_rtl.cpp
std::vector<RtlBlock> rtl_pom_unit();  // pom_unit_rtl.cpp
RtlBlock rtl_ellipse();     // ellipse_rtl.cpp
RtlBlock rtl_ellipse_rec(); // ellipse_rtl.cpp
RtlBlock rtl_ewa();         // ewa_rtl.cpp
RtlBlock rtl_ewa_k4();      // ewa_rtl.cpp
RtlBlock rtl_ewa_border();  // ewa_border_rtl.cpp
RtlBlock rtl_feline();      // feline_rtl.cpp
RtlBlock rtl_afvis();       // afvis_rtl.cpp
RtlBlock rtl_objspace_sample();  // objspace_rtl.cpp
RtlBlock rtl_texel_addr();  // texel_addr_rtl.cpp
RtlBlock rtl_texel_decode();  // texel_decode_rtl.cpp
RtlBlock rtl_bc1_decode();  // bc1_decode_rtl.cpp
std::vector<RtlBlock> rtl_brdf();  // brdf_rtl.cpp
std::vector<RtlBlock> rtl_perlin();  // perlin_rtl.cpp (incl. the octave-serial variants)

const RtlBlock& find_rtl(const std::string& name) {
  static const std::vector<RtlBlock> rtl = {rtl_reciprocal(), rtl_persp(), rtl_persp_k4(), rtl_persp_setup(), rtl_texel_depth(), rtl_pom_layers(),
                                            rtl_pom_march(), rtl_iter_parallax(), rtl_ellipse(), rtl_ellipse_rec(), rtl_ewa(), rtl_ewa_k4(), rtl_feline(),
                                            rtl_ewa_border(), rtl_afvis(), rtl_objspace_sample(), rtl_texel_addr(),
                                            rtl_texel_decode(), rtl_bc1_decode()};
  for (const auto& r : rtl)
    if (r.name == name) return r;
  static const std::vector<RtlBlock> gauss = rtl_gauss();
  for (const auto& r : gauss)
    if (r.name == name) return r;
  static const std::vector<RtlBlock> pom_unit = rtl_pom_unit();
  for (const auto& r : pom_unit)
    if (r.name == name) return r;
  static const std::vector<RtlBlock> brdf = rtl_brdf();
  for (const auto& r : brdf)
    if (r.name == name) return r;
  static const std::vector<RtlBlock> perlin = rtl_perlin();
  for (const auto& r : perlin)
    if (r.name == name) return r;
  throw std::invalid_argument("block '" + name + "' has no RTL co-simulation model");
}

namespace {
std::string hex_row(const Row& r) {
  std::ostringstream os;
  for (size_t i = 0; i < r.size(); ++i) os << (i ? " " : "") << std::hex << r[i];
  return os.str();
}
std::string num(double x, int digits = 6) {
  if (!std::isfinite(x)) return "null";
  std::ostringstream os;
  os << std::setprecision(digits) << x;
  return os.str();
}
}  // namespace

std::string Report::json() const {
  std::ostringstream os;
  os << "{\"block\": \"" << block << "\", \"vectors\": " << vectors << ", \"outputs\": " << outputs
     << ", \"mismatches\": " << mismatches << ", \"model_mismatches\": " << model_mismatches
     << ", \"extra_outputs\": " << extra_outputs << ", \"in_order\": " << (in_order ? "true" : "false")
     << ", \"hung\": " << (hung ? "true" : "false") << ", \"max_abs_err\": " << num(max_abs_err)
     << ", \"max_ulp_err\": " << num(max_ulp_err) << ", \"rms_err\": " << num(rms_err)
     << ", \"err_points\": " << err_points << ", \"err_sum_sq\": " << num(err_sum_sq, 17)
     << ", \"flagged\": " << flagged << ", \"latency_cycles\": " << latency_cycles
     << ", \"ii_cycles\": " << num(ii_cycles) << ", \"sim_cycles\": " << sim_cycles
     << ", \"stall_prob\": " << num(stall_prob) << ", \"wall_s\": " << num(wall_s)
     << (err_metric.empty() ? "" : ", \"" + err_metric + "\": " + num(max_abs_err));
  if (!shard.empty()) {
    os << ", \"shard\": \"" << shard << "\", \"set\": \"" << set << "\", \"seed\": " << seed
       << ", \"first_vector\": " << first_vector << ", \"rtl\": \"" << rtl << "\"";
    if (!file_hash.empty()) os << ", \"file_vectors\": " << file_vectors << ", \"file_hash\": \"" << file_hash << "\"";
  }
  os << ", \"ok\": " << (ok() ? "true" : "false") << "}";
  return os.str();
}

Report run(const vec::VectorFile& vf, const Options& opt) {
  const auto& block = blocks::find(vf.block);
  const auto& rtl = find_rtl(opt.rtl.empty() ? vf.block : opt.rtl);
  if (rtl.block != vf.block)  // another block's ports: its outputs would only "mismatch"
    throw std::invalid_argument("RTL '" + rtl.name + "' runs block '" + rtl.block + "' vectors, not block '" +
                                vf.block + "' (--rtl)");
  if (vf.fields.size() != block.fields.size())
    throw std::invalid_argument("vector file fields do not match block '" + block.name + "'");
  for (size_t i = 0; i < vf.fields.size(); ++i) {
    const auto& a = vf.fields[i];
    const auto& b = block.fields[i];
    if (a.name != b.name || a.role != b.role || a.fmt.str() != b.fmt.str())
      throw std::invalid_argument("vector file field '" + a.name + ":" + a.fmt.str() +
                                  "' does not match block field '" + b.name + ":" +
                                  b.fmt.str() + "'");
  }
  const auto in_idx = vf.indices(vec::Role::In);
  const auto out_idx = vf.indices(vec::Role::Out);
  const auto ref_idx = vf.indices(vec::Role::Ref);
  std::vector<Row> inputs;
  inputs.reserve(vf.rows.size());
  for (const auto& r : vf.rows) inputs.push_back(blocks::pick(r, in_idx));
  // A non-finite reference value must be the block's own (a reciprocal of 0 is +inf, an undefined
  // LOD NaN): any other is a corrupt file, and would drop out of the error statistics unseen.
  for (size_t i = 0; i < vf.rows.size(); ++i)
    for (size_t k = 0; k < ref_idx.size(); ++k) {
      const double x = vec::bits_f64(vf.rows[i][static_cast<size_t>(ref_idx[k])]);
      if (std::isfinite(x)) continue;
      const double want = vec::bits_f64(block.ref(inputs[i]).at(k));
      if (std::isnan(x) ? std::isnan(want) : x == want) continue;
      std::ostringstream os;
      os << "vector " << i + opt.first_vector << ": ref field '" << vf.fields[static_cast<size_t>(ref_idx[k])].name
         << "' is " << x << ", the block's float reference gives " << want;
      throw std::invalid_argument(os.str());
    }

  Report rep;
  rep.block = vf.block;
  rep.err_metric = block.err_metric;
  rep.vectors = vf.rows.size();
  rep.stall_prob = opt.run.stall_prob;
  const auto t_start = std::chrono::steady_clock::now();

  if (!inputs.empty()) {
    const std::vector<Row> prefix(inputs.begin(),
                                  inputs.begin() + static_cast<long>(std::min(inputs.size(),
                                                                              opt.timing_vectors)));
    const auto [lat, ii] = rtl.timing(prefix);
    rep.latency_cycles = lat;
    rep.ii_cycles = ii;
  }
  const RunResult rr = rtl.run(inputs, opt.run);
  rep.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  rep.outputs = rr.outputs.size();
  rep.extra_outputs = rr.extra_outputs;
  rep.hung = rr.hung;
  rep.sim_cycles = rr.sim_cycles;
  double sum_sq = 0;
  uint64_t n_err = 0;
  for (size_t i = 0; i < rr.outputs.size() && i < vf.rows.size(); ++i) {
    const Row expected = blocks::pick(vf.rows[i], out_idx);
    const Row model = block.model(inputs[i]);
    if (model != expected) {
      ++rep.model_mismatches;
      if (rep.first_mismatch.empty())
        rep.first_mismatch = "vector " + std::to_string(i + opt.first_vector) + ": C model gives " + hex_row(model) +
                             ", file expects " + hex_row(expected);
    }
    if (rr.outputs[i] != expected) {
      ++rep.mismatches;
      if (rep.first_mismatch.empty())
        rep.first_mismatch = "vector " + std::to_string(i + opt.first_vector) + " (in " + hex_row(inputs[i]) +
                             "): RTL gives " + hex_row(rr.outputs[i]) + ", expected " +
                             hex_row(expected);
    }
    const auto e = block.error(inputs[i], rr.outputs[i], blocks::pick(vf.rows[i], ref_idx));
    if (!e.valid) {
      ++rep.flagged;
      continue;
    }
    rep.max_abs_err = std::max(rep.max_abs_err, e.abs);
    rep.max_ulp_err = std::max(rep.max_ulp_err, e.ulp);
    sum_sq += e.abs * e.abs;
    ++n_err;
  }
  rep.in_order = rep.mismatches == 0;
  rep.rms_err = n_err ? std::sqrt(sum_sq / static_cast<double>(n_err)) : 0;
  rep.err_points = n_err;
  rep.err_sum_sq = sum_sq;
  return rep;
}

}  // namespace tu::cosim
