// RTL binding of the visibility engine (rtl/ewa/tu_afvis.sv, Verilated as the top), block "afvis":
// the block's texture (bricks colour 256 x 256, repeat) in the texel RAM at address 0 (border
// word, level 0 at 1; SyncReadRam on tex_*, 1 << 17 words) and its depth map (bricks 64 x 64) in
// the depth RAM at address 0 (one code per word, the low 8 bits on d_data_i; SyncReadRam on d_*,
// 1 << 16 words). The vector row's fields go to the ports of the same name (generated glue); the
// texture and depth-map set-up, which are not fields, are driven here.
#include "Vtu_afvis.h"
#include "afvis_block.hpp"
#include "cosim.hpp"
#include "sync_read_ram.hpp"
#include "texel_ram.hpp"

namespace tu::cosim {

RtlBlock rtl_afvis() {
  auto drive = [](Vtu_afvis& d, const Row& in) {
    const tex::Texture& tex = blocks::afvis_texture();
    glue::drive_afvis(d, in);  // the block's fields by name (generated glue)
    d.base_i = 1;  // after the border word at 0
    d.lw_i = static_cast<uint8_t>(log2_size(tex.levels[0].width));
    d.lh_i = static_cast<uint8_t>(log2_size(tex.levels[0].height));
    d.wrap_i = wrap_code(tex.addressing);
    d.hbase_i = 0;
    d.hlw_i = static_cast<uint8_t>(log2_size(blocks::afvis_depth().width));
    d.hlh_i = static_cast<uint8_t>(log2_size(blocks::afvis_depth().height));
  };
  auto sample = [](Vtu_afvis& d) {
    const uint32_t c = d.rgba_o;
    return Row{c & 0xff, (c >> 8) & 0xff, (c >> 16) & 0xff, c >> 24, d.level_o, d.visited_o, d.inside_o,
               d.flags_o, d.kept_o, d.traced_o, d.steps_o};
  };
  auto env = []() {
    static const auto words = std::make_shared<const SyncReadRam::Image>(texture_words(blocks::afvis_texture()));
    static const auto depth = std::make_shared<const SyncReadRam::Image>(blocks::afvis_depth().px.begin(),
                                                                         blocks::afvis_depth().px.end());
    Env<Vtu_afvis> e;
    attach_ram<Vtu_afvis>(e, std::make_shared<SyncReadRam>(words, uint64_t(1) << 17),
                          [](Vtu_afvis& d) -> auto& { return d.tex_req_o; },
                          [](Vtu_afvis& d) -> auto& { return d.tex_addr_o; },
                          [](Vtu_afvis& d) -> auto& { return d.tex_data_i; });
    attach_ram<Vtu_afvis>(e, std::make_shared<SyncReadRam>(depth, uint64_t(1) << 16, 1, fmt::kTexAddrW, 8),
                          [](Vtu_afvis& d) -> auto& { return d.d_req_o; },
                          [](Vtu_afvis& d) -> auto& { return d.d_addr_o; },
                          [](Vtu_afvis& d) -> auto& { return d.d_data_i; });
    return e;
  };
  return make_rtl<Vtu_afvis>("afvis", drive, sample, env);
}

}  // namespace tu::cosim
