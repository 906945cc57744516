#include "pom/pom_layers.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include "texunit/convert.hpp"

namespace tu::pom {

namespace {
constexpr int64_t kOne = int64_t(1) << fmt::kPomVzF;
constexpr int kShift = fmt::kPomVzF - fmt::kPomIdxF;

uint32_t clamp_n(int64_t n, uint32_t nmin, uint32_t nmax) {
  const int64_t lo = std::max<int64_t>(nmin, 1);
  const int64_t hi = std::max<int64_t>(nmax, lo);
  return static_cast<uint32_t>(std::clamp(n, lo, hi));
}
}  // namespace

uint32_t vz_index(int32_t vz) {
  const int64_t a = std::min<int64_t>(std::llabs(vz), kOne);
  return static_cast<uint32_t>((a + (int64_t(1) << (kShift - 1))) >> kShift);
}

const std::vector<uint32_t>& f_table() {
  static const std::vector<uint32_t> t = [] {
    std::vector<uint32_t> v(kRomSize);
    for (int i = 0; i < kRomSize; ++i) {
      const double u = 1.0 - std::ldexp(static_cast<double>(i), -fmt::kPomIdxF);
      v[static_cast<size_t>(i)] =
          static_cast<uint32_t>(std::lround(std::ldexp(std::pow(u, 0.8), fmt::kPomFF)));
    }
    return v;
  }();
  return t;
}

uint32_t div255(uint32_t y) {
  return static_cast<uint32_t>((uint64_t(y) * fmt::kPomDivM) >> fmt::kPomDivS);
}

uint32_t layers_idx(uint32_t idx, uint32_t code, uint32_t nmin, uint32_t nmax) {
  const int64_t f = f_table()[idx];
  const int64_t t = 255 * (int64_t(nmax) - 2 * int64_t(nmin)) + int64_t(nmax) * code;
  const int64_t p = f * t;                      // PomPW bits, exact
  const int64_t q = p >> (fmt::kPomFF + 1);     // floor (arithmetic shift)
  const auto y = static_cast<uint32_t>(q + 255 * fmt::kPomBias);
  const int64_t n = int64_t(nmin) + div255(y) - fmt::kPomBias;
  return clamp_n(n, nmin, nmax);
}

Layers layers(int32_t vz, uint32_t code, uint32_t nmin, uint32_t nmax) {
  return {layers_idx(vz_index(vz), code, nmin, nmax), vz < 0};
}

uint32_t layers_ref(double a, double c, uint32_t nmin, uint32_t nmax, double* exact) {
  a = std::min(std::fabs(a), 1.0);
  const double f = std::pow(1.0 - a, 0.8);
  const double n = nmin + f * ((nmax / 2.0 - nmin) + (nmax / 2.0) * c);
  if (exact) *exact = n;
  return clamp_n(floor_i64(n), nmin, nmax);
}

}  // namespace tu::pom
