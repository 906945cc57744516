// RTL binding of the BC1 texel decode (rtl/top/tu_bc1_decode.sv through tu_bc1_decode_sim), block
// "bc1_decode": the fields by port name (generated glue).
#include "Vtu_bc1_decode_sim.h"
#include "cosim.hpp"

namespace tu::cosim {

RtlBlock rtl_bc1_decode() {
  return make_rtl<Vtu_bc1_decode_sim>("bc1_decode", glue::drive_bc1_decode<Vtu_bc1_decode_sim>,
                                      glue::sample_bc1_decode<Vtu_bc1_decode_sim>);
}

}  // namespace tu::cosim
