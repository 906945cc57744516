// RTL binding of the texel decode stage (rtl/top/tu_texel_decode.sv through tu_texel_decode_sim),
// block "texel_decode".
#include "Vtu_texel_decode_sim.h"
#include "cosim.hpp"

namespace tu::cosim {

RtlBlock rtl_texel_decode() {
  auto drive = [](Vtu_texel_decode_sim& d, const Row& in) {
    d.fmt_i = static_cast<uint8_t>(in[0]);
    d.srgb_i = static_cast<uint8_t>(in[1]);
    d.word_i = static_cast<uint32_t>(in[2]);
  };
  auto sample = [](Vtu_texel_decode_sim& d) { return Row{d.rgba_o}; };
  return make_rtl<Vtu_texel_decode_sim>("texel_decode", drive, sample);
}

}  // namespace tu::cosim
