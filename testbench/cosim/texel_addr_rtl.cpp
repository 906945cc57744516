// RTL binding of the texel addressing (rtl/top/tu_texel_addr.sv through tu_texel_addr_sim), block
// "texel_addr".
#include "Vtu_texel_addr_sim.h"
#include "cosim.hpp"

namespace tu::cosim {

RtlBlock rtl_texel_addr() {
  auto drive = [](Vtu_texel_addr_sim& d, const Row& in) {
    d.base_i = static_cast<uint32_t>(in[0]);
    d.lw_i = static_cast<uint8_t>(in[1]);
    d.lh_i = static_cast<uint8_t>(in[2]);
    d.wrap_i = static_cast<uint8_t>(in[3]);
    d.level_i = static_cast<uint8_t>(in[4]);
    d.x_i = static_cast<uint32_t>(in[5]);
    d.y_i = static_cast<uint32_t>(in[6]);
  };
  auto sample = [](Vtu_texel_addr_sim& d) { return Row{d.addr_o}; };
  return make_rtl<Vtu_texel_addr_sim>("texel_addr", drive, sample);
}

}  // namespace tu::cosim
