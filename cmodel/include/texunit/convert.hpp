// Float -> integer conversions defined for every double. static_cast<int64_t>(x) is undefined
// behaviour when x is NaN or outside the integer's range (UBSan: float-cast-overflow); these
// saturate to the range and map NaN to 0, so a float reference stays defined on any input (the
// callers' results are then flagged or clamped by their own range checks).
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>

namespace tu {

template <class I>
I sat_cast(double x) {
  static_assert(std::numeric_limits<I>::is_integer);
  if (std::isnan(x)) return 0;
  // Bounds as doubles: the lower one is exact (-2^k or 0); the upper one rounds up to 2^k for
  // 64-bit types, hence >=.
  constexpr double lo = static_cast<double>(std::numeric_limits<I>::min());
  constexpr double hi = static_cast<double>(std::numeric_limits<I>::max());
  if (x <= lo) return std::numeric_limits<I>::min();
  if (x >= hi) return std::numeric_limits<I>::max();
  return static_cast<I>(x);
}

inline int64_t floor_i64(double x) { return sat_cast<int64_t>(std::floor(x)); }
inline int64_t ceil_i64(double x) { return sat_cast<int64_t>(std::ceil(x)); }
// Round half away from zero (std::llround), saturated.
inline int64_t round_i64(double x) { return sat_cast<int64_t>(std::round(x)); }

}  // namespace tu
