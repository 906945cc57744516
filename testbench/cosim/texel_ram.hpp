// Texture layout of the texel RAM (SyncReadRam in the co-simulation, addressed by tu_texel_addr):
// RGBA8 words r | g << 8 | b << 16 | a << 24, every mip level of a texture one after another from
// level 0, row-major, after one word holding the border colour: texture_words(t) loaded at A puts
// the texture's base (level 0) at A + 1 (tex::texel_addr).
#pragma once

#include <cstdint>
#include <vector>

#include "texture/texture.hpp"

namespace tu::cosim {

inline uint32_t pack_rgba(const img::Rgba8& p) {
  return uint32_t(p.r) | uint32_t(p.g) << 8 | uint32_t(p.b) << 16 | uint32_t(p.a) << 24;
}
inline img::Rgba8 unpack_rgba(uint32_t w) {
  return {uint8_t(w), uint8_t(w >> 8), uint8_t(w >> 16), uint8_t(w >> 24)};
}
inline std::vector<uint32_t> texture_words(const tex::Texture& t) {
  if (!t.words.empty()) return t.words;  // a stored format: its packed words (tu_texel_decode)
  std::vector<uint32_t> w = {pack_rgba(t.addressing.border)};  // at base - 1 (tex::texel_addr)
  for (const auto& lv : t.levels)
    for (const auto& p : lv.px) w.push_back(pack_rgba(p));
  return w;
}
// tu_texel_addr wrap_i: {v, u} Wrap codes.
inline uint8_t wrap_code(const tex::Addressing& a) {
  return static_cast<uint8_t>(static_cast<int>(a.u) | static_cast<int>(a.v) << schema::kWrapW);
}
inline int log2_size(int n) {  // n: a power of two
  int l = 0;
  while ((1 << l) < n) ++l;
  return l;
}

}  // namespace tu::cosim
