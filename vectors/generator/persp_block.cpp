// Vector sets for the perspective divide unit (B1). One vector = one pixel of a span:
//   in : the span's per-scanline seeds p_u0, p_v0, q0 (values at the span start x0), the per-pixel
//        increments A, D, G and the pixel's offset n in the span
//   out: u, v (texels, s32.8) and the guard flag
//   ref: u, v as the exact rational (p_u0 + n A) / (q0 + n G) of the quantised coefficients
//        (long double), +inf when the guard applies.
// Spans are written as consecutive rows n = 0, 1, 2, ...: the C model evaluates each row directly
// (stateless), the RTL accumulates (loads the seeds when n = 0, otherwise adds the increments),
// so co-simulation also checks direct == incremental.
#include <cmath>
#include <random>

#include "block.hpp"
#include "persp_block.hpp"
#include "persp/persp.hpp"
#include "persp/schemes.hpp"
#include "persp/texel_depth.hpp"

namespace tu::blocks {

namespace {
using persp::Unit;
using persp::Uv;
using persp::Xy;
using P = Unit::P;
using Q = Unit::Q;
constexpr int kPW = fmt::kPerspPW, kQW = fmt::kPerspQW, kN = fmt::kPerspXyW;
constexpr int64_t kGuard = int64_t(1) << (fmt::kPerspF - fmt::kPerspGuardLog2);
constexpr double kUvDomain = 4096;  // texels: domain of the proven error bound

void emit_span(std::vector<Row>& rows, P pu, P pv, Q q, P a, P d, Q g, int n) {
  for (int i = 0; i < n; ++i)
    rows.push_back({pu.bits(), pv.bits(), q.bits(), a.bits(), d.bits(), g.bits(),
                    static_cast<uint64_t>(i)});
}

// A span of the quantised map k on row y, pixels x0 .. x0+n-1; false if set-up rejects it.
bool emit_map(std::vector<Row>& rows, const persp::Coef9& k, int y, int x0, int n) {
  try {
    const auto c = Unit::quantise(k, "span");
    const auto s = Unit::setup(c, y, x0, x0 + n - 1, "span");
    emit_span(rows, s.pu, s.pv, s.q, c.a, c.d, c.g, n);
    return true;
  } catch (const persp::SetupError&) {
    return false;
  }
}

persp::Camera floor_camera(int w, int h) {
  persp::Camera cam;
  cam.width = w;
  cam.height = h;
  cam.pos[1] = 1.0;
  cam.look_at[1] = 0.98;  // almost horizontal: the horizon is near the image centre
  return cam;
}
// A large floor quad half (y = 0 plane), 1 texel per 1/64 unit, reaching far away.
persp::Triangle floor_tri() {
  persp::Triangle t;
  t.name = "floor";
  t.v[0] = {{-40, 0, -0.5}, {0, 0}};
  t.v[1] = {{40, 0, -0.5}, {4096, 0}};
  t.v[2] = {{-40, 0, -500}, {0, 4096}};
  return t;
}

std::vector<Row> golden_inputs() {
  std::vector<Row> rows;
  const auto cam = floor_camera(64, 48);
  const auto k = persp::coefficients(cam, floor_tri());
  emit_map(rows, k, 40, 10, 6);  // near the bottom of the image
  emit_map(rows, persp::span_map(7, 0, 4095, 1.0, 0.001, 3.5, 4000, -100, 2048, 0, 0, 0), 7, 0, 5);
  // q crosses zero: the last pixels are flagged.
  emit_map(rows, persp::span_map(0, 0, 5, 0.002, -0.001, 1, 2, 3, 4, 0, 0, 0), 0, 0, 6);
  return rows;
}

std::vector<Row> stiff_inputs() {
  std::vector<Row> rows;
  // Grazing planes / long spans: 4096 pixels, depth ratio 1000, far ends at +-4096 texels.
  emit_map(rows, persp::span_map(4095, 0, 4095, 1.0, 0.001, 0, 4096, 0, -4096, 0, 0.5, -0.5), 4095, 0, 4096);
  emit_map(rows, persp::span_map(0, 0, 4095, 0.001, 1.0, -4096, 17.25, 4096, 0.5, 0, 0, 0), 0, 0, 4096);
  emit_map(rows, persp::span_map(2000, 0, 4095, 0.5, 0.0011, 4095.9, -4095.9, 1, 4095, 0, 0, 0), 2000, 0, 4096);
  // Horizon-near spans of a floor seen by a 4096-wide camera: rows just below the horizon
  // (q tiny, constant along the row), and a rolled camera whose rows cross the horizon.
  {
    const auto cam = floor_camera(4096, 2048);
    const auto k = persp::coefficients(cam, floor_tri());
    for (int y = 0; y < 2048; ++y) {
      double u, v, q;
      persp::eval_ref(k, 2048, y, &u, &v, &q);
      if (q > 0 && q < 0.004) {
        emit_map(rows, k, y, 0, 1024);
        if (rows.size() > 3 * 4096 + 4 * 1024) break;
      }
    }
    auto rolled = cam;
    rolled.up[0] = 0.3;  // roll: each row runs from below to above the horizon (q crosses 0)
    const auto kr = persp::coefficients(rolled, floor_tri());
    emit_map(rows, kr, 1000, 0, 4096);
  }
  // q near the guard: walk q across 2^-10 one LSB per pixel, both directions; and from just above
  // the guard with a tiny slope.
  const P one = P::from_double(1.0), big = P::from_raw(P::kMaxRaw), nbig = P::from_raw(P::kMinRaw);
  emit_span(rows, one, nbig, Q::from_raw(kGuard + 4), P::from_raw(1), P::from_raw(1), Q::from_raw(-1), 9);
  emit_span(rows, big, one, Q::from_raw(kGuard - 4), P::from_raw(-1), P::from_raw(0), Q::from_raw(1), 9);
  emit_span(rows, big, nbig, Q::from_raw(kGuard), P::from_raw(-12345), P::from_raw(999), Q::from_raw(7), 64);
  // Negative q: a span crossing q = 0 exactly, the most negative q, and q <= 0 throughout.
  emit_span(rows, one, one, Q::from_raw(int64_t(5) << 30), P::from_raw(3), P::from_raw(-3),
            Q::from_raw(-(int64_t(1) << 30)), 12);
  emit_span(rows, one, one, Q::from_raw(Q::kMinRaw), P::from_raw(0), P::from_raw(0), Q::from_raw(0), 3);
  emit_map(rows, persp::span_map(10, 100, 611, -0.01, -1.0, 5, 6, 7, 8, 0, 0, 0), 10, 100, 512);
  // Largest q and largest |p|: outputs at the edges of their ranges.
  emit_span(rows, big, nbig, Q::from_raw(Q::kMaxRaw), P::from_raw(0), P::from_raw(0), Q::from_raw(0), 2);
  return rows;
}

std::vector<Row> random_inputs(uint64_t count, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(0, 1);
  std::vector<Row> rows;
  rows.reserve(count + 4096);
  while (rows.size() < count) {
    const int len = U(rng) < 0.1 ? 4096 : std::max(1, static_cast<int>(std::pow(4096.0, U(rng))));
    const int x0 = static_cast<int>(rng() % static_cast<uint64_t>(4097 - len));
    const int x1 = x0 + len - 1;
    const int y = static_cast<int>(rng() % 4096);
    const double kind = U(rng);
    double q0, q1;
    if (kind < 0.8) {  // visible, depth ratio up to 1000
      q0 = std::pow(1000.0, -U(rng));
      q1 = std::pow(1000.0, -U(rng));
    } else if (kind < 0.9) {  // crossing the eye plane
      q0 = U(rng);
      q1 = -U(rng);
    } else {  // hugging the guard
      q0 = std::ldexp(1.0, -fmt::kPerspGuardLog2) * (1 + (U(rng) - 0.5) * 0.01);
      q1 = std::ldexp(1.0, -fmt::kPerspGuardLog2) * (1 + (U(rng) - 0.5) * 0.01);
    }
    const auto k = persp::random_span_map(rng, y, x0, x1, q0, q1);
    emit_map(rows, k, y, x0, len);
  }
  rows.resize(count);  // a prefix of a span is still a valid span
  return rows;
}

// C model of the pixel at span offset n (n may run past 4095 in the last k-lane group).
Row model_at(const Row& in, int64_t n) {
  using N = UFixed<fmt::kPerspXyW + 1, 0>;
  const N nf = N::from_raw(n);
  const P pu = (P::from_bits(in[0]) + P::from_bits(in[3]) * nf).as<P>();
  const P pv = (P::from_bits(in[1]) + P::from_bits(in[4]) * nf).as<P>();
  const Q q = (Q::from_bits(in[2]) + Q::from_bits(in[5]) * nf).as<Q>();
  const persp::Pixel px = Unit::pixel({pu, pv, q});
  return Row{Uv::from_raw(px.u).bits(), Uv::from_raw(px.v).bits(), px.flag ? 1u : 0u};
}

struct Eval {
  long double pu, pv, q;
  bool guarded;
};
Eval eval_row(const Row& in, int64_t offset = 0) {
  const i128 n = static_cast<i128>(in[6]) + offset;
  const i128 pu = vec::sext(in[0], kPW) + n * vec::sext(in[3], kPW);
  const i128 pv = vec::sext(in[1], kPW) + n * vec::sext(in[4], kPW);
  const i128 q = vec::sext(in[2], kQW) + n * vec::sext(in[5], kQW);
  return {static_cast<long double>(pu), static_cast<long double>(pv), static_cast<long double>(q),
          q < kGuard};
}
Row ref_at(const Row& in, int64_t off) {
  const Eval e = eval_row(in, off);
  if (e.guarded) return Row{vec::f64_bits(INFINITY), vec::f64_bits(INFINITY)};
  return Row{vec::f64_bits(static_cast<double>(e.pu / e.q)),
             vec::f64_bits(static_cast<double>(e.pv / e.q))};
}

// Error of one output pixel (u, v, flag) against the reference (uref, vref); `guarded`: the
// pixel must be flagged and saturated (its reference is +inf).
ErrPoint uv_error(const Row& out, const Row& ref, bool guarded) {
  ErrPoint e;
  const double ur = vec::bits_f64(ref[0]), vr = vec::bits_f64(ref[1]);
  const uint64_t sat = Uv::from_raw(Uv::kMaxRaw).bits();
  if (guarded) {  // must be flagged and saturated
    const bool ok = out[2] == 1 && out[0] == sat && out[1] == sat && std::isinf(ur);
    e.valid = !ok;
    e.abs = e.ulp = ok ? 0 : INFINITY;
    return e;
  }
  if (out[2] != 0) {
    e.abs = e.ulp = INFINITY;
    return e;
  }
  // The error bound (docs/blocks/persp.md) is stated for |u|, |v| <= 4096 texels; the stiff
  // set's format-limit pixels (|u| up to 2^23) are checked bit-exactly but left out of the
  // error statistics (counted under "flagged").
  if (std::fabs(ur) > kUvDomain || std::fabs(vr) > kUvDomain) {
    e.valid = false;
    return e;
  }
  const double u = std::ldexp(static_cast<double>(vec::sext(out[0], fmt::kPerspUvW)), -fmt::kPerspUvF);
  const double v = std::ldexp(static_cast<double>(vec::sext(out[1], fmt::kPerspUvW)), -fmt::kPerspUvF);
  e.abs = std::max(std::fabs(u - ur), std::fabs(v - vr));
  e.ulp = std::ldexp(e.abs, fmt::kPerspUvF);
  return e;
}
// Error of one pixel (offset `off` from the row's n) against the exact rational reference.
ErrPoint pixel_error(const Row& in, const Row& out, const Row& ref, int64_t off) {
  return uv_error(out, ref, eval_row(in, off).guarded);
}
}  // namespace

Block make_persp() {
  Block b;
  b.name = "persp";
  b.description =
      "perspective divide: u = p_u/q, v = p_v/q per pixel, incremental accumulators, "
      "reciprocal + 2 multiplies, II = 1";
  auto fmt_s = [](int w, int f) { return "s" + std::to_string(w) + "." + std::to_string(f); };
  const std::string pf = fmt_s(kPW, fmt::kPerspF), qf = fmt_s(kQW, fmt::kPerspF),
                    uvf = fmt_s(fmt::kPerspUvW, fmt::kPerspUvF);
  b.fields = {field("pu0", vec::Role::In, pf),  field("pv0", vec::Role::In, pf),
              field("q0", vec::Role::In, qf),   field("a", vec::Role::In, pf),
              field("d", vec::Role::In, pf),    field("g", vec::Role::In, qf),
              field("n", vec::Role::In, "u" + std::to_string(kN) + ".0"),
              field("u", vec::Role::Out, uvf),  field("v", vec::Role::Out, uvf),
              field("flag", vec::Role::Out, "u1.0"),
              field("uref", vec::Role::Ref, "f64"), field("vref", vec::Role::Ref, "f64")};
  b.sets = {"golden", "stiff", "random"};
  b.inputs = standard_sets(golden_inputs, stiff_inputs, random_inputs);
  b.model = [](const Row& in) { return model_at(in, static_cast<int64_t>(in[6])); };
  b.ref = [](const Row& in) { return ref_at(in, 0); };
  b.error = [](const Row& in, const Row& out, const Row& ref) { return pixel_error(in, out, ref, 0); };
  b.starts_run = [](const Row& in) { return in[6] == 0; };  // n = 0: a span's first pixel
  b.latency_cycles = fmt::kPerspLatency;
  b.ii_cycles = 1;
  b.err_metric = "max_texel_err";
  return b;
}


// ---------------- texel-depth variant (persp/texel_depth.hpp) from B1's seeds ----------------
// One vector = one pixel of a span, as block persp, plus the span's last offset m2: the variant
// needs both ends (T1, T2, q1, q2 from the same quantised seeds and increments as B1). Error: the
// same as B1's, against the same exact rational; a span with a guarded end is flagged throughout.
namespace {
persp::texel_depth::Span td_span(const Row& in) {
  return persp::texel_depth::setup({P::from_bits(in[0]), P::from_bits(in[1]), Q::from_bits(in[2])}, P::from_bits(in[3]),
                            P::from_bits(in[4]), Q::from_bits(in[5]), static_cast<int>(in[7]));
}
}  // namespace

Block make_persp_texel_depth() {
  const Block px = make_persp();
  Block b;
  b.name = "persp_texel_depth";
  b.description = "texel-depth texturing (seed 001 §3): w = z1 s / (z2 - s (z2 - z1)) from the span ends, "
                  "T = T1 + (T2 - T1) w; 1 reciprocal + 3 multiplies per pixel";
  b.fields.assign(px.fields.begin(), px.fields.begin() + 7);
  b.fields.push_back(field("m2", vec::Role::In, "u" + std::to_string(kN) + ".0"));
  b.fields.insert(b.fields.end(), px.fields.begin() + 7, px.fields.end());
  b.sets = px.sets;
  b.inputs = [px](const std::string& set, uint64_t count, uint64_t seed) {
    std::vector<Row> rows = px.inputs(set, count, seed);
    // m2 of a row = the last offset of its span (rows n = 0, 1, ... until the next n = 0).
    for (size_t i = 0; i < rows.size();) {
      size_t j = i + 1;
      while (j < rows.size() && rows[j][6] != 0) ++j;
      for (size_t k = i; k < j; ++k) rows[k].push_back(rows[j - 1][6]);
      i = j;
    }
    return rows;
  };
  b.model = [](const Row& in) {
    const persp::Pixel p = persp::texel_depth::pixel(td_span(in), static_cast<int>(in[6]));
    return Row{Uv::from_raw(p.u).bits(), Uv::from_raw(p.v).bits(), p.flag ? 1u : 0u};
  };
  // A span with a guarded end is flagged throughout (its reference: +inf).
  b.ref = [](const Row& in) { return td_span(in).guard ? Row{vec::f64_bits(INFINITY), vec::f64_bits(INFINITY)} : ref_at(in, 0); };
  b.error = [](const Row& in, const Row& out, const Row& ref) { return uv_error(out, ref, td_span(in).guard); };
  b.starts_run = [](const Row& in) { return in[6] == 0; };
  b.latency_cycles = sched::schedule(persp::texel_depth_scheme()).latency;
  b.ii_cycles = 1;
  b.err_metric = "max_texel_err";
  return b;
}

// ---------------- texel-depth per-pixel datapath (rtl/persp/tu_texel_depth.sv) ----------------
// One vector = one pixel m of a span with the span's record, as the RTL receives it: q1, q2
// (B1's exact q at x0, x1), T1 = (t1u, t1v), T2 = (t2u, t2v) (B1's outputs at the ends), m2.
// The rows are persp_texel_depth's (B1's sets), each turned into its span record by
// texel_depth::setup, so the two blocks hold the same pixels in the same order.
//   ref: the exact perspective interpolation of the end codes, T1 + (T2 - T1) w with
//        w = m q2 / (m2 q1 + m (q2 - q1)) (long double): the datapath's own error (w's and the
//        final rounding); persp_texel_depth's ref, the exact map, adds B1's end roundings.
namespace {
persp::texel_depth::Span td_record(const Row& in) {
  const int64_t t1[2] = {static_cast<int64_t>(vec::sext(in[2], fmt::kPerspUvW)), static_cast<int64_t>(vec::sext(in[3], fmt::kPerspUvW))};
  const int64_t t2[2] = {static_cast<int64_t>(vec::sext(in[4], fmt::kPerspUvW)), static_cast<int64_t>(vec::sext(in[5], fmt::kPerspUvW))};
  return persp::texel_depth::record(static_cast<int64_t>(vec::sext(in[0], kQW)), static_cast<int64_t>(vec::sext(in[1], kQW)),
                                    t1, t2, static_cast<int>(in[6]));
}
}  // namespace

Row texel_depth_record_row(const Row& in) {
  const auto s = td_span(in);
  return {Q::from_raw(s.q1).bits(),        Q::from_raw(s.q2).bits(),        Uv::from_raw(s.t1[0]).bits(),
          Uv::from_raw(s.t1[1]).bits(),    Uv::from_raw(s.t2[0]).bits(),    Uv::from_raw(s.t2[1]).bits(),
          static_cast<uint64_t>(s.m2), in[6]};
}

Block make_texel_depth() {
  const Block td = make_persp_texel_depth();
  Block b;
  b.name = "texel_depth";
  b.description = "texel depth per pixel from the span record (q1, q2, T1, T2, m2): w = m q2 / (m2 q1 + m (q2 - q1)), "
                  "T = T1 + (T2 - T1) w; 1 reciprocal + 3 multiplies per pixel, II = 1";
  auto fmt_s = [](char sg, int w, int f) { return sg + std::to_string(w) + "." + std::to_string(f); };
  const std::string qf = fmt_s('s', kQW, fmt::kPerspF), uvf = fmt_s('s', fmt::kPerspUvW, fmt::kPerspUvF),
                    nf = fmt_s('u', kN, 0);
  b.fields = {field("q1", vec::Role::In, qf),   field("q2", vec::Role::In, qf),   field("t1u", vec::Role::In, uvf),
              field("t1v", vec::Role::In, uvf), field("t2u", vec::Role::In, uvf), field("t2v", vec::Role::In, uvf),
              field("m2", vec::Role::In, nf),   field("m", vec::Role::In, nf)};
  b.fields.insert(b.fields.end(), td.fields.begin() + 8, td.fields.end());  // u, v, flag, uref, vref
  b.sets = td.sets;
  b.inputs = [td](const std::string& set, uint64_t count, uint64_t seed) {
    std::vector<Row> rows;
    for (const Row& r : td.inputs(set, count, seed)) rows.push_back(texel_depth_record_row(r));
    return rows;
  };
  b.model = [](const Row& in) {
    const persp::Pixel p = persp::texel_depth::pixel(td_record(in), static_cast<int>(in[7]));
    return Row{Uv::from_raw(p.u).bits(), Uv::from_raw(p.v).bits(), p.flag ? 1u : 0u};
  };
  b.ref = [](const Row& in) {
    const auto s = td_record(in);
    if (s.guard) return Row{vec::f64_bits(INFINITY), vec::f64_bits(INFINITY)};
    const long double m = static_cast<long double>(in[7]), m2 = s.m2;
    const long double w = s.m2 == 0 ? 0.0L : m * s.q2 / (m2 * s.q1 + m * (s.q2 - s.q1));
    auto t = [&](int c) {
      const long double t1 = std::ldexp(static_cast<long double>(s.t1[c]), -fmt::kPerspUvF);
      const long double t2 = std::ldexp(static_cast<long double>(s.t2[c]), -fmt::kPerspUvF);
      return vec::f64_bits(static_cast<double>(t1 + (t2 - t1) * w));
    };
    return Row{t(0), t(1)};
  };
  b.error = [](const Row& in, const Row& out, const Row& ref) { return uv_error(out, ref, td_record(in).guard); };
  b.starts_run = [](const Row& in) { return in[7] == 0; };  // m = 0: a span's first pixel (loads N, D)
  b.latency_cycles = fmt::kTexelDepthLatency;
  b.ii_cycles = 1;
  b.err_metric = "max_texel_err";
  return b;
}

// ---------------- k-lane unit (rtl/persp/tu_persp_klane.sv), K = 4 ----------------
// One vector = a group of 4 consecutive pixels of a span starting at offset n (a multiple of 4),
// taken from the persp sets; a span's last group may run past its end and is kept while those
// pixels still fit the accumulator formats (the RTL computes all 4 lanes).
namespace {
constexpr int kLanes = 4;
bool group_fits(const Row& in) {
  const i128 n = static_cast<i128>(in[6]) + kLanes - 1;
  auto fits = [](i128 v, int w) { return v >= -(i128(1) << (w - 1)) && v < (i128(1) << (w - 1)); };
  return fits(vec::sext(in[0], kPW) + n * vec::sext(in[3], kPW), kPW) &&
         fits(vec::sext(in[1], kPW) + n * vec::sext(in[4], kPW), kPW) &&
         fits(vec::sext(in[2], kQW) + n * vec::sext(in[5], kQW), kQW);
}
}  // namespace

Block make_persp_k4() {
  const Block px = make_persp();
  Block b;
  b.name = "persp_k4";
  b.description = "perspective divide, 4 lanes: 4 pixels per clock (p_n = p_{n-4} + 4A), II = 1";
  b.fields.assign(px.fields.begin(), px.fields.begin() + 7);
  const std::string uvf = "s" + std::to_string(fmt::kPerspUvW) + "." + std::to_string(fmt::kPerspUvF);
  for (int j = 0; j < kLanes; ++j) {
    const std::string k = std::to_string(j);
    b.fields.push_back(field("u" + k, vec::Role::Out, uvf));
    b.fields.push_back(field("v" + k, vec::Role::Out, uvf));
    b.fields.push_back(field("flag" + k, vec::Role::Out, "u1.0"));
  }
  for (int j = 0; j < kLanes; ++j) {
    b.fields.push_back(field("uref" + std::to_string(j), vec::Role::Ref, "f64"));
    b.fields.push_back(field("vref" + std::to_string(j), vec::Role::Ref, "f64"));
  }
  b.sets = px.sets;
  b.inputs = [px](const std::string& set, uint64_t count, uint64_t seed) {
    std::vector<Row> rows;
    for (const auto& r : px.inputs(set, count * kLanes, seed))
      if (r[6] % kLanes == 0 && group_fits(r)) rows.push_back(r);
    if (set == "random" && rows.size() > count) rows.resize(count);
    return rows;
  };
  b.model = [](const Row& in) {
    Row out;
    for (int j = 0; j < kLanes; ++j)
      for (uint64_t c : model_at(in, static_cast<int64_t>(in[6]) + j)) out.push_back(c);
    return out;
  };
  b.ref = [](const Row& in) {
    Row out;
    for (int j = 0; j < kLanes; ++j)
      for (uint64_t c : ref_at(in, j)) out.push_back(c);
    return out;
  };
  b.error = [](const Row& in, const Row& out, const Row& ref) {
    ErrPoint e;
    e.valid = false;
    for (int j = 0; j < kLanes; ++j) {
      const Row o(out.begin() + 3 * j, out.begin() + 3 * j + 3);
      const Row r(ref.begin() + 2 * j, ref.begin() + 2 * j + 2);
      const ErrPoint p = pixel_error(in, o, r, j);
      if (std::isinf(p.abs)) return p;  // wrong guard / flag: infinite error
      if (!p.valid) continue;
      e.valid = true;
      e.abs = std::max(e.abs, p.abs);
      e.ulp = std::max(e.ulp, p.ulp);
    }
    return e;
  };
  b.starts_run = [](const Row& in) { return in[6] == 0; };  // n = 0: a span's first pixel
  b.latency_cycles = fmt::kPerspLatency;
  b.ii_cycles = 1;
  b.err_metric = "max_texel_err";
  return b;
}

}  // namespace tu::blocks

// ---------------- per-scanline set-up (rtl/persp/tu_persp_setup.sv) ----------------
// One vector = one span: the quantised coefficients A..I, the span ends x0, x1 and the row y.
//   out: p_u, p_v, q at x0 (modulo 2^W when they overflow) and the overflow flag
//        (persp::Model::setup_span: some accumulator at x0 or x1 outside its format)
//   ref: p_u, p_v, q at x0 as the exact value A x0 + B y + C (i128 -> long double -> f64).
namespace tu::blocks {
namespace {
using SetupRow = Row;  // a..i, x0, x1, y

SetupRow setup_row(const Unit::Coefs& c, int x0, int x1, int y) {
  return {c.a.bits(), c.b.bits(), c.c.bits(), c.d.bits(), c.e.bits(), c.f.bits(),
          c.g.bits(), c.h.bits(), c.i.bits(), static_cast<uint64_t>(x0),
          static_cast<uint64_t>(x1),  static_cast<uint64_t>(y)};
}
Unit::Coefs setup_coefs(const Row& in) {
  return {P::from_bits(in[0]), P::from_bits(in[1]), P::from_bits(in[2]),
          P::from_bits(in[3]), P::from_bits(in[4]), P::from_bits(in[5]),
          Q::from_bits(in[6]), Q::from_bits(in[7]), Q::from_bits(in[8])};
}
// Independent of the model: exact i128 evaluation of one accumulator (k = 0 p_u, 1 p_v, 2 q).
i128 setup_exact(const Row& in, int k, uint64_t x) {
  const int w = k == 2 ? kQW : kPW;
  return vec::sext(in[3 * k], w) * static_cast<i128>(x) +
         vec::sext(in[3 * k + 1], w) * static_cast<i128>(in[11]) + vec::sext(in[3 * k + 2], w);
}
bool setup_overflows(const Row& in) {
  for (uint64_t x : {in[9], in[10]})
    for (int k = 0; k < 3; ++k) {
      const int w = k == 2 ? kQW : kPW;
      const i128 v = setup_exact(in, k, x);
      if (v < -(i128(1) << (w - 1)) || v >= (i128(1) << (w - 1))) return true;
    }
  return false;
}

// Spans of a float map on row y: quantised like the software path (skipped when a coefficient
// does not fit: that is the per-triangle quantise step, not this block).
void emit_setup_map(std::vector<Row>& rows, const persp::Coef9& k, int y, int x0, int x1) {
  try {
    rows.push_back(setup_row(Unit::quantise(k, "span"), x0, x1, y));
  } catch (const persp::SetupError&) {
  }
}

std::vector<Row> setup_golden() {
  std::vector<Row> rows;
  const auto k = persp::coefficients(floor_camera(64, 48), floor_tri());
  for (int y : {0, 24, 40, 47}) emit_setup_map(rows, k, y, 10, 15);
  emit_setup_map(rows, persp::span_map(7, 0, 4095, 1.0, 0.001, 3.5, 4000, -100, 2048, 0, 0, 0), 7, 0, 4095);
  emit_setup_map(rows, persp::span_map(0, 0, 5, 0.002, -0.001, 1, 2, 3, 4, 0, 0, 0), 0, 0, 5);
  // Fits at x0, p_u overflows at the far end (the unit test's 'tri#3').
  emit_setup_map(rows, persp::span_map(0, 0, 4095, 1, 1.5, 0, 8000, 0, 0, 0, 0, 0), 0, 0, 4095);
  return rows;
}

std::vector<Row> setup_stiff() {
  std::vector<Row> rows;
  const P pmax = P::from_raw(P::kMaxRaw), pmin = P::from_raw(P::kMinRaw), p0 = P::from_raw(0);
  const Q qmax = Q::from_raw(Q::kMaxRaw), qmin = Q::from_raw(Q::kMinRaw), q0 = Q::from_raw(0);
  const P pv[5] = {pmin, P::from_raw(-1), p0, P::from_raw(1), pmax};
  const Q qv[5] = {qmin, Q::from_raw(-1), q0, Q::from_raw(1), qmax};
  const P pc[3] = {pmin, p0, pmax};
  const Q qc[3] = {qmin, q0, qmax};
  const int xs[2] = {0, (1 << kN) - 1};
  // Format limits x {x0, x1, y} in {0, 4095}: every combination for p_u; p_v and q see the same
  // corners in other combinations (rotated indices).
  int n = 0;
  for (int ia = 0; ia < 5; ++ia)
    for (int ib = 0; ib < 3; ++ib)
      for (int ic = 0; ic < 3; ++ic)
        for (int x0 : xs)
          for (int x1 : xs)
            for (int y : xs) {
              ++n;
              const Unit::Coefs c{pv[ia], pc[ib], pc[ic], pv[(ia + n) % 5], pc[(ib + n) % 3],
                                  pc[(ic + 2 * n) % 3], qv[(ia + 2 * n) % 5], qc[(ib + 2 * n) % 3],
                                  qc[(ic + n) % 3]};
              rows.push_back(setup_row(c, x0, x1, y));
            }
  // Exactly at the format boundary and one LSB past it, both signs, at x0 and at x1, for each
  // accumulator: A x + B y + C = max (fits) / max + 1 (overflow), min / min - 1.
  for (int k = 0; k < 3; ++k)
    for (int at = 0; at < 2; ++at)
      for (int past = 0; past < 2; ++past)
        for (int sign = 0; sign < 2; ++sign) {
          const int x = at == 0 ? 0 : 4095, y = 4095;
          const int w = k == 2 ? kQW : kPW;
          const i128 lim = sign == 0 ? (i128(1) << (w - 1)) - 1 : -(i128(1) << (w - 1));
          const i128 slope = sign == 0 ? 1000003 : -999983;  // per pixel, odd
          const i128 target = lim + (past ? (sign == 0 ? 1 : -1) : 0);
          // at == 0: the boundary value at x0 = 0, the span moving inward; at == 1: at x1 = 4095.
          const i128 bslope = sign == 0 ? 7 : -7;  // keeps C inside its format
          const i128 s = at == 0 ? -slope : slope;
          const i128 c0 = target - bslope * y - (at == 0 ? 0 : slope * x);
          Row r = setup_row({p0, p0, p0, p0, p0, p0, q0, q0, q0}, 0, at == 0 ? 5 : 4095, y);
          const uint64_t mask = (uint64_t(1) << w) - 1;
          r[3 * k] = static_cast<uint64_t>(s) & mask;
          r[3 * k + 1] = static_cast<uint64_t>(bslope) & mask;
          r[3 * k + 2] = static_cast<uint64_t>(c0) & mask;
          rows.push_back(r);
        }
  // Negative coefficients of a real mapping (u, v decreasing, q decreasing), and a map whose
  // span runs right to left (x1 < x0: both ends are still checked).
  emit_setup_map(rows, persp::span_map(3000, 0, 4095, 1.0, 0.002, 4095, -4095, 4000, -4000, -1e-5, -0.25, -0.25), 3000, 0, 4095);
  emit_setup_map(rows, persp::span_map(5, 0, 4095, 0.5, 0.001, 100, -100, -7, 7, 0, 0, 0), 5, 4095, 0);
  return rows;
}

std::vector<Row> setup_random(uint64_t count, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(0, 1);
  std::vector<Row> rows;
  rows.reserve(count);
  auto rnd_x = [&] { return static_cast<int>(rng() % (1u << kN)); };
  // Signed raw code of width w with a log-uniform magnitude (1..w-1 bits).
  auto rnd_code = [&](int w) {
    const int bits = 1 + static_cast<int>(rng() % static_cast<uint64_t>(w - 1));
    const uint64_t m = bits >= 64 ? rng() : rng() & ((uint64_t(1) << bits) - 1);
    const uint64_t mask = (uint64_t(1) << w) - 1;
    return ((rng() & 1) ? (~m + 1) : m) & mask;
  };
  while (rows.size() < count) {
    const double kind = U(rng);
    const int y = rnd_x();
    int x0 = rnd_x(), x1 = rnd_x();
    if (kind < 0.6) {  // realistic spans of random perspective maps (x0 <= x1)
      if (x1 < x0) std::swap(x0, x1);
      const double q0 = std::pow(1000.0, -U(rng)), q1 = U(rng) < 0.1 ? -U(rng) : std::pow(1000.0, -U(rng));
      emit_setup_map(rows, persp::random_span_map(rng, y, x0, x1, q0, q1), y, x0, x1);
    } else if (kind < 0.8) {  // random codes of random magnitude: many overflows
      Row r(12);
      for (int k = 0; k < 9; ++k) r[k] = rnd_code(k >= 6 ? kQW : kPW);
      r[9] = static_cast<uint64_t>(x0);
      r[10] = static_cast<uint64_t>(x1);
      r[11] = static_cast<uint64_t>(y);
      rows.push_back(r);
    } else {  // near a format boundary: C chosen so that one end lands within +-2^10 LSB of it
      Row r(12);
      for (int k = 0; k < 9; ++k) r[k] = rnd_code(k >= 6 ? kQW - 14 : kPW - 14);
      r[9] = static_cast<uint64_t>(x0);
      r[10] = static_cast<uint64_t>(x1);
      r[11] = static_cast<uint64_t>(y);
      const int k = static_cast<int>(rng() % 3), w = k == 2 ? kQW : kPW;
      const i128 lim = (rng() & 1) ? (i128(1) << (w - 1)) - 1 : -(i128(1) << (w - 1));
      const i128 target = lim + static_cast<i128>(rng() % 2049) - 1024;
      const uint64_t x = (rng() & 1) ? r[9] : r[10];
      const i128 c = target - vec::sext(r[3 * k], w) * static_cast<i128>(x) -
                     vec::sext(r[3 * k + 1], w) * static_cast<i128>(y);
      if (c < -(i128(1) << (w - 1)) || c >= (i128(1) << (w - 1))) continue;  // C must fit
      r[3 * k + 2] = static_cast<uint64_t>(c) & ((uint64_t(1) << w) - 1);
      rows.push_back(r);
    }
  }
  return rows;
}
}  // namespace

Block make_persp_setup() {
  Block b;
  b.name = "persp_setup";
  b.description =
      "perspective per-scanline set-up: p_u, p_v, q at x0 from A..I (9 exact products), "
      "overflow flag for either span end, II = 1";
  auto fmt_s = [](int w, int f) { return "s" + std::to_string(w) + "." + std::to_string(f); };
  const std::string pf = fmt_s(kPW, fmt::kPerspF), qf = fmt_s(kQW, fmt::kPerspF),
                    xf = "u" + std::to_string(kN) + ".0";
  for (const char* n : {"a", "b", "c", "d", "e", "f"}) b.fields.push_back(field(n, vec::Role::In, pf));
  for (const char* n : {"g", "h", "i"}) b.fields.push_back(field(n, vec::Role::In, qf));
  for (const char* n : {"x0", "x1", "y"}) b.fields.push_back(field(n, vec::Role::In, xf));
  b.fields.push_back(field("pu", vec::Role::Out, pf));
  b.fields.push_back(field("pv", vec::Role::Out, pf));
  b.fields.push_back(field("q", vec::Role::Out, qf));
  b.fields.push_back(field("ovf", vec::Role::Out, "u1.0"));
  for (const char* n : {"puref", "pvref", "qref"}) b.fields.push_back(field(n, vec::Role::Ref, "f64"));
  b.sets = {"golden", "stiff", "random"};
  b.inputs = standard_sets(setup_golden, setup_stiff, setup_random);
  b.model = [](const Row& in) {
    const auto s = Unit::setup_span(setup_coefs(in), static_cast<int>(in[11]),
                                    static_cast<int>(in[9]), static_cast<int>(in[10]));
    return Row{s.acc.pu.bits(), s.acc.pv.bits(), s.acc.q.bits(), s.ovf ? 1u : 0u};
  };
  b.ref = [](const Row& in) {
    Row r;
    for (int k = 0; k < 3; ++k)
      r.push_back(vec::f64_bits(static_cast<double>(
          std::ldexp(static_cast<long double>(setup_exact(in, k, in[9])), -fmt::kPerspF))));
    return r;
  };
  b.error = [](const Row& in, const Row& out, const Row& ref) {
    ErrPoint e;
    const bool ovf = setup_overflows(in);
    if (ovf || out[3] != 0) {  // flagged rows: only the flag is checked against the reference
      e.valid = !(ovf && out[3] == 1);
      e.abs = e.ulp = (ovf && out[3] == 1) ? 0 : INFINITY;
      return e;
    }
    for (int k = 0; k < 3; ++k) {
      const int w = k == 2 ? kQW : kPW;
      const double o = std::ldexp(static_cast<double>(vec::sext(out[k], w)), -fmt::kPerspF);
      e.abs = std::max(e.abs, std::fabs(o - vec::bits_f64(ref[k])));
    }
    e.ulp = std::ldexp(e.abs, fmt::kPerspF);
    return e;
  };
  b.latency_cycles = persp::kSetupLatency;
  b.ii_cycles = 1;
  return b;
}

}  // namespace tu::blocks
