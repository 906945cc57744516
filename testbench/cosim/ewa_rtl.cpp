// RTL binding of the EWA engine (rtl/ewa/tu_ewa.sv through the simulation top tu_ewa_sim with
// the texel RAM model), block "ewa": the block's fixed texture (bricks colour 256 x 256, repeat)
// is loaded into the RAM at address 0 during reset (its border word at 0, level 0 at 1).
#include "Vtu_ewa_sim.h"
#include "cosim.hpp"
#include "texel_ram.hpp"

namespace tu::cosim {

RtlBlock rtl_ewa() {
  static const tex::Texture tex = tex::Texture::build("bricks", tex::bricks(256).color, tex::Wrap::Repeat);
  // The block's fields by name (generated glue), then the texture set-up, which is not a field.
  auto drive = [](Vtu_ewa_sim& d, const Row& in) {
    glue::drive_ewa(d, in);
    d.base_i = 1;  // after the border word at 0
    d.lw_i = static_cast<uint8_t>(log2_size(tex.levels[0].width));
    d.lh_i = static_cast<uint8_t>(log2_size(tex.levels[0].height));
    d.wrap_i = wrap_code(tex.addressing);
  };
  // rgba_o packs the four colour out-fields (r least significant).
  auto sample = [](Vtu_ewa_sim& d) {
    const uint32_t c = d.rgba_o;
    return Row{c & 0xff, (c >> 8) & 0xff, (c >> 16) & 0xff, c >> 24, d.level_o, d.visited_o, d.inside_o,
               d.flags_o};
  };
  auto init = [](Vtu_ewa_sim& d, const std::function<void()>& tick) {
    static const std::vector<uint32_t> words = texture_words(tex);
    load_words(d, tick, 0, words);
  };
  return make_rtl<Vtu_ewa_sim>("ewa", drive, sample, init);
}

}  // namespace tu::cosim
