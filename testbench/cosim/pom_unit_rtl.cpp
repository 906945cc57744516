// RTL bindings of the POM set-up, refinement and per-pixel unit (rtl/pom/tu_pom_{setup,refine,unit}.sv).
#include "Vtu_pom_refine.h"
#include "Vtu_pom_setup.h"
#include "Vtu_pom_unit.h"
#include "cosim.hpp"

namespace tu::cosim {

std::vector<RtlBlock> rtl_pom_unit() {
  auto setup_drive = [](Vtu_pom_setup& d, const Row& in) {
    d.vx_i = static_cast<uint16_t>(in[0]);
    d.vy_i = static_cast<uint16_t>(in[1]);
    d.vz_i = static_cast<uint16_t>(in[2]);
    d.s_i = static_cast<uint16_t>(in[3]);
    d.n_i = static_cast<uint8_t>(in[4]);
    d.side_i = 0;
  };
  auto setup_sample = [](Vtu_pom_setup& d) {
    return Row{d.du_o, d.dv_o, d.n_o, d.back_o, d.clamped_o};
  };
  auto refine_drive = [](Vtu_pom_refine& d, const Row& in) {
    d.u_i = static_cast<uint32_t>(in[0]);
    d.v_i = static_cast<uint32_t>(in[1]);
    d.du_i = static_cast<uint32_t>(in[2]);
    d.dv_i = static_cast<uint32_t>(in[3]);
    d.steps_i = static_cast<uint8_t>(in[4]);
    d.a_i = static_cast<uint16_t>(in[5]);
    d.den_i = static_cast<uint16_t>(in[6]);
    d.wrap_i = static_cast<uint8_t>(in[7]);
    d.side_i = 0;
  };
  auto refine_sample = [](Vtu_pom_refine& d) {
    return Row{d.u_o, d.v_o, d.steps_o, d.w_o, d.discard_o};
  };
  auto unit_drive = [](Vtu_pom_unit& d, const Row& in) {
    d.u_i = static_cast<uint32_t>(in[0]);
    d.v_i = static_cast<uint32_t>(in[1]);
    d.vx_i = static_cast<uint16_t>(in[2]);
    d.vy_i = static_cast<uint16_t>(in[3]);
    d.vz_i = static_cast<uint16_t>(in[4]);
    d.s_i = static_cast<uint16_t>(in[5]);
    d.n_i = static_cast<uint8_t>(in[6]);
    d.wrap_i = static_cast<uint8_t>(in[7]);
  };
  auto unit_sample = [](Vtu_pom_unit& d) {
    return Row{d.u_o, d.v_o, d.steps_o, d.w_o, d.discard_o, d.back_o, d.clamped_o};
  };
  return {make_rtl<Vtu_pom_setup>("pom_setup", setup_drive, setup_sample),
          make_rtl<Vtu_pom_refine>("pom_refine", refine_drive, refine_sample),
          make_rtl<Vtu_pom_unit>("pom_unit", unit_drive, unit_sample)};
}

}  // namespace tu::cosim
