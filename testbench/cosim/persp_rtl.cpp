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

RtlBlock rtl_persp() { return make_rtl<Vtu_persp>("persp", glue::drive_persp<Vtu_persp>, glue::sample_persp<Vtu_persp>); }
RtlBlock rtl_persp_direct() {
  return make_rtl<Vtu_persp_direct>("persp", glue::drive_persp<Vtu_persp_direct>, glue::sample_persp<Vtu_persp_direct>);
}

// k-lane unit (K = 4): one transaction = 4 pixels; outputs per lane j: u_j, v_j, flag_j.
RtlBlock rtl_persp_k4() {
  // Outputs are per-lane port arrays (u_o[j], v_o[j], flag_o bit j), the file's out-fields lane by lane.
  auto sample = [](Vtu_persp_klane& d) {
    Row r;
    for (int j = 0; j < 4; ++j) {
      r.push_back(d.u_o[j]);
      r.push_back(d.v_o[j]);
      r.push_back((d.flag_o >> j) & 1u);
    }
    return r;
  };
  return make_rtl<Vtu_persp_klane>("persp_k4", glue::drive_persp_k4<Vtu_persp_klane>, sample);
}

// Per-scanline set-up (rtl/persp/tu_persp_setup.sv): one transaction = one span.
RtlBlock rtl_persp_setup() {
  return make_rtl<Vtu_persp_setup>("persp_setup", glue::drive_persp_setup<Vtu_persp_setup>,
                                   glue::sample_persp_setup<Vtu_persp_setup>);
}

// Texel-depth per-pixel datapath: one transaction = one pixel with its span record.
RtlBlock rtl_texel_depth() {
  return make_rtl<Vtu_texel_depth>("texel_depth", glue::drive_texel_depth<Vtu_texel_depth>,
                                   glue::sample_texel_depth<Vtu_texel_depth>);
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
  b.name = b.block = "persp_texel_depth";
  b.run = [=](const std::vector<Row>& in, const RunOptions& o) { return td.run(records(in), o); };
  b.timing = [=](const std::vector<Row>& in) { return td.timing(records(in)); };
  return b;
}

}  // namespace tu::cosim
