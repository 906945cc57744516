#include <algorithm>
#include <cmath>

#include "brdf_shade.hpp"
#include "texunit/fixed.hpp"

namespace tu::brdf::shade {

namespace {
constexpr int kDotDown = 2 * fmt::kShadeVecF - fmt::kBrdfCF;
static_assert(kDotDown > 0, "N.H is rounded down to BrdfCF fraction bits");
// |sum of three products| < 3 * 2^(2 (ShadeVecW - 1)): fits the declared dot width.
static_assert(2 * (fmt::kShadeVecW - 1) + 2 + 1 <= fmt::kShadeDotW, "ShadeDotW holds N.H exactly");
static_assert(1 + 9 * fmt::kShadeVecW + fmt::kBrdfNW + fmt::kBrdfClW + 7 * fmt::kShadeColW <= fmt::kShadeWordW,
              "the shade port word holds every field");
constexpr int64_t kVecMax = (int64_t(1) << (fmt::kShadeVecW - 1)) - 1;
constexpr int64_t kColMax = (int64_t(1) << fmt::kShadeColW) - 1;

uint8_t channel(img::Rgba8 t, int ch) { return ch == 0 ? t.r : ch == 1 ? t.g : t.b; }
}  // namespace

int64_t dot(const Vec& a, const Vec& b) {
  const i128 s = i128(a.x) * b.x + i128(a.y) * b.y + i128(a.z) * b.z;  // exact, ShadeDotW bits
  const i128 r = (s + (i128(1) << (kDotDown - 1))) >> kDotDown;       // half up (floor shift)
  const i128 lim = i128(1) << (fmt::kBrdfCW - 1);
  return static_cast<int64_t>(std::clamp<i128>(r, -lim, lim - 1));
}

Result eval(Model m, const In& in, img::Rgba8 t) {
  Result out;
  out.rgba = t;
  if (!in.on) return out;
  const int64_t one = int64_t(1) << fmt::kBrdfCF;
  const int64_t nl = dot(in.n, in.l), nh = dot(in.n, in.h);
  const int64_t dcl = std::clamp<int64_t>(nl, 0, one);
  constexpr int kDDown = fmt::kBrdfCF - fmt::kShadeColF;
  out.d = static_cast<uint32_t>((dcl + (int64_t(1) << (kDDown - 1))) >> kDDown);
  if (nl > 0) {
    const uint64_t cmask = (uint64_t(1) << fmt::kBrdfCW) - 1;
    const brdf::Result r = brdf::eval(m, {static_cast<uint64_t>(nh) & cmask, in.nexp, in.ccut});
    out.f = r.f;
    out.flag = r.flag;
  }
  const uint32_t half = 1u << (fmt::kShadeColF - 1);
  uint8_t res[3];
  for (int ch = 0; ch < 3; ++ch) {
    const uint64_t e = in.amb + ((uint64_t(in.lc[ch]) * out.d + half) >> fmt::kShadeColF);  // ShadeEW
    const uint64_t acc = (uint64_t(channel(t, ch)) * e << fmt::kShadeColF) + 255 * uint64_t(in.ks[ch]) * out.f;
    constexpr int kDown = 2 * fmt::kShadeColF;  // E and ks F both carry 2 ShadeColF fraction bits
    res[ch] = static_cast<uint8_t>(std::min<uint64_t>(255, (acc + (uint64_t(1) << (kDown - 1))) >> kDown));
  }
  out.rgba = {res[0], res[1], res[2], t.a};
  return out;
}

std::array<double, 3> ref_channels(Model m, const RefIn& in, img::Rgba8 t) {
  const double nl = in.n[0] * in.l[0] + in.n[1] * in.l[1] + in.n[2] * in.l[2];
  const double nh = in.n[0] * in.h[0] + in.n[1] * in.h[1] + in.n[2] * in.h[2];
  const double f = nl > 0 ? ref_value(m, std::clamp(nh, 0.0, 1.0), in.nexp) : 0.0;
  std::array<double, 3> out{};
  for (int ch = 0; ch < 3; ++ch)
    out[static_cast<size_t>(ch)] = channel(t, ch) * (in.amb + in.lc[ch] * std::clamp(nl, 0.0, 1.0)) + 255 * in.ks[ch] * f;
  return out;
}

img::Rgba8 ref(Model m, const RefIn& in, img::Rgba8 t) {
  const auto c = ref_channels(m, in, t);
  auto to8 = [](double x) { return static_cast<uint8_t>(std::clamp(std::floor(x + 0.5), 0.0, 255.0)); };
  return {to8(c[0]), to8(c[1]), to8(c[2]), t.a};
}

int64_t vec_code(double x) {
  const double c = std::nearbyint(std::ldexp(std::clamp(x, -2.0, 2.0), fmt::kShadeVecF));
  return std::clamp<int64_t>(static_cast<int64_t>(c), -kVecMax - 1, kVecMax);
}

uint32_t col_code(double x) {
  const double c = std::nearbyint(std::ldexp(std::clamp(x, 0.0, 2.0), fmt::kShadeColF));
  return static_cast<uint32_t>(std::clamp<int64_t>(static_cast<int64_t>(c), 0, kColMax));
}

In quantise(const RefIn& r, uint64_t ccut) {
  In q;
  q.on = true;
  auto v = [](const double* a) { return Vec{vec_code(a[0]), vec_code(a[1]), vec_code(a[2])}; };
  q.n = v(r.n), q.l = v(r.l), q.h = v(r.h);
  q.nexp = static_cast<uint32_t>(std::clamp(r.nexp, 1, fmt::kBrdfNMax));
  q.ccut = ccut;
  for (int ch = 0; ch < 3; ++ch) q.ks[ch] = col_code(r.ks[ch]), q.lc[ch] = col_code(r.lc[ch]);
  q.amb = col_code(r.amb);
  return q;
}

std::array<uint32_t, kWordWords> pack(const In& in) {
  std::array<uint32_t, kWordWords> w{};
  int pos = 0;  // fields from the least significant bit up (amb first)
  auto put = [&](uint64_t v, int width) {
    v &= (uint64_t(1) << width) - 1;
    for (int b = 0; b < width; ++b, ++pos)
      if ((v >> b) & 1) w[static_cast<size_t>(pos / 32)] |= 1u << (pos % 32);
  };
  put(in.amb, fmt::kShadeColW);
  for (int ch = 2; ch >= 0; --ch) put(in.lc[ch], fmt::kShadeColW);
  for (int ch = 2; ch >= 0; --ch) put(in.ks[ch], fmt::kShadeColW);
  put(in.ccut, fmt::kBrdfClW);
  put(in.nexp, fmt::kBrdfNW);
  for (const Vec* v : {&in.h, &in.l, &in.n}) {
    put(static_cast<uint64_t>(v->z), fmt::kShadeVecW);
    put(static_cast<uint64_t>(v->y), fmt::kShadeVecW);
    put(static_cast<uint64_t>(v->x), fmt::kShadeVecW);
  }
  put(in.on, 1);
  return w;
}

int latency(Model m) {
  switch (m) {
    case Model::Blinn: return fmt::kBrdfBlinnLatency;
    case Model::Schlick: return fmt::kBrdfSchlickLatency;
    case Model::Msh: return fmt::kBrdfMshLatency;
    case Model::Dsh: return fmt::kBrdfDshLatency;
    case Model::Scos2: return fmt::kBrdfScos2Latency;
    case Model::St16: return fmt::kBrdfSt16Latency;
    case Model::Qr: return fmt::kBrdfQrLatency;
  }
  return 0;
}

}  // namespace tu::brdf::shade
