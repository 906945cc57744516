// RTL binding of the visibility engine (rtl/ewa/tu_afvis.sv through tu_afvis_sim with the texel
// and depth RAM models), block "afvis": the block's texture (bricks colour 256 x 256, repeat) at
// texel address 0 (border word, level 0 at 1) and its depth map (bricks 64 x 64) at depth
// address 0, loaded during reset.
#include "Vtu_afvis_sim.h"
#include "afvis_block.hpp"
#include "cosim.hpp"
#include "texel_ram.hpp"

namespace tu::cosim {

RtlBlock rtl_afvis() {
  auto drive = [](Vtu_afvis_sim& d, const Row& in) {
    const tex::Texture& tex = blocks::afvis_texture();
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
    d.vx_i = static_cast<uint16_t>(in[11]);
    d.vy_i = static_cast<uint16_t>(in[12]);
    d.vz_i = static_cast<uint16_t>(in[13]);
    d.scale_i = static_cast<uint16_t>(in[14]);
    d.dmin_i = static_cast<uint8_t>(in[15]);
    d.bias_i = static_cast<uint8_t>(in[16]);
    d.rule_i = static_cast<uint8_t>(in[17]);
    d.base_i = 1;  // after the border word at 0
    d.lw_i = static_cast<uint8_t>(log2_size(tex.levels[0].width));
    d.lh_i = static_cast<uint8_t>(log2_size(tex.levels[0].height));
    d.wrap_i = wrap_code(tex.addressing);
    d.hbase_i = 0;
    d.hlw_i = static_cast<uint8_t>(log2_size(blocks::afvis_depth().width));
    d.hlh_i = static_cast<uint8_t>(log2_size(blocks::afvis_depth().height));
  };
  auto sample = [](Vtu_afvis_sim& d) {
    const uint32_t c = d.rgba_o;
    return Row{c & 0xff, (c >> 8) & 0xff, (c >> 16) & 0xff, c >> 24, d.level_o, d.visited_o, d.inside_o,
               d.flags_o, d.kept_o, d.traced_o, d.steps_o};
  };
  auto init = [](Vtu_afvis_sim& d, const std::function<void()>& tick) {
    static const std::vector<uint32_t> words = texture_words(blocks::afvis_texture());
    static const std::vector<uint32_t> depth(blocks::afvis_depth().px.begin(), blocks::afvis_depth().px.end());
    d.ram_sel_i = 0;
    load_words(d, tick, 0, words);
    d.ram_sel_i = 1;
    load_words(d, tick, 0, depth);
    d.ram_sel_i = 0;
  };
  RtlBlock b;
  b.name = "afvis";
  b.run = [=](const std::vector<Row>& in, const RunOptions& o) {
    return Harness<Vtu_afvis_sim>(drive, sample, init).run(in, o);
  };
  b.timing = [=](const std::vector<Row>& in) {
    return Harness<Vtu_afvis_sim>(drive, sample, init).measure_timing(in);
  };
  return b;
}

}  // namespace tu::cosim
