#include "persp/texel_depth.hpp"

#include <algorithm>
#include <bit>

namespace tu::persp::texel_depth {

namespace {
using P = Unit::P;
using Q = Unit::Q;
using N1 = UFixed<fmt::kPerspXyW + 1, 0>;  // span offsets 0..4096
constexpr int64_t kGuard = int64_t(1) << (fmt::kPerspF - fmt::kPerspGuardLog2);

Unit::Acc at(const Unit::Acc& s0, P a, P d, Q g, int m) {
  const N1 n = N1::from_raw(m);
  return {(s0.pu + a * n).as<P>(), (s0.pv + d * n).as<P>(), (s0.q + g * n).as<Q>()};
}
}  // namespace

Span record(int64_t q1, int64_t q2, const int64_t t1[2], const int64_t t2[2], int m2) {
  Span s;
  s.m2 = m2;
  s.t1[0] = t1[0], s.t1[1] = t1[1], s.t2[0] = t2[0], s.t2[1] = t2[1];
  s.q1 = q1, s.q2 = q2;
  s.guard = q1 < kGuard || q2 < kGuard;
  return s;
}

Span setup(const Unit::Acc& s0, P a, P d, Q g, int m2) {
  const Unit::Acc s1 = at(s0, a, d, g, m2);
  const Pixel p1 = Unit::pixel(s0), p2 = Unit::pixel(s1);
  const int64_t t1[2] = {p1.u, p1.v}, t2[2] = {p2.u, p2.v};
  // record()'s guard is B1's flag at the ends (B1 flags exactly q < 2^-PerspGuardLog2).
  return record(static_cast<int64_t>(s0.q.raw()), static_cast<int64_t>(s1.q.raw()), t1, t2, m2);
}

uint64_t w_code(const Span& s, int m) {
  constexpr uint64_t kOne = uint64_t(1) << kWF;
  if (m <= 0 || s.m2 <= 0) return 0;
  if (m >= s.m2) return kOne;
  const i128 num = static_cast<i128>(m) * s.q2;                                      // N = m q2 > 0
  const i128 den = static_cast<i128>(s.m2) * s.q1 + static_cast<i128>(m) * (s.q2 - s.q1);  // D = m2 q(m) > 0
  const int e = 127 - std::countl_zero(static_cast<u128>(den));
  constexpr int mb = fmt::kRecipMantW - 1;
  const u128 mant = e >= mb ? static_cast<u128>(den) >> (e - mb) : static_cast<u128>(den) << (mb - e);  // truncate
  const i128 r = recip::core(recip::Mant::from_raw(static_cast<i128>(mant))).raw();
  // w = N R 2^(-RecipOutF - e); code with kWF fraction bits, round half up.
  const int sh = fmt::kRecipOutF + e - kWF;
  const i128 prod = num * r;
  const i128 w = sh > 0 ? (prod + (i128(1) << (sh - 1))) >> sh : prod << -sh;
  return static_cast<uint64_t>(std::clamp<i128>(w, 0, static_cast<i128>(kOne)));
}

Pixel pixel(const Span& s, int m) {
  if (s.guard) return {static_cast<int64_t>(Uv::kMaxRaw), static_cast<int64_t>(Uv::kMaxRaw), true};
  const i128 w = static_cast<i128>(w_code(s, m));
  auto lerp = [&](int c) {
    const i128 d = static_cast<i128>(s.t2[c]) - s.t1[c];
    const i128 t = s.t1[c] + ((d * w + (i128(1) << (kWF - 1))) >> kWF);
    return static_cast<int64_t>(std::clamp<i128>(t, Uv::kMinRaw, Uv::kMaxRaw));
  };
  return {lerp(0), lerp(1), false};
}

void pixel_ref(const Coef9& k, int y, int x0, int x1, int x, double* u, double* v) {
  double u1, v1, q1, u2, v2, q2;
  eval_ref(k, x0, y, &u1, &v1, &q1);
  eval_ref(k, x1, y, &u2, &v2, &q2);
  const double z1 = 1 / q1, z2 = 1 / q2;  // depths (up to a common scale, which cancels)
  const double s = x1 == x0 ? 0 : static_cast<double>(x - x0) / static_cast<double>(x1 - x0);
  const double w = z1 * s / (z2 - s * (z2 - z1));  // eq. 2.32
  *u = u1 + (u2 - u1) * w;
  *v = v1 + (v2 - v1) * w;
}

}  // namespace tu::persp::texel_depth
