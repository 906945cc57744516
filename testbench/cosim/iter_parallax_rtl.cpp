// RTL binding of the iterative parallax engine (rtl/pom/tu_iter_parallax.sv).
#include "Vtu_iter_parallax.h"
#include "cosim.hpp"
#include "texunit/formats.hpp"

namespace tu::cosim {

RtlBlock rtl_iter_parallax() {
  auto drive = [](Vtu_iter_parallax& d, const Row& in) {
    d.u_i = static_cast<uint32_t>(in[0]);
    d.v_i = static_cast<uint32_t>(in[1]);
    d.su_i = static_cast<uint32_t>(in[2]);
    d.sv_i = static_cast<uint32_t>(in[3]);
    d.sh_i = static_cast<uint32_t>(in[4]);
    d.cap_i = fmt::kIpxCap;  // the block's vectors use the default cap
  };
  auto sample = [](Vtu_iter_parallax& d) {
    return Row{d.u_o, d.v_o, d.iters_o, d.nonconv_o};
  };
  return make_rtl<Vtu_iter_parallax>("iter_parallax", drive, sample);
}

}  // namespace tu::cosim
