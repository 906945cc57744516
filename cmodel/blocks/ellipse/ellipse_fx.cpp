#include "ellipse_fx.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "reciprocal/reciprocal.hpp"

namespace tu::ellipse::fx {

namespace {
constexpr int kPF = fmt::kPerspF;
constexpr int kNF = fmt::kEllNumF;
constexpr int kL1 = fmt::kEllLogF + 1;  // internal log fraction bits
constexpr int64_t kGuard = int64_t(1) << (kPF - fmt::kPerspGuardLog2);

// Leading-one position of x > 0 (__builtin_clzll: no zero test, x > 0 by contract).
int msb64(uint64_t x) { return 63 - __builtin_clzll(x); }
int msb(u128 x) {  // x > 0
  const uint64_t hi = static_cast<uint64_t>(x >> 64);
  return hi ? 127 - __builtin_clzll(hi) : msb64(static_cast<uint64_t>(x));
}
i128 sat(i128 v, int w) {
  const i128 hi = (i128(1) << (w - 1)) - 1, lo = -(i128(1) << (w - 1));
  return std::clamp(v, lo, hi);
}
int64_t sat64(int64_t v, int w) {
  const int64_t hi = (int64_t(1) << (w - 1)) - 1;
  return std::clamp(v, -hi - 1, hi);
}
i128 rnd(i128 v, int d) { return detail::shift_round(v, d, Round::HalfUp); }
// Top `w` bits of x > 0 (truncated or zero-filled): a mantissa 1.(w-1).
u128 top_bits(u128 x, int w) {
  const int p = msb(x);
  return p >= w - 1 ? x >> (p - (w - 1)) : x << ((w - 1) - p);
}
// 64-bit forms for values proven below 2^64 (the per-pixel path: docs/performance.md §2).
// Top `w` bits of x > 0 whose leading one is at p = msb64(x), as top_bits.
uint64_t top64(uint64_t x, int p, int w) { return p >= w - 1 ? x >> (p - (w - 1)) : x << ((w - 1) - p); }
// log2_frac_serial is non-decreasing in m (a truncated square keeps the order, and a bit that
// differs makes the larger mantissa's result larger), so it is a staircase of 2^kL1 steps over
// the mantissas: kStep[k] = the smallest mantissa whose result is >= k. A mantissa's bucket (its
// top kL1 fraction bits) is at most 1.5 steps wide (d result / d m <= 2^kL1 / (2^(mw-1) ln 2)),
// so from the result at the bucket's first mantissa two branch-free steps reach the answer (the
// constructor checks that no bucket holds more than two steps).
struct Log2Table {
  static constexpr int kMw = fmt::kEllLogMantW;
  static constexpr int kSteps = 1 << kL1;
  static constexpr int kBucketShift = kMw - 1 - kL1;
  std::vector<uint32_t> step;       // kSteps + 1 entries, step[kSteps] = 2^mw (sentinel)
  std::vector<uint16_t> at_bucket;  // result at each bucket's first mantissa
  Log2Table() : step(kSteps + 1), at_bucket(kSteps) {
    const uint64_t lo = uint64_t(1) << (kMw - 1), hi = uint64_t(1) << kMw;
    step[0] = static_cast<uint32_t>(lo);
    step[kSteps] = static_cast<uint32_t>(hi);
    for (int k = 1; k < kSteps; ++k) {  // bisection for the first mantissa reaching k
      uint64_t a = step[k - 1], b = hi;  // result(a) < k or a is the lowest candidate
      while (a < b) {
        const uint64_t mid = a + (b - a) / 2;
        if (log2_frac_serial(mid) >= static_cast<uint32_t>(k)) b = mid;
        else a = mid + 1;
      }
      step[k] = static_cast<uint32_t>(a);
    }
    for (int i = 0; i < kSteps; ++i)
      at_bucket[i] = static_cast<uint16_t>(log2_frac_serial(lo + (uint64_t(i) << kBucketShift)));
    for (int i = 0; i < kSteps; ++i) {
      const uint64_t last = lo + (uint64_t(i + 1) << kBucketShift) - 1;
      if (log2_frac_serial(last) > at_bucket[i] + 2u)
        throw std::logic_error("log2 table: a bucket holds more than two steps");
    }
  }
  uint32_t frac(uint64_t m) const {
    uint32_t k = at_bucket[(m >> kBucketShift) & (kSteps - 1)];
    k += m >= step[k + 1];  // k + 1 <= kSteps: step[kSteps] is the sentinel 2^mw > m
    k += m >= step[k + 1];
    return k;
  }
};
// Built on first use (a few milliseconds); inlined: the per-pixel path fetches it once.
[[gnu::always_inline]] inline const Log2Table& log2_table() {
  static const Log2Table t;
  return t;
}
// log2 unit on a value below 2^64 and on any value (the same bits as log2_fx_serial).
int64_t log2_64(const Log2Table& lt, uint64_t x) {
  const int p = msb64(x);
  return int64_t(p) * (1 << kL1) + lt.frac(top64(x, p, fmt::kEllLogMantW));
}
int64_t log2_128(const Log2Table& lt, u128 x) {
  const uint64_t hi = static_cast<uint64_t>(x >> 64);
  if (hi == 0) return log2_64(lt, static_cast<uint64_t>(x));
  const int p = 64 + msb64(hi);  // > EllLogMantW - 1: the mantissa is a right shift
  return int64_t(p) * (1 << kL1) + lt.frac(static_cast<uint64_t>(x >> (p - (fmt::kEllLogMantW - 1))));
}
// Floor square root of x < 2^52 (exact in a double; the correctly rounded root is then off by
// at most one): the 64-bit form of isqrt.
uint64_t isqrt52(uint64_t x) {
  uint64_t r = static_cast<uint64_t>(std::sqrt(static_cast<double>(static_cast<int64_t>(x))));
  while (r * r > x) --r;
  while ((r + 1) * (r + 1) <= x) ++r;
  return r;
}
// Reciprocal of a positive value x (raw): R (u25.24) and e = msb(x) so that 1/x ~ R 2^(-24-e).
uint64_t recip_of(u128 x, int* e) {
  *e = msb(x);
  const u128 m = top_bits(x, fmt::kRecipMantW);
  return static_cast<uint64_t>(recip::core(recip::Mant::from_raw(static_cast<i128>(m))).raw());
}

// Ellipse from the numerators (or Jacobian entries): exact sums at 2 NumF fraction bits, output
// in block floating point: codes = sums >> k (floor), k = max(0, msb(Ae'+Ce') - 61).
struct Ell {
  i128 a, b, c;  // exact
  u128 s;        // a + c
  u128 px, py;   // GL LOD: sums by screen axis, nUx^2 + nVx^2 and nUy^2 + nVy^2 (exact)
};
Ell ellipse_of(int64_t ux, int64_t vx, int64_t uy, int64_t vy) {
  const i128 uxx = i128(ux) * ux, vxx = i128(vx) * vx, uyy = i128(uy) * uy, vyy = i128(vy) * vy;
  const i128 a = vxx + vyy, c = uxx + uyy;
  const i128 b = -2 * (i128(ux) * vx + i128(uy) * vy);
  return {a, b, c, static_cast<u128>(a) + static_cast<u128>(c), static_cast<u128>(uxx + vxx),
          static_cast<u128>(uyy + vyy)};
}
void set_ellipse(const Ell& el, int ps, Out* o) {  // ps = msb(el.s), or -1 for s = 0
  const int k = std::max(0, ps - (fmt::kEllCoefW - 3));
  o->ae = static_cast<uint64_t>(el.a >> k);
  o->ce = static_cast<uint64_t>(el.c >> k);
  o->be = static_cast<int64_t>(el.b >> k);
  o->eexp = static_cast<uint32_t>(k);
}

// The shared LOD unit. lf: log2|f| (kL1 fraction bits) or none (f == 0); lq: log2 q (0 for the
// forward difference, whose ellipse is not scaled).
// ps = msb(el.s) (-1 for s = 0).
void lod_unit(const Log2Table& lt, const In& in, const Ell& el, int ps, bool f_zero, int64_t lf, int64_t lq, Out* o) {
  {  // GL LOD: log2 rho = (log2 max(Px', Py') - 4 log2 q) / 2 (Px' = Py' = 0 iff s = 0)
    const u128 pm = std::max(el.px, el.py);
    o->lrho = pm == 0 ? kLogNegInf
                      : static_cast<int32_t>(sat64((log2_128(lt, pm) - int64_t(2 * kNF) * (1 << kL1) - 4 * lq) >> 2,
                                                   fmt::kEllLogW));
  }
  if (ps < 0) {
    o->flags |= kDegenerate | kMagnify;
    o->lmaj = o->lmin = kLogNegInf;
    o->lod = 0;
    return;
  }
  const i128 d = el.a - el.c, b = el.b;
  const int k = std::max(0, ps - (fmt::kEllNrmW - 1));
  // After the shift sn = s >> k < 2^NrmW, and |d|, |b| <= s (|b| <= s by 2|xy| <= x^2 + y^2), so
  // |dn|, |bn| <= 2^NrmW (a floor shift of a negative value may add one): dn^2 + bn^2 <= 2^(2 NrmW
  // + 1) < 2^52 and lam < 2^(NrmW + 2), all exact in 64 bits (SpeedEquivalence.AnalyticEqualsWideDefinition).
  static_assert(2 * fmt::kEllNrmW + 1 < 52, "isqrt52: the LOD unit's radicand is below 2^52");
  const uint64_t sn = static_cast<uint64_t>(el.s >> k);
  const int64_t dn = static_cast<int64_t>(d >> k), bn = static_cast<int64_t>(b >> k);
  const uint64_t r = isqrt52(static_cast<uint64_t>(dn * dn + bn * bn));
  const uint64_t lam = sn + r;  // 2 lambda_max, scaled by 2^(k - NumF)
  const int64_t ll = log2_64(lt, lam) + int64_t(k - 2 * kNF - 1) * (1 << kL1);  // log2 lambda_max
  const int64_t lmaj2 = ll - 4 * lq;                                     // 2 log2 major
  auto to_out = [](int64_t l2) {  // 2 log2 (kL1 frac) -> log2 (EllLogF frac), floor, saturate
    return static_cast<int32_t>(sat64(l2 >> 2, fmt::kEllLogW));
  };
  const int32_t lmaj = to_out(lmaj2);
  const int32_t cap = static_cast<int32_t>(sat64(int64_t(lmaj) - in.laniso, fmt::kEllLogW));
  int32_t lmin;
  if (f_zero) {
    o->flags |= kDegenerate | kAnisoClamp;
    lmin = cap;
  } else {
    lmin = to_out(2 * lf - ll);  // 2 log2 minor = log2 Fe' - log2 lambda_max
    if (cap > lmin) {
      o->flags |= kAnisoClamp;
      lmin = cap;
    }
  }
  o->lmaj = lmaj;
  o->lmin = lmin;
  const int32_t lod = lmin >> (fmt::kEllLogF - fmt::kEllLodF);
  const int32_t top = static_cast<int32_t>(in.max_lod) << fmt::kEllLodF;
  if (lod < 0) {
    o->flags |= kMagnify;
    o->lod = 0;
  } else if (lod > top) {
    o->flags |= kLodSat;
    o->lod = static_cast<uint32_t>(top);
  } else {
    o->lod = static_cast<uint32_t>(lod);
  }
}

// |f| = af * 2^exp_off (af < 2^64 with its leading one at p): mantissa 1.31 truncated, exponent.
void set_f64(uint64_t af, int p, int exp_off, Out* o) {
  o->fm = static_cast<uint32_t>(top64(af, p, fmt::kEllFmW));
  o->fexp = std::clamp(p + exp_off, -(1 << (fmt::kEllFexpW - 1)), (1 << (fmt::kEllFexpW - 1)) - 1);
}
}  // namespace

ExactNum numerators_direct(const Coefs& c, int x, int y) { return numerators_at(c, persp::Unit::direct(c, x, y)); }

ExactNum numerators_at(const Coefs& c, const persp::Unit::Acc& s) {
  const i128 pu = s.pu.raw(), pv = s.pv.raw(), q = s.q.raw();
  return {c.a.raw() * q - c.g.raw() * pu, c.d.raw() * q - c.g.raw() * pv,
          c.b.raw() * q - c.h.raw() * pu, c.e.raw() * q - c.h.raw() * pv};
}

std::vector<ExactNum> numerators_span(const Coefs& c, int x0, int y, int n) {
  const i128 a = c.a.raw(), b = c.b.raw(), cc = c.c.raw(), d = c.d.raw(), e = c.e.raw(),
             f = c.f.raw(), g = c.g.raw(), h = c.h.raw(), i = c.i.raw();
  const i128 m = a * h - b * g, nn = d * h - e * g;  // per triangle
  // per scanline
  const i128 nux = a * i - cc * g + m * y, nvx = d * i - f * g + nn * y;
  i128 nuy = b * i - cc * h - m * x0, nvy = e * i - f * h - nn * x0;
  std::vector<ExactNum> out;
  for (int k = 0; k < n; ++k) {  // per pixel
    out.push_back({nux, nvx, nuy, nvy});
    nuy -= m;
    nvy -= nn;
  }
  return out;
}

int64_t round_num(i128 n) {  // half up (floor of n + half), saturated; the same as rnd then sat
  constexpr int d = 2 * kPF - kNF;
  return static_cast<int64_t>(sat((n + (i128(1) << (d - 1))) >> d, fmt::kEllNumW));
}

namespace {
// Normalise an exact value v * 2^-f to the det3 float format (truncating the magnitude).
void det_norm(i128 v, int f, int64_t* dm, int32_t* dexp) {
  if (v == 0) {
    *dm = 0;
    *dexp = 0;
    return;
  }
  const u128 av = static_cast<u128>(v < 0 ? -v : v);
  const int p = msb(av);
  const int64_t m = static_cast<int64_t>(top_bits(av, fmt::kEllDetW - 1));
  *dm = v < 0 ? -m : m;
  *dexp = p - f;
}
}  // namespace

Det3 det3(const Coefs& c) {
  Det3 d;
  det3(c, &d.dm, &d.dexp);
  return d;
}

void det3(const Coefs& c, int64_t* dm, int32_t* dexp) {
  const i128 a = c.a.raw(), b = c.b.raw(), cc = c.c.raw(), d = c.d.raw(), e = c.e.raw(),
             f = c.f.raw(), g = c.g.raw(), h = c.h.raw(), i = c.i.raw();
  const i128 m1 = rnd(e * i - f * h, kPF), m2 = rnd(d * i - f * g, kPF), m3 = rnd(d * h - e * g, kPF);
  det_norm(a * m1 - b * m2 + cc * m3, 2 * kPF, dm, dexp);
}

double det3_value(const In& in) {
  return std::ldexp(static_cast<double>(in.dm), in.dexp - (fmt::kEllDetW - 2));
}

In make_in(const Coefs& c, int x, int y, uint32_t laniso, uint32_t max_lod) {
  return make_in(c, persp::Unit::direct(c, x, y), det3(c), laniso, max_lod);
}

In make_in(const Coefs& c, const persp::Unit::Acc& s, const Det3& d, uint32_t laniso, uint32_t max_lod) {
  const auto n = numerators_at(c, s);
  In in;
  in.nux = round_num(n.nux);
  in.nvx = round_num(n.nvx);
  in.nuy = round_num(n.nuy);
  in.nvy = round_num(n.nvy);
  in.q = static_cast<int64_t>(s.q.raw());
  in.dm = d.dm;
  in.dexp = d.dexp;
  in.laniso = laniso;
  in.max_lod = max_lod;
  return in;
}

Coef9 local_map(const Local& l) {
  // u = pu / q with pu = u q at the pixel: Ux = (A - G u) / q  ->  A = q Ux + G u, etc.
  return {l.q * l.ux + l.g * l.u, l.q * l.uy + l.h * l.u, l.u * l.q,
          l.q * l.vx + l.g * l.v, l.q * l.vy + l.h * l.v, l.v * l.q, l.g, l.h, l.q};
}

namespace {
int64_t code(double v, int f, int w) {
  const long double x = std::nearbyint(std::ldexp(static_cast<long double>(v), f));
  const long double lim = std::ldexp(1.0L, w - 1);
  if (!(x > -lim)) return static_cast<int64_t>(-lim);
  if (x > lim - 1) return static_cast<int64_t>(lim - 1);
  return static_cast<int64_t>(x);
}
}  // namespace

int64_t q_code(double v) { return code(v, kPF, fmt::kPerspQW); }

In in_from_map(const Coef9& k, uint32_t laniso, uint32_t max_lod) {
  const auto n = ellipse::numerators(k, 0, 0);
  In in;
  in.nux = code(n.nux, kNF, fmt::kEllNumW);
  in.nvx = code(n.nvx, kNF, fmt::kEllNumW);
  in.nuy = code(n.nuy, kNF, fmt::kEllNumW);
  in.nvy = code(n.nvy, kNF, fmt::kEllNumW);
  in.q = q_code(n.q);
  {
    int ex;
    const double m = std::frexp(ellipse::det3(k), &ex);  // |m| in [0.5, 1)
    det_norm(static_cast<i128>(std::ldexp(m, 62)), 62 - ex, &in.dm, &in.dexp);
  }
  in.laniso = laniso;
  in.max_lod = max_lod;
  return in;
}

Local random_local(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> U(0, 1);
  Local l;
  l.q = std::exp2(-9 * U(rng));
  const double s1 = std::min(std::exp2(-6 + 20 * U(rng)), std::exp2(13) / (l.q * l.q));
  const double s2 = s1 * std::exp2(-10 * U(rng) * U(rng));
  const double t = 2 * M_PI * U(rng), p = 2 * M_PI * U(rng), sg = U(rng) < 0.5 ? -1 : 1;
  // J = R(t) diag(s1, sg s2) R(p)
  const double ct = std::cos(t), st = std::sin(t), cp = std::cos(p), sp = std::sin(p);
  l.ux = ct * s1 * cp - st * sg * s2 * sp;
  l.uy = -ct * s1 * sp - st * sg * s2 * cp;
  l.vx = st * s1 * cp + ct * sg * s2 * sp;
  l.vy = -st * s1 * sp + ct * sg * s2 * cp;
  l.g = l.q * (U(rng) - 0.5) / 32;
  l.h = l.q * (U(rng) - 0.5) / 32;
  l.u = (U(rng) - 0.5) * 8192;
  l.v = (U(rng) - 0.5) * 8192;
  return l;
}

uint32_t log2_frac_serial(uint64_t m) {
  constexpr int mw = fmt::kEllLogMantW;
  uint32_t fr = 0;
  for (int i = 0; i < kL1; ++i) {
    m = static_cast<uint64_t>((u128(m) * m) >> (mw - 1));
    const bool bit = m >> mw;
    if (bit) m >>= 1;
    fr = (fr << 1) | (bit ? 1 : 0);
  }
  return fr;
}

uint32_t log2_frac(uint64_t m) { return log2_table().frac(m); }

int64_t log2_fx_serial(u128 x) {
  return int64_t(msb(x)) * (1 << kL1) +
         log2_frac_serial(static_cast<uint64_t>(top_bits(x, fmt::kEllLogMantW)));
}

int64_t log2_fx(u128 x) { return log2_128(log2_table(), x); }

uint64_t isqrt_serial(u128 x) {
  u128 r = 0;
  for (int b = 63; b >= 0; --b) {
    const u128 t = r | (u128(1) << b);
    if (t * t <= x) r = t;
  }
  return static_cast<uint64_t>(r);
}

uint64_t isqrt(u128 x) {
  // Floating-point estimate, then exact integer correction (the loops make any estimate exact; a
  // close one makes them short). Below 2^52 x is exact in a double and the correctly rounded root
  // is off by at most one; below 2^104 a double estimate is within a few units of a root < 2^52;
  // above, the 64-bit long double significand keeps the estimate within a few units of the root.
  if (x < (u128(1) << 52)) return isqrt52(static_cast<uint64_t>(x));
  uint64_t r;
  if (x < (u128(1) << 104)) {  // a double estimate (relative error ~2^-52: within a unit or two of the root)
    const double xd = static_cast<double>(static_cast<uint64_t>(x >> 64)) * 0x1p64 + static_cast<double>(static_cast<uint64_t>(x));
    r = static_cast<uint64_t>(std::sqrt(xd));
  } else {
    const long double e = std::sqrt(static_cast<long double>(x));
    r = e >= 0x1p64L ? ~uint64_t(0) : static_cast<uint64_t>(e);
  }
  while (u128(r) * r > x) --r;
  while (r != ~uint64_t(0) && u128(r + 1) * (r + 1) <= x) ++r;
  return r;
}

Out analytic(const In& in) {
  Out o;
  if (in.q < kGuard) {
    o.flags = kHorizon;
    return o;
  }
  const Ell el = ellipse_of(in.nux, in.nvx, in.nuy, in.nvy);
  const int ps = el.s == 0 ? -1 : msb(el.s);
  set_ellipse(el, ps, &o);
  const Log2Table& lt = log2_table();
  // q in [kGuard, 2^(PerspQW-1)): 64-bit; its B1 mantissa m (truncated) and R = recip(m).
  const uint64_t q = static_cast<uint64_t>(in.q);
  const int e = msb64(q);
  const uint64_t mq = top64(q, e, fmt::kRecipMantW);
  const uint64_t r = static_cast<uint64_t>(recip::core(recip::Mant::from_raw(static_cast<i128>(mq))).raw());
  // f = det3 / q = p * 2^(dexp - (DetW-2) - RecipOutF + PerspF - e). |dm| <= 2^(DetW-1) (s40) and
  // R <= 2^RecipOutF (R <= 1), so |p| <= 2^63: |p| is exact in 64 bits (SpeedEquivalence.AnalyticEqualsWideDefinition).
  static_assert(fmt::kEllDetW - 1 + fmt::kRecipOutF <= 63, "|dm| R fits 64 bits");
  const int off = in.dexp - (fmt::kEllDetW - 2) - fmt::kRecipOutF + kPF - e;
  const uint64_t ap = (in.dm < 0 ? uint64_t(0) - static_cast<uint64_t>(in.dm) : static_cast<uint64_t>(in.dm)) * r;
  int64_t lf = 0;
  if (ap != 0) {
    const int pa = msb64(ap);
    set_f64(ap, pa, off, &o);
    lf = int64_t(pa + off) * (1 << kL1) + lt.frac(top64(ap, pa, fmt::kEllLogMantW));
  }
  // log2 q from the same (truncated) mantissa B1 uses: q ~ m 2^(e - (MantW-1) - PerspF); m's
  // leading one is at MantW - 1, so log2 m = (MantW - 1) + frac(m).
  static_assert(fmt::kRecipMantW == fmt::kEllLogMantW, "log2 q: B1's mantissa is the log2 unit's");
  const int64_t lq = int64_t(e - kPF) * (1 << kL1) + lt.frac(mq);
  lod_unit(lt, in, el, ps, ap == 0, lf, lq, &o);
  return o;
}

In rec_front(const In& in, int64_t qg, int64_t qh) {
  In f = in;
  if (in.q < kGuard || qg < kGuard || qh < kGuard) {
    f.q = 0;  // the back end's horizon guard: Out{flags = kHorizon}
    return f;
  }
  // U = n * 2^(2 PerspF) / dX, dX = q (q + G) (2 PerspF fraction bits): n R 2^(2 PF - 24 - e)
  auto col = [&](int64_t qq, int64_t n1, int64_t n2, int64_t* u1, int64_t* u2) {
    int e;
    const uint64_t r = recip_of(static_cast<u128>(i128(in.q) * qq), &e);
    const int sh = fmt::kRecipOutF + e - 2 * kPF;  // in [4, 30] for every unguarded q
    *u1 = static_cast<int64_t>(sat(rnd(i128(n1) * r, sh), fmt::kEllNumW));
    *u2 = static_cast<int64_t>(sat(rnd(i128(n2) * r, sh), fmt::kEllNumW));
  };
  col(qg, in.nux, in.nvx, &f.nux, &f.nvx);
  col(qh, in.nuy, in.nvy, &f.nuy, &f.nvy);
  f.q = int64_t(1) << kPF;  // q := 1: log2 q = 0, 1/q = R(1.0) = 1 exactly
  det_norm(i128(f.nux) * f.nvy - i128(f.nuy) * f.nvx, 2 * kNF, &f.dm, &f.dexp);
  return f;
}

Out recurrence(const In& in, int64_t qg, int64_t qh) { return analytic(rec_front(in, qg, qh)); }

Out forward_difference(const In& in, int64_t g, int64_t h) { return recurrence(in, in.q + g, in.q + h); }

Out pixel(const Coefs& c, int x, int y, uint32_t laniso, uint32_t max_lod, bool recurrence) {
  return pixel(c, persp::Unit::direct(c, x, y), det3(c), laniso, max_lod, recurrence);
}

Out pixel(const Coefs& c, const persp::Unit::Acc& s, const Det3& d, uint32_t laniso, uint32_t max_lod, bool recurrence) {
  const In in = make_in(c, s, d, laniso, max_lod);
  return recurrence ? forward_difference(in, static_cast<int64_t>(c.g.raw()), static_cast<int64_t>(c.h.raw()))
                    : analytic(in);
}

double lod_value(const Out& o) { return std::ldexp(double(o.lod), -fmt::kEllLodF); }
double log_value(int32_t l) { return l == kLogNegInf ? -INFINITY : std::ldexp(double(l), -fmt::kEllLogF); }
double fe_value(const Out& o) {
  const double f = std::ldexp(double(o.fm), o.fexp - (fmt::kEllFmW - 1));
  return f * f;
}

}  // namespace tu::ellipse::fx

namespace tu::ellipse::fx {
double coef_value(double code, const Out& o) {
  return std::ldexp(code, static_cast<int>(o.eexp) - 2 * fmt::kEllNumF);
}
}  // namespace tu::ellipse::fx
