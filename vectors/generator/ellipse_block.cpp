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

Row row_of(const fx::In& in) {
  return {field_bits(in.nux, fmt::kEllNumW), field_bits(in.nvx, fmt::kEllNumW), field_bits(in.nuy, fmt::kEllNumW),
          field_bits(in.nvy, fmt::kEllNumW), field_bits(in.q, fmt::kPerspQW),   field_bits(in.dm, fmt::kEllDetW),
          field_bits(in.dexp, fmt::kEllDetExpW), in.laniso, in.max_lod};
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
    r[4] = field_bits(q, fmt::kPerspQW);
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

// Random local maps (fx::random_local), 1/8 with a random anisotropy limit and 1/8 with a random
// max_lod, each turned into a row by `to_row` (local, laniso, max_lod).
using LocalRow = Row (*)(const fx::Local&, uint32_t, uint32_t);
std::vector<Row> random_rows(uint64_t count, uint64_t seed, LocalRow to_row) {
  std::mt19937_64 rng(seed);
  std::vector<Row> rows;
  rows.reserve(count);
  while (rows.size() < count) {
    const auto l = fx::random_local(rng);
    const uint64_t k = rng() % 8;
    const uint32_t la = k == 0 ? static_cast<uint32_t>(rng() % (11u << fmt::kEllLogF)) : kAniso16;
    const uint32_t ml = k == 1 ? static_cast<uint32_t>(rng() % 16) : 12;
    rows.push_back(to_row(l, la, ml));
  }
  return rows;
}
std::vector<Row> random_inputs(uint64_t count, uint64_t seed) { return random_rows(count, seed, from_local); }

// Every fifth stiff row and 12 random ones.
std::vector<Row> golden_of(const std::vector<Row>& stiff, std::vector<Row> random) {
  std::vector<Row> rows;
  for (size_t i = 0; i < stiff.size(); i += 5) rows.push_back(stiff[i]);
  rows.insert(rows.end(), random.begin(), random.end());
  return rows;
}
std::vector<Row> golden_inputs() { return golden_of(stiff_inputs(), random_inputs(12, 99)); }

std::string sf(int w, int f) { return "s" + std::to_string(w) + "." + std::to_string(f); }
std::string uf(int w, int f) { return "u" + std::to_string(w) + "." + std::to_string(f); }
std::string num_format() { return sf(fmt::kEllNumW, fmt::kEllNumF); }
// Outputs and float references shared by both variants (fx::Out).
void add_out_fields(Block* b) {
  using vec::Role;
  for (const auto& f : {field("ae", Role::Out, uf(fmt::kEllCoefW, 0)), field("be", Role::Out, sf(fmt::kEllCoefW, 0)),
                        field("ce", Role::Out, uf(fmt::kEllCoefW, 0)), field("eexp", Role::Out, uf(fmt::kEllEexpW, 0)),
                        field("fm", Role::Out, uf(fmt::kEllFmW, fmt::kEllFmW - 1)),
                        field("fexp", Role::Out, sf(fmt::kEllFexpW, 0)),
                        field("lmaj", Role::Out, sf(fmt::kEllLogW, fmt::kEllLogF)),
                        field("lmin", Role::Out, sf(fmt::kEllLogW, fmt::kEllLogF)),
                        field("lod", Role::Out, uf(fmt::kEllLodW, fmt::kEllLodF)), field("flags", Role::Out, uf(5, 0)),
                        field("lrho", Role::Out, sf(fmt::kEllLogW, fmt::kEllLogF)), field("lod_ref", Role::Ref, "f64"),
                        field("lmaj_ref", Role::Ref, "f64"), field("lmin_ref", Role::Ref, "f64")})
    b->fields.push_back(f);
}
Row out_row(const fx::Out& o) {
  return Row{o.ae,
             static_cast<uint64_t>(o.be),
             o.ce,
             o.eexp,
             o.fm,
             field_bits(o.fexp, fmt::kEllFexpW),
             field_bits(o.lmaj, fmt::kEllLogW),
             field_bits(o.lmin, fmt::kEllLogW),
             o.lod,
             o.flags,
             field_bits(o.lrho, fmt::kEllLogW)};
}
Row footprint_row(const ellipse::Jacobian& j, const fx::In& in) {
  ellipse::FootprintParams p;
  p.max_aniso = std::exp2(std::ldexp(double(in.laniso), -fmt::kEllLogF));
  p.max_lod = in.max_lod;
  const auto f = ellipse::footprint(j, p);
  return {vec::f64_bits(f.lod), vec::f64_bits(std::log2(f.major)), vec::f64_bits(std::log2(f.minor_clamped))};
}
ErrPoint lod_error(const Row& out, const Row& ref) {
  ErrPoint e;
  const double lod = std::ldexp(double(out[8]), -fmt::kEllLodF);
  e.abs = std::fabs(lod - vec::bits_f64(ref[0]));
  e.ulp = std::ldexp(e.abs, fmt::kEllLodF);
  return e;
}
// Horizon rows must be flagged with every output 0 (out[9] flags, out[8] lod); then unmeasured.
ErrPoint horizon_error(bool hz, const Row& out) {
  ErrPoint e;
  const bool ok = hz && out[9] == fx::kHorizon && out[8] == 0;
  e.valid = !ok;
  e.abs = e.ulp = ok ? 0 : INFINITY;
  return e;
}

bool horizon(const fx::In& in) { return in.q < (int64_t(1) << (fmt::kPerspF - fmt::kPerspGuardLog2)); }

Row ref_of(const Row& r) {
  const fx::In in = in_of(r);
  if (horizon(in)) return {vec::f64_bits(NAN), vec::f64_bits(NAN), vec::f64_bits(NAN)};
  const double q = std::ldexp(double(in.q), -fmt::kPerspF), q2 = q * q;
  auto j = [&](int64_t n) { return std::ldexp(double(n), -fmt::kEllNumF) / q2; };
  return footprint_row({j(in.nux), j(in.nvx), j(in.nuy), j(in.nvy)}, in);
}
}  // namespace

Block make_ellipse() {
  Block b;
  b.name = "ellipse";
  b.description =
      "pixel footprint (analytic, q^4-scaled EWA ellipse): Ae', Be', Ce', Fe', axes, anisotropy "
      "clamp, mip LOD; II = 1";
  using vec::Role;
  b.fields = {field("nux", Role::In, num_format()), field("nvx", Role::In, num_format()),
              field("nuy", Role::In, num_format()), field("nvy", Role::In, num_format()),
              field("q", Role::In, sf(fmt::kPerspQW, fmt::kPerspF)),
              field("dm", Role::In, sf(fmt::kEllDetW, 0)),
              field("dexp", Role::In, sf(fmt::kEllDetExpW, 0)),
              field("laniso", Role::In, uf(fmt::kEllAnisoW, fmt::kEllLogF)),
              field("maxlod", Role::In, uf(fmt::kEllMaxLodW, 0))};
  add_out_fields(&b);
  b.sets = {"golden", "stiff", "random"};
  b.inputs = [](const std::string& set, uint64_t count, uint64_t seed) {
    if (set == "golden") return golden_inputs();
    if (set == "stiff") return stiff_inputs();
    return random_inputs(count, seed);
  };
  b.model = [](const Row& r) { return out_row(fx::analytic(in_of(r))); };
  b.ref = ref_of;
  b.error = [](const Row& in, const Row& out, const Row& ref) {
    const bool hz = horizon(in_of(in));
    if (hz || (out[9] & fx::kHorizon)) return horizon_error(hz, out);  // must agree
    ErrPoint e;
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
    return lod_error(out, ref);
  };
  b.latency_cycles = fmt::kEllLatency;
  b.ii_cycles = 1;
  b.err_metric = "max_lod_err";
  return b;
}

namespace {
// Recurrence variant (tu_ellipse_rec): in = nux, nvx, nuy, nvy, q, qg = q + G, qh = q + H, laniso,
// maxlod (no det3: det J is formed inside).
struct RecIn {
  fx::In in;
  int64_t qg = 0, qh = 0;
};
Row rec_row(const fx::In& in, int64_t qg, int64_t qh) {
  return {field_bits(in.nux, fmt::kEllNumW), field_bits(in.nvx, fmt::kEllNumW), field_bits(in.nuy, fmt::kEllNumW),
          field_bits(in.nvy, fmt::kEllNumW), field_bits(in.q, fmt::kPerspQW),   field_bits(qg, fmt::kEllRecQW),
          field_bits(qh, fmt::kEllRecQW),    in.laniso,                   in.max_lod};
}
RecIn rec_of(const Row& r) {
  RecIn x;
  x.in.nux = vec::sext(r[0], fmt::kEllNumW);
  x.in.nvx = vec::sext(r[1], fmt::kEllNumW);
  x.in.nuy = vec::sext(r[2], fmt::kEllNumW);
  x.in.nvy = vec::sext(r[3], fmt::kEllNumW);
  x.in.q = vec::sext(r[4], fmt::kPerspQW);
  x.qg = vec::sext(r[5], fmt::kEllRecQW);
  x.qh = vec::sext(r[6], fmt::kEllRecQW);
  x.in.laniso = static_cast<uint32_t>(r[7]);
  x.in.max_lod = static_cast<uint32_t>(r[8]);
  return x;
}
// A local map with its G, H (q + G, q + H codes as the span walk forms them).
Row rec_from_local(const fx::Local& l, uint32_t laniso = kAniso16, uint32_t max_lod = 12) {
  const fx::In in = fx::in_from_map(fx::local_map(l), laniso, max_lod);
  return rec_row(in, in.q + fx::q_code(l.g), in.q + fx::q_code(l.h));
}
bool rec_horizon(const RecIn& x) {
  const int64_t g = int64_t(1) << (fmt::kPerspF - fmt::kPerspGuardLog2);
  return x.in.q < g || x.qg < g || x.qh < g;
}

// The analytic block's stiff set with G = H = 0, then the recurrence's own extremes: q + G or
// q + H at / below the guard while q is not, strong G/q and H/q (the 1 + G/q departure), the
// largest q + G.
std::vector<Row> rec_stiff_inputs() {
  std::vector<Row> rows;
  for (const Row& r : stiff_inputs()) {
    const fx::In in = in_of(r);
    rows.push_back(rec_row(in, in.q, in.q));
  }
  const int64_t guard = int64_t(1) << (fmt::kPerspF - fmt::kPerspGuardLog2);
  const fx::In base = fx::in_from_map(fx::local_map(local(0.01, 300, 6, 0.4)));
  for (int64_t dq : {int64_t(-1), int64_t(0), int64_t(1)}) {
    rows.push_back(rec_row(base, guard + dq, base.q));  // q + G at the guard
    rows.push_back(rec_row(base, base.q, guard + dq));  // q + H at the guard
  }
  rows.push_back(rec_row(base, 0, base.q));
  rows.push_back(rec_row(base, base.q, -(int64_t(1) << (fmt::kEllRecQW - 1))));
  for (double gq : {-0.5, -0.25, 0.25, 0.5, 1.0, 4.0})
    for (int axis = 0; axis < 2; ++axis)
      rows.push_back(rec_from_local(local(0.05, 64, 8, 0.3 + axis, axis ? 0 : 0.05 * gq, axis ? 0.05 * gq : 0)));
  {  // largest q and q + G, q + H; largest numerators
    const int64_t qmax = (int64_t(1) << (fmt::kPerspQW - 1)) - 1;
    const int64_t gmax = (int64_t(1) << (fmt::kEllRecQW - 1)) - 1;
    const int64_t big = -(int64_t(1) << (fmt::kEllNumW - 1)), top = (int64_t(1) << (fmt::kEllNumW - 1)) - 1;
    rows.push_back(rec_row(fx::In{big, big, big, big, qmax, 0, 0, kAniso16, 15}, gmax, gmax));
    rows.push_back(rec_row(fx::In{top, big, big, top, guard, 0, 0, kAniso16, 15}, guard, guard));
    rows.push_back(rec_row(fx::In{top, big, big, top, qmax, 0, 0, 16383, 15}, guard, gmax));
    rows.push_back(rec_row(fx::In{1, 0, 0, 1, guard, 0, 0, kAniso16, 15}, guard, guard));
  }
  return rows;
}
std::vector<Row> rec_random_inputs(uint64_t count, uint64_t seed) { return random_rows(count, seed, rec_from_local); }
std::vector<Row> rec_golden_inputs() { return golden_of(rec_stiff_inputs(), rec_random_inputs(12, 99)); }
// The analytic float Jacobian of the same codes, J = n / q^2 (what both variants approximate):
// the error then holds the forward difference's departure log2(1 + G/q) as well as the widths'.
Row rec_ref_of(const Row& r) {
  const RecIn x = rec_of(r);
  if (rec_horizon(x)) return {vec::f64_bits(NAN), vec::f64_bits(NAN), vec::f64_bits(NAN)};
  Row row = row_of(x.in);  // (dm, dexp unused by the analytic reference)
  return ref_of(row);
}
}  // namespace

Block make_ellipse_rec() {
  Block b;
  b.name = "ellipse_rec";
  b.description =
      "pixel footprint, recurrence variant (seed 001: forward differences over q (q+G), q (q+H)), "
      "then the analytic unit on J; II = 1";
  using vec::Role;
  const std::string qf = sf(fmt::kEllRecQW, fmt::kPerspF);
  b.fields = {field("nux", Role::In, num_format()), field("nvx", Role::In, num_format()),
              field("nuy", Role::In, num_format()), field("nvy", Role::In, num_format()),
              field("q", Role::In, sf(fmt::kPerspQW, fmt::kPerspF)),
              field("qg", Role::In, qf),
              field("qh", Role::In, qf),
              field("laniso", Role::In, uf(fmt::kEllAnisoW, fmt::kEllLogF)),
              field("maxlod", Role::In, uf(fmt::kEllMaxLodW, 0))};
  add_out_fields(&b);
  b.sets = {"golden", "stiff", "random"};
  b.inputs = [](const std::string& set, uint64_t count, uint64_t seed) {
    if (set == "golden") return rec_golden_inputs();
    if (set == "stiff") return rec_stiff_inputs();
    return rec_random_inputs(count, seed);
  };
  b.model = [](const Row& r) {
    const RecIn x = rec_of(r);
    return out_row(fx::recurrence(x.in, x.qg, x.qh));
  };
  b.ref = rec_ref_of;
  b.error = [](const Row& in, const Row& out, const Row& ref) {
    const RecIn x = rec_of(in);
    const bool hz = rec_horizon(x);
    if (hz || (out[9] & fx::kHorizon)) return horizon_error(hz, out);  // must agree
    // Rows whose Jacobian leaves s(EllNumW).EllNumF (the format-extreme rows) saturate: bit-exact
    // only, not measured.
    const fx::In j = fx::rec_front(x.in, x.qg, x.qh);
    const int64_t lim = (int64_t(1) << (fmt::kEllNumW - 1)) - 1;
    for (int64_t c : {j.nux, j.nvx, j.nuy, j.nvy})
      if (c >= lim || c <= -lim) {
        ErrPoint e;
        e.valid = false;
        return e;
      }
    return lod_error(out, ref);
  };
  b.latency_cycles = fmt::kEllRecLatency;
  b.ii_cycles = 1;
  b.err_metric = "max_lod_err";
  return b;
}

}  // namespace tu::blocks
