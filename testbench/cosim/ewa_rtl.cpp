// RTL binding of the EWA engine (rtl/ewa/tu_ewa.sv through the simulation top tu_ewa_sim with
// the texel RAM model), block "ewa": the block's fixed texture (bricks colour 256 x 256, repeat)
// is loaded into the RAM at address 0 during reset (its border word at 0, level 0 at 1).
// "ewa_k4": the same block's vectors on the multi-texel engine (tu_ewa Lanes = 4, Setups = 2:
// tu_ewa_walk_lanes over four bank ports; Vtu_ewa_sim_k4), run with cosim::Options::rtl.
#include "Vtu_ewa_sim.h"
#include "Vtu_ewa_sim_k4.h"
#include "cosim.hpp"
#include "texel_ram.hpp"

#include <memory>

namespace tu::cosim {

namespace {
template <class V>
RtlBlock ewa_block(const std::string& name, std::shared_ptr<const tex::Texture> tp) {
  auto drive = [tp](V& d, const Row& in) {
    const tex::Texture& tex = *tp;
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
  auto sample = [](V& d) {
    const uint32_t c = d.rgba_o;
    return Row{c & 0xff, (c >> 8) & 0xff, (c >> 16) & 0xff, c >> 24, d.level_o, d.visited_o, d.inside_o,
               d.flags_o};
  };
  auto init = [words = texture_words(*tp)](V& d, const std::function<void()>& tick) { load_words(d, tick, 0, words); };
  RtlBlock b;
  b.name = name;
  b.run = [=](const std::vector<Row>& in, const RunOptions& o) { return Harness<V>(drive, sample, init).run(in, o); };
  b.timing = [=](const std::vector<Row>& in) { return Harness<V>(drive, sample, init).measure_timing(in); };
  return b;
}

std::shared_ptr<const tex::Texture> block_texture() {
  static const auto t = std::make_shared<const tex::Texture>(
      tex::Texture::build("bricks", tex::bricks(256).color, tex::Wrap::Repeat));
  return t;
}
}  // namespace

RtlBlock rtl_ewa() { return ewa_block<Vtu_ewa_sim>("ewa", block_texture()); }
RtlBlock rtl_ewa_k4() { return ewa_block<Vtu_ewa_sim_k4>("ewa_k4", block_texture()); }
RtlBlock rtl_ewa_k4_with(const tex::Texture& t) {
  return ewa_block<Vtu_ewa_sim_k4>("ewa_k4", std::make_shared<const tex::Texture>(t));
}

}  // namespace tu::cosim
