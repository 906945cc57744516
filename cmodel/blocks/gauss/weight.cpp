#include "weight.hpp"

#include <cmath>

namespace tu::gauss {

namespace {
uint32_t entry(double w) {
  const double s = std::ldexp(w, fmt::kWtabEntryW);
  const double top = std::ldexp(1.0, fmt::kWtabEntryW) - 1;
  return static_cast<uint32_t>(std::min(top, std::floor(s + 0.5)));
}
// a + (b - a) * f / 2^fb, rounded half up (f < 2^fb).
uint32_t lerp(uint32_t a, uint32_t b, uint32_t f, int fb) {
  if (fb == 0) return a;
  const int64_t d = (static_cast<int64_t>(b) - a) * f;
  return static_cast<uint32_t>(a + ((d + (int64_t(1) << (fb - 1))) >> fb));
}
}  // namespace

double weight_ref(double q) {
  if (q < 0 || q > 1) return 0;
  return std::pow(1 - q / 2, 8);
}

WeightStats weight_exhaustive() {
  WeightStats s;
  const double lsb = std::ldexp(1.0, -fmt::kGaussSqF);
  double ss = 0;
  uint32_t prev = ~0u;
  const uint32_t n = uint32_t(1) << fmt::kGaussQW;
  for (uint32_t q = 0; q < n; ++q) {
    const uint32_t w = weight(q);
    const double e = std::fabs(w * lsb - weight_ref(std::ldexp(static_cast<double>(q), -fmt::kGaussQF)));
    s.max_abs = std::max(s.max_abs, e);
    ss += e * e;
    if (w > prev) s.monotonic = false;
    prev = w;
  }
  s.rms = std::sqrt(ss / n);
  s.max_ulp = s.max_abs / lsb;
  return s;
}

Table1D::Table1D(int l) : log2n(l) {
  const int n = 1 << l;
  for (int k = 0; k <= n; ++k) e.push_back(entry(weight_ref(static_cast<double>(k) / n)));
}

uint32_t Table1D::lookup(uint32_t q) const {
  if (q > (uint32_t(1) << fmt::kGaussQF)) return 0;
  const int fb = fmt::kGaussQF - log2n;
  const uint32_t idx = q >> fb, f = q & ((uint32_t(1) << fb) - 1);
  if (f == 0) return e[idx];
  return lerp(e[idx], e[idx + 1], f, fb);
}

Table2D::Table2D(int l) : log2n(l) {
  const int n = 1 << l;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x = static_cast<double>(i) / n, y = static_cast<double>(j) / n;
      e.push_back(entry(weight_ref(x * x + y * y)));
    }
}

uint32_t Table2D::lookup(int32_t xi, int32_t eta) const {
  const uint32_t one = uint32_t(1) << kXiF;
  const uint32_t x = static_cast<uint32_t>(std::abs(xi)), y = static_cast<uint32_t>(std::abs(eta));
  if (x > one || y > one) return 0;
  const int fb = kXiF - log2n;
  const uint32_t n1 = (uint32_t(1) << log2n) + 1;
  const uint32_t mask = (uint32_t(1) << fb) - 1;
  const uint32_t i = x >> fb, j = y >> fb, fx = x & mask, fy = y & mask;
  auto at = [&](uint32_t ii, uint32_t jj) {
    return (ii < n1 && jj < n1) ? e[jj * n1 + ii] : 0u;
  };
  const uint32_t r0 = lerp(at(i, j), at(i + 1, j), fx, fb);
  const uint32_t r1 = lerp(at(i, j + 1), at(i + 1, j + 1), fx, fb);
  return lerp(r0, r1, fy, fb);
}

uint32_t q_of(int32_t xi, int32_t eta) {
  const int64_t s = static_cast<int64_t>(xi) * xi + static_cast<int64_t>(eta) * eta;  // 28 frac
  const int64_t q = (s + (int64_t(1) << (kXiF - 1))) >> kXiF;                       // 14 frac
  const int64_t top = (int64_t(1) << fmt::kGaussQW) - 1;
  return static_cast<uint32_t>(q > top ? top : q);
}

TableStats table_stats(int kind, int log2n, int step_code) {
  TableStats st;
  const Table1D t1(kind == 0 ? log2n : 0);
  const Table2D t2(kind == 1 ? log2n : 0);
  const int lim = (5 << kXiF) / 4 / step_code;  // 1.25
  double se = 0, sw = 0;
  for (int j = -lim; j <= lim; ++j)
    for (int i = -lim; i <= lim; ++i) {
      const int32_t xi = i * step_code, eta = j * step_code;
      const double x = std::ldexp(static_cast<double>(xi), -kXiF);
      const double y = std::ldexp(static_cast<double>(eta), -kXiF);
      const double qv = x * x + y * y;
      const double ref = weight_ref(qv);
      double got;
      if (kind == 0) got = std::ldexp(static_cast<double>(t1.lookup(q_of(xi, eta))), -fmt::kWtabEntryW);
      else if (kind == 1) got = std::ldexp(static_cast<double>(t2.lookup(xi, eta)), -fmt::kWtabEntryW);
      else got = std::ldexp(static_cast<double>(weight(q_of(xi, eta))), -fmt::kGaussSqF);
      const double e = got - ref;
      se += e * e;
      sw += ref * ref;
      st.max_abs = std::max(st.max_abs, std::fabs(e));
      if (qv <= 0.9) st.max_abs_inner = std::max(st.max_abs_inner, std::fabs(e));
      ++st.samples;
    }
  st.nmse = se / sw;
  st.rms = std::sqrt(se / static_cast<double>(st.samples));
  st.memory_bits = kind == 0 ? t1.memory_bits() : kind == 1 ? t2.memory_bits() : 0;
  return st;
}

}  // namespace tu::gauss
