#include "ewa_fx.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <vector>

#include "ewa/ewa_lanes.hpp"
#include "gauss/weight.hpp"
#include "reciprocal/reciprocal.hpp"
#include "texunit/convert.hpp"

namespace tu::ewa::fx {

namespace {
constexpr int kAngW = fmt::kEwaAngW;
constexpr int32_t kHalfTurn = int32_t(1) << (kAngW - 1), kQuarter = int32_t(1) << (kAngW - 2);
constexpr int kRotF = fmt::kEwaCordW - 3;  // rotation datapath fraction bits (guard bits over CsF)
constexpr int kQF = 2 * (fmt::kEwaKF + fmt::kEwaPosF);  // Q fraction bits
constexpr int64_t kStep = int64_t(1) << fmt::kEwaPosF;   // one texel in offset codes
static_assert(fmt::kTexUvF >= fmt::kEwaPosF, "centre: u / 2^L is rounded to EwaPosF bits");
static_assert(kQF - fmt::kGaussQF > 0 && fmt::kEwaKF + fmt::kEwaPosF > fmt::kGaussXiF);

int32_t wrap_angle(int64_t z) {  // two's-complement wrap to EwaAngW bits
  const uint32_t m = (uint32_t(1) << kAngW) - 1;
  const uint32_t u = static_cast<uint32_t>(z) & m;
  return static_cast<int32_t>(u << (32 - kAngW)) >> (32 - kAngW);
}
int msb64(uint64_t x) { return 63 - std::countl_zero(x); }
int64_t round_shift(int64_t v, int d) { return (v + (int64_t(1) << (d - 1))) >> d; }  // half up
// Ceiling square root of an exact sum of squares.
uint64_t isqrt_ceil(u128 x) {
  const uint64_t r = ellipse::fx::isqrt(x);
  return static_cast<u128>(r) * r < x ? r + 1 : r;
}
// Conservative half extent: sqrt(p^2 + q^2) (p, q: a.EwaE2F x c.EwaCsF codes) rounded up to
// EwaPosF bits, plus the margin for the quantised frame (see the header).
uint32_t half_extent(int64_t p, int64_t q) {
  const int shift = fmt::kEwaE2F + fmt::kEwaCsF - fmt::kEwaPosF;
  const uint64_t r = isqrt_ceil(static_cast<u128>(i128(p) * p) + static_cast<u128>(i128(q) * q));
  const uint64_t h = (r + (uint64_t(1) << shift) - 1) >> shift;
  return static_cast<uint32_t>(h + (h >> fmt::kEwaPosF) + 1);
}
int64_t floor_div_step(int64_t c) { return c >> fmt::kEwaPosF; }
int64_t ceil_div_step(int64_t c) { return -((-c) >> fmt::kEwaPosF); }

const gauss::Table1D& table1d() {
  static const gauss::Table1D t(gauss::kWtabRtlLog2N);
  return t;
}
const gauss::Table2D& table2d() {
  static const gauss::Table2D t(gauss::kWtab2dRtlLog2N);
  return t;
}
uint32_t weight_of(Weights w, uint64_t q, int64_t xi, int64_t eta) {
  switch (w) {
    case Weights::Formula: return gauss::weight(static_cast<uint32_t>(q >> (kQF - fmt::kGaussQF)));
    case Weights::Table1d: return table1d().lookup(static_cast<uint32_t>(q >> (kQF - fmt::kGaussQF)));
    case Weights::Table2d: {
      const int sh = fmt::kEwaKF + fmt::kEwaPosF - fmt::kGaussXiF;  // floor
      return table2d().lookup(static_cast<int32_t>(xi >> sh), static_cast<int32_t>(eta >> sh));
    }
  }
  return 0;
}
}  // namespace

const std::array<int32_t, fmt::kEwaCordIter>& atan_table() {
  static const auto t = [] {
    std::array<int32_t, fmt::kEwaCordIter> a{};
    for (int i = 0; i < fmt::kEwaCordIter; ++i)
      a[static_cast<size_t>(i)] = static_cast<int32_t>(
          std::floor(std::atan(std::ldexp(1.0, -i)) / (2 * M_PI) * std::ldexp(1.0, kAngW) + 0.5));
    return a;
  }();
  return t;
}

const std::array<uint32_t, 1u << fmt::kEwaExpF>& exp2_table() {
  static const auto t = [] {
    std::array<uint32_t, 1u << fmt::kEwaExpF> e{};
    for (uint32_t i = 0; i < e.size(); ++i)
      e[i] = static_cast<uint32_t>(std::floor(
          std::exp2(std::ldexp(double(i), -fmt::kEwaExpF)) * std::ldexp(1.0, fmt::kEwaE2F) + 0.5));
    return e;
  }();
  return t;
}

int32_t cordic_gain_code() {
  static const int32_t code = [] {  // once: rotation() starts every pixel from it
    double k = 1;
    for (int i = 0; i < fmt::kEwaCordIter; ++i) k /= std::sqrt(1 + std::ldexp(1.0, -2 * i));
    return static_cast<int32_t>(std::floor(std::ldexp(k, kRotF) + 0.5));
  }();
  return code;
}

int32_t vectoring(int64_t d, int64_t b) {
  if (d == 0 && b == 0) return 0;
  // Block-normalise (floor shifts) so that the CORDIC gain (1.65 sqrt 2) cannot overflow.
  const uint64_t m = std::max<uint64_t>(d < 0 ? -static_cast<uint64_t>(d) : d,
                                        b < 0 ? -static_cast<uint64_t>(b) : b);
  const int k = std::max(0, msb64(m) + 1 - (fmt::kEwaCordW - 3));
  int64_t x = d >> k, y = b >> k;
  int64_t z = 0;
  if (x < 0) {  // pre-rotation by a half turn into the right half-plane
    x = -x;
    y = -y;
    z = kHalfTurn;
  }
  const auto& at = atan_table();
  for (int i = 0; i < fmt::kEwaCordIter; ++i) {
    const int64_t xs = x >> i, ys = y >> i;
    if (y >= 0) {
      x += ys, y -= xs, z += at[static_cast<size_t>(i)];
    } else {
      x -= ys, y += xs, z -= at[static_cast<size_t>(i)];
    }
  }
  return wrap_angle(z);
}

void rotation(int32_t theta, int32_t* c, int32_t* s) {
  int64_t x = cordic_gain_code(), y = 0, z = theta;
  const auto& at = atan_table();
  for (int i = 0; i < fmt::kEwaCordIter; ++i) {
    const int64_t xs = x >> i, ys = y >> i;
    if (z >= 0) {
      x -= ys, y += xs, z -= at[static_cast<size_t>(i)];
    } else {
      x += ys, y -= xs, z += at[static_cast<size_t>(i)];
    }
  }
  *c = static_cast<int32_t>(round_shift(x, kRotF - fmt::kEwaCsF));
  *s = static_cast<int32_t>(round_shift(y, kRotF - fmt::kEwaCsF));
}

uint32_t exp2_pos(uint32_t e) {
  return exp2_table()[e & ((1u << fmt::kEwaExpF) - 1)] << (e >> fmt::kEwaExpF);
}
uint32_t exp2_neg(uint32_t e) {
  // 2^-e = 2^-(n+1) 2^(1-f) for a fraction f > 0.
  const uint32_t n = e >> fmt::kEwaExpF, f = e & ((1u << fmt::kEwaExpF) - 1);
  if (f == 0) return (uint32_t(1) << fmt::kEwaE2F) >> n;
  return exp2_table()[(1u << fmt::kEwaExpF) - f] >> (n + 1);
}

PixelSetup setup(const In& in, const tex::Texture& t, const Config& cfg) {
  namespace efx = ellipse::fx;
  const efx::Out& o = in.b2;
  PixelSetup su;
  const int top = t.num_levels() - 1;
  const bool unit = (o.flags & efx::kHorizon) || o.lmaj == efx::kLogNegInf;
  // The sampler's level (base level and above, render_cmodel); a unit disc too.
  int level = std::min(static_cast<int>(o.lod >> fmt::kEllLodF), top);
  if (unit) {
    su.flags |= kUnitDisc;
  } else {
    if (static_cast<int>(o.lod >> fmt::kEllLodF) > top) su.flags |= kLodSat;
    // ae, ce < 2^62 (B2 block floating point; the ewa vector fields are u62): the difference
    // fits int64.
    const int64_t d = static_cast<int64_t>(o.ae) - static_cast<int64_t>(o.ce);
    su.two_phi = vectoring(d, o.be);
    // phi = 2 phi / 2 is the minor axis; the major axis is a quarter turn away, modulo a half
    // turn. A circle (d = b = 0) has no direction: theta = 0.
    if (d != 0 || o.be != 0) {
      su.theta = (su.two_phi >> 1) + kQuarter;
      if (su.theta >= kQuarter) su.theta -= kHalfTurn;
    }
  }
  rotation(su.theta, &su.c, &su.s);
  constexpr int kDrop = fmt::kEllLogF - fmt::kEwaExpF;
  for (;; ++level) {
    const auto& lv = t.levels[static_cast<size_t>(level)];
    const int log2lim = std::countr_zero(static_cast<unsigned>(std::max(lv.width, lv.height)));
    const int64_t emax = int64_t(std::min(log2lim, fmt::kEwaAxisMaxLog2)) << fmt::kEwaExpF;
    int64_t ea = 0, eb = 0;
    su.flags &= ~uint32_t(kAxisClamp);
    if (!unit) {
      const int64_t ra = (int64_t(o.lmaj) - (int64_t(level) << fmt::kEllLogF)) >> kDrop;
      const int64_t rb = o.lmin == efx::kLogNegInf
                             ? 0
                             : (int64_t(o.lmin) - (int64_t(level) << fmt::kEllLogF)) >> kDrop;
      if (ra > emax) su.flags |= kAxisClamp;
      ea = std::clamp<int64_t>(ra, 0, emax);
      eb = std::clamp<int64_t>(rb, 0, ea);
    }
    su.level = level;
    su.ea = static_cast<uint32_t>(ea);
    su.eb = static_cast<uint32_t>(eb);
    su.a = exp2_pos(su.ea);
    su.b = exp2_pos(su.eb);
    su.inv_a = exp2_neg(su.ea);
    su.inv_b = exp2_neg(su.eb);
    auto k = [](int64_t cs, uint32_t inv) {
      return static_cast<int32_t>(round_shift(cs * inv, fmt::kEwaCsF + fmt::kEwaE2F - fmt::kEwaKF));
    };
    su.kxu = k(su.c, su.inv_a);
    su.kxv = k(su.s, su.inv_a);
    su.kyu = k(-int64_t(su.s), su.inv_b);
    su.kyv = k(su.c, su.inv_b);
    su.hu = half_extent(int64_t(su.a) * su.c, int64_t(su.b) * su.s);
    su.hv = half_extent(int64_t(su.a) * su.s, int64_t(su.b) * su.c);
    if (cfg.clip) {  // border texels up to 1/2 texel outside the ellipse
      su.hu += kBorderGrow;
      su.hv += kBorderGrow;
    }
    // Centre at level L with texel i at i: u / 2^L rounded half up to EwaPosF bits, minus 1/2.
    const int sh = fmt::kTexUvF + level - fmt::kEwaPosF;
    su.cu = (sh > 0 ? round_shift(in.u, sh) : in.u) - kStep / 2;
    su.cv = (sh > 0 ? round_shift(in.v, sh) : in.v) - kStep / 2;
    su.x0 = ceil_div_step(su.cu - su.hu);
    su.x1 = floor_div_step(su.cu + su.hu);
    su.y0 = ceil_div_step(su.cv - su.hv);
    su.y1 = floor_div_step(su.cv + su.hv);
    su.box = static_cast<uint64_t>((su.x1 - su.x0 + 1) * (su.y1 - su.y0 + 1));
    if (su.box > cfg.max_texels && level < top) {
      su.flags |= kCapped;
      continue;
    }
    return su;
  }
}

Border border(const PixelSetup& su, int64_t q, int64_t xi, int64_t eta) {
  constexpr int64_t kOne = int64_t(1) << kQF;
  Border b;
  if (q < kOne / 4) return b;  // Inside
  if (q > kOne / 4 * 9) {
    b.zone = Zone::Outside;
    return b;
  }
  // g = K^T (xi, eta): 2 EwaKF + EwaPosF fraction bits exact, floored to EwaGradF.
  constexpr int kGSh = 2 * fmt::kEwaKF + fmt::kEwaPosF - fmt::kEwaGradF;
  // Wrapped to EwaGradW bits as the RTL registers them (a no-op on a walk: |g| < 2^(GradW-1)
  // there, EwaBorder.DistanceWithinOneLsbOfDouble; other inputs of the vector block wrap alike).
  auto wrap = [](int64_t x) {
    const uint64_t m = (uint64_t(1) << fmt::kEwaGradW) - 1, u = static_cast<uint64_t>(x) & m;
    return static_cast<int32_t>(static_cast<int64_t>(u << (64 - fmt::kEwaGradW)) >> (64 - fmt::kEwaGradW));
  };
  b.gu = wrap((int64_t(su.kxu) * xi + int64_t(su.kyu) * eta) >> kGSh);
  b.gv = wrap((int64_t(su.kxv) * xi + int64_t(su.kyv) * eta) >> kGSh);
  b.g = static_cast<uint32_t>(ellipse::fx::isqrt(static_cast<u128>(int64_t(b.gu) * b.gu + int64_t(b.gv) * b.gv)));
  // r = floor(sqrt Q): Q has 2 (EwaKF + EwaPosF) = 2 EwaGradF fraction bits.
  static_assert(kQF == 2 * fmt::kEwaGradF, "r = isqrt(Q) lands on EwaGradF fraction bits");
  b.r = static_cast<uint32_t>(ellipse::fx::isqrt(static_cast<u128>(q)));
  // d = (1 - r) r / |g|: num has 2 EwaGradF fraction bits, d = num / (g 2^(EwaGradF - ClipInF)).
  const int64_t num = ((int64_t(1) << fmt::kEwaGradF) - int64_t(b.r)) * int64_t(b.r);
  const int64_t den = int64_t(b.g) << (fmt::kEwaGradF - fmt::kClipInF);
  const int64_t mag = num < 0 ? -num : num;
  // |d| <= 1/2 iff round(mag / den) <= 2^(ClipInF-1) iff mag < (2^(ClipInF-1) + 1/2) den.
  if (b.g == 0 || mag >= (int64_t(clip::kHalfCode) * 2 + 1) * den / 2) {
    b.zone = num > 0 ? Zone::Inside : Zone::Outside;
    return b;
  }
  b.zone = Zone::Band;
  const int32_t dm = static_cast<int32_t>((mag + den / 2) / den);  // half up in magnitude
  b.d = num < 0 ? -dm : dm;
  return b;
}

uint32_t apply_border(const Border& b, int64_t q, uint32_t w, const clip::Variant& v) {
  constexpr int64_t kOne = int64_t(1) << kQF;
  if (b.zone == Zone::Outside) return 0;
  if (b.zone == Zone::Inside) return w;
  // The boundary weight outside (w(1) = 2^-8 of the formula and the 1-D table exactly).
  constexpr uint32_t kEdgeW = uint32_t(1) << (fmt::kGaussSqF - 8);
  const uint64_t wb = q < kOne ? w : kEdgeW;
  return static_cast<uint32_t>((wb * clip::eval(v, b.d) + (uint64_t(1) << (fmt::kClipOutF - 1))) >> fmt::kClipOutF);
}

uint32_t border_weight(const PixelSetup& su, const Config& cfg, int64_t q, int64_t xi, int64_t eta) {
  const Border b = border(su, q, xi, eta);
  constexpr int64_t kOne = int64_t(1) << kQF;
  const uint32_t w = b.zone != Zone::Outside && q < kOne ? weight_of(cfg.weights, static_cast<uint64_t>(q), xi, eta) : 0;
  return apply_border(b, q, w, *cfg.clip);
}

namespace {
// 1/wsum as the unit forms it once per pixel: R and the shift of acc * R.
struct InvSum {
  uint32_t mant;
  int sh;
};
InvSum inv_sum(uint64_t wsum) {
  const int p = msb64(wsum), top = fmt::kEwaNrmW - 1;
  const uint64_t m = p >= top ? wsum >> (p - top) : wsum << (top - p);  // floor
  const recip::Result r = recip::eval(static_cast<int32_t>(m));
  // 1/wsum ~= R 2^-(RecipOutF + shift + p - top); shift == top (m's msb).
  return {r.mant, fmt::kRecipOutF + static_cast<int>(r.shift) + p - top};
}
uint32_t channel(uint64_t acc, InvSum r) {
  const u128 v = (static_cast<u128>(acc) * r.mant + (u128(1) << (r.sh - 1))) >> r.sh;
  return static_cast<uint32_t>(std::min<u128>(v, 255));
}
}  // namespace

uint32_t normalise(uint64_t acc, uint64_t wsum) { return channel(acc, inv_sum(wsum)); }

uint32_t texel_weight(const PixelSetup& su, const Config& cfg, int64_t q, int64_t xi, int64_t eta) {
  if (cfg.clip) return border_weight(su, cfg, q, xi, eta);
  return q < (int64_t(1) << kQF) ? weight_of(cfg.weights, static_cast<uint64_t>(q), xi, eta) : 0;
}

void finish(const PixelSetup& su, const tex::Texture& t, const Sums& s, Out* out) {
  if (s.wsum == 0) {
    out->flags |= kNoWeight;
    out->color = t.fetch(su.level, floor_div_step(su.cu + kStep / 2), floor_div_step(su.cv + kStep / 2));
    return;
  }
  const InvSum r = inv_sum(s.wsum);  // shared by the four channels
  out->color = {static_cast<uint8_t>(channel(s.acc[0], r)), static_cast<uint8_t>(channel(s.acc[1], r)),
                static_cast<uint8_t>(channel(s.acc[2], r)), static_cast<uint8_t>(channel(s.acc[3], r))};
}

Out walk_out(const PixelSetup& su) {
  Out out;
  out.level = su.level;
  out.flags = su.flags;
  out.capped = (su.flags & kCapped) != 0;
  out.lane_blocks = static_cast<uint32_t>(lane_blocks(su.x0, su.x1, su.y0, su.y1, 4));
  return out;
}

QuadForm quad_form(const PixelSetup& su) {
  QuadForm f;
  f.a = int64_t(su.kxu) * su.kxu + int64_t(su.kyu) * su.kyu;
  f.b = 2 * (int64_t(su.kxu) * su.kxv + int64_t(su.kyu) * su.kyv);
  f.ddq = 2 * f.a * kStep * kStep;
  return f;
}

namespace {
// The texel reads of a walk at one level, as Texture::fetch makes them: each column of the box
// wrapped once per pixel and each row once (tex::wrap_index), then one load per texel; -1 (the
// border colour) as fetch. While a TexelTrace records, every read goes through fetch instead.
class LevelReader {
 public:
  LevelReader(const tex::Texture& t, int level, int64_t x0, int64_t x1)
      : t_(t), level_(std::clamp(level, 0, t.num_levels() - 1)), im_(t.levels[static_cast<size_t>(level_)]),
        trace_(tex::TexelTrace::active()), x0_(x0) {
    if (trace_) return;
    static thread_local std::vector<int32_t> cols;  // reused: no allocation per pixel
    cols.resize(static_cast<size_t>(std::max<int64_t>(0, x1 - x0 + 1)));
    const int lw = std::countr_zero(static_cast<unsigned>(im_.width));
    for (int64_t x = x0; x <= x1; ++x)
      cols[static_cast<size_t>(x - x0)] = static_cast<int32_t>(tex::wrap_index(x, lw, t.addressing.u));
    cols_ = cols.data();
  }
  void row(int64_t y) {
    y_ = y;
    if (trace_) return;
    const int64_t yi = tex::wrap_index(y, std::countr_zero(static_cast<unsigned>(im_.height)), t_.addressing.v);
    row_ = yi < 0 ? nullptr : im_.px.data() + static_cast<size_t>(yi) * static_cast<size_t>(im_.width);
  }
  img::Rgba8 at(int64_t x) const {
    if (trace_) return t_.fetch(level_, x, y_);
    const int32_t xi = cols_[x - x0_];
    return row_ && xi >= 0 ? row_[xi] : t_.addressing.border;
  }

 private:
  const tex::Texture& t_;
  int level_;
  const img::Rgba8Image& im_;
  bool trace_;
  int64_t x0_, y_ = 0;
  const int32_t* cols_ = nullptr;
  const img::Rgba8* row_ = nullptr;
};

// The walk without statistics, incremental Q (filter's path), for one weight source `wf(q, xi,
// eta)`: the same texels in the same order, weights and sums as the generic loop in walk(),
// with the sums and counters in locals (registers) instead of memory.
template <class W>
Out walk_fast(const PixelSetup& su, const tex::Texture& t, W wf) {
  Out out = walk_out(su);
  const QuadForm qf = quad_form(su);
  const int64_t A = qf.a, B = qf.b, ddq = qf.ddq;
  const int64_t kxu = su.kxu, kxv = su.kxv, kyu = su.kyu, kyv = su.kyv;
  const int64_t dxi = kxu * kStep, deta = kyu * kStep;
  uint64_t a0 = 0, a1 = 0, a2 = 0, a3 = 0, wsum = 0;
  uint32_t inside = 0;
  LevelReader texels(t, su.level, su.x0, su.x1);
  for (int64_t y = su.y0; y <= su.y1 && su.x0 <= su.x1; ++y) {
    texels.row(y);
    const int64_t dv = y * kStep - su.cv, du0 = su.x0 * kStep - su.cu;
    int64_t xi = kxu * du0 + kxv * dv;
    int64_t eta = kyu * du0 + kyv * dv;
    int64_t q = xi * xi + eta * eta;
    int64_t dq = A * (2 * du0 * kStep + kStep * kStep) + B * dv * kStep;
    for (int64_t x = su.x0;; ++x) {
      const uint32_t w = wf(q, xi, eta);
      if (w > 0) {
        ++inside;
        const img::Rgba8 px = texels.at(x);
        a0 += uint64_t(w) * px.r, a1 += uint64_t(w) * px.g;
        a2 += uint64_t(w) * px.b, a3 += uint64_t(w) * px.a;
        wsum += w;
      }
      if (x == su.x1) break;
      q += dq;  // Heckbert: first and second differences along x
      dq += ddq;
      xi += dxi;
      eta += deta;
    }
  }
  if (su.x1 >= su.x0 && su.y1 >= su.y0)
    out.texels_visited = static_cast<uint32_t>((su.x1 - su.x0 + 1) * (su.y1 - su.y0 + 1));
  out.texels_inside = inside;
  Sums sums;
  sums.acc[0] = a0, sums.acc[1] = a1, sums.acc[2] = a2, sums.acc[3] = a3;
  sums.wsum = wsum;
  finish(su, t, sums, &out);
  return out;
}
}  // namespace

Out walk(const PixelSetup& su, const tex::Texture& t, const Config& cfg, bool direct, WalkStats* st) {
  if (!direct && st == nullptr) {  // the render's path: one loop per weight source
    constexpr int64_t kOne = int64_t(1) << kQF;
    if (cfg.clip)
      return walk_fast(su, t, [&](int64_t q, int64_t xi, int64_t eta) { return border_weight(su, cfg, q, xi, eta); });
    switch (cfg.weights) {
      case Weights::Formula:
        return walk_fast(su, t, [](int64_t q, int64_t, int64_t) {
          return q < kOne ? gauss::weight(static_cast<uint32_t>(q >> (kQF - fmt::kGaussQF))) : 0u;
        });
      case Weights::Table1d: {
        const gauss::Table1D& tab = table1d();
        return walk_fast(su, t, [&tab](int64_t q, int64_t, int64_t) {
          return q < kOne ? tab.lookup(static_cast<uint32_t>(q >> (kQF - fmt::kGaussQF))) : 0u;
        });
      }
      case Weights::Table2d: {
        const gauss::Table2D& tab = table2d();
        constexpr int sh = fmt::kEwaKF + fmt::kEwaPosF - fmt::kGaussXiF;  // floor
        return walk_fast(su, t, [&tab](int64_t q, int64_t xi, int64_t eta) {
          return q < kOne ? tab.lookup(static_cast<int32_t>(xi >> sh), static_cast<int32_t>(eta >> sh)) : 0u;
        });
      }
    }
  }
  Out out = walk_out(su);
  const QuadForm qf = quad_form(su);
  const int64_t A = qf.a, B = qf.b, ddq = qf.ddq;
  Sums sums;
  uint64_t* const acc = sums.acc;
  LevelReader texels(t, su.level, su.x0, su.x1);
  for (int64_t y = su.y0; y <= su.y1; ++y) {
    texels.row(y);
    const int64_t dv = y * kStep - su.cv, du0 = su.x0 * kStep - su.cu;
    int64_t xi = int64_t(su.kxu) * du0 + int64_t(su.kxv) * dv;
    int64_t eta = int64_t(su.kyu) * du0 + int64_t(su.kyv) * dv;
    int64_t q = xi * xi + eta * eta;
    int64_t dq = A * (2 * du0 * kStep + kStep * kStep) + B * dv * kStep;
    for (int64_t x = su.x0; x <= su.x1; ++x) {
      if (direct) {
        const int64_t du = x * kStep - su.cu;
        xi = int64_t(su.kxu) * du + int64_t(su.kxv) * dv;
        eta = int64_t(su.kyu) * du + int64_t(su.kyv) * dv;
        q = xi * xi + eta * eta;
      }
      if (st) {
        st->max_abs_d = std::max({st->max_abs_d, std::abs(x * kStep - su.cu), std::abs(dv)});
        st->max_abs_xi = std::max({st->max_abs_xi, std::abs(xi), std::abs(eta)});
        st->max_q = std::max({st->max_q, static_cast<uint64_t>(q), static_cast<uint64_t>(std::abs(dq))});
        st->max_ddq = std::max(st->max_ddq, static_cast<uint64_t>(ddq));
      }
      if (st && st->q_trace) st->q_trace->push_back(q);
      ++out.texels_visited;
      const uint32_t w = texel_weight(su, cfg, q, xi, eta);
      if (st && cfg.clip) {
        const Border b = border(su, q, xi, eta);
        st->max_abs_g = std::max({st->max_abs_g, int64_t(std::abs(b.gu)), int64_t(std::abs(b.gv))});
        st->max_root = std::max({st->max_root, uint64_t(b.r), uint64_t(b.g)});
      }
      if (w > 0) {
        ++out.texels_inside;
        const img::Rgba8 px = texels.at(x);
        acc[0] += uint64_t(w) * px.r, acc[1] += uint64_t(w) * px.g;
        acc[2] += uint64_t(w) * px.b, acc[3] += uint64_t(w) * px.a;
        sums.wsum += w;
      }
      if (!direct && x < su.x1) {  // Heckbert: first and second differences along x
        q += dq;
        dq += ddq;
        xi += int64_t(su.kxu) * kStep;
        eta += int64_t(su.kyu) * kStep;
      }
    }
  }
  if (st) {
    st->wsum = std::max(st->wsum, sums.wsum);
    st->max_acc = std::max({st->max_acc, acc[0], acc[1], acc[2], acc[3]});
  }
  finish(su, t, sums, &out);
  return out;
}

Out filter(const In& in, const tex::Texture& t, const Config& cfg, bool direct, WalkStats* st) {
  return walk(setup(in, t, cfg), t, cfg, direct, st);
}

In in_from_local(const ellipse::fx::Local& l, uint32_t laniso, uint32_t max_lod) {
  In in;
  const auto code = [](double x) {
    return floor_i64(std::ldexp(x, fmt::kTexUvF) + 0.5);
  };
  in.u = code(l.u);
  in.v = code(l.v);
  in.b2 = ellipse::fx::analytic(ellipse::fx::in_from_map(ellipse::fx::local_map(l), laniso, max_lod));
  return in;
}

ellipse::fx::Local footprint_local(double major, double aniso, double theta, double u, double v) {
  ellipse::fx::Local l;
  l.q = 0.5;
  const double c = std::cos(theta), s = std::sin(theta), minor = aniso > 0 ? major / aniso : 0;
  l.ux = c * major, l.vx = s * major, l.uy = -s * minor, l.vy = c * minor;
  l.u = u, l.v = v;
  return l;
}

In random_in(std::mt19937_64& rng) {
  auto l = ellipse::fx::random_local(rng);
  std::uniform_real_distribution<double> pos(-1024, 1024);
  l.u = pos(rng);
  l.v = pos(rng);
  return in_from_local(l, 4 << fmt::kEllLogF, rng() % 8 == 0 ? 12 : 8);
}

double theta_ref_b2(const ellipse::fx::Out& o) {
  const double d = double(o.ae) - double(o.ce), b = double(o.be);
  return d == 0 && b == 0 ? 0 : 0.5 * std::atan2(b, d) + M_PI / 2;
}

Result filter_ref_b2(const In& in, const tex::Texture& t, uint32_t max_texels, bool clip) {
  return filter_ref_b2(in, t, Params{16, static_cast<int>(max_texels), clip});
}
Result filter_ref_b2(const In& in, const tex::Texture& t, const Params& p) {
  const auto& o = in.b2;
  const double u = std::ldexp(double(in.u), -fmt::kTexUvF), v = std::ldexp(double(in.v), -fmt::kTexUvF);
  if ((o.flags & ellipse::fx::kHorizon) || o.lmaj == ellipse::fx::kLogNegInf)
    return filter_axes(t, u, v, 1, 1, 0, p);
  const double theta = theta_ref_b2(o);
  const double s1 = std::exp2(ellipse::fx::log_value(o.lmaj));
  const double s2 = o.lmin == ellipse::fx::kLogNegInf ? 0 : std::exp2(ellipse::fx::log_value(o.lmin));
  return filter_axes(t, u, v, s1, s2, theta, p);
}

double theta_value(int32_t theta) { return std::ldexp(double(theta), -kAngW) * 2 * M_PI; }

}  // namespace tu::ewa::fx
