// RTL binding of the Feline engine (rtl/top/tu_feline.sv, Verilated as the top), block "feline":
// the block's fixed texture (bricks colour 256 x 256, repeat) in the texel RAM at address 0 (its
// border word at 0, level 0 at 1; SyncReadRam on tex_*, 1 << 17 words).
#include "Vtu_feline.h"
#include "cosim.hpp"
#include "sync_read_ram.hpp"
#include "texel_ram.hpp"
#include "texture/trilinear_lod.hpp"

namespace tu::cosim {

RtlBlock rtl_feline() {
  static const tex::Texture tex = tex::Texture::build("bricks", tex::bricks(256).color, tex::Wrap::Repeat);
  auto drive = [](Vtu_feline& d, const Row& in) {
    const glue::feline_in f = glue::in_feline(in);  // the block's fields by name (generated glue)
    d.u_i = static_cast<uint32_t>(f.u);
    d.v_i = static_cast<uint32_t>(f.v);
    d.ae_i = f.ae;
    d.ce_i = f.ce;
    d.be_i = f.be;
    d.lmaj_i = static_cast<uint32_t>(f.lmaj);
    d.lmin_i = static_cast<uint32_t>(f.lmin);
    d.lrho_i = static_cast<uint32_t>(f.lrho);
    d.eflags_i = static_cast<uint8_t>(f.b2flags);
    d.guard_i = static_cast<uint8_t>(f.guard);
    d.nmax_i = static_cast<uint8_t>(f.nmax);
    d.bias_i = static_cast<uint16_t>(f.bias);
    d.minlod_i = static_cast<uint16_t>(f.min_lod);
    d.maxlod_i = static_cast<uint16_t>(f.max_lod);
    // the material's levels on the texture's pyramid (the unit's lbase_i, ltop_i)
    tex::LodParams lp;
    lp.base_level = static_cast<uint32_t>(f.base_level);
    lp.max_level = static_cast<uint32_t>(f.max_level);
    const tex::LevelRange lv = tex::level_range(lp, tex.num_levels() - 1);
    d.lbase_i = static_cast<uint8_t>(lv.base);
    d.ltop_i = static_cast<uint8_t>(lv.top);
    d.base_i = 1;  // after the border word at 0
    d.lw_i = static_cast<uint8_t>(log2_size(tex.levels[0].width));
    d.lh_i = static_cast<uint8_t>(log2_size(tex.levels[0].height));
    d.wrap_i = wrap_code(tex.addressing);
  };
  auto sample = [](Vtu_feline& d) {
    const uint32_t c = d.rgba_o;
    return Row{c & 0xff, (c >> 8) & 0xff, (c >> 16) & 0xff, c >> 24, d.level_o, d.texels_o, d.probes_o, d.flags_o};
  };
  auto env = []() {
    static const auto words = std::make_shared<const SyncReadRam::Image>(texture_words(tex));
    Env<Vtu_feline> e;
    attach_ram<Vtu_feline>(e, std::make_shared<SyncReadRam>(words, uint64_t(1) << 17),
                           [](Vtu_feline& d) -> auto& { return d.tex_req_o; },
                           [](Vtu_feline& d) -> auto& { return d.tex_addr_o; },
                           [](Vtu_feline& d) -> auto& { return d.tex_data_i; });
    return e;
  };
  return make_rtl<Vtu_feline>("feline", drive, sample, env);
}

}  // namespace tu::cosim
