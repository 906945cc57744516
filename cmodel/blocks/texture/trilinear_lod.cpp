#include "texture/trilinear_lod.hpp"

#include <algorithm>
#include <cmath>

namespace tu::tex {

LodParams lod_params(double bias, double min_lod, double max_lod, int base_level, int max_level) {
  const double one = std::ldexp(1.0, fmt::kTexLodF), hi = std::ldexp(1.0, fmt::kEllLodW) - 1;
  LodParams p;
  p.bias = static_cast<int32_t>(std::floor(std::clamp(bias, -16.0, 16.0) * one + 0.5));
  p.min_lod = static_cast<uint32_t>(std::clamp(std::floor(min_lod * one + 0.5), 0.0, hi));
  p.max_lod = static_cast<uint32_t>(std::clamp(std::floor(max_lod * one + 0.5), 0.0, hi));
  p.base_level = static_cast<uint32_t>(std::clamp(base_level, 0, 1000));
  p.max_level = static_cast<uint32_t>(std::clamp(max_level, 0, 1000));
  return p;
}

LevelRange level_range(int base_level, int max_level, int top) {
  LevelRange r;
  r.base = std::clamp(base_level, 0, std::max(top, 0));
  r.top = std::clamp(max_level, r.base, std::max(top, r.base));
  return r;
}

TriLod trilinear_lod(int32_t lrho, const LodParams& p, int pyramid_top) {
  const LevelRange lv = level_range(p, pyramid_top);
  const int32_t base_code = lv.base << fmt::kTexLodF;
  // lrho >= -2^17, |bias| <= 2^12 and base <= 15 levels: no overflow in 32 bits.
  int32_t lam = (lrho >> (fmt::kEllLogF - fmt::kTexLodF)) + p.bias - base_code;
  TriLod o;
  const auto lo = static_cast<int32_t>(p.min_lod), hi = static_cast<int32_t>(p.max_lod);
  // The clamp flag marks a level changed by min_lod / max_lod: min_lod = 0 only does what the
  // magnification switch does anyway.
  if ((lam < lo && lo > 0) || lam > hi) o.flags |= kTriLodClamp;
  lam = std::clamp(lam, lo, std::max(lo, hi));
  const int32_t span_code = (lv.top - lv.base) << fmt::kTexLodF;
  if (lam <= 0) {
    o.flags |= kTriMagnify;
    lam = 0;
  } else if (lam >= span_code) {
    o.flags |= kTriLodSat;
    lam = span_code;
  }
  o.lod = static_cast<uint32_t>(lam + base_code);
  return o;
}

double trilinear_lod_ref(double ux, double vx, double uy, double vy, double bias, double min_lod,
                         double max_lod, int top, uint32_t* flags, int base_level, int max_level) {
  const double rho2 = std::max(ux * ux + vx * vx, uy * uy + vy * vy);
  return lod_rule_ref(rho2 > 0 ? 0.5 * std::log2(rho2) : -INFINITY, bias, min_lod, max_lod, top, flags,
                      base_level, max_level);
}

double lod_rule_ref(double log2_rho, double bias, double min_lod, double max_lod, int pyramid_top,
                    uint32_t* flags, int base_level, int max_level) {
  const LevelRange lv = level_range(base_level, max_level, pyramid_top);
  double lam = log2_rho - lv.base + bias;
  uint32_t f = 0;
  if ((lam < min_lod && min_lod > 0) || lam > max_lod) f |= kTriLodClamp;
  lam = std::clamp(lam, min_lod, std::max(min_lod, max_lod));
  if (lam <= 0) {
    f |= kTriMagnify;
    lam = 0;
  } else if (lam >= lv.top - lv.base) {
    f |= kTriLodSat;
    lam = lv.top - lv.base;
  }
  if (flags) *flags = f;
  return lam + lv.base;
}

}  // namespace tu::tex
