// The EWA engine's per-pixel in-fields shared by the vector blocks "ewa" and "afvis" (fields 0..10,
// in tu_ewa's port order): u, v (s32.8), B2's ae, ce, be, lmaj, lmin, lod, flags, the weight source
// (0 formula, 1 1-D table, 2 2-D table) and the texel cap. One encoder and one checked decoder, so
// the two blocks cannot disagree on a field.
#pragma once

#include <stdexcept>
#include <string>

#include "block.hpp"
#include "ewa/ewa_fx.hpp"
#include "texunit/formats.hpp"
#include "vector_file.hpp"

namespace tu::blocks {

inline constexpr size_t kEwaPixelFields = 11;

inline Row ewa_pixel_row(const ewa::fx::In& in, const ewa::fx::Config& cfg) {
  const auto& o = in.b2;
  return {field_bits(in.u, fmt::kPerspUvW), field_bits(in.v, fmt::kPerspUvW), o.ae, o.ce,
          static_cast<uint64_t>(o.be), field_bits(o.lmaj, fmt::kEllLogW), field_bits(o.lmin, fmt::kEllLogW), o.lod,
          o.flags, static_cast<uint64_t>(cfg.weights), cfg.max_texels};
}

// Fields 0..10 of r into in and cfg (cfg's other members untouched); a weight source outside 0..2
// is refused naming the block and the field.
inline void ewa_pixel_of(const Row& r, const std::string& block, ewa::fx::In& in, ewa::fx::Config& cfg) {
  in.u = vec::sext(r[0], fmt::kPerspUvW);
  in.v = vec::sext(r[1], fmt::kPerspUvW);
  in.b2.ae = r[2];
  in.b2.ce = r[3];
  in.b2.be = static_cast<int64_t>(r[4]);
  in.b2.lmaj = static_cast<int32_t>(vec::sext(r[5], fmt::kEllLogW));
  in.b2.lmin = static_cast<int32_t>(vec::sext(r[6], fmt::kEllLogW));
  in.b2.lod = static_cast<uint32_t>(r[7]);
  in.b2.flags = static_cast<uint32_t>(r[8]);
  if (r[9] > 2) throw std::invalid_argument(block + ": field wsrc = " + std::to_string(r[9]) + " (0..2)");
  cfg.weights = static_cast<ewa::fx::Weights>(r[9]);
  cfg.max_texels = static_cast<uint32_t>(r[10]);
}

}  // namespace tu::blocks
