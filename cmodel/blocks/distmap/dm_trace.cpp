#include "distmap/dm_trace.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "texunit/formats.hpp"

namespace tu::dm {

namespace {
constexpr int64_t kDOne = int64_t(1) << fmt::kDmDF;
static_assert(fmt::kDmDF + fmt::kPomUvF - fmt::kDmQF + fmt::kDmKF == 44, "K numerator 2^44");

int64_t rsh(int64_t x, int s) { return (x + (int64_t(1) << (s - 1))) >> s; }  // round half up

struct Ray {  // T - D P in fixed point
  int64_t u, v, pu, pv;
  int64_t at_u(int64_t d) const { return u - rsh(d * pu, fmt::kDmDF); }
  int64_t at_v(int64_t d) const { return v - rsh(d * pv, fmt::kDmDF); }
};

// POM's hit rule at depth D (DmDF bits): D >= code / 255 (exact).
bool below(const img::Gray8& depth, const Ray& r, int64_t d) {
  return 255 * d >= int64_t(pom::tex_nearest(depth, r.at_u(d), r.at_v(d))) * kDOne;
}

// Bisection between lo (above) and hi (at or below): DmBisect fetches; returns hi.
int64_t bisect(const img::Gray8& depth, const Ray& r, int64_t lo, int64_t hi, uint32_t* fetches) {
  for (int i = 0; i < fmt::kDmBisect; ++i) {
    const int64_t mid = (lo + hi) >> 1;
    ++*fetches;
    (below(depth, r, mid) ? hi : lo) = mid;
  }
  return hi;
}

// Linear steps of dl from d0 (at most n), then the bisection; returns the final D.
int64_t lin_bin(const img::Gray8& depth, const Ray& r, int64_t d0, int64_t dl, uint32_t n, uint32_t* fetches) {
  ++*fetches;
  if (below(depth, r, d0)) return d0;
  int64_t d = d0;
  for (uint32_t i = 0; i < n; ++i) {
    const int64_t nd = std::min(d + dl, kDOne);
    ++*fetches;
    if (below(depth, r, nd)) return bisect(depth, r, d, nd, fetches);
    d = nd;
    if (d == kDOne) break;
  }
  return d;
}

int log2_side(int n) { return std::countr_zero(static_cast<unsigned>(n)); }
}  // namespace

uint64_t isqrt_ceil(uint64_t x) {
  uint64_t r = static_cast<uint64_t>(std::sqrt(static_cast<double>(x)));
  while (static_cast<unsigned __int128>(r) * r > x) --r;
  while (static_cast<unsigned __int128>(r + 1) * (r + 1) <= x) ++r;
  return static_cast<unsigned __int128>(r) * r == x ? r : r + 1;
}

Setup setup(const Map& m, const pom::View& view) {
  if (view.scale != m.scale_code)
    throw std::invalid_argument("dm::trace: the view's scale code " + std::to_string(view.scale) +
                                " differs from the distance map's " + std::to_string(m.scale_code));
  const pom::Parallax p = pom::parallax(view);
  const int lw = log2_side(m.w);
  Setup s;
  s.pu = p.pu;
  s.pv = p.pv;
  s.clamped = p.clamped;
  s.back = p.back;
  const uint64_t wu = static_cast<uint64_t>(std::llabs(p.pu)) << lw, wv = static_cast<uint64_t>(std::llabs(p.pv)) << lw;
  const uint64_t z = uint64_t(view.scale) << lw;
  s.lambda = isqrt_ceil(wu * wu + wv * wv + z * z);  // < 2^32: |P| < 64, W <= 512
  s.k = (uint64_t(1) << 44) / s.lambda;
  return s;
}

TraceOut trace(const Map& m, const img::Gray8& depth, int64_t u, int64_t v, const pom::View& view, uint32_t cap,
               uint32_t finish) {
  const Setup s = setup(m, view);
  const Ray r{u, v, s.pu, s.pv};
  const int lw = log2_side(m.w);
  TraceOut o;
  o.clamped = s.clamped;
  o.back = s.back;
  int64_t d = 0;
  for (;;) {
    const int x = static_cast<int>((r.at_u(d) >> (fmt::kPomUvF - lw)) & (m.w - 1));
    const int y = static_cast<int>((r.at_v(d) >> (fmt::kPomUvF - lw)) & (m.h - 1));
    const int k = static_cast<int>(std::min<int64_t>((d * m.layers) >> fmt::kDmDF, m.layers - 1));
    const uint32_t c = m.at(x, y, k);
    if (c == 0) break;
    if (o.steps == cap) {
      o.capped = true;
      break;
    }
    d += static_cast<int64_t>((c * s.k) >> fmt::kDmKF);
    ++o.steps;
    if (d >= kDOne) {
      d = kDOne;
      o.bottom = true;
      break;
    }
  }
  if (finish > 0) d = lin_bin(depth, r, d, kDOne / m.layers, finish, &o.finish_steps);
  o.d = static_cast<uint32_t>(d);
  o.u = r.at_u(d);
  o.v = r.at_v(d);
  return o;
}

TraceRef trace_ref(const Map& m, const img::Gray8& depth, double u, double v, double vx, double vy, double vz,
                   double scale, uint32_t cap, uint32_t finish) {
  const double a = std::max(std::fabs(vz), std::ldexp(double(fmt::kPomVzMin), -fmt::kPomVzF));
  const double pu = vx / a * scale, pv = vy / a * scale, zt = scale * m.w;
  const double lambda = std::sqrt(pu * m.w * pu * m.w + pv * m.w * pv * m.w + zt * zt);
  auto wrap = [](double t, int n) {
    const double i = std::floor(t * n);
    return static_cast<int>(std::fmod(std::fmod(i, n) + n, n));
  };
  TraceRef o;
  double d = 0;
  for (;;) {
    const int k = std::min(static_cast<int>(std::floor(d * m.layers)), m.layers - 1);
    const double t = m.safe[m.index(wrap(u - d * pu, m.w), wrap(v - d * pv, m.h), k)];
    if (t < kQuantum) break;
    if (o.steps == cap) {
      o.capped = true;
      break;
    }
    d = std::min(d + t / lambda, 1.0);
    ++o.steps;
    if (d >= 1) break;
  }
  if (finish > 0) {
    auto below_f = [&](double dd) { return 255 * dd >= pom::tex_nearest_f(depth, u - dd * pu, v - dd * pv); };
    ++o.finish_steps;
    if (!below_f(d)) {
      double lo = d;
      bool hit = false;
      for (uint32_t i = 0; i < finish && !hit; ++i) {
        const double nd = std::min(lo + 1.0 / m.layers, 1.0);
        ++o.finish_steps;
        if (below_f(nd)) {
          hit = true;
          double hi = nd;
          for (int b = 0; b < fmt::kDmBisect; ++b, ++o.finish_steps) {
            const double mid = 0.5 * (lo + hi);
            (below_f(mid) ? hi : lo) = mid;
          }
          d = hi;
        } else {
          lo = nd;
          d = nd;
          if (nd >= 1) break;
        }
      }
    }
  }
  o.d = d;
  o.u = u - d * pu;
  o.v = v - d * pv;
  return o;
}

TraceOut linbin(const img::Gray8& depth, int64_t u, int64_t v, const pom::View& view, uint32_t n) {
  if (n < 1 || n > 255) throw std::invalid_argument("dm::linbin: n must be 1..255");
  const pom::Parallax p = pom::parallax(view);
  const Ray r{u, v, p.pu, p.pv};
  TraceOut o;
  o.clamped = p.clamped;
  o.back = p.back;
  const int64_t d = lin_bin(depth, r, 0, (kDOne + n - 1) / n, n, &o.finish_steps);
  o.steps = o.finish_steps;
  o.d = static_cast<uint32_t>(d);
  o.u = r.at_u(d);
  o.v = r.at_v(d);
  return o;
}

}  // namespace tu::dm
