// Vector sets for the EWA border weight of one walked texel (docs/blocks/ewa.md "Border weights",
// ewa::fx::border + apply_border, RTL rtl/ewa/tu_ewa_border.sv with the mm_p1 clip volume):
//   in : Q (u63.44), xi, eta (s32.22), the frame kxu, kxv, kyu, kyv (s18.16), w = the weight
//        source's value at Q (u17.16; used for Q < 1 only)
//   out: zone (0 inside, 1 band, 2 outside), d (s13.12, band only), the border weight (u17.16)
//   ref: the weight in double from the same integers: d with the exact roots and division,
//        v = Phi(d / 0.2); error unit: the weight (0..1).
#include <cmath>
#include <random>

#include "block.hpp"
#include "ewa/ewa_cycles.hpp"
#include "ewa/ewa_fx.hpp"
#include "gauss/weight.hpp"

namespace tu::blocks {

namespace {
namespace efx = ewa::fx;
constexpr int kQF = 2 * (fmt::kEwaKF + fmt::kEwaPosF);
constexpr int64_t kStep = int64_t(1) << fmt::kEwaPosF;
const char* const kVariant = "mm_p1";  // tu_ewa_border's default ClipVariant 0 (tu_clip_p1)

struct Texel {
  int64_t q = 0, xi = 0, eta = 0;
  int32_t k[4] = {0, 0, 0, 0};  // kxu, kxv, kyu, kyv
  uint32_t w = 0;
};
Row row_of(const Texel& t) {
  return {static_cast<uint64_t>(t.q), field_bits(t.xi, fmt::kEwaXiW), field_bits(t.eta, fmt::kEwaXiW),
          field_bits(t.k[0], fmt::kEwaKW), field_bits(t.k[1], fmt::kEwaKW), field_bits(t.k[2], fmt::kEwaKW),
          field_bits(t.k[3], fmt::kEwaKW), t.w};
}
Texel texel_of(const Row& r) {
  Texel t;
  t.q = static_cast<int64_t>(r[0]);
  t.xi = vec::sext(r[1], fmt::kEwaXiW);
  t.eta = vec::sext(r[2], fmt::kEwaXiW);
  for (int i = 0; i < 4; ++i) t.k[i] = static_cast<int32_t>(vec::sext(r[3 + static_cast<size_t>(i)], fmt::kEwaKW));
  t.w = static_cast<uint32_t>(r[7]);
  return t;
}
efx::PixelSetup frame_of(const Texel& t) {
  efx::PixelSetup su;
  su.kxu = t.k[0], su.kxv = t.k[1], su.kyu = t.k[2], su.kyv = t.k[3];
  return su;
}
// The walked texels of random pixels of the EWA vector set (border walk), 3 in 4 from the zone
// 1/4 <= Q <= 9/4; w = the formula weight for Q < 1, a random code otherwise (must be ignored).
std::vector<Row> walk_rows(uint64_t count, uint64_t seed) {
  std::mt19937_64 rng(seed);
  efx::Config cfg;
  cfg.clip = &clip::variant(kVariant);
  std::vector<Row> rows;
  while (rows.size() < count) {
    static const tex::Texture pyramid = tex::Texture::build("t", img::Rgba8Image(256, 256, {}), tex::Wrap::Repeat);
    const efx::PixelSetup su = efx::setup(efx::random_in(rng), pyramid, cfg);
    for (int64_t y = su.y0; y <= su.y1 && rows.size() < count; ++y)
      for (int64_t x = su.x0; x <= su.x1 && rows.size() < count; ++x) {
        const int64_t du = x * kStep - su.cu, dv = y * kStep - su.cv;
        Texel t;
        t.xi = int64_t(su.kxu) * du + int64_t(su.kxv) * dv;
        t.eta = int64_t(su.kyu) * du + int64_t(su.kyv) * dv;
        t.q = t.xi * t.xi + t.eta * t.eta;
        const bool zone = t.q >= (int64_t(1) << (kQF - 2)) && t.q <= (int64_t(9) << (kQF - 2));
        if (!zone && rng() % 4 != 0) continue;
        t.k[0] = su.kxu, t.k[1] = su.kxv, t.k[2] = su.kyu, t.k[3] = su.kyv;
        t.w = t.q < (int64_t(1) << kQF) ? gauss::weight(static_cast<uint32_t>(t.q >> (kQF - fmt::kGaussQF)))
                                        : static_cast<uint32_t>(rng() % (1u << fmt::kGaussSqW));
        rows.push_back(row_of(t));
      }
  }
  return rows;
}
// Zone edges and extremes on a circle of radius 1 texel (k = identity), any direction.
std::vector<Row> edge_rows() {
  std::vector<Row> rows;
  const int32_t one = 1 << fmt::kEwaKF;
  for (int64_t qc : {int64_t(0), int64_t(1) << (kQF - 2), (int64_t(1) << (kQF - 2)) - 1, int64_t(9) << (kQF - 2),
                     (int64_t(9) << (kQF - 2)) + 1, int64_t(1) << kQF, (int64_t(1) << kQF) - 1,
                     (int64_t(1) << kQF) + 1, (int64_t(1) << 62) + 12345, INT64_MAX}) {
    for (int dir = 0; dir < 2; ++dir) {
      Texel t;
      t.q = qc;
      const int64_t r = static_cast<int64_t>(std::sqrt(std::ldexp(double(qc), -kQF)) * std::ldexp(1.0, kQF / 2));
      (dir ? t.eta : t.xi) = std::min<int64_t>(r, (int64_t(1) << (fmt::kEwaXiW - 1)) - 1);
      t.k[0] = one, t.k[3] = one;
      t.w = 12345;
      rows.push_back(row_of(t));
    }
  }
  // No gradient (k = 0): the zone by the sign of (1 - r) r; extreme frame and offsets.
  for (int64_t qc : {int64_t(1) << (kQF - 1), int64_t(3) << (kQF - 1)}) {
    Texel t;
    t.q = qc, t.w = 777;
    rows.push_back(row_of(t));
  }
  Texel ext;
  ext.q = int64_t(1) << kQF;
  ext.xi = (int64_t(1) << (fmt::kEwaXiW - 1)) - 1, ext.eta = -(int64_t(1) << (fmt::kEwaXiW - 1));
  for (int i = 0; i < 4; ++i) ext.k[i] = (i % 2) ? -(1 << (fmt::kEwaKW - 1)) : (1 << (fmt::kEwaKW - 1)) - 1;
  ext.w = (1u << fmt::kGaussSqW) - 1;
  rows.push_back(row_of(ext));
  return rows;
}
}  // namespace

Block make_ewa_border() {
  Block b;
  b.name = "ewa_border";
  b.description = "EWA sub-texel border weight of one texel: d = (1 - r) r / |g|, clip volume mm_p1, w v(d)";
  b.fields = {field("q", vec::Role::In, "u63.44"),   field("xi", vec::Role::In, "s32.22"),
              field("eta", vec::Role::In, "s32.22"), field("kxu", vec::Role::In, "s18.16"),
              field("kxv", vec::Role::In, "s18.16"), field("kyu", vec::Role::In, "s18.16"),
              field("kyv", vec::Role::In, "s18.16"), field("w", vec::Role::In, "u17.16"),
              field("zone", vec::Role::Out, "u2.0"), field("d", vec::Role::Out, "s13.12"),
              field("wo", vec::Role::Out, "u17.16"), field("ref", vec::Role::Ref, "f64")};
  b.ports = {{"wo", "w"}};  // tu_ewa_border's w_o (w_i is the interior weight)
  b.sets = {"golden", "stiff", "random"};
  b.inputs = standard_sets([] { return walk_rows(64, 1); }, [] { return edge_rows(); },
                           [](uint64_t count, uint64_t seed) { return walk_rows(count, seed); });
  b.model = [](const Row& in) {
    const Texel t = texel_of(in);
    const efx::Border br = efx::border(frame_of(t), t.q, t.xi, t.eta);
    return Row{static_cast<uint64_t>(br.zone), field_bits(br.d, fmt::kClipInW),
               efx::apply_border(br, t.q, t.w, clip::variant(kVariant))};
  };
  b.ref = [](const Row& in) {
    const Texel t = texel_of(in);
    const double q = std::ldexp(double(t.q), -kQF), r = std::sqrt(q);
    const double xi = std::ldexp(double(t.xi), -kQF / 2), eta = std::ldexp(double(t.eta), -kQF / 2);
    const double k = std::ldexp(1.0, -fmt::kEwaKF);
    const double g = std::hypot((t.k[0] * xi + t.k[2] * eta) * k, (t.k[1] * xi + t.k[3] * eta) * k);
    const double w = std::ldexp(double(t.w), -fmt::kGaussSqF);
    double out;
    const double d = q < 0.25 ? HUGE_VAL : q > 2.25 ? -HUGE_VAL : g > 0 ? (1 - r) * r / g : (r < 1 ? HUGE_VAL : -HUGE_VAL);
    if (d > 0.5) out = w;
    else if (d < -0.5) out = 0;
    else out = (q < 1 ? w : std::ldexp(1.0, -8)) * 0.5 * std::erfc(-d / (0.2 * std::sqrt(2.0)));
    return Row{vec::f64_bits(out)};
  };
  b.error = [](const Row&, const Row& out, const Row& ref) {
    ErrPoint e;
    e.abs = std::fabs(std::ldexp(static_cast<double>(out[2]), -fmt::kGaussSqF) - vec::bits_f64(ref[0]));
    e.ulp = e.abs / std::ldexp(1.0, -fmt::kGaussSqF);
    return e;
  };
  // S1 g, S2 g^2, 24 root stages, S27 num / den, 12 divider stages, S40 d, the clip scheme, the weight.
  b.latency_cycles = ewa::border_latency(ewa::rtl_clip_code(kVariant));
  b.ii_cycles = 1;
  return b;
}

}  // namespace tu::blocks
