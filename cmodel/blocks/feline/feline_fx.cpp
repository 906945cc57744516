#include "feline/feline_fx.hpp"

#include <algorithm>
#include <cmath>

#include "gauss/weight.hpp"

namespace tu::feline::fx {

namespace {
namespace efx = ellipse::fx;
constexpr int kDrop = fmt::kEllLogF - fmt::kEwaExpF;  // log codes to the exp2 ROM's EwaExpF bits
static_assert(fmt::kFelSigF == fmt::kEwaE2F, "s1 is the exp2 ROM's value");
static_assert(fmt::kFelTF == fmt::kEwaE2F, "r = s2 / s1 is the exp2 ROM's value");
static_assert(fmt::kFelSigF > fmt::kTexUvF && 2 * fmt::kFelTF > fmt::kGaussQF);

int64_t round_shift(int64_t v, int d) { return (v + (int64_t(1) << (d - 1))) >> d; }  // half up

int64_t sat_uv(int64_t x) {
  const int64_t hi = (int64_t(1) << (fmt::kPerspUvW - 1)) - 1;
  return std::clamp(x, -hi - 1, hi);
}

// 2^(l / 2^EllLogF) with l truncated to EwaExpF fraction bits, clamped (flag): u.FelSigF.
uint64_t sigma(int32_t l, uint32_t* flags) {
  const int64_t lo = -(int64_t(fmt::kFelSigF) << fmt::kEwaExpF);
  const int64_t hi = int64_t(fmt::kFelAxisMaxLog2) << fmt::kEwaExpF;
  int64_t e = int64_t(l) >> kDrop;
  if (e < lo || e > hi) *flags |= kAxisClamp;
  e = std::clamp(e, lo, hi);
  return e >= 0 ? ewa::fx::exp2_pos(static_cast<uint32_t>(e)) : ewa::fx::exp2_neg(static_cast<uint32_t>(-e));
}
}  // namespace

const std::array<int32_t, fmt::kFelNMax + 1>& log2_int_table() {
  static const auto t = [] {
    std::array<int32_t, fmt::kFelNMax + 1> a{};
    for (int n = 1; n <= fmt::kFelNMax; ++n)
      a[static_cast<size_t>(n)] = static_cast<int32_t>(std::floor(std::log2(double(n)) * (1 << fmt::kEllLogF)));
    return a;
  }();
  return t;
}

const std::array<uint32_t, fmt::kFelNMax>& recip_table() {
  static const auto t = [] {
    std::array<uint32_t, fmt::kFelNMax> a{};
    for (int m = 1; m < fmt::kFelNMax; ++m)
      a[static_cast<size_t>(m)] = static_cast<uint32_t>(std::floor(std::ldexp(1.0, fmt::kFelRecipF) / m + 0.5));
    return a;
  }();
  return t;
}

int probe_count(int64_t e, int max_probes) {
  const auto& lg = log2_int_table();
  int n = 1;
  while (n < max_probes && e > lg[static_cast<size_t>(n)] + kRatioTol) ++n;
  return n;
}

Setup setup(const ewa::fx::In& in, const tex::Texture& t, const Config& cfg) {
  const efx::Out& o = in.b2;
  const int top = t.num_levels() - 1;
  const int nmax = std::clamp(cfg.max_probes, 1, fmt::kFelNMax);
  Setup su;
  if ((o.flags & efx::kHorizon) || o.lmaj == efx::kLogNegInf || o.lmin == efx::kLogNegInf) {
    su.flags = kUnit;
    su.lam = o.lrho;
  } else {
    const int64_t e = std::max<int64_t>(0, int64_t(o.lmaj) - o.lmin);
    su.n = probe_count(e, nmax);
    if (e > log2_int_table()[static_cast<size_t>(nmax)] + kRatioTol) su.flags |= kClamped;
    su.lam = std::max<int32_t>(o.lmin, o.lmaj - log2_int_table()[static_cast<size_t>(nmax)]);
    // The EWA's direction: phi (vectoring) is the minor axis, the major a quarter turn away.
    const int64_t d = static_cast<int64_t>(o.ae) - static_cast<int64_t>(o.ce);
    int32_t theta = 0;
    if (d != 0 || o.be != 0) {
      constexpr int32_t kQuarter = int32_t(1) << (fmt::kEwaAngW - 2);
      theta = (ewa::fx::vectoring(d, o.be) >> 1) + kQuarter;
      if (theta >= kQuarter) theta -= 2 * kQuarter;
    }
    ewa::fx::rotation(theta, &su.c, &su.s);
    su.sig1 = sigma(o.lmaj, &su.flags);
    // r = m / s1 with m the clamped minor (2^lam): log2 ratio truncated to EwaExpF bits, at most
    // FelTF integer bits (r = 2^-16: one code).
    const int64_t el = std::max<int64_t>(0, int64_t(o.lmaj) - su.lam);  // B2 may floor lmin a code above lmaj
    const int64_t er = std::min<int64_t>(el >> kDrop, int64_t(fmt::kFelTF) << fmt::kEwaExpF);
    su.rho = (1u << fmt::kFelTF) - ewa::fx::exp2_neg(static_cast<uint32_t>(er));
    su.delta = static_cast<uint64_t>(round_shift(static_cast<int64_t>(su.sig1 * su.rho), fmt::kFelTF));
    su.recip = recip_table()[static_cast<size_t>(su.n - 1)];
    const int64_t dr = round_shift(static_cast<int64_t>(su.delta * su.recip), fmt::kFelRecipF);
    su.hu = round_shift(dr * su.c, fmt::kEwaCsF);
    su.hv = round_shift(dr * su.s, fmt::kEwaCsF);
    su.tq = static_cast<uint32_t>(round_shift(int64_t(su.rho) * su.recip, fmt::kFelRecipF));
  }
  const auto tl = tex::trilinear_lod(su.lam, cfg.lod, top);
  su.lod = tl.lod;
  su.tri_flags = tl.flags;
  return su;
}

Probe probe(const Setup& su, const ewa::fx::In& in, int i) {
  const int64_t k = 2 * i - (su.n - 1);
  constexpr int kSh = fmt::kFelSigF - fmt::kTexUvF;
  Probe p;
  p.u = sat_uv(in.u + round_shift(k * su.hu, kSh));
  p.v = sat_uv(in.v + round_shift(k * su.hv, kSh));
  const uint64_t tt = uint64_t(k < 0 ? -k : k) * su.tq;
  p.q = static_cast<uint32_t>(std::min<uint64_t>((tt * tt) >> (2 * fmt::kFelTF - fmt::kGaussQF),
                                                 (uint64_t(1) << fmt::kGaussQW) - 1));
  p.w = gauss::weight(p.q);
  return p;
}

Out filter(const ewa::fx::In& in, const tex::Texture& t, const Config& cfg) {
  const Setup su = setup(in, t, cfg);
  Out out;
  out.probes = su.n;
  out.lod = su.lod;
  out.tri_flags = su.tri_flags;
  out.flags = su.flags;
  const bool one_level = (su.lod >> fmt::kTexLodF) >= static_cast<uint32_t>(t.num_levels() - 1);
  out.texels = su.n * (one_level ? 4 : 8);
  uint64_t acc[4] = {0, 0, 0, 0}, wsum = 0;
  for (int i = 0; i < su.n; ++i) {
    const Probe p = probe(su, in, i);
    const img::Rgba8 c = tex::trilinear(t, su.lod, p.u, p.v);
    acc[0] += uint64_t(p.w) * c.r, acc[1] += uint64_t(p.w) * c.g;
    acc[2] += uint64_t(p.w) * c.b, acc[3] += uint64_t(p.w) * c.a;
    wsum += p.w;
  }
  // wsum > 0: the inner probes have |k| <= 1 and t <= rho < 1 (Q < 1, w >= 2^-8).
  out.color = {static_cast<uint8_t>(ewa::fx::normalise(acc[0], wsum)),
               static_cast<uint8_t>(ewa::fx::normalise(acc[1], wsum)),
               static_cast<uint8_t>(ewa::fx::normalise(acc[2], wsum)),
               static_cast<uint8_t>(ewa::fx::normalise(acc[3], wsum))};
  return out;
}

Result filter_ref_b2(const ewa::fx::In& in, const tex::Texture& t, const Params& p) {
  const efx::Out& o = in.b2;
  const double u = std::ldexp(double(in.u), -fmt::kTexUvF), v = std::ldexp(double(in.v), -fmt::kTexUvF);
  if ((o.flags & efx::kHorizon) || o.lmaj == efx::kLogNegInf || o.lmin == efx::kLogNegInf) {
    Result r;
    r.lod = tex::lod_rule_ref(efx::log_value(o.lrho), p.lod_bias, p.min_lod, p.max_lod,
                              t.num_levels() - 1, &r.tri_flags, p.base_level, p.max_level);
    r.color = tex::trilinear_ref(t, r.lod, u, v);
    r.texels = r.lod >= t.num_levels() - 1 ? 4 : 8;
    return r;
  }
  return filter_axes(t, u, v, std::exp2(efx::log_value(o.lmaj)), std::exp2(efx::log_value(o.lmin)),
                     ewa::fx::theta_ref_b2(o), p);
}

}  // namespace tu::feline::fx
