// Perspective-correct texture coordinates: the incremental perspective divide unit (B1).
//
//   u = (A x + B y + C) / (G x + H y + I),   v = (D x + E y + F) / (G x + H y + I)
//
// x, y are integer pixel indices (the pixel-centre offset +0.5 is folded into C, F, I by the
// float reference). Structure (docs/blocks/persp.md):
//   per triangle : quantise A..I to PerspF fraction bits (round to nearest even); overflow of a
//                  coefficient format -> SetupError naming the triangle
//   per scanline : p_u = A x0 + B y + C, p_v = D x0 + E y + F, q = G x0 + H y + I  (exact),
//                  both span ends checked against the accumulator formats -> SetupError
//   per pixel    : guard (q < 2^-PerspGuardLog2, incl. q <= 0 -> flag, u = v = max code);
//                  leading-one detect of q, M = top RecipMantW bits (truncated), R = recip::core(M),
//                  u = round_half_up(p_u * R * 2^(PerspF - e - RecipOutF)) to s(PerspUvW).PerspUvF,
//                  saturating; then p_u += A, p_v += D, q += G (exact).
// Traversals (direct, sequential incremental, k-lane, two-ended) produce identical bits: every
// accumulator value is the exact value A*x + B*y + C of the quantised coefficients.
//
// Everything is templated on the fraction-bit count F so that the drift study can evaluate
// narrower widths with the same code; the unit itself is Model<fmt::kPerspF>.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "reciprocal/reciprocal.hpp"
#include "texunit/fixed.hpp"
#include "texunit/formats.hpp"

namespace tu::persp {

// Set-up failure (coefficient or span accumulator out of its format); the message names the
// triangle.
struct SetupError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Screen -> texture coefficients in double (float reference output), row-major A..I.
struct Coef9 {
  double a, b, c, d, e, f, g, h, i;
};

using Xy = UFixed<fmt::kPerspXyW, 0>;
using Uv = SFixed<fmt::kPerspUvW, fmt::kPerspUvF>;

struct Pixel {
  int64_t u = 0, v = 0;  // Uv raw codes
  bool flag = false;     // guard hit: u, v saturated
  friend bool operator==(const Pixel&, const Pixel&) = default;
};

template <int F>
struct Model {
  static constexpr int kF = F;
  static constexpr int kPW = F + (fmt::kPerspPW - fmt::kPerspF);
  static constexpr int kQW = F + (fmt::kPerspQW - fmt::kPerspF);
  using P = SFixed<kPW, F>;  // A..F, p_u, p_v
  using Q = SFixed<kQW, F>;  // G..I, q

  struct Coefs {
    P a, b, c, d, e, f;
    Q g, h, i;
  };
  struct Acc {  // accumulator state at one pixel
    P pu, pv;
    Q q;
  };

  // Quantise the float coefficients; throws SetupError naming `tri` when one does not fit.
  static Coefs quantise(const Coef9& k, const std::string& tri) {
    auto qp = [&](double x, const char* n) { return fit<P>(x, n, tri); };
    auto qq = [&](double x, const char* n) { return fit<Q>(x, n, tri); };
    return {qp(k.a, "A"), qp(k.b, "B"), qp(k.c, "C"), qp(k.d, "D"), qp(k.e, "E"),
            qp(k.f, "F"), qq(k.g, "G"), qq(k.h, "H"), qq(k.i, "I")};
  }

  // Direct evaluation at pixel (x, y), exact; the caller guarantees the format holds the value
  // (checked for the span ends by setup()).
  static Acc direct(const Coefs& c, int x, int y) {
    const Xy xf = Xy::from_raw(x), yf = Xy::from_raw(y);
    return {(c.a * xf + c.b * yf + c.c).template as<P>(),
            (c.d * xf + c.e * yf + c.f).template as<P>(),
            (c.g * xf + c.h * yf + c.i).template as<Q>()};
  }

  // Per-scanline set-up of one span as the hardware computes it (rtl/persp/tu_persp_setup.sv):
  // the accumulators at x0 (exact; wrapped to their formats when they overflow) and a flag set
  // when p_u, p_v or q at either span end x0, x1 does not fit its format. `what` and `at` name the
  // first failure (checked in the order x0: p_u, p_v, q; then x1).
  struct SpanSetup {
    Acc acc;
    bool ovf = false;
    const char* what = nullptr;
    int at = 0;
  };
  static SpanSetup setup_span(const Coefs& c, int y, int x0, int x1) {
    SpanSetup r{direct(c, x0, y)};
    for (int x : {x0, x1}) {
      const Xy xf = Xy::from_raw(x), yf = Xy::from_raw(y);
      const bool ok[3] = {fits<P>(c.a * xf + c.b * yf + c.c), fits<P>(c.d * xf + c.e * yf + c.f),
                          fits<Q>(c.g * xf + c.h * yf + c.i)};
      static constexpr const char* kName[3] = {"p_u", "p_v", "q"};
      for (int k = 0; k < 3; ++k)
        if (!ok[k] && !r.ovf) r = {r.acc, true, kName[k], x};
    }
    return r;
  }

  // Per-scanline set-up (software path): the accumulators at x0, after checking both span ends
  // [x0, x1] fit; throws SetupError naming the triangle, the accumulator and the pixel.
  static Acc setup(const Coefs& c, int y, int x0, int x1, const std::string& tri) {
    const SpanSetup s = setup_span(c, y, x0, x1);
    if (s.ovf) {
      const bool q = s.what[0] == 'q';
      throw SetupError("persp set-up: triangle '" + tri + "': " + s.what + " at pixel (" +
                       std::to_string(s.at) + ", " + std::to_string(y) + ") overflows s" +
                       std::to_string(q ? Q::kW : P::kW) + "." + std::to_string(F));
    }
    return s.acc;
  }

  // Per-pixel evaluation: guard, normalise, reciprocal, two multiplies, round, saturate.
  static Pixel pixel(const Acc& s) {
    const int64_t qr = static_cast<int64_t>(s.q.raw());
    constexpr int64_t kGuard = int64_t(1) << (F - fmt::kPerspGuardLog2);
    if (qr < kGuard) return {static_cast<int64_t>(Uv::kMaxRaw), static_cast<int64_t>(Uv::kMaxRaw), true};
    const int e = 63 - std::countl_zero(static_cast<uint64_t>(qr));  // msb position, >= F-Guard
    constexpr int mb = fmt::kRecipMantW - 1;
    const uint64_t m = e >= mb ? static_cast<uint64_t>(qr) >> (e - mb)   // truncate
                               : static_cast<uint64_t>(qr) << (mb - e);
    const i128 r = recip::core(recip::Mant::from_raw(static_cast<i128>(m))).raw();
    // u = p * R * 2^(F - e - RecipOutF) in real units; the code has PerspUvF fraction bits.
    const int sh = fmt::kRecipOutF + e - fmt::kPerspUvF;  // > 0 for every unguarded q
    return {scale(static_cast<i128>(s.pu.raw()) * r, sh), scale(static_cast<i128>(s.pv.raw()) * r, sh),
            false};
  }

  // ---- traversal variants over the span [x0, x0 + n) on row y ----
  static void span_direct(const Coefs& c, int y, int x0, int n, Pixel* out) {
    for (int i = 0; i < n; ++i) out[i] = pixel(direct(c, x0 + i, y));
  }
  static void span_incremental(const Coefs& c, int y, int x0, int n, Pixel* out,
                               const std::string& tri = "span") {
    Acc s = setup(c, y, x0, x0 + n - 1, tri);
    for (int i = 0; i < n; ++i) {
      out[i] = pixel(s);
      step(s, c.a, c.d, c.g);
    }
  }
  // k lanes: lane j seeded directly at x0 + j ("preparation cycle"), then p_n = p_{n-k} + k*A.
  template <int K>
  static void span_klane(const Coefs& c, int y, int x0, int n, Pixel* out) {
    const Xy k = Xy::from_raw(K);
    const P ka = (c.a * k).template as<P>(), kd = (c.d * k).template as<P>();
    const Q kg = (c.g * k).template as<Q>();
    Acc lane[K];
    for (int j = 0; j < K && j < n; ++j) lane[j] = direct(c, x0 + j, y);
    for (int i = 0; i < n; i += K)
      for (int j = 0; j < K && i + j < n; ++j) {
        out[i + j] = pixel(lane[j]);
        step(lane[j], ka, kd, kg);
      }
  }
  // Two-ended (counter-direction): one walker from each end, meeting in the middle.
  static void span_two_ended(const Coefs& c, int y, int x0, int n, Pixel* out) {
    if (n <= 0) return;
    Acc l = direct(c, x0, y), r = direct(c, x0 + n - 1, y);
    int i = 0, j = n - 1;
    while (i <= j) {
      out[i++] = pixel(l);
      step(l, c.a, c.d, c.g);
      if (j >= i) {
        out[j--] = pixel(r);
        unstep(r, c.a, c.d, c.g);
      }
    }
  }

 private:
  static void step(Acc& s, P a, P d, Q g) {
    s.pu = (s.pu + a).template as<P>();
    s.pv = (s.pv + d).template as<P>();
    s.q = (s.q + g).template as<Q>();
  }
  static void unstep(Acc& s, P a, P d, Q g) {
    s.pu = (s.pu - a).template as<P>();
    s.pv = (s.pv - d).template as<P>();
    s.q = (s.q - g).template as<Q>();
  }

 public:
  // The shift sh = RecipOutF + e - PerspUvF over every unguarded q (e = msb(q) in
  // [F - PerspGuardLog2, kQW - 2]), and |p * R| < 2^(kPW - 1 + RecipOutF).
  static constexpr int kMinSh = fmt::kRecipOutF + F - fmt::kPerspGuardLog2 - fmt::kPerspUvF;
  static constexpr int kMaxSh = fmt::kRecipOutF + kQW - 2 - fmt::kPerspUvF;
  // With 1 <= sh <= 63 and |prod| < 2^(62 + sh) the rounded, shifted value fits int64: it is the
  // low 64 bits of the 128-bit shift, formed from the two halves without a 128-bit shift and
  // saturated in 64 bits (SpeedEquivalence.PerspScaleFastEqualsWide compares the forms).
  static constexpr bool kScale64 = kMinSh >= 1 && kMaxSh <= 63 && kPW - 1 + fmt::kRecipOutF <= 62 + kMinSh;
  // Round half up prod * 2^-sh to the Uv code and saturate (prod = p R, sh as above).
  static int64_t scale(i128 prod, int sh) {
    if constexpr (kScale64) {
      const u128 v = static_cast<u128>(prod + (int64_t(1) << (sh - 1)));  // half: a 64-bit constant
      const uint64_t lo = static_cast<uint64_t>(v), hi = static_cast<uint64_t>(v >> 64);
      const int64_t r = static_cast<int64_t>((lo >> sh) | (hi << (64 - sh)));
      return std::clamp<int64_t>(r, static_cast<int64_t>(Uv::kMinRaw), static_cast<int64_t>(Uv::kMaxRaw));
    } else {
      return scale_wide(prod, sh);
    }
  }
  // The same in 128 bits (any sh >= 1): the reference of scale.
  static int64_t scale_wide(i128 prod, int sh) {
    const i128 v = (prod + (i128(1) << (sh - 1))) >> sh;  // round half up
    if (v > Uv::kMaxRaw) return static_cast<int64_t>(Uv::kMaxRaw);
    if (v < Uv::kMinRaw) return static_cast<int64_t>(Uv::kMinRaw);
    return static_cast<int64_t>(v);
  }

 private:
  template <class T>
  static T fit(double x, const char* name, const std::string& tri) {
    const long double lim = std::ldexp(1.0L, T::kI - 1);
    if (!(x >= -lim && x < lim))
      throw SetupError("persp set-up: triangle '" + tri + "': coefficient " + name + " = " +
                       std::to_string(x) + " overflows s" + std::to_string(T::kW) + "." +
                       std::to_string(T::kF));
    return T::template from_double<Round::HalfEven, Ovf::Sat>(x);
  }
  template <class T, class V>
  static bool fits(V v) {
    const i128 r = static_cast<i128>(v.raw()) >> (V::kF - T::kF);  // same F: shift 0
    return r >= T::kMinRaw && r <= T::kMaxRaw;
  }
};

using Unit = Model<fmt::kPerspF>;

// Latency in cycles of the per-scanline set-up RTL (rtl/persp/tu_persp_setup.sv), II = 1.
inline constexpr int kSetupLatency = fmt::kPerspSetupLatency;

// ---------------- float reference (double, GLM) ----------------
struct Camera {
  double pos[3] = {0, 0, 0};
  double look_at[3] = {0, 0, -1};
  double up[3] = {0, 1, 0};
  double fovy_deg = 60;
  int width = 640, height = 480;
  double z_near = 0.1;  // used to normalise q when the triangle reaches the eye plane
};
struct Vertex {
  double p[3];
  double uv[2];  // texels
};
struct Triangle {
  std::string name;
  Vertex v[3];
};

// uv rebase (docs/blocks/persp.md "uv rebase"). B1's accumulators hold |p| = |u q| < 2^13 texels
// and q = 1 at the nearest vertex, so a triangle whose uv lies far from 0 cannot be set up as
// given; along an axis whose address rule is periodic (period[k] > 0, level-0 texels) the sampler
// cannot tell uv from uv - j period. The offset per axis (texels, subtracted from every vertex):
// 0 while every vertex has |uv| < kRebaseFrom, unless `force` (the caller's set-up as given
// failed), else the multiple of the period nearest the axis' mid-range (halves rounded down),
// which leaves |uv| <= period / 2 + the triangle's extent / 2. A function of uv modulo the period:
// a triangle and the same one shifted by whole periods rebase to the same uv.
inline constexpr double kRebaseFrom = double(int64_t(1) << (fmt::kPerspPW - fmt::kPerspF - 1));
std::array<double, 2> rebase_offset(const Triangle& t, const std::array<double, 2>& period, bool force = false);
// t with rebase_offset(t, period, force) subtracted from its uv (exact: the offset is an integer
// and the difference is no larger than the uv).
Triangle rebased(const Triangle& t, const std::array<double, 2>& period, bool force = false);

// A..I for integer pixel indices (pixel centres at x + 0.5, y + 0.5; y grows downwards),
// scaled so that q = z_min / z_view (q = 1 at the nearest vertex, z_min >= camera z_near).
// Throws SetupError when the triangle's plane contains the eye (degenerate).
Coef9 coefficients(const Camera& cam, const Triangle& t);

// Ray through the centre of pixel (x, y) intersected with the triangle's plane; uv by barycentric
// interpolation. Returns false when the ray is parallel to the plane or the hit is behind the eye.
bool ray_uv(const Camera& cam, const Triangle& t, int x, int y, double* u, double* v);
// The same ray's hit with the triangle's plane: point p0 + s (p1 - p0) + r (p2 - p0) at distance
// `dist` along the unit ray (inside the triangle iff s >= 0, r >= 0, s + r <= 1).
struct Hit {
  double s = 0, r = 0, dist = 0;
};
bool ray_hit(const Camera& cam, const Triangle& t, int x, int y, Hit* h);

// ray_hit for many pixels of one camera: the camera basis (normalize, cross, tan) is computed
// once; hit() performs ray_hit's per-pixel arithmetic unchanged, so the results are the same bits.
class RayCaster {
 public:
  explicit RayCaster(const Camera& cam);
  bool hit(const Triangle& t, int x, int y, Hit* h) const;
  // hit() in two parts: the unit ray direction through pixel (x, y) (d[3]), and its hit with a
  // triangle: hit(t, x, y, h) == hit_dir(t, d, h) for d = dir(x, y) (one ray for many triangles).
  void dir(int x, int y, double* d) const;
  bool hit_dir(const Triangle& t, const double* d, Hit* h) const;
  // Pixel rectangle [x0, x1] x [y0, y1] (clipped to the image) outside which no pixel centre's
  // ray hits inside t: the vertices' projections plus a 2-pixel margin (far beyond rounding).
  // False when a vertex is not in front of the eye (the projection then bounds nothing).
  bool bounds(const Triangle& t, int* x0, int* x1, int* y0, int* y1) const;

 private:
  double pos_[3], fwd_[3], right_[3], up_[3];
  double th_, aspect_;
  int width_, height_;
};

// A synthetic mapping (any 3x3 map with q > 0 on the span is the view of some plane): on row y,
// q runs linearly from q0 at x0 to q1 at x1 and u (v) from u0 (v0) to u1 (v1) projectively;
// bq, bu, bv are the per-row slopes H, B, E. Used by the drift study and the vector sets.
Coef9 span_map(int y, int x0, int x1, double q0, double q1, double u0, double u1, double v0,
               double v1, double bq, double bu, double bv);

// A random span_map with q0, q1 given: u, v in [-4096, 4096] texels at the ends, with
// |p(x1) - p(x0)| <= 0.8 (x1 - x0), q1 clamped to |G| x1 <= 4, and per-row slopes |B|, |E| <= 1/4, |H| <= 2^-14 so that
// C, F (the map extrapolated to pixel (0, 0)) usually fit their format. Deterministic per rng.
Coef9 random_span_map(std::mt19937_64& rng, int y, int x0, int x1, double q0, double q1);

// Exact mapping of float coefficients (long double).
inline void eval_ref(const Coef9& k, int x, int y, double* u, double* v, double* q) {
  const long double X = x, Y = y;
  const long double qq = k.g * X + k.h * Y + k.i;
  *q = static_cast<double>(qq);
  *u = static_cast<double>((k.a * X + k.b * Y + k.c) / qq);
  *v = static_cast<double>((k.d * X + k.e * Y + k.f) / qq);
}

}  // namespace tu::persp
