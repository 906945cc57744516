// Vector sets for the object-space per-sample datapath (rtl/objspace/tu_objspace_sample.sv,
// docs/blocks/objspace.md). One vector = one sample:
//   in : one tile's projective map A..I in B1's formats (s54.40 / s44.40) and the grid indices i, j
//   out: the top-left covering pixel x, y (s24.0), the four splat weights w00, w10, w01, w11
//        (u17.16, sum 2^16) and the guard flag (guarded: x = y = 0, weights 0)
//   ref: px, py as the exact rational (A i + B j + C) / (G i + H j + I) of the quantised map
//        (i128 -> long double), +inf when the guard applies.
// Error: the position the weights encode, x + w10 + w11 (y + w01 + w11), against the reference,
// in pixels (the same measure as ObjSpace.PerSampleDatapathErrorBound).
// Sets: golden = a few samples of a fronto-parallel quad and a grazing floor (64 x 48); stiff =
// the stiff planes' tile corners and edges (objspace::stiff_quad_vertices, 64 x 48, up to 16 tiles
// each), the guard crossed one LSB at a time, q <= 0, the largest indices and |p|; random =
// samples of random planes seen by a 256 x 192 camera (objspace::random_quad_vertices), 90 %
// inside the polygon, 10 % anywhere on the tile's grid (the datapath does not know the polygon).
#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "objspace_block.hpp"

namespace tu::blocks {

namespace {
using persp::Unit;
using P = Unit::P;
using Q = Unit::Q;
constexpr int kPW = fmt::kPerspPW, kQW = fmt::kPerspQW, kN = fmt::kPerspXyW;
constexpr int kIW = fmt::kPerspUvW - fmt::kPerspUvF;  // integer pixel bits of x, y
constexpr int64_t kGuard = int64_t(1) << (fmt::kPerspF - fmt::kPerspGuardLog2);
constexpr double kDomain = 4096;  // pixels: positions beyond are checked bit-exactly, not in the error

Unit::Coefs coefs(const Row& in) {
  return {P::from_bits(in[0]), P::from_bits(in[1]), P::from_bits(in[2]), P::from_bits(in[3]), P::from_bits(in[4]),
          P::from_bits(in[5]), Q::from_bits(in[6]), Q::from_bits(in[7]), Q::from_bits(in[8])};
}
// The exact accumulator k (0 p_u, 1 p_v, 2 q) of a row, independent of the model.
i128 exact(const Row& in, int k) {
  const int w = k == 2 ? kQW : kPW;
  return vec::sext(in[3 * k], w) * static_cast<i128>(in[9]) + vec::sext(in[3 * k + 1], w) * static_cast<i128>(in[10]) +
         vec::sext(in[3 * k + 2], w);
}
bool fits(const Row& in) {
  for (int k = 0; k < 3; ++k) {
    const int w = k == 2 ? kQW : kPW;
    const i128 v = exact(in, k);
    if (v < -(i128(1) << (w - 1)) || v >= (i128(1) << (w - 1))) return false;
  }
  return true;
}

// The quantised tiles of a quad scene (set-up only: no sample cap).
struct QTile {
  const objspace::Tile* tile;
  Unit::Coefs k;
};
struct Plane {
  std::vector<objspace::TriangleSetup> tris;
  std::vector<QTile> tiles;
  // `max_samples`: objspace::setup's cap (a grid over 4x that throws std::runtime_error).
  explicit Plane(const scene::Scene& s, uint64_t max_samples = uint64_t(1) << 44)
      : tris(objspace::setup(s, {1, max_samples})) {
    for (const auto& t : tris)
      for (const auto& tile : t.tiles) tiles.push_back({&tile, Unit::quantise(tile.screen, "objspace tile")});
  }
};

void push(std::vector<Row>& rows, const Unit::Coefs& k, int i, int j) {
  Row r = objspace_sample_in(k, i, j);
  if (fits(r)) rows.push_back(std::move(r));  // the set-up keeps every grid point in format
}

std::vector<Row> golden_inputs() {
  std::vector<Row> rows;
  for (const std::string& v : {std::string("[[-2, -1.5, -2], [2, -1.5, -2], [2, 1.5, -2], [-2, 1.5, -2]]"),
                              objspace::stiff_quad_vertices()[0]}) {
    const Plane p(objspace::quad_scene(v));
    for (const auto& t : p.tiles) {
      int n = 0;
      for (int j = 0; j < t.tile->nj && n < 12; j += 7)
        for (int i = 0; i < t.tile->ni && n < 12; i += 5)
          if (t.tile->inside(i, j)) push(rows, t.k, i, j), ++n;
    }
  }
  return rows;
}

std::vector<Row> stiff_inputs() {
  std::vector<Row> rows;
  for (const auto& v : objspace::stiff_quad_vertices()) {
    // 64 x 48 pixels: the same planes with 16 x fewer tiles than at 256 x 192 (the 150-unit floor
    // 0.002 below the eye still has thousands); up to 16 tiles per plane, evenly spread.
    const Plane p(objspace::quad_scene(v));
    const size_t step = std::max<size_t>(1, p.tiles.size() / 16);
    for (size_t k = 0; k < p.tiles.size(); k += step) {
      const auto& t = p.tiles[k];
      const int ni = t.tile->ni, nj = t.tile->nj;
      for (int j : {0, nj / 2, nj - 1})
        for (int s = 0; s <= 64; ++s) push(rows, t.k, static_cast<int>(int64_t(ni - 1) * s / 64), j);
      for (int i : {0, ni / 2, ni - 1})
        for (int s = 0; s <= 64; ++s) push(rows, t.k, i, static_cast<int>(int64_t(nj - 1) * s / 64));
    }
  }
  // Synthetic maps: q walks across the guard one LSB per column, both ways; q <= 0; the largest
  // indices with the largest |p| (saturating positions); q = its format's maximum.
  const P zero = P::from_raw(0), one = P::from_double(1.0), big = P::from_raw(P::kMaxRaw >> kN),
          nbig = P::from_raw(P::kMinRaw >> kN);
  const Q qz = Q::from_raw(0);
  const Unit::Coefs down{one, zero, one, zero, one, one, Q::from_raw(-1), qz, Q::from_raw(kGuard + 4)};
  const Unit::Coefs up{one, zero, nbig, zero, one, big, Q::from_raw(1), Q::from_raw(0), Q::from_raw(kGuard - 4)};
  for (int i = 0; i < 9; ++i) push(rows, down, i, 3), push(rows, up, i, 4095);
  const Unit::Coefs neg{one, one, one, one, one, one, Q::from_raw(-(int64_t(1) << 28)), Q::from_raw(-(int64_t(1) << 28)),
                        Q::from_raw(int64_t(1) << 38)};
  for (int s = 0; s < 16; ++s) push(rows, neg, s * 273, s * 199);
  const Unit::Coefs edge{big, zero, big, nbig, zero, nbig, Q::from_raw(0), Q::from_raw(0), Q::from_raw(kGuard)};
  for (int s : {0, 1, 2047, 4095}) push(rows, edge, s, 4095 - s);
  const Unit::Coefs qmax{one, one, one, one, one, one, qz, qz, Q::from_raw(Q::kMaxRaw)};
  push(rows, qmax, 4095, 4095);
  push(rows, qmax, 0, 0);
  return rows;
}

std::vector<Row> random_inputs(uint64_t count, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<Row> rows;
  rows.reserve(count);
  constexpr size_t kPlanes = 60;
  std::vector<Plane> planes;
  // Planes whose grid exceeds 2^28 points (16 tiles; a plane nearly through the eye) are drawn
  // again: 60 of them stay in memory at once.
  while (planes.size() < kPlanes) {
    try {
      planes.emplace_back(objspace::quad_scene(objspace::random_quad_vertices(rng), 256, 192), uint64_t(1) << 26);
    } catch (const std::runtime_error&) {
    }
  }
  while (rows.size() < count) {
    const auto& p = planes[rng() % planes.size()];
    if (p.tiles.empty()) continue;
    const auto& t = p.tiles[rng() % p.tiles.size()];
    const int i = static_cast<int>(rng() % static_cast<uint64_t>(t.tile->ni));
    const int j = static_cast<int>(rng() % static_cast<uint64_t>(t.tile->nj));
    if (rng() % 10 != 0 && !t.tile->inside(i, j)) continue;
    push(rows, t.k, i, j);
  }
  return rows;
}
}  // namespace

Row objspace_sample_in(const Unit::Coefs& c, int i, int j) {
  return {c.a.bits(), c.b.bits(), c.c.bits(), c.d.bits(), c.e.bits(), c.f.bits(),
          c.g.bits(), c.h.bits(), c.i.bits(), static_cast<uint64_t>(i), static_cast<uint64_t>(j)};
}
Row objspace_sample_out(const objspace::Splat& s) {
  const uint64_t mask = (uint64_t(1) << kIW) - 1;
  return Row{static_cast<uint64_t>(s.x) & mask, static_cast<uint64_t>(s.y) & mask, s.w[0], s.w[1], s.w[2], s.w[3],
             s.guard ? 1u : 0u};
}
objspace::Splat objspace_sample_splat(const Row& out) {
  objspace::Splat s;
  s.x = vec::sext(out[0], kIW), s.y = vec::sext(out[1], kIW);
  for (int k = 0; k < 4; ++k) s.w[k] = static_cast<uint32_t>(out[2 + static_cast<size_t>(k)]);
  s.guard = out[6] != 0;
  return s;
}

Block make_objspace_sample() {
  Block b;
  b.name = "objspace_sample";
  b.description =
      "object-space per-sample datapath: (i, j) -> projective map (B1 back end) -> floor + 4 bilinear splat weights, "
      "II = 1";
  auto fmt_s = [](int w, int f) { return "s" + std::to_string(w) + "." + std::to_string(f); };
  const std::string pf = fmt_s(kPW, fmt::kPerspF), qf = fmt_s(kQW, fmt::kPerspF), nf = "u" + std::to_string(kN) + ".0",
                    wf = "u" + std::to_string(fmt::kObjSplatWW) + "." + std::to_string(fmt::kObjSplatWF);
  for (const char* n : {"a", "b", "c", "d", "e", "f"}) b.fields.push_back(field(n, vec::Role::In, pf));
  for (const char* n : {"g", "h", "i"}) b.fields.push_back(field(n, vec::Role::In, qf));
  b.fields.push_back(field("gi", vec::Role::In, nf));
  b.fields.push_back(field("gj", vec::Role::In, nf));
  b.fields.push_back(field("x", vec::Role::Out, fmt_s(kIW, 0)));
  b.fields.push_back(field("y", vec::Role::Out, fmt_s(kIW, 0)));
  for (const char* n : {"w00", "w10", "w01", "w11"}) b.fields.push_back(field(n, vec::Role::Out, wf));
  b.fields.push_back(field("guard", vec::Role::Out, "u1.0"));
  b.fields.push_back(field("pxref", vec::Role::Ref, "f64"));
  b.fields.push_back(field("pyref", vec::Role::Ref, "f64"));
  b.sets = {"golden", "stiff", "random"};
  b.inputs = standard_sets(golden_inputs, stiff_inputs, random_inputs);
  b.model = [](const Row& in) {
    return objspace_sample_out(objspace::splat_fx(coefs(in), static_cast<int>(in[9]), static_cast<int>(in[10])));
  };
  b.ref = [](const Row& in) {
    const i128 q = exact(in, 2);
    if (q < kGuard) return Row{vec::f64_bits(INFINITY), vec::f64_bits(INFINITY)};
    const long double lq = static_cast<long double>(q);
    return Row{vec::f64_bits(static_cast<double>(static_cast<long double>(exact(in, 0)) / lq)),
               vec::f64_bits(static_cast<double>(static_cast<long double>(exact(in, 1)) / lq))};
  };
  b.error = [](const Row& in, const Row& out, const Row& ref) {
    ErrPoint e;
    const double pr[2] = {vec::bits_f64(ref[0]), vec::bits_f64(ref[1])};
    if (std::isinf(pr[0])) {  // must be flagged, position and weights zero
      const bool ok = out[6] == 1 && out[0] == 0 && out[1] == 0 && out[2] + out[3] + out[4] + out[5] == 0;
      e.valid = !ok;
      e.abs = e.ulp = ok ? 0 : INFINITY;
      return e;
    }
    if (out[6] != 0 || !fits(in)) {
      e.abs = e.ulp = INFINITY;
      return e;
    }
    if (std::fabs(pr[0]) > kDomain || std::fabs(pr[1]) > kDomain) {
      e.valid = false;
      return e;
    }
    const double one = std::ldexp(1.0, -fmt::kObjSplatWF);
    const double px = static_cast<double>(vec::sext(out[0], kIW)) + static_cast<double>(out[3] + out[5]) * one;
    const double py = static_cast<double>(vec::sext(out[1], kIW)) + static_cast<double>(out[4] + out[5]) * one;
    e.abs = std::max(std::fabs(px - pr[0]), std::fabs(py - pr[1]));
    e.ulp = std::ldexp(e.abs, fmt::kPerspUvF);
    return e;
  };
  b.latency_cycles = fmt::kPerspLatency + 1;  // the map stage, B1's back end, the weights (objspace::sample_scheme)
  b.ii_cycles = 1;
  b.err_metric = "max_pixel_err";
  return b;
}

}  // namespace tu::blocks
