// RTL binding of the texel addressing (rtl/top/tu_texel_addr.sv through tu_texel_addr_sim), block
// "texel_addr": ports named after the block's fields (generated glue).
#include "Vtu_texel_addr_sim.h"
#include "cosim.hpp"

namespace tu::cosim {

RtlBlock rtl_texel_addr() {
  return make_rtl<Vtu_texel_addr_sim>("texel_addr", glue::drive_texel_addr<Vtu_texel_addr_sim>,
                                      glue::sample_texel_addr<Vtu_texel_addr_sim>);
}

}  // namespace tu::cosim
