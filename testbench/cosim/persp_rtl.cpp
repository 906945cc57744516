// RTL bindings of the perspective divide unit: rtl/persp/tu_persp.sv (incremental accumulators,
// block "persp") and rtl/persp/tu_persp_direct.sv (direct evaluation, same ports and vectors);
// the per-scanline set-up rtl/persp/tu_persp_setup.sv (block "persp_setup"); the texel-depth
// per-pixel datapath rtl/persp/tu_texel_depth.sv (block "texel_depth").
#include "Vtu_persp.h"
#include "Vtu_persp_direct.h"
#include "Vtu_persp_klane.h"
#include "Vtu_persp_setup.h"
#include "Vtu_texel_depth.h"
#include "cosim.hpp"
#include "persp_block.hpp"

namespace tu::cosim {

namespace {
template <class V>
RtlBlock bind(const std::string& name) {
  auto drive = [](V& d, const Row& in) {
    d.pu0_i = in[0];
    d.pv0_i = in[1];
    d.q0_i = in[2];
    d.a_i = in[3];
    d.d_i = in[4];
    d.g_i = in[5];
    d.n_i = static_cast<uint16_t>(in[6]);
  };
  auto sample = [](V& d) { return Row{d.u_o, d.v_o, d.flag_o}; };
  RtlBlock b;
  b.name = name;
  b.run = [=](const std::vector<Row>& in, const RunOptions& o) {
    return Harness<V>(drive, sample).run(in, o);
  };
  b.timing = [=](const std::vector<Row>& in) {
    return Harness<V>(drive, sample).measure_timing(in);
  };
  return b;
}
}  // namespace

RtlBlock rtl_persp() { return bind<Vtu_persp>("persp"); }
RtlBlock rtl_persp_direct() { return bind<Vtu_persp_direct>("persp"); }

// k-lane unit (K = 4): one transaction = 4 pixels; outputs per lane j: u_j, v_j, flag_j.
RtlBlock rtl_persp_k4() {
  auto drive = [](Vtu_persp_klane& d, const Row& in) {
    d.pu0_i = in[0];
    d.pv0_i = in[1];
    d.q0_i = in[2];
    d.a_i = in[3];
    d.d_i = in[4];
    d.g_i = in[5];
    d.n_i = static_cast<uint16_t>(in[6]);
  };
  auto sample = [](Vtu_persp_klane& d) {
    Row r;
    for (int j = 0; j < 4; ++j) {
      r.push_back(d.u_o[j]);
      r.push_back(d.v_o[j]);
      r.push_back((d.flag_o >> j) & 1u);
    }
    return r;
  };
  RtlBlock b;
  b.name = "persp_k4";
  b.run = [=](const std::vector<Row>& in, const RunOptions& o) {
    return Harness<Vtu_persp_klane>(drive, sample).run(in, o);
  };
  b.timing = [=](const std::vector<Row>& in) {
    return Harness<Vtu_persp_klane>(drive, sample).measure_timing(in);
  };
  return b;
}

// Per-scanline set-up (rtl/persp/tu_persp_setup.sv): one transaction = one span.
RtlBlock rtl_persp_setup() {
  auto drive = [](Vtu_persp_setup& d, const Row& in) {
    d.a_i = in[0];
    d.b_i = in[1];
    d.c_i = in[2];
    d.d_i = in[3];
    d.e_i = in[4];
    d.f_i = in[5];
    d.g_i = in[6];
    d.h_i = in[7];
    d.i_i = in[8];
    d.x0_i = static_cast<uint16_t>(in[9]);
    d.x1_i = static_cast<uint16_t>(in[10]);
    d.y_i = static_cast<uint16_t>(in[11]);
  };
  auto sample = [](Vtu_persp_setup& d) { return Row{d.pu_o, d.pv_o, d.q_o, d.ovf_o}; };
  RtlBlock b;
  b.name = "persp_setup";
  b.run = [=](const std::vector<Row>& in, const RunOptions& o) {
    return Harness<Vtu_persp_setup>(drive, sample).run(in, o);
  };
  b.timing = [=](const std::vector<Row>& in) {
    return Harness<Vtu_persp_setup>(drive, sample).measure_timing(in);
  };
  return b;
}

// Texel-depth per-pixel datapath: one transaction = one pixel with its span record.
RtlBlock rtl_texel_depth() {
  auto drive = [](Vtu_texel_depth& d, const Row& in) {
    d.q1_i = in[0];
    d.q2_i = in[1];
    d.t1u_i = static_cast<uint32_t>(in[2]);
    d.t1v_i = static_cast<uint32_t>(in[3]);
    d.t2u_i = static_cast<uint32_t>(in[4]);
    d.t2v_i = static_cast<uint32_t>(in[5]);
    d.m2_i = static_cast<uint16_t>(in[6]);
    d.m_i = static_cast<uint16_t>(in[7]);
  };
  auto sample = [](Vtu_texel_depth& d) { return Row{d.u_o, d.v_o, d.flag_o}; };
  return make_rtl<Vtu_texel_depth>("texel_depth", drive, sample);
}

// The same RTL on persp_texel_depth rows (B1's seeds): each row becomes its span record first
// (blocks::texel_depth_record_row, the C model of the two end evaluations), so the report row
// persp/texel_depth carries the error against the exact map and the RTL's cycles.
RtlBlock rtl_persp_texel_depth() {
  const RtlBlock td = rtl_texel_depth();
  auto records = [](const std::vector<Row>& in) {
    std::vector<Row> r;
    r.reserve(in.size());
    for (const Row& x : in) r.push_back(blocks::texel_depth_record_row(x));
    return r;
  };
  RtlBlock b;
  b.name = "persp_texel_depth";
  b.run = [=](const std::vector<Row>& in, const RunOptions& o) { return td.run(records(in), o); };
  b.timing = [=](const std::vector<Row>& in) { return td.timing(records(in)); };
  return b;
}

}  // namespace tu::cosim
