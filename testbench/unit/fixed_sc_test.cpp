// Proof of semantics: tu::Fixed is bit-identical to SystemC sc_fixed / sc_ufixed for add, sub,
// mul, shifts and casts (every rounding and overflow mode we offer), on edge operands (min, max,
// +-1 LSB, zero, rounding ties) and seeded random operands. Zero mismatches allowed.
#include <gtest/gtest.h>
#include <systemc.h>

#include <random>
#include <tuple>
#include <vector>

#include "texunit/fixed.hpp"

namespace {
using namespace tu;

constexpr sc_dt::sc_q_mode sc_q(Round r) {
  switch (r) {
    case Round::Trunc: return sc_dt::SC_TRN;
    case Round::TruncZero: return sc_dt::SC_TRN_ZERO;
    case Round::HalfUp: return sc_dt::SC_RND;
    case Round::HalfZero: return sc_dt::SC_RND_ZERO;
    case Round::HalfEven: return sc_dt::SC_RND_CONV;
  }
  return sc_dt::SC_TRN;
}
constexpr sc_dt::sc_o_mode sc_o(Ovf o) { return o == Ovf::Sat ? sc_dt::SC_SAT : sc_dt::SC_WRAP; }

// The SystemC type with the same word length, integer bits, quantisation and overflow.
template <int W, int F, bool S, Round R = Round::Trunc, Ovf O = Ovf::Wrap>
using Sc = std::conditional_t<S, sc_dt::sc_fixed<W, W - F, sc_q(R), sc_o(O)>,
                              sc_dt::sc_ufixed<W, W - F, sc_q(R), sc_o(O)>>;

template <int W, int F, bool S>
Sc<W, F, S> to_sc(Fixed<W, F, S> x) {
  Sc<W, F, S> s;
  s.range(W - 1, 0) = static_cast<sc_dt::uint64>(x.bits());
  return s;
}
template <class ScT>
uint64_t sc_bits(const ScT& s) {
  return static_cast<uint64_t>(s.range(s.wl() - 1, 0).to_uint64());
}

// Edge and random raw codes of a format.
template <int W, int F, bool S>
std::vector<Fixed<W, F, S>> operands(std::mt19937_64& rng, int n_random) {
  using T = Fixed<W, F, S>;
  std::vector<i128> raws = {T::kMinRaw, T::kMinRaw + 1, T::kMaxRaw, T::kMaxRaw - 1, 0, 1};
  if (S) raws.push_back(-1);
  // Rounding ties and neighbours: patterns ending in 1000.., 0111.., 1001..
  for (int k = 1; k < W && k < 12; ++k) {
    const i128 half = i128(1) << (k - 1);
    for (i128 base : {i128(0), i128(1) << k, i128(3) << k, -(i128(1) << k), -(i128(3) << k)})
      for (i128 d : {half - 1, half, half + 1}) raws.push_back(base + d);
  }
  std::vector<T> out;
  for (i128 r : raws)
    if (r >= T::kMinRaw && r <= T::kMaxRaw) out.push_back(T::from_raw(r));
  for (int i = 0; i < n_random; ++i) out.push_back(T::from_bits(rng()));
  return out;
}

int64_t g_checked = 0;

// Every cast of x into <W2, F2, S2> for all rounding and overflow modes.
template <int W2, int F2, bool S2, class T, class ScV>
void check_casts(const T& x, const ScV& sx, const char* what) {
  auto one = [&]<Round R, Ovf O>() {
    const auto ours = x.template cast<W2, F2, S2, R, O>();
    const Sc<W2, F2, S2, R, O> theirs = sx;
    ASSERT_EQ(ours.bits(), sc_bits(theirs))
        << what << " -> " << (S2 ? "s" : "u") << W2 << "." << F2 << " round " << int(R)
        << " ovf " << int(O) << " value " << sx.to_string();
    ++g_checked;
  };
  [&]<Round... Rs>(std::integer_sequence<Round, Rs...>) {
    (one.template operator()<Rs, Ovf::Wrap>(), ...);
    (one.template operator()<Rs, Ovf::Sat>(), ...);
  }(std::integer_sequence<Round, Round::Trunc, Round::TruncZero, Round::HalfUp, Round::HalfZero,
                          Round::HalfEven>{});
}

// a (op) b for all ops, compared exactly (the full-precision result) and after casts.
template <int W1, int F1, bool S1, int W2, int F2, bool S2, int WR, int FR, bool SR>
void check_pair(int n_random, uint64_t seed) {
  std::mt19937_64 rng(seed);
  const int64_t before = g_checked;
  const auto as = operands<W1, F1, S1>(rng, n_random);
  const auto bs = operands<W2, F2, S2>(rng, n_random);
  for (const auto& a : as) {
    const auto sa = to_sc(a);
    // Casts and shifts of a single operand.
    check_casts<WR, FR, SR>(a, sa, "cast");
    check_casts<WR, FR, SR>(a.template shl<3>(), sc_dt::sc_fxval(sa << 3), "shl3");
    check_casts<WR, FR, SR>(a.template shr<5>(), sc_dt::sc_fxval(sa >> 5), "shr5");
    for (const auto& b : bs) {
      const auto sb = to_sc(b);
      const auto sum = a + b;
      const auto dif = a - b;
      const auto prd = a * b;
      // The exact result formats hold the sc_fxval result without any loss.
      ASSERT_EQ(sum.to_ldouble(), static_cast<long double>((sa + sb).to_double()));
      check_casts<WR, FR, SR>(sum, sc_dt::sc_fxval(sa + sb), "add");
      check_casts<WR, FR, SR>(dif, sc_dt::sc_fxval(sa - sb), "sub");
      check_casts<WR, FR, SR>(prd, sc_dt::sc_fxval(sa * sb), "mul");
      // Exact product bits: compare in a format wide enough to hold it unchanged.
      using P = decltype(prd);
      if constexpr (P::kW <= 64) {
        const Sc<P::kW, P::kF, P::kS> exact = sa * sb;
        ASSERT_EQ(prd.bits(), sc_bits(exact)) << "exact product";
        const auto sd = sc_dt::sc_fxval(sa - sb);
        using D = decltype(dif);
        const Sc<D::kW, D::kF, D::kS> exact_d = sd;
        ASSERT_EQ(dif.bits(), sc_bits(exact_d)) << "exact difference";
      }
    }
  }
  // Guard against a sweep that silently compares nothing.
  EXPECT_GT(g_checked - before, 10 * static_cast<int64_t>(as.size() * bs.size()));
}

TEST(FixedVsSystemC, SignedSigned) {
  check_pair<12, 6, true, 10, 8, true, 9, 4, true>(40, 1);
  check_pair<16, 15, true, 16, 15, true, 16, 15, true>(40, 2);
  check_pair<20, 4, true, 7, -2, true, 12, 0, true>(30, 3);
}
TEST(FixedVsSystemC, UnsignedUnsigned) {
  check_pair<12, 6, false, 10, 8, false, 9, 4, false>(40, 4);
  check_pair<24, 23, false, 15, 23, false, 18, 22, false>(30, 5);
}
TEST(FixedVsSystemC, MixedSignedness) {
  check_pair<12, 6, true, 10, 8, false, 9, 4, true>(40, 6);
  check_pair<14, 12, false, 25, 22, true, 26, 30, true>(30, 7);
  check_pair<10, 3, false, 11, 9, true, 8, 2, false>(40, 8);
}
TEST(FixedVsSystemC, NegativeAndLargeIntegerBits) {
  // I = W - F below zero (pure fraction below 2^-1) and F < 0 (coarse integers).
  check_pair<8, 12, true, 9, 11, false, 10, 14, true>(40, 9);
  check_pair<10, -3, true, 6, -1, true, 12, -2, true>(40, 10);
}
TEST(FixedVsSystemC, WideOperands) {
  check_pair<32, 30, true, 30, 20, true, 33, 30, true>(20, 11);
  check_pair<48, 28, true, 15, 0, false, 40, 24, true>(20, 12);
}
TEST(FixedVsSystemC, FromDouble) {
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> d(-300, 300);
  for (int i = 0; i < 20000; ++i) {
    double x = d(rng);
    if (i % 4 == 0) x = std::ldexp(std::round(std::ldexp(x, 5)) + 0.5, -5);  // exact ties
    const auto ours = SFixed<16, 5>::from_double<Round::HalfEven, Ovf::Sat>(x);
    const sc_dt::sc_fixed<16, 11, sc_dt::SC_RND_CONV, sc_dt::SC_SAT> theirs = x;
    ASSERT_EQ(ours.bits(), sc_bits(theirs)) << x;
    const auto ours2 = UFixed<10, 2>::from_double<Round::HalfUp, Ovf::Wrap>(x);
    const sc_dt::sc_ufixed<10, 8, sc_dt::SC_RND, sc_dt::SC_WRAP> theirs2 = x;
    ASSERT_EQ(ours2.bits(), sc_bits(theirs2)) << x;
  }
}
}  // namespace
