// texunit fixed-point arithmetic: a small header-only type for bit-accurate models.
//
// Fixed<W, F, S>: a W-bit two's-complement (S = true) or unsigned (S = false) number with F
// fraction bits, value = raw * 2^-F. W is 1..126; F may be negative or larger than W, as in
// SystemC (integer bits I = W - F may be negative).
//
// Semantics (proven bit-identical to sc_fixed/sc_ufixed by testbench/unit/fixed_sc_test.cpp):
//   * a + b, a - b, a * b are exact: the result format widens to hold every possible value
//     (sum: max integer bits + 1, max fraction bits; product: W1 + W2, F1 + F2). A difference
//     is always signed.
//   * every narrowing is an explicit cast<W2, F2, S2, Round, Overflow>() that states its rounding
//     (Round::Trunc = SC_TRN, toward -inf; Round::HalfUp = SC_RND, ties toward +inf;
//     Round::HalfEven = SC_RND_CONV; Round::HalfZero = SC_RND_ZERO; Round::TruncZero = SC_TRN_ZERO)
//     and overflow (Ovf::Wrap = SC_WRAP, Ovf::Sat = SC_SAT).
//   * shl<n>() / shr<n>() rescale exactly (same raw bits, F -/+ n), like sc_fixed's << and >>
//     followed by an assignment; narrowing afterwards is again an explicit cast.
// Storage is int64_t when the value fits in 63 bits and __int128 otherwise, so the common case
// runs at plain-integer speed.
#pragma once

#include <cmath>
#include <cstdint>
#include <type_traits>

namespace tu {

enum class Round { Trunc, HalfUp, HalfEven, HalfZero, TruncZero };
enum class Ovf { Wrap, Sat };

using i128 = __int128;
using u128 = unsigned __int128;

namespace detail {
constexpr int imax(int a, int b) { return a > b ? a : b; }

// floor(v / 2^d) with the requested rounding, d >= 1, v in i128.
constexpr i128 shift_round(i128 v, int d, Round r) {
  if (d <= 0) return v;
  if (d >= 126) {  // every bit leaves: result is 0 or -1 (or rounding thereof)
    switch (r) {
      case Round::Trunc: return v < 0 ? -1 : 0;
      default: return 0;  // |v| < 2^126 <= half an LSB is never reached for valid values
    }
  }
  const i128 one = 1;
  const i128 mask = (one << d) - 1;
  const i128 floor_q = v >> d;  // arithmetic shift: floor
  const i128 rem = v & mask;    // 0 .. 2^d - 1, v = floor_q * 2^d + rem
  const i128 half = one << (d - 1);
  switch (r) {
    case Round::Trunc: return floor_q;
    case Round::TruncZero: return (v < 0 && rem != 0) ? floor_q + 1 : floor_q;
    case Round::HalfUp: return rem >= half ? floor_q + 1 : floor_q;
    case Round::HalfZero:
      if (rem > half) return floor_q + 1;
      if (rem < half) return floor_q;
      return v < 0 ? floor_q + 1 : floor_q;  // tie: toward zero
    case Round::HalfEven:
      if (rem > half) return floor_q + 1;
      if (rem < half) return floor_q;
      return (floor_q & 1) ? floor_q + 1 : floor_q;
  }
  return floor_q;
}

constexpr i128 wrap_to(i128 v, int w, bool s) {
  const u128 mask = (w >= 128) ? ~u128(0) : ((u128(1) << w) - 1);
  u128 u = static_cast<u128>(v) & mask;
  if (s && w < 128 && ((u >> (w - 1)) & 1)) u |= ~mask;  // sign-extend
  return static_cast<i128>(u);
}
}  // namespace detail

template <int W, int F, bool S>
class Fixed {
  static_assert(W >= 1 && W <= 126, "Fixed: word length must be 1..126");

 public:
  static constexpr int kW = W;
  static constexpr int kF = F;
  static constexpr bool kS = S;
  static constexpr int kI = W - F;
  using raw_t = std::conditional_t<(W + (S ? 0 : 1) <= 64), int64_t, i128>;

  static constexpr i128 kMinRaw = S ? -(i128(1) << (W - 1)) : i128(0);
  static constexpr i128 kMaxRaw = S ? (i128(1) << (W - 1)) - 1 : (i128(1) << W) - 1;

  constexpr Fixed() = default;

  // Raw two's-complement code; must already be in range (checked in debug builds by callers).
  static constexpr Fixed from_raw(i128 r) {
    Fixed f;
    f.raw_ = static_cast<raw_t>(r);
    return f;
  }
  // Raw code from the low W bits of an unsigned pattern (e.g. a hex field or an RTL port).
  static constexpr Fixed from_bits(uint64_t bits) {
    return from_raw(detail::wrap_to(static_cast<i128>(bits), W, S));
  }
  // Nearest representable value of a double, with the given rounding and overflow.
  template <Round R = Round::HalfEven, Ovf O = Ovf::Sat>
  static Fixed from_double(double x) {
    // x * 2^F is exact in long double (64-bit significand >= 53); split floor and remainder.
    const long double scaled = std::ldexp(static_cast<long double>(x), F);
    const long double lim = 0x1p124L;
    if (scaled >= lim) return from_raw(narrow<R, O>(i128(1) << 124, 0 + F));
    if (scaled <= -lim) return from_raw(narrow<R, O>(-(i128(1) << 124), 0 + F));
    const long double fl = std::floor(scaled);
    const long double rem = scaled - fl;  // exact, in [0, 1)
    // Encode value*4 = 4*floor + {0: rem==0, 1: 0<rem<.5, 2: rem==.5, 3: rem>.5}, round 2 bits.
    const int frac2 = rem == 0 ? 0 : rem < 0.5L ? 1 : rem == 0.5L ? 2 : 3;
    const i128 v = static_cast<i128>(fl) * 4 + frac2;
    return from_raw(narrow<R, O>(v, F + 2));
  }

  constexpr raw_t raw() const { return raw_; }
  constexpr uint64_t bits() const {  // low W bits (W <= 64)
    return static_cast<uint64_t>(static_cast<u128>(static_cast<i128>(raw_)) &
                                 ((W >= 64) ? ~u128(0) >> 64 : ((u128(1) << W) - 1)));
  }
  constexpr double to_double() const { return std::ldexp(static_cast<double>(raw_), -F); }
  constexpr long double to_ldouble() const {
    return std::ldexp(static_cast<long double>(raw_), -F);
  }

  // Round/overflow a raw code with f fraction bits into this format's raw code.
  template <Round R, Ovf O>
  static constexpr i128 narrow(i128 v, int f) {
    i128 q;
    if (f > F) q = detail::shift_round(v, f - F, R);
    else q = v << (F - f);  // exact widening (caller keeps within 126 bits)
    if constexpr (O == Ovf::Sat) {
      if (q > kMaxRaw) return kMaxRaw;
      if (q < kMinRaw) return kMinRaw;
      return q;
    } else {
      return detail::wrap_to(q, W, S);
    }
  }

  template <int W2, int F2, bool S2, Round R = Round::Trunc, Ovf O = Ovf::Wrap>
  constexpr Fixed<W2, F2, S2> cast() const {
    return Fixed<W2, F2, S2>::from_raw(Fixed<W2, F2, S2>::template narrow<R, O>(raw_, F));
  }
  // Cast into the format of another Fixed type.
  template <class T, Round R = Round::Trunc, Ovf O = Ovf::Wrap>
  constexpr T as() const {
    return cast<T::kW, T::kF, T::kS, R, O>();
  }

  // Exact rescaling by 2^n (same bits, moved binary point).
  template <int N>
  constexpr Fixed<W, F - N, S> shl() const {
    return Fixed<W, F - N, S>::from_raw(raw_);
  }
  template <int N>
  constexpr Fixed<W, F + N, S> shr() const {
    return Fixed<W, F + N, S>::from_raw(raw_);
  }

  // Bit-select helpers for hardware-style slicing of the raw code (unsigned field).
  constexpr uint64_t slice(int lsb, int width) const {
    return static_cast<uint64_t>((static_cast<u128>(static_cast<i128>(raw_)) >> lsb) &
                                 ((u128(1) << width) - 1));
  }

  friend constexpr bool operator==(Fixed a, Fixed b) { return a.raw_ == b.raw_; }

 private:
  raw_t raw_ = 0;
};

template <int W, int F>
using SFixed = Fixed<W, F, true>;
template <int W, int F>
using UFixed = Fixed<W, F, false>;

namespace detail {
// Format of an exact sum of two formats.
template <int W1, int F1, bool S1, int W2, int F2, bool S2, bool Sub>
struct SumFmt {
  static constexpr bool s = S1 || S2 || Sub;
  // An unsigned operand entering a signed result needs one more integer bit.
  static constexpr int i1 = (W1 - F1) + ((s && !S1) ? 1 : 0);
  static constexpr int i2 = (W2 - F2) + ((s && !S2) ? 1 : 0);
  static constexpr int f = imax(F1, F2);
  static constexpr int w = imax(i1, i2) + 1 + f;
};
template <int W1, bool S1, int W2, bool S2>
struct MulW {
  // signed x unsigned: W1 + W2 bits still hold every product exactly.
  static constexpr int w = W1 + W2;
};
}  // namespace detail

template <int W1, int F1, bool S1, int W2, int F2, bool S2>
constexpr auto operator+(Fixed<W1, F1, S1> a, Fixed<W2, F2, S2> b) {
  using Fm = detail::SumFmt<W1, F1, S1, W2, F2, S2, false>;
  using R = Fixed<Fm::w, Fm::f, Fm::s>;
  const i128 ra = static_cast<i128>(a.raw()) << (Fm::f - F1);
  const i128 rb = static_cast<i128>(b.raw()) << (Fm::f - F2);
  return R::from_raw(ra + rb);
}

template <int W1, int F1, bool S1, int W2, int F2, bool S2>
constexpr auto operator-(Fixed<W1, F1, S1> a, Fixed<W2, F2, S2> b) {
  using Fm = detail::SumFmt<W1, F1, S1, W2, F2, S2, true>;
  using R = Fixed<Fm::w, Fm::f, Fm::s>;
  const i128 ra = static_cast<i128>(a.raw()) << (Fm::f - F1);
  const i128 rb = static_cast<i128>(b.raw()) << (Fm::f - F2);
  return R::from_raw(ra - rb);
}

template <int W, int F, bool S>
constexpr auto operator-(Fixed<W, F, S> a) {
  using R = Fixed<W + 1, F, true>;
  return R::from_raw(-static_cast<i128>(a.raw()));
}

template <int W1, int F1, bool S1, int W2, int F2, bool S2>
constexpr auto operator*(Fixed<W1, F1, S1> a, Fixed<W2, F2, S2> b) {
  using R = Fixed<detail::MulW<W1, S1, W2, S2>::w, F1 + F2, S1 || S2>;
  return R::from_raw(static_cast<i128>(a.raw()) * static_cast<i128>(b.raw()));
}

template <int W1, int F1, bool S1, int W2, int F2, bool S2>
constexpr auto operator<=>(Fixed<W1, F1, S1> a, Fixed<W2, F2, S2> b) {
  constexpr int f = detail::imax(F1, F2);
  const i128 ra = static_cast<i128>(a.raw()) << (f - F1);
  const i128 rb = static_cast<i128>(b.raw()) << (f - F2);
  return ra <=> rb;
}

}  // namespace tu
