// RTL binding of the Feline engine (rtl/top/tu_feline.sv through the simulation top tu_feline_sim
// with the texel RAM model), block "feline": the block's fixed texture (bricks colour 256 x 256,
// repeat) is loaded into the RAM at address 0 during reset (its border word at 0, level 0 at 1).
#include "Vtu_feline_sim.h"
#include "cosim.hpp"
#include "texel_ram.hpp"
#include "texture/trilinear_lod.hpp"

namespace tu::cosim {

RtlBlock rtl_feline() {
  static const tex::Texture tex = tex::Texture::build("bricks", tex::bricks(256).color, tex::Wrap::Repeat);
  auto drive = [](Vtu_feline_sim& d, const Row& in) {
    d.u_i = static_cast<uint32_t>(in[0]);
    d.v_i = static_cast<uint32_t>(in[1]);
    d.ae_i = in[2];
    d.ce_i = in[3];
    d.be_i = in[4];
    d.lmaj_i = static_cast<uint32_t>(in[5]);
    d.lmin_i = static_cast<uint32_t>(in[6]);
    d.lrho_i = static_cast<uint32_t>(in[7]);
    d.eflags_i = static_cast<uint8_t>(in[8]);
    d.guard_i = static_cast<uint8_t>(in[9]);
    d.nmax_i = static_cast<uint8_t>(in[10]);
    d.bias_i = static_cast<uint16_t>(in[11]);
    d.minlod_i = static_cast<uint16_t>(in[12]);
    d.maxlod_i = static_cast<uint16_t>(in[13]);
    // the material's levels on the texture's pyramid (the unit's lbase_i, ltop_i)
    tex::LodParams lp;
    lp.base_level = static_cast<uint32_t>(in[14]);
    lp.max_level = static_cast<uint32_t>(in[15]);
    const tex::LevelRange lv = tex::level_range(lp, tex.num_levels() - 1);
    d.lbase_i = static_cast<uint8_t>(lv.base);
    d.ltop_i = static_cast<uint8_t>(lv.top);
    d.base_i = 1;  // after the border word at 0
    d.lw_i = static_cast<uint8_t>(log2_size(tex.levels[0].width));
    d.lh_i = static_cast<uint8_t>(log2_size(tex.levels[0].height));
    d.wrap_i = wrap_code(tex.addressing);
  };
  auto sample = [](Vtu_feline_sim& d) {
    const uint32_t c = d.rgba_o;
    return Row{c & 0xff, (c >> 8) & 0xff, (c >> 16) & 0xff, c >> 24, d.level_o, d.texels_o, d.probes_o, d.flags_o};
  };
  auto init = [](Vtu_feline_sim& d, const std::function<void()>& tick) {
    static const std::vector<uint32_t> words = texture_words(tex);
    load_words(d, tick, 0, words);
  };
  RtlBlock b;
  b.name = "feline";
  b.run = [=](const std::vector<Row>& in, const RunOptions& o) {
    return Harness<Vtu_feline_sim>(drive, sample, init).run(in, o);
  };
  b.timing = [=](const std::vector<Row>& in) {
    return Harness<Vtu_feline_sim>(drive, sample, init).measure_timing(in);
  };
  return b;
}

}  // namespace tu::cosim
