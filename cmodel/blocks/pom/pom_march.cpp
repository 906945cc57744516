#include "pom/pom_march.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "reciprocal/reciprocal.hpp"
#include "texunit/convert.hpp"

namespace tu::pom {

namespace {
// Round half up of x / 2^s (arithmetic shift = floor), s >= 1.
int64_t rsh(int64_t x, int s) { return (x + (int64_t(1) << (s - 1))) >> s; }

int log2_side(int n) {
  if (n <= 0 || (n & (n - 1)) != 0) throw std::invalid_argument("pom: texture side must be a power of two");
  return std::countr_zero(static_cast<unsigned>(n));
}

// x * (1/q) for a positive integer q (q < 2^23) by the reciprocal unit, rounded: 1/q = R*2^-(p+24).
int64_t mul_recip(int64_t x, int64_t q) {
  const auto r = recip::eval(static_cast<int32_t>(q));
  return rsh(x * static_cast<int64_t>(r.mant), static_cast<int>(r.shift) + fmt::kRecipOutF);
}
}  // namespace

uint8_t tex_nearest(const img::Gray8& d, int64_t u, int64_t v) {
  const int lw = log2_side(d.width), lh = log2_side(d.height);
  const int x = static_cast<int>((u >> (fmt::kPomUvF - lw)) & (d.width - 1));
  const int y = static_cast<int>((v >> (fmt::kPomUvF - lh)) & (d.height - 1));
  return d.at(x, y);
}

uint8_t tex_nearest_f(const img::Gray8& d, double u, double v) {
  auto wrap = [](double t, int n) {
    const int64_t i = floor_i64(t * n);
    return static_cast<int>(((i % n) + n) % n);
  };
  return d.at(wrap(u, d.width), wrap(v, d.height));
}

Parallax parallax(const View& vw) {
  Parallax p;
  p.back = vw.vz < 0;
  int64_t a = std::llabs(vw.vz);
  if (a < fmt::kPomVzMin) {
    a = fmt::kPomVzMin;
    p.clamped = true;
  }
  // P = Vxy * S / a:  Vxy 2^-14, S 2^-16, 1/a = R * 2^(14 - p - 24)  ->  2^-16 units: >> (p + 24)
  const auto r = recip::eval(static_cast<int32_t>(a));
  const int sh = static_cast<int>(r.shift) + fmt::kRecipOutF;
  const int64_t s = vw.scale;
  p.pu = rsh(int64_t(vw.vx) * s * int64_t(r.mant), sh);
  p.pv = rsh(int64_t(vw.vy) * s * int64_t(r.mant), sh);
  static_assert(fmt::kPomSF == fmt::kPomUvF, "P scaling assumes S and uv share fraction bits");
  return p;
}

Setup setup(const View& view, uint32_t n) {
  if (n < 1 || n > 63) throw std::invalid_argument("pom::setup: n must be 1..63");
  const Parallax p = parallax(view);
  return {mul_recip(p.pu, n), mul_recip(p.pv, n), p.back, p.clamped};
}

MarchOut refine(const MarchCore& c, int64_t du, int64_t dv, bool wrap) {
  MarchOut o;
  o.steps = c.steps;
  int64_t tu = c.u, tv = c.v;
  if (c.steps > 0) {
    const int64_t a = c.a, den = c.den;
    const int64_t w = std::min<int64_t>(mul_recip(a << fmt::kPomWF, den), int64_t(1) << fmt::kPomWF);
    o.w = static_cast<uint32_t>(w);
    tu += rsh(w * du, fmt::kPomWF);
    tv += rsh(w * dv, fmt::kPomWF);
  }
  if (wrap) {
    tu &= kUvOne - 1;
    tv &= kUvOne - 1;
  } else {
    o.discard = tu < 0 || tv < 0 || tu > kUvOne || tv > kUvOne;
  }
  o.u = tu;
  o.v = tv;
  return o;
}

MarchOut march(const img::Gray8& depth, int64_t u, int64_t v, const View& view, uint32_t n,
               bool wrap) {
  const Setup s = setup(view, n);
  MarchOut o = refine(march_core(depth, u, v, s.du, s.dv, n), s.du, s.dv, wrap);
  o.back = s.back;
  o.clamped = s.clamped;
  return o;
}

uint64_t march_cycles(const std::vector<uint32_t>& steps) {
  uint64_t c = 2;
  for (uint32_t k : steps) c += k + 1;
  return c;
}

uint64_t unit_cycles(const std::vector<uint32_t>& steps) {
  return march_cycles(steps) + fmt::kPomSetupLatency + fmt::kPomRefineLatency;
}

MarchCore march_core(const img::Gray8& depth, int64_t u, int64_t v, int64_t du, int64_t dv,
                     uint32_t n) {
  const int64_t N = n;
  int64_t tu = u, tv = v;
  int64_t h = tex_nearest(depth, tu, tv), hp = h;
  int64_t i = 0;
  while (255 * i < h * N) {  // exact: i/N < h/255
    hp = h;
    tu -= du;
    tv -= dv;
    h = tex_nearest(depth, tu, tv);
    ++i;
  }
  MarchCore c;
  c.u = tu;
  c.v = tv;
  c.steps = static_cast<uint32_t>(i);
  if (i > 0) {
    const int64_t a = 255 * i - h * N;         // -(after), >= 0
    const int64_t b = hp * N - 255 * (i - 1);  // before, > 0
    c.a = static_cast<uint32_t>(a);
    c.den = static_cast<uint32_t>(a + b);
  }
  return c;
}

MarchRef march_ref(const img::Gray8& depth, double u, double v, double vx, double vy, double vz,
                   double scale, uint32_t n) {
  const double a = std::max(std::fabs(vz), std::ldexp(double(fmt::kPomVzMin), -fmt::kPomVzF));
  const double du = vx / a * scale / n, dv = vy / a * scale / n;
  const int64_t N = n;
  int64_t i = 0;
  int64_t h = tex_nearest_f(depth, u, v), hp = h;
  while (255 * i < h * N) {
    hp = h;
    ++i;
    h = tex_nearest_f(depth, u - double(i) * du, v - double(i) * dv);
  }
  MarchRef r;
  r.steps = static_cast<uint32_t>(i);
  double tu = u - double(i) * du, tv = v - double(i) * dv;
  if (i > 0) {
    const double A = double(255 * i - h * N), B = double(hp * N - 255 * (i - 1));
    const double w = A / (A + B);
    tu += w * du;
    tv += w * dv;
  }
  r.tu = tu;
  r.tv = tv;
  r.u = tu - std::floor(tu);
  r.v = tv - std::floor(tv);
  return r;
}

IpxDir ipx_dir_seed(const View& vw) {
  IpxDir d;
  // S*Vxy: 2^-16 * 2^-14 -> 2^-16 units
  d.su = rsh(int64_t(vw.vx) * vw.scale, fmt::kPomVzF);
  d.sv = rsh(int64_t(vw.vy) * vw.scale, fmt::kPomVzF);
  const int64_t a = std::max<int64_t>(std::llabs(vw.vz), fmt::kPomVzMin);
  d.sh = a << (fmt::kPomUvF - fmt::kPomVzF);
  return d;
}

IpxDir ipx_dir_normalised(const View& vw) {
  const Parallax p = parallax(vw);
  return {p.pu, p.pv, kUvOne};
}

IpxOut iter_parallax(const img::Gray8& depth, int64_t u, int64_t v, const IpxDir& dir,
                     uint32_t cap, uint32_t eps) {
  IpxOut o;
  int64_t tu = u, tv = v, D = 0;
  for (;;) {
    const int64_t d = int64_t(tex_nearest(depth, tu, tv)) * 257 - D;
    if (std::llabs(d) < int64_t(eps)) break;
    if (o.iters == cap) {
      o.nonconv = true;
      break;
    }
    tu -= rsh(d * dir.su, fmt::kPomUvF);  // 2 multiplies, 2 adds
    tv -= rsh(d * dir.sv, fmt::kPomUvF);
    D += rsh(d * dir.sh, fmt::kPomUvF);   // 1 multiply, 1 add  (+1 add for d)
    ++o.iters;
  }
  o.u = tu & (kUvOne - 1);
  o.v = tv & (kUvOne - 1);
  return o;
}

}  // namespace tu::pom
