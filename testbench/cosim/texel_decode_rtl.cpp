// RTL binding of the texel decode stage (rtl/top/tu_texel_decode.sv through tu_texel_decode_sim),
// block "texel_decode": the fields by port name (generated glue).
#include "Vtu_texel_decode_sim.h"
#include "cosim.hpp"

namespace tu::cosim {

RtlBlock rtl_texel_decode() {
  return make_rtl<Vtu_texel_decode_sim>("texel_decode", glue::drive_texel_decode<Vtu_texel_decode_sim>,
                                        glue::sample_texel_decode<Vtu_texel_decode_sim>);
}

}  // namespace tu::cosim
