// RTL binding of the EWA engine (rtl/ewa/tu_ewa.sv through the simulation top tu_ewa_sim with
// the texel RAM model), block "ewa": the block's fixed texture (bricks colour 256 x 256, repeat)
// is loaded into the RAM at address 0 during reset (its border word at 0, level 0 at 1).
#include "Vtu_ewa_sim.h"
#include "cosim.hpp"
#include "texel_ram.hpp"

namespace tu::cosim {

RtlBlock rtl_ewa() {
  static const tex::Texture tex = tex::Texture::build("bricks", tex::bricks(256).color, tex::Wrap::Repeat);
  auto drive = [](Vtu_ewa_sim& d, const Row& in) {
    d.u_i = static_cast<uint32_t>(in[0]);
    d.v_i = static_cast<uint32_t>(in[1]);
    d.ae_i = in[2];
    d.ce_i = in[3];
    d.be_i = in[4];
    d.lmaj_i = static_cast<uint32_t>(in[5]);
    d.lmin_i = static_cast<uint32_t>(in[6]);
    d.lod_i = static_cast<uint16_t>(in[7]);
    d.eflags_i = static_cast<uint8_t>(in[8]);
    d.wsrc_i = static_cast<uint8_t>(in[9]);
    d.cap_i = static_cast<uint32_t>(in[10]);
    d.clip_i = static_cast<uint8_t>(in[11]);
    d.base_i = 1;  // after the border word at 0
    d.lw_i = static_cast<uint8_t>(log2_size(tex.levels[0].width));
    d.lh_i = static_cast<uint8_t>(log2_size(tex.levels[0].height));
    d.wrap_i = wrap_code(tex.addressing);
  };
  auto sample = [](Vtu_ewa_sim& d) {
    const uint32_t c = d.rgba_o;
    return Row{c & 0xff, (c >> 8) & 0xff, (c >> 16) & 0xff, c >> 24, d.level_o, d.visited_o, d.inside_o,
               d.flags_o};
  };
  auto init = [](Vtu_ewa_sim& d, const std::function<void()>& tick) {
    static const std::vector<uint32_t> words = texture_words(tex);
    load_words(d, tick, 0, words);
  };
  RtlBlock b;
  b.name = "ewa";
  b.run = [=](const std::vector<Row>& in, const RunOptions& o) {
    return Harness<Vtu_ewa_sim>(drive, sample, init).run(in, o);
  };
  b.timing = [=](const std::vector<Row>& in) {
    return Harness<Vtu_ewa_sim>(drive, sample, init).measure_timing(in);
  };
  return b;
}

}  // namespace tu::cosim
