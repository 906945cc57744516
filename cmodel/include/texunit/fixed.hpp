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
// Storage is int64_t when the value fits in 64 two's-complement bits and __int128 otherwise.
// Every operator and cast picks its arithmetic type at compile time from the formats: int64_t
// when every intermediate provably fits in 64 two's-complement bits (a signed value of <= 64
// bits, an unsigned one of <= 63), __int128 only beyond, so the common case runs at
// plain-integer speed (testbench/bench/fixed_bench.cpp: against a hand-written int64 kernel).
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

// Two's-complement bits that hold every value of a W-bit signed/unsigned format.
constexpr int span_bits(int w, bool s) { return w + (s ? 0 : 1); }
// The narrowest arithmetic type holding every value of `bits` two's-complement bits.
template <int Bits>
using acc_t = std::conditional_t<(Bits <= 64), int64_t, i128>;

// floor(v / 2^d) with the requested rounding, d >= 1, v in T (int64_t or i128). The result
// never needs more bits than v (d >= 1 leaves room for the +1 of a rounding).
template <class T>
constexpr T shift_round(T v, int d, Round r) {
  if (d <= 0) return v;
  if constexpr (std::is_same_v<T, int64_t>) {
    if (d >= 63) return static_cast<T>(shift_round<i128>(v, d, r));  // rare: every bit leaves
  } else {
    if (d >= 126) {  // every bit leaves: result is 0 or -1 (or rounding thereof)
      switch (r) {
        case Round::Trunc: return v < 0 ? -1 : 0;
        default: return 0;  // |v| < 2^126 <= half an LSB is never reached for valid values
      }
    }
  }
  const T one = 1;
  const T mask = (one << d) - 1;
  const T floor_q = v >> d;  // arithmetic shift: floor
  const T rem = v & mask;    // 0 .. 2^d - 1, v = floor_q * 2^d + rem
  const T half = one << (d - 1);
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
// The same on 64 bits (w <= 64 signed, <= 63 unsigned): only the low w bits of u matter, so a
// caller may compute u modulo 2^64.
constexpr int64_t wrap_to64(uint64_t u, int w, bool s) {
  if (w >= 64) return static_cast<int64_t>(u);
  if (s) return static_cast<int64_t>(u << (64 - w)) >> (64 - w);  // C++20: arithmetic shift
  return static_cast<int64_t>(u & ((uint64_t(1) << w) - 1));
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
  static constexpr int kSpan = detail::span_bits(W, S);  // two's-complement bits of any value
  static constexpr bool kFits64 = kSpan <= 64;
  using raw_t = detail::acc_t<kSpan>;

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
    if constexpr (kFits64) return from_raw(detail::wrap_to64(bits, W, S));
    else return from_raw(detail::wrap_to(static_cast<i128>(bits), W, S));
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
    const uint64_t low = static_cast<uint64_t>(raw_);  // modulo 2^64 for either raw_t
    return W >= 64 ? low : low & ((uint64_t(1) << (W >= 64 ? 0 : W)) - 1);
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

  // The same with the source format known at compile time (v holds a value of a Ws-bit,
  // Ss-signed format with Fs fraction bits): int64_t arithmetic whenever every intermediate
  // fits, bit-identical to narrow().
  template <Round R, Ovf O, int Ws, int Fs, bool Ss, class T>
  static constexpr raw_t narrow_from(T v) {
    constexpr int src_span = detail::span_bits(Ws, Ss);
    if constexpr (Fs > F) {  // drop fraction bits: the quotient never outgrows the source
      // One more bit of headroom lets half-up rounding add half an LSB before the shift.
      constexpr bool add_half = R == Round::HalfUp && Fs - F < 63 && src_span < 64;
      using A = detail::acc_t<src_span + (add_half ? 1 : 0)>;
      if constexpr (add_half) {
        const A q = (static_cast<A>(v) + (A(1) << (Fs - F - 1))) >> (Fs - F);
        return saturate_or_wrap<O, src_span>(q);
      } else {
        const A q = detail::shift_round<A>(static_cast<A>(v), Fs - F, R);
        return saturate_or_wrap<O, src_span>(q);
      }
    } else if constexpr (O == Ovf::Wrap && kFits64) {  // only the low W bits survive
      if constexpr (F - Fs >= 64) return 0;
      else return static_cast<raw_t>(
          detail::wrap_to64(static_cast<uint64_t>(v) << (F - Fs), W, S));
    } else {  // exact widening (caller keeps within 126 bits)
      using A = detail::acc_t<src_span + (F - Fs)>;
      return saturate_or_wrap<O, src_span + (F - Fs)>(static_cast<A>(v) << (F - Fs));
    }
  }

  template <int W2, int F2, bool S2, Round R = Round::Trunc, Ovf O = Ovf::Wrap>
  constexpr Fixed<W2, F2, S2> cast() const {
    return Fixed<W2, F2, S2>::from_raw(
        Fixed<W2, F2, S2>::template narrow_from<R, O, W, F, S>(raw_));
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
    if constexpr (kFits64) {  // the same bits as the i128 form: sign-filled above bit 63
      const uint64_t mask = width >= 64 ? ~uint64_t(0) : (uint64_t(1) << width) - 1;
      return static_cast<uint64_t>(raw_ >> (lsb > 63 ? 63 : lsb)) & mask;
    }
    return static_cast<uint64_t>((static_cast<u128>(static_cast<i128>(raw_)) >> lsb) &
                                 ((u128(1) << width) - 1));
  }

  friend constexpr bool operator==(Fixed a, Fixed b) { return a.raw_ == b.raw_; }

 private:
  // q (of at most QSpan two's-complement bits) into this format's range.
  template <Ovf O, int QSpan, class A>
  static constexpr raw_t saturate_or_wrap(A q) {
    if constexpr (O == Ovf::Sat) {
      // Bounds the value cannot exceed need no test (and may not even fit in A).
      if constexpr (QSpan > kSpan || !S) {  // an unsigned range also bounds below
        if constexpr (QSpan > kSpan)
          if (q > static_cast<A>(kMaxRaw)) return static_cast<raw_t>(kMaxRaw);
        if (q < static_cast<A>(kMinRaw)) return static_cast<raw_t>(kMinRaw);
      }
      return static_cast<raw_t>(q);
    } else if constexpr (kFits64) {
      return detail::wrap_to64(static_cast<uint64_t>(q), W, S);
    } else {
      return static_cast<raw_t>(detail::wrap_to(static_cast<i128>(q), W, S));
    }
  }

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
  using A = typename R::raw_t;  // both aligned operands and the sum fit in the result format
  const A ra = static_cast<A>(a.raw()) << (Fm::f - F1);
  const A rb = static_cast<A>(b.raw()) << (Fm::f - F2);
  return R::from_raw(ra + rb);
}

template <int W1, int F1, bool S1, int W2, int F2, bool S2>
constexpr auto operator-(Fixed<W1, F1, S1> a, Fixed<W2, F2, S2> b) {
  using Fm = detail::SumFmt<W1, F1, S1, W2, F2, S2, true>;
  using R = Fixed<Fm::w, Fm::f, Fm::s>;
  using A = typename R::raw_t;
  const A ra = static_cast<A>(a.raw()) << (Fm::f - F1);
  const A rb = static_cast<A>(b.raw()) << (Fm::f - F2);
  return R::from_raw(ra - rb);
}

template <int W, int F, bool S>
constexpr auto operator-(Fixed<W, F, S> a) {
  using R = Fixed<W + 1, F, true>;
  return R::from_raw(-static_cast<typename R::raw_t>(a.raw()));
}

template <int W1, int F1, bool S1, int W2, int F2, bool S2>
constexpr auto operator*(Fixed<W1, F1, S1> a, Fixed<W2, F2, S2> b) {
  using R = Fixed<detail::MulW<W1, S1, W2, S2>::w, F1 + F2, S1 || S2>;
  using A = typename R::raw_t;  // the exact product fits in the result format
  return R::from_raw(static_cast<A>(a.raw()) * static_cast<A>(b.raw()));
}

template <int W1, int F1, bool S1, int W2, int F2, bool S2>
constexpr auto operator<=>(Fixed<W1, F1, S1> a, Fixed<W2, F2, S2> b) {
  constexpr int f = detail::imax(F1, F2);
  using A = detail::acc_t<detail::imax(detail::span_bits(W1, S1) + f - F1,
                                       detail::span_bits(W2, S2) + f - F2)>;
  const A ra = static_cast<A>(a.raw()) << (f - F1);
  const A rb = static_cast<A>(b.raw()) << (f - F2);
  return ra <=> rb;
}

}  // namespace tu
