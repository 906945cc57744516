// Vector sets for the pixel-footprint unit (B2, analytic variant, rtl/ellipse/tu_ellipse.sv).
//   in : numerators nux, nvx, nuy, nvy (s48.32), q (s44.40, B1's accumulator), det3 as mantissa
//        dm (s40) and exponent dexp (s8), log2(max anisotropy) laniso (u14.10), max_lod (u4)
//   out: Ae', Be', Ce' codes with shared exponent eexp, |f| = fm 2^(fexp-31) (Fe' = f^2),
//        log2 major / minor_clamped (s18.10), lod (u12.8), flags (horizon, degenerate,
//        aniso-clamped, lod-saturated, magnified), lrho = log2 rho of trilinear's GL LOD rule
//        (s18.10, texture/trilinear_lod.hpp)
//   ref: float footprint (ellipse_ref.hpp) of the analytic Jacobian J = n / q^2 of the same codes:
//        lod, log2 major, log2 minor_clamped (NaN at the horizon).
// Error unit: mip levels (|lod - lod_ref|); ulp = LOD LSBs (2^-EllLodF).
#include <cmath>
#include <random>

#include "block.hpp"
#include "ellipse/ellipse_fx.hpp"

namespace tu::blocks {

namespace {
namespace fx = ellipse::fx;
constexpr uint32_t kAniso16 = 4u << fmt::kEllLogF;

uint64_t bits(int64_t v, int w) { return static_cast<uint64_t>(v) & (w == 64 ? ~0ull : ((1ull << w) - 1)); }

Row row_of(const fx::In& in) {
  return {bits(in.nux, fmt::kEllNumW), bits(in.nvx, fmt::kEllNumW), bits(in.nuy, fmt::kEllNumW),
          bits(in.nvy, fmt::kEllNumW), bits(in.q, fmt::kPerspQW),   bits(in.dm, fmt::kEllDetW),
          bits(in.dexp, fmt::kEllDetExpW), in.laniso, in.max_lod};
}
fx::In in_of(const Row& r) {
  fx::In in;
  in.nux = vec::sext(r[0], fmt::kEllNumW);
  in.nvx = vec::sext(r[1], fmt::kEllNumW);
  in.nuy = vec::sext(r[2], fmt::kEllNumW);
  in.nvy = vec::sext(r[3], fmt::kEllNumW);
  in.q = vec::sext(r[4], fmt::kPerspQW);
  in.dm = vec::sext(r[5], fmt::kEllDetW);
  in.dexp = static_cast<int32_t>(vec::sext(r[6], fmt::kEllDetExpW));
  in.laniso = static_cast<uint32_t>(r[7]);
  in.max_lod = static_cast<uint32_t>(r[8]);
  return in;
}

// Local map with a given major axis, anisotropy and orientation.
fx::Local local(double q, double major, double aniso, double theta, double g = 0, double h = 0) {
  fx::Local l;
  l.q = q;
  const double c = std::cos(theta), s = std::sin(theta), minor = aniso > 0 ? major / aniso : 0;
  l.ux = c * major;
  l.vx = s * major;
  l.uy = -s * minor;
  l.vy = c * minor;
  l.g = g;
  l.h = h;
  l.u = 100;
  l.v = -200;
  return l;
}
Row from_local(const fx::Local& l, uint32_t laniso = kAniso16, uint32_t max_lod = 12) {
  return row_of(fx::in_from_map(fx::local_map(l), laniso, max_lod));
}

// The curated stiff set (docs/blocks/ellipse.md, "Stiff cases"); behaviour tested in
// testbench/unit/ellipse_fx_test.cpp.
std::vector<Row> stiff_inputs() {
  std::vector<Row> rows;
  // 1. Grazing planes: anisotropy 1:10 ... 1:1000 before the clamp, 16 orientations.
  for (double an : {10.0, 16.0, 100.0, 1000.0})
    for (int t = 0; t < 16; ++t) rows.push_back(from_local(local(0.05, 64, an, t * M_PI / 16)));
  // 2. Footprints larger than the texture: lod saturates at max_lod (12, 8, 0).
  for (uint32_t ml : {12u, 8u, 0u}) {
    rows.push_back(from_local(local(0.01, 8192, 1, 0.3), kAniso16, ml));
    rows.push_back(from_local(local(0.002, 20000, 2, 1.1), kAniso16, ml));
  }
  // 3. Degenerate footprints: a line (rank-1 Jacobian, det3 = 0) and a point (J = 0).
  rows.push_back(from_local(local(0.5, 32, 0, 0.7)));
  rows.push_back(from_local(local(0.5, 0.25, 0, 2.0)));
  {
    fx::Local p = local(0.5, 0, 1, 0);
    p.ux = p.vx = p.uy = p.vy = 0;
    rows.push_back(from_local(p));
  }
  // 4. Horizon: q just below the guard, 0, negative, most negative; and just above the guard.
  for (int64_t q : {(int64_t(1) << 30) - 1, int64_t(0), int64_t(-5), -(int64_t(1) << 43),
                    int64_t(1) << 30}) {
    Row r = from_local(local(0.001, 900, 3, 0.2));
    r[4] = bits(q, fmt::kPerspQW);
    rows.push_back(r);
  }
  for (double q : {0.002, 0.00098, 0.0011}) rows.push_back(from_local(local(q, 1 / q, 5, 0.9, q / 40, -q / 50)));
  // 5. Magnification: footprints of 1/2 ... 1/1024 texel: lod 0.
  for (double s : {0.5, 0.1, 1.0 / 1024}) rows.push_back(from_local(local(0.7, s, 1.5, 0.4)));
  // 6. Anisotropy parameter: 1:1 (isotropic LOD from the major axis), 2, 8, 1024.
  for (uint32_t la : {0u, 1u << 10, 3u << 10, 10u << 10}) rows.push_back(from_local(local(0.3, 50, 40, 1.3), la));
  // 7. Format extremes: largest numerators, largest q, largest / smallest det3 exponent.
  {
    const int64_t big = -(int64_t(1) << (fmt::kEllNumW - 1)), top = (int64_t(1) << (fmt::kEllNumW - 1)) - 1;
    const int64_t qmax = (int64_t(1) << (fmt::kPerspQW - 1)) - 1;
    const int64_t dmax = (int64_t(1) << (fmt::kEllDetW - 1)) - 1;
    for (int dexp : {-128, 0, 127})
      for (int64_t q : {qmax, int64_t(1) << 30}) {
        rows.push_back(row_of({big, big, big, big, q, dmax, dexp, kAniso16, 15}));
        rows.push_back(row_of({top, big, big, top, q, -dmax, dexp, kAniso16, 15}));
        rows.push_back(row_of({1, 0, 0, 1, q, 1ll << (fmt::kEllDetW - 2), dexp, 16383, 15}));
      }
  }
  return rows;
}

std::vector<Row> random_inputs(uint64_t count, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<Row> rows;
  rows.reserve(count);
  while (rows.size() < count) {
    const auto l = fx::random_local(rng);
    const uint64_t k = rng() % 8;
    const uint32_t la = k == 0 ? static_cast<uint32_t>(rng() % (11u << fmt::kEllLogF)) : kAniso16;
    const uint32_t ml = k == 1 ? static_cast<uint32_t>(rng() % 16) : 12;
    rows.push_back(from_local(l, la, ml));
  }
  return rows;
}

std::vector<Row> golden_inputs() {
  std::vector<Row> rows;
  const auto s = stiff_inputs();
  for (size_t i = 0; i < s.size(); i += 5) rows.push_back(s[i]);
  const auto r = random_inputs(12, 99);
  rows.insert(rows.end(), r.begin(), r.end());
  return rows;
}

bool horizon(const fx::In& in) { return in.q < (int64_t(1) << (fmt::kPerspF - fmt::kPerspGuardLog2)); }

Row ref_of(const Row& r) {
  const fx::In in = in_of(r);
  if (horizon(in)) return {vec::f64_bits(NAN), vec::f64_bits(NAN), vec::f64_bits(NAN)};
  const double q = std::ldexp(double(in.q), -fmt::kPerspF), q2 = q * q;
  auto j = [&](int64_t n) { return std::ldexp(double(n), -fmt::kEllNumF) / q2; };
  ellipse::FootprintParams p;
  p.max_aniso = std::exp2(std::ldexp(double(in.laniso), -fmt::kEllLogF));
  p.max_lod = in.max_lod;
  const auto f = ellipse::footprint({j(in.nux), j(in.nvx), j(in.nuy), j(in.nvy)}, p);
  return {vec::f64_bits(f.lod), vec::f64_bits(std::log2(f.major)), vec::f64_bits(std::log2(f.minor_clamped))};
}
}  // namespace

Block make_ellipse() {
  Block b;
  b.name = "ellipse";
  b.description =
      "pixel footprint (analytic, q^4-scaled EWA ellipse): Ae', Be', Ce', Fe', axes, anisotropy "
      "clamp, mip LOD; II = 1";
  auto F = [](const char* n, vec::Role r, const std::string& f) {
    return vec::Field{n, r, vec::FieldFormat::parse(f)};
  };
  auto sf = [](int w, int f) { return "s" + std::to_string(w) + "." + std::to_string(f); };
  auto uf = [](int w, int f) { return "u" + std::to_string(w) + "." + std::to_string(f); };
  const std::string nf = sf(fmt::kEllNumW, fmt::kEllNumF);
  using vec::Role;
  b.fields = {F("nux", Role::In, nf),
              F("nvx", Role::In, nf),
              F("nuy", Role::In, nf),
              F("nvy", Role::In, nf),
              F("q", Role::In, sf(fmt::kPerspQW, fmt::kPerspF)),
              F("dm", Role::In, sf(fmt::kEllDetW, 0)),
              F("dexp", Role::In, sf(fmt::kEllDetExpW, 0)),
              F("laniso", Role::In, uf(fmt::kEllAnisoW, fmt::kEllLogF)),
              F("maxlod", Role::In, uf(fmt::kEllMaxLodW, 0)),
              F("ae", Role::Out, uf(fmt::kEllCoefW, 0)),
              F("be", Role::Out, sf(fmt::kEllCoefW, 0)),
              F("ce", Role::Out, uf(fmt::kEllCoefW, 0)),
              F("eexp", Role::Out, uf(fmt::kEllEexpW, 0)),
              F("fm", Role::Out, uf(fmt::kEllFmW, fmt::kEllFmW - 1)),
              F("fexp", Role::Out, sf(fmt::kEllFexpW, 0)),
              F("lmaj", Role::Out, sf(fmt::kEllLogW, fmt::kEllLogF)),
              F("lmin", Role::Out, sf(fmt::kEllLogW, fmt::kEllLogF)),
              F("lod", Role::Out, uf(fmt::kEllLodW, fmt::kEllLodF)),
              F("flags", Role::Out, uf(5, 0)),
              F("lrho", Role::Out, sf(fmt::kEllLogW, fmt::kEllLogF)),
              F("lod_ref", Role::Ref, "f64"),
              F("lmaj_ref", Role::Ref, "f64"),
              F("lmin_ref", Role::Ref, "f64")};
  b.sets = {"golden", "stiff", "random"};
  b.inputs = [](const std::string& set, uint64_t count, uint64_t seed) {
    if (set == "golden") return golden_inputs();
    if (set == "stiff") return stiff_inputs();
    return random_inputs(count, seed);
  };
  b.model = [](const Row& r) {
    const auto o = fx::analytic(in_of(r));
    return Row{o.ae,
               static_cast<uint64_t>(o.be),
               o.ce,
               o.eexp,
               o.fm,
               bits(o.fexp, fmt::kEllFexpW),
               bits(o.lmaj, fmt::kEllLogW),
               bits(o.lmin, fmt::kEllLogW),
               o.lod,
               o.flags,
               bits(o.lrho, fmt::kEllLogW)};
  };
  b.ref = ref_of;
  b.error = [](const Row& in, const Row& out, const Row& ref) {
    ErrPoint e;
    const bool hz = horizon(in_of(in));
    if (hz || (out[9] & fx::kHorizon)) {  // must agree; flagged outputs are not measured
      const bool ok = hz && out[9] == fx::kHorizon && out[8] == 0;
      e.valid = !ok;
      e.abs = e.ulp = ok ? 0 : INFINITY;
      return e;
    }
    // Rows whose det3 is not the determinant of the numerators (nUx nVy - nUy nVx = det3 q) are
    // no projective map (the format-extreme rows of the stiff set): bit-exact only, not measured.
    const fx::In x = in_of(in);
    auto nf = [](int64_t c) { return std::ldexp(double(c), -fmt::kEllNumF); };
    const double dn = nf(x.nux) * nf(x.nvy) - nf(x.nuy) * nf(x.nvx);
    const double d3 = fx::det3_value(x) * std::ldexp(double(x.q), -fmt::kPerspF);
    if (std::fabs(dn - d3) > 1e-3 * std::max(std::fabs(dn), std::fabs(d3)) + 1e-12) {
      e.valid = false;
      return e;
    }
    const double lod = std::ldexp(double(out[8]), -fmt::kEllLodF);
    e.abs = std::fabs(lod - vec::bits_f64(ref[0]));
    e.ulp = std::ldexp(e.abs, fmt::kEllLodF);
    return e;
  };
  b.latency_cycles = fmt::kEllLatency;
  b.ii_cycles = 1;
  b.err_metric = "max_lod_err";
  return b;
}

}  // namespace tu::blocks
