#include "clip.hpp"

#include <cmath>
#include <stdexcept>
#include "texunit/convert.hpp"

namespace tu::clip {

namespace {
constexpr int kCF = fmt::kClipCoefF;
int64_t raw(double x) { return Coef::from_double<Round::HalfEven, Ovf::Sat>(x).raw(); }
std::vector<int64_t> raws(std::initializer_list<double> xs) {
  std::vector<int64_t> r;
  for (double x : xs) r.push_back(raw(x));
  return r;
}
std::vector<double> vals(const std::vector<int64_t>& c) {
  std::vector<double> r;
  for (auto x : c) r.push_back(std::ldexp(static_cast<double>(x), -kCF));
  return r;
}
Variant horner(std::string name, std::string origin, std::vector<int64_t> c,
               std::vector<double> printed) {
  Variant v{std::move(name), std::move(origin), Scheme::Horner, std::move(c), std::move(printed),
            {}, {}, {}, 0};
  if (v.printed.empty()) v.printed = vals(v.c);
  return v;
}
int64_t a_code_of(double a) { return round_i64(std::ldexp(a, fmt::kClipInF)); }

std::vector<Variant> build() {
  std::vector<Variant> vs;
  // Seed 003 §2, exactly as printed (rounded to nearest in the s22.18 coefficient format).
  {
    Variant p1{"seed_p1", "seed 003 P1 as printed", Scheme::Piecewise, {}, {}, {}, {}, {}, 0};
    p1.seg_c0 = raws({0.506, 0.636, 0.853});
    p1.seg_c1 = raws({1.79, 1.008, 0.295});
    p1.breaks = {a_code_of(0.165), a_code_of(0.305)};  // 0.165, 0.305 rounded to 2^-12
    p1.printed = {0.506, 1.79, 0.636, 1.008, 0.853, 0.295};
    vs.push_back(p1);
  }
  vs.push_back(horner("seed_p2", "seed 003 P2 as printed", raws({0.5, 2.151, -2.358}),
                      {0.5, 2.151, -2.358}));
  vs.push_back(horner("seed_p3", "seed 003 P3 as printed", raws({0.496, 2.288, -3.074, 0.956}),
                      {0.496, 2.288, -3.074, 0.956}));
  // Own minimax: scripts/minimax_clip_p1.py (segments), scripts/minimax_clip.sollya (fpminimax
  // directly in the 2^-18 fixed-point coefficient lattice).
  {
    Variant m1{"mm_p1", "scripts/minimax_clip_p1.py", Scheme::Piecewise, {}, {}, {}, {}, {}, 0};
    m1.seg_c0 = {132811, 167245, 223372};
    m1.seg_c1 = {467279, 262571, 77763};
    m1.breaks = {689, 1244};
    for (int s = 0; s < 3; ++s) {
      m1.printed.push_back(std::ldexp(static_cast<double>(m1.seg_c0[static_cast<size_t>(s)]), -kCF));
      m1.printed.push_back(std::ldexp(static_cast<double>(m1.seg_c1[static_cast<size_t>(s)]), -kCF));
    }
    vs.push_back(m1);
  }
  vs.push_back(horner("mm_p2", "scripts/minimax_clip.sollya", {132129, 555028, -602662}, {}));
  vs.push_back(horner("mm_p3", "scripts/minimax_clip.sollya", {130060, 594384, -773398, 204813}, {}));
  {
    Variant e = horner("mm_p3_estrin", "mm_p3 coefficients, Estrin order",
                       {130060, 594384, -773398, 204813}, {});
    e.scheme = Scheme::Estrin3;
    vs.push_back(e);
  }
  vs.push_back(horner("mm_p4", "scripts/minimax_clip.sollya",
                      {130864, 539812, -201236, -1692248, 1948708}, {}));
  // Own idea: 16 uniform segments of width 1/32 indexed by the top bits of a (a table, no
  // comparators), each line the chord shifted by half its gap (minimax for concave v).
  {
    Variant t{"tab16", "16 uniform minimax line segments (a ROM)", Scheme::Uniform,
              {}, {}, {}, {}, {}, fmt::kClipInF - 5};
    for (int s = 0; s < 16; ++s) {
      const double l = s / 32.0, r = (s + 1) / 32.0;
      const double vl = reference(l), vr = reference(r);
      const double m = (vr - vl) / (r - l);
      const double sg = 0.2;
      const double xi = sg * std::sqrt(std::max(0.0, -2 * std::log(m * sg * std::sqrt(2 * M_PI))));
      const double e = (reference(xi) - vl - m * (xi - l)) / 2;
      t.seg_c0.push_back(raw(vl - m * l + e));
      t.seg_c1.push_back(raw(m));
    }
    for (size_t s = 0; s < 16; ++s) {
      t.printed.push_back(std::ldexp(static_cast<double>(t.seg_c0[s]), -kCF));
      t.printed.push_back(std::ldexp(static_cast<double>(t.seg_c1[s]), -kCF));
    }
    vs.push_back(t);
  }
  return vs;
}

Acc mul_floor(Acc x, A a) { return (x * a).as<Acc>(); }  // floor to ClipCoefF, wrap (bounded)
Acc coef(int64_t r) { return Coef::from_raw(r).as<Acc>(); }

int segment(const Variant& v, uint32_t a) {
  if (v.scheme == Scheme::Uniform) {
    const int s = static_cast<int>(a >> v.uniform_shift);
    const int n = static_cast<int>(v.seg_c0.size());
    return s < n ? s : n - 1;
  }
  int s = 0;
  for (auto b : v.breaks) s += static_cast<int64_t>(a) >= b ? 1 : 0;
  return s;
}
}  // namespace

const std::vector<Variant>& variants() {
  static const std::vector<Variant> vs = build();
  return vs;
}

const Variant& variant(const std::string& name) {
  for (const auto& v : variants())
    if (v.name == name) return v;
  throw std::invalid_argument("unknown clip-volume variant '" + name + "'");
}

double reference(double d) {
  const double x = std::min(0.5, std::max(-0.5, d));
  return 0.5 * (1.0 + std::erf(x / (0.2 * std::sqrt(2.0))));
}

uint32_t abs_clamp(int32_t d) {
  const int32_t m = d < 0 ? -d : d;
  return static_cast<uint32_t>(m > kHalfCode ? kHalfCode : m);
}

uint32_t eval_half(const Variant& v, uint32_t a_code) {
  const A a = A::from_raw(a_code);
  Acc acc;
  switch (v.scheme) {
    case Scheme::Horner: {
      const int n = static_cast<int>(v.c.size()) - 1;
      acc = coef(v.c[static_cast<size_t>(n)]);
      for (int k = n - 1; k >= 0; --k)
        acc = (coef(v.c[static_cast<size_t>(k)]) + mul_floor(acc, a)).as<Acc>();
      break;
    }
    case Scheme::Estrin3: {
      const Acc a2 = (a * a).as<Acc>();
      const Acc u = mul_floor(coef(v.c[3]), a);
      const Acc w = mul_floor(coef(v.c[1]), a);
      const Acc hi = (coef(v.c[2]) + u).as<Acc>();
      const Acc t = (hi * a2).as<Acc>();
      acc = ((coef(v.c[0]) + w).as<Acc>() + t).as<Acc>();
      break;
    }
    case Scheme::Piecewise:
    case Scheme::Uniform: {
      const auto s = static_cast<size_t>(segment(v, a_code));
      acc = (coef(v.seg_c0[s]) + mul_floor(coef(v.seg_c1[s]), a)).as<Acc>();
      break;
    }
  }
  // Round half up to ClipOutF bits, saturate p to [1, 2^16 - 1] so that 1 - p is representable.
  const int64_t sh = fmt::kClipCoefF - fmt::kClipOutF;
  int64_t p = (static_cast<int64_t>(acc.raw()) + (int64_t(1) << (sh - 1))) >> sh;
  const int64_t top = (int64_t(1) << fmt::kClipOutW) - 1;
  if (p < 1) p = 1;
  if (p > top) p = top;
  return static_cast<uint32_t>(p);
}

uint32_t eval(const Variant& v, int32_t d) {
  const uint32_t p = eval_half(v, abs_clamp(d));
  return d < 0 ? (uint32_t(1) << fmt::kClipOutF) - p : p;
}

double approx_half(const Variant& v, double a) {
  const auto cv = [](int64_t r) { return std::ldexp(static_cast<double>(r), -kCF); };
  switch (v.scheme) {
    case Scheme::Horner:
    case Scheme::Estrin3: {
      double y = 0;
      for (size_t k = v.c.size(); k-- > 0;) y = y * a + cv(v.c[k]);
      return y;
    }
    case Scheme::Piecewise:
    case Scheme::Uniform: {
      const auto s = static_cast<size_t>(segment(v, static_cast<uint32_t>(a_code_of(a))));
      return cv(v.seg_c0[s]) + cv(v.seg_c1[s]) * a;
    }
  }
  return 0;
}

ErrorStats exhaustive(const Variant& v) {
  ErrorStats st;
  const int w = fmt::kClipInW;
  const double lsb = std::ldexp(1.0, -fmt::kClipOutF);
  double sum_sq = 0;
  int64_t prev = -1;
  for (int32_t d = -(1 << (w - 1)); d < (1 << (w - 1)); ++d) {
    const double dv = std::ldexp(static_cast<double>(d), -fmt::kClipInF);
    const uint32_t o = eval(v, d);
    const double got = o * lsb;
    const double ref = reference(dv);
    const double a = std::ldexp(static_cast<double>(abs_clamp(d)), -fmt::kClipInF);
    const double pa = approx_half(v, a);
    const double poly = d < 0 ? 1.0 - pa : pa;
    const double e = std::fabs(got - ref);
    st.max_abs = std::max(st.max_abs, e);
    st.max_approx = std::max(st.max_approx, std::fabs(poly - ref));
    st.max_round = std::max(st.max_round, std::fabs(got - poly));
    sum_sq += e * e;
    if (static_cast<int64_t>(o) < prev) st.monotonic_full = false;
    prev = o;
    if (d != 0 && d > -(1 << (w - 1)) &&
        o + eval(v, -d) != (uint32_t(1) << fmt::kClipOutF))
      st.symmetric = false;
    ++st.codes;
  }
  for (uint32_t a = 1; a <= kHalfCode; ++a)
    if (eval_half(v, a) < eval_half(v, a - 1)) st.monotonic_half = false;
  st.rms = std::sqrt(sum_sq / static_cast<double>(st.codes));
  st.max_ulp = st.max_abs / lsb;
  return st;
}

}  // namespace tu::clip
