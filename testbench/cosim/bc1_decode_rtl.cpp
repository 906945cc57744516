// RTL binding of the BC1 texel decode (rtl/top/tu_bc1_decode.sv through tu_bc1_decode_sim), block
// "bc1_decode".
#include "Vtu_bc1_decode_sim.h"
#include "cosim.hpp"

namespace tu::cosim {

RtlBlock rtl_bc1_decode() {
  auto drive = [](Vtu_bc1_decode_sim& d, const Row& in) {
    d.block_i = in[0];
    d.texel_i = static_cast<uint8_t>(in[1]);
  };
  auto sample = [](Vtu_bc1_decode_sim& d) { return Row{d.rgba_o}; };
  return make_rtl<Vtu_bc1_decode_sim>("bc1_decode", drive, sample);
}

}  // namespace tu::cosim
