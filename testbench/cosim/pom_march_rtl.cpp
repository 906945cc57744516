// RTL binding of the POM march engine (rtl/pom/tu_pom_march.sv).
#include "Vtu_pom_march.h"
#include "cosim.hpp"

namespace tu::cosim {

RtlBlock rtl_pom_march() {
  auto drive = [](Vtu_pom_march& d, const Row& in) {
    d.u_i = static_cast<uint32_t>(in[0]);
    d.v_i = static_cast<uint32_t>(in[1]);
    d.du_i = static_cast<uint32_t>(in[2]);
    d.dv_i = static_cast<uint32_t>(in[3]);
    d.n_i = static_cast<uint8_t>(in[4]);
    d.side_i = 0;
  };
  auto sample = [](Vtu_pom_march& d) {
    return Row{d.u_o, d.v_o, d.steps_o, d.a_o, d.den_o};
  };
  return make_rtl<Vtu_pom_march>("pom_march", drive, sample);
}

}  // namespace tu::cosim
