#include "reciprocal.hpp"

#include <bit>
#include <cmath>

namespace tu::recip {

const std::array<Coef, kSegments>& table() {
  static const std::array<Coef, kSegments> tab = [] {
    std::array<Coef, kSegments> t{};
    const double h = std::ldexp(1.0, -fmt::kRecipIdxW);  // segment width
    // Chebyshev nodes of degree 2 on [0, h]: h/2 * (1 + {-s, 0, s}), s = sqrt(3)/2.
    const double s = std::sqrt(3.0) / 2.0;
    const double xs[3] = {h / 2 * (1 - s), h / 2, h / 2 * (1 + s)};
    for (int k = 0; k < kSegments; ++k) {
      const double m0 = 1.0 + k * h;
      double ys[3];
      for (int j = 0; j < 3; ++j) ys[j] = 1.0 / (m0 + xs[j]);
      // Newton divided differences -> monomial coefficients in dx.
      const double d01 = (ys[1] - ys[0]) / (xs[1] - xs[0]);
      const double d12 = (ys[2] - ys[1]) / (xs[2] - xs[1]);
      const double d012 = (d12 - d01) / (xs[2] - xs[0]);
      const double c2 = d012;
      const double c1 = d01 - d012 * (xs[0] + xs[1]);
      const double c0 = ys[0] - d01 * xs[0] + d012 * xs[0] * xs[1];
      t[k].c0 = C0::from_double<Round::HalfEven, Ovf::Sat>(c0);
      t[k].c1 = C1::from_double<Round::HalfEven, Ovf::Sat>(c1);
      t[k].c2 = C2::from_double<Round::HalfEven, Ovf::Sat>(c2);
    }
    return t;
  }();
  return tab;
}

Result eval(int32_t q) {
  // Bring the RecipInW-bit code to a canonical sign-extended value.
  const int w = fmt::kRecipInW;
  const int32_t qs = static_cast<int32_t>(static_cast<uint32_t>(q) << (32 - w)) >> (32 - w);
  if (qs <= 0) return {static_cast<uint32_t>(Out::kMaxRaw), 0, true};
  const auto x = static_cast<uint32_t>(qs);
  const int p = 31 - std::countl_zero(x);                   // msb position, 0..w-2
  const Mant m = Mant::from_raw(static_cast<uint64_t>(x) << (fmt::kRecipMantW - 1 - p));
  return {static_cast<uint32_t>(core(m).raw()), static_cast<uint32_t>(p), false};
}

double value(const Result& r, int f) {
  if (r.flag) return INFINITY;
  return std::ldexp(static_cast<double>(r.mant), f - static_cast<int>(r.shift) - fmt::kRecipOutF);
}

}  // namespace tu::recip
