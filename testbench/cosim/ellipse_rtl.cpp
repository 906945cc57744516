// RTL bindings of the pixel-footprint units rtl/ellipse/tu_ellipse.sv (block "ellipse", analytic)
// and rtl/ellipse/tu_ellipse_rec.sv (block "ellipse_rec", the seed's recurrences).
#include "Vtu_ellipse.h"
#include "Vtu_ellipse_rec.h"
#include "cosim.hpp"

namespace tu::cosim {

namespace {
template <class V>
Row sample(V& d) {
  return Row{d.ae_o, d.be_o, d.ce_o, d.eexp_o, d.fm_o, d.fexp_o, d.lmaj_o, d.lmin_o, d.lod_o, d.flags_o, d.lrho_o};
}
template <class V, class Drive>
RtlBlock bind(const char* name, Drive drive) {
  RtlBlock b;
  b.name = name;
  b.run = [=](const std::vector<Row>& in, const RunOptions& o) {
    return Harness<V>(drive, sample<V>).run(in, o);
  };
  b.timing = [=](const std::vector<Row>& in) { return Harness<V>(drive, sample<V>).measure_timing(in); };
  return b;
}
}  // namespace

RtlBlock rtl_ellipse() {
  return bind<Vtu_ellipse>("ellipse", [](Vtu_ellipse& d, const Row& in) {
    d.nux_i = in[0];
    d.nvx_i = in[1];
    d.nuy_i = in[2];
    d.nvy_i = in[3];
    d.q_i = in[4];
    d.dm_i = in[5];
    d.dexp_i = static_cast<uint8_t>(in[6]);
    d.laniso_i = static_cast<uint16_t>(in[7]);
    d.maxlod_i = static_cast<uint8_t>(in[8]);
  });
}

RtlBlock rtl_ellipse_rec() {
  return bind<Vtu_ellipse_rec>("ellipse_rec", [](Vtu_ellipse_rec& d, const Row& in) {
    d.nux_i = in[0];
    d.nvx_i = in[1];
    d.nuy_i = in[2];
    d.nvy_i = in[3];
    d.q_i = in[4];
    d.qg_i = in[5];
    d.qh_i = in[6];
    d.laniso_i = static_cast<uint16_t>(in[7]);
    d.maxlod_i = static_cast<uint8_t>(in[8]);
  });
}

}  // namespace tu::cosim
