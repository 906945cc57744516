// RTL binding of the EWA engine (rtl/ewa/tu_ewa.sv, Verilated as the top: HasClip 1, ClipVariant
// 0, guard_i tied low), block "ewa": the block's fixed texture (bricks colour 256 x 256, repeat)
// in the texel RAM (SyncReadRam on tex_*: the border word at 0, level 0 at 1, 1 << 17 words). "ewa_k4": the same block's vectors on the multi-texel engine (Lanes = 4,
// Setups = 2: tu_ewa_walk_lanes over four bank ports, one RAM with four read ports; Vtu_ewa_k4),
// run with cosim::Options::rtl.
#include "Vtu_ewa.h"
#include "Vtu_ewa_k4.h"
#include "cosim.hpp"
#include "sync_read_ram.hpp"
#include "texel_ram.hpp"

#include <memory>

namespace tu::cosim {

namespace {
// Lanes: the model's tu_ewa Lanes (its texel RAM's read ports).
template <class V, int Lanes>
RtlBlock ewa_block(const std::string& name, std::shared_ptr<const tex::Texture> tp) {
  // The block's fields by name (generated glue), then the texture set-up, which is not a field.
  auto drive = [tp](V& d, const Row& in) {
    const tex::Texture& tex = *tp;
    glue::drive_ewa(d, in);
    d.guard_i = 0;
    d.base_i = 1;  // after the border word at 0
    d.lw_i = static_cast<uint8_t>(log2_size(tex.levels[0].width));
    d.lh_i = static_cast<uint8_t>(log2_size(tex.levels[0].height));
    d.wrap_i = wrap_code(tex.addressing);
  };
  // rgba_o packs the four colour out-fields (r least significant).
  auto sample = [](V& d) {
    const uint32_t c = d.rgba_o;
    return Row{c & 0xff, (c >> 8) & 0xff, (c >> 16) & 0xff, c >> 24, d.level_o, d.visited_o, d.inside_o,
               d.flags_o};
  };
  auto env = [image = std::make_shared<const SyncReadRam::Image>(texture_words(*tp))]() {
    Env<V> e;
    attach_ram<V>(e, std::make_shared<SyncReadRam>(image, uint64_t(1) << 17, Lanes),
                  [](V& d) -> auto& { return d.tex_req_o; }, [](V& d) -> auto& { return d.tex_addr_o; },
                  [](V& d) -> auto& { return d.tex_data_i; });
    return e;
  };
  return make_rtl<V>(name, drive, sample, env);
}

std::shared_ptr<const tex::Texture> block_texture() {
  static const auto t = std::make_shared<const tex::Texture>(
      tex::Texture::build("bricks", tex::bricks(256).color, tex::Wrap::Repeat));
  return t;
}
}  // namespace

RtlBlock rtl_ewa() { return ewa_block<Vtu_ewa, 1>("ewa", block_texture()); }
RtlBlock rtl_ewa_k4_with(const tex::Texture& t) {
  RtlBlock b = ewa_block<Vtu_ewa_k4, 4>("ewa_k4", std::make_shared<const tex::Texture>(t));
  b.block = "ewa";  // the ewa block's vectors on the multi-texel engine
  return b;
}
RtlBlock rtl_ewa_k4() {
  RtlBlock b = ewa_block<Vtu_ewa_k4, 4>("ewa_k4", block_texture());
  b.block = "ewa";
  return b;
}

}  // namespace tu::cosim
