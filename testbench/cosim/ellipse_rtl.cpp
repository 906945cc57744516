// RTL binding of the pixel-footprint unit rtl/ellipse/tu_ellipse.sv (block "ellipse").
#include "Vtu_ellipse.h"
#include "cosim.hpp"

namespace tu::cosim {

RtlBlock rtl_ellipse() {
  auto drive = [](Vtu_ellipse& d, const Row& in) {
    d.nux_i = in[0];
    d.nvx_i = in[1];
    d.nuy_i = in[2];
    d.nvy_i = in[3];
    d.q_i = in[4];
    d.dm_i = in[5];
    d.dexp_i = static_cast<uint8_t>(in[6]);
    d.laniso_i = static_cast<uint16_t>(in[7]);
    d.maxlod_i = static_cast<uint8_t>(in[8]);
  };
  auto sample = [](Vtu_ellipse& d) {
    return Row{d.ae_o, d.be_o, d.ce_o, d.eexp_o, d.fm_o, d.fexp_o, d.lmaj_o, d.lmin_o, d.lod_o, d.flags_o, d.lrho_o};
  };
  RtlBlock b;
  b.name = "ellipse";
  b.run = [=](const std::vector<Row>& in, const RunOptions& o) {
    return Harness<Vtu_ellipse>(drive, sample).run(in, o);
  };
  b.timing = [=](const std::vector<Row>& in) { return Harness<Vtu_ellipse>(drive, sample).measure_timing(in); };
  return b;
}

}  // namespace tu::cosim
