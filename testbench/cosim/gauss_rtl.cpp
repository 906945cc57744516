// RTL bindings of the Gaussian pixel-model blocks (rtl/gauss/).
#include "Vtu_clip_estrin.h"
#include "Vtu_clip_horner.h"
#include "Vtu_clip_p1.h"
#include "Vtu_clip_seq.h"
#include "Vtu_gauss_weight.h"
#include "Vtu_weight_table_1d.h"
#include "Vtu_weight_table_2d.h"
#include "cosim.hpp"

namespace tu::cosim {

namespace {
template <class V>
RtlBlock clip_binding(const std::string& name) {
  auto drive = [](V& d, const Row& in) { d.d_i = static_cast<uint16_t>(in[0]); };
  auto sample = [](V& d) { return Row{d.v_o}; };
  RtlBlock b;
  b.name = name;
  b.run = [=](const std::vector<Row>& in, const RunOptions& o) {
    return Harness<V>(drive, sample).run(in, o);
  };
  b.timing = [=](const std::vector<Row>& in) { return Harness<V>(drive, sample).measure_timing(in); };
  return b;
}
}  // namespace

std::vector<RtlBlock> rtl_gauss() {
  std::vector<RtlBlock> v = {clip_binding<Vtu_clip_p1>("clip_p1"),
                             clip_binding<Vtu_clip_horner>("clip_horner"),
                             clip_binding<Vtu_clip_estrin>("clip_estrin"),
                             clip_binding<Vtu_clip_seq>("clip_seq")};
  auto drive = [](Vtu_gauss_weight& d, const Row& in) { d.q_i = static_cast<uint16_t>(in[0]); };
  auto sample = [](Vtu_gauss_weight& d) { return Row{d.w_o}; };
  RtlBlock w;
  w.name = "gauss_weight";
  w.run = [=](const std::vector<Row>& in, const RunOptions& o) {
    return Harness<Vtu_gauss_weight>(drive, sample).run(in, o);
  };
  w.timing = [=](const std::vector<Row>& in) {
    return Harness<Vtu_gauss_weight>(drive, sample).measure_timing(in);
  };
  v.push_back(w);
  auto tdrive = [](Vtu_weight_table_1d& d, const Row& in) { d.q_i = static_cast<uint16_t>(in[0]); };
  auto tsample = [](Vtu_weight_table_1d& d) { return Row{d.w_o}; };
  RtlBlock t;
  t.name = "weight_table_1d";
  t.run = [=](const std::vector<Row>& in, const RunOptions& o) {
    return Harness<Vtu_weight_table_1d>(tdrive, tsample).run(in, o);
  };
  t.timing = [=](const std::vector<Row>& in) {
    return Harness<Vtu_weight_table_1d>(tdrive, tsample).measure_timing(in);
  };
  v.push_back(t);
  auto t2drive = [](Vtu_weight_table_2d& d, const Row& in) {
    d.xi_i = static_cast<uint16_t>(in[0]);
    d.eta_i = static_cast<uint16_t>(in[1]);
  };
  auto t2sample = [](Vtu_weight_table_2d& d) { return Row{d.w_o}; };
  RtlBlock t2;
  t2.name = "weight_table_2d";
  t2.run = [=](const std::vector<Row>& in, const RunOptions& o) {
    return Harness<Vtu_weight_table_2d>(t2drive, t2sample).run(in, o);
  };
  t2.timing = [=](const std::vector<Row>& in) {
    return Harness<Vtu_weight_table_2d>(t2drive, t2sample).measure_timing(in);
  };
  v.push_back(t2);
  return v;
}

}  // namespace tu::cosim
