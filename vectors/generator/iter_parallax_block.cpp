// Vector sets for the iterative parallax engine (rtl/pom/tu_iter_parallax.sv, seed 002,
// docs/blocks/relief-appendix.md §7). Inputs: T = (u, v) (u16 = [0,1) uv), step direction (su, sv, sh)
// (s32.16, from pom::ipx_dir_seed / ipx_dir_normalised of a view). Depth: pom::map_bricks(64).
// Outputs: fract(T) (u16.16), updates (u5), nonconv (u1). Reference: the same iteration in double
// (no rounding); error = uv distance in 2^-16 units, non-converged pixels excluded (flagged).
#include <cmath>
#include <random>

#include "block.hpp"
#include "pom_vec_common.hpp"

namespace tu::blocks {

namespace {
using namespace pomvec;
Row row(uint64_t u, uint64_t v, const pom::IpxDir& d) {
  return {u & 0xffff, v & 0xffff, c32(d.su), c32(d.sv), static_cast<uint64_t>(d.sh)};
}

std::vector<Row> golden_inputs() {
  std::vector<Row> rows;
  for (double ang : {0.0, 45.0, 60.0, 80.0, 85.0})
    for (int kind = 0; kind < 2; ++kind) {
      const auto vw = view(ang, 30, 0.05);
      const auto d = kind ? pom::ipx_dir_normalised(vw) : pom::ipx_dir_seed(vw);
      for (uint64_t u : {512u, 20992u, 32000u, 65000u}) rows.push_back(row(u, u / 3 + 777, d));
    }
  return rows;
}

std::vector<Row> stiff_inputs() {
  std::vector<Row> rows;
  const int64_t big = (int64_t(1) << 22) - 1;
  for (int64_t su : {-big, int64_t(-1), int64_t(0), int64_t(1), big})
    for (int64_t sh : {int64_t(fmt::kPomVzMin) << 2, int64_t(30000), int64_t(65536)})
      for (uint64_t u : {0u, 1023u, 1024u, 65535u})
        rows.push_back(row(u, 65535 - u, pom::IpxDir{su, -su / 3, sh}));
  return rows;
}

std::vector<Row> random_inputs(uint64_t count, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> ang(0, 88), az(0, 360), sc(0.01, 0.2);
  std::vector<Row> rows;
  rows.reserve(count);
  for (uint64_t i = 0; i < count; ++i) {
    const auto vw = view(ang(rng), az(rng), sc(rng));
    const uint64_t r = rng();
    const auto d = (r >> 40) & 1 ? pom::ipx_dir_normalised(vw) : pom::ipx_dir_seed(vw);
    rows.push_back(row(r, r >> 16, d));
  }
  return rows;
}
}  // namespace

Block make_iter_parallax() {
  Block b;
  b.name = "iter_parallax";
  b.description = "iterative parallax (seed 002): 3 mul + 4 add per iteration, cap, threshold, flag";
  const auto F = field;  // block.hpp
  b.fields = {F("u", vec::Role::In, "u16.16"),      F("v", vec::Role::In, "u16.16"),
              F("su", vec::Role::In, "s32.16"),     F("sv", vec::Role::In, "s32.16"),
              // sh in [0, 2): what ipx_dir_seed / ipx_dir_normalised give (|Vz|, 1). Beyond 2 the
              // depth iteration D += (h - D) sh diverges (|1 - sh| > 1) and d * su overflows
              // 64 bits within the cap: the field is narrowed so that every code it holds is
              // defined (the RTL port stays 32 bits).
              F("sh", vec::Role::In, "u17.16"),     F("tu", vec::Role::Out, "u16.16"),
              F("tv", vec::Role::Out, "u16.16"),    F("iters", vec::Role::Out, "u5.0"),
              F("nonconv", vec::Role::Out, "u1.0"), F("ref_u", vec::Role::Ref, "f64"),
              F("ref_v", vec::Role::Ref, "f64")};
  b.ports = {{"tu", "u"}, {"tv", "v"}};  // tu_iter_parallax's u_o / v_o
  b.sets = {"golden", "stiff", "random"};
  b.inputs = standard_sets(golden_inputs, stiff_inputs, random_inputs);
  b.model = [](const Row& in) {
    const auto o = pom::iter_parallax(depth(), static_cast<int64_t>(in[0]),
                                      static_cast<int64_t>(in[1]),
                                      pom::IpxDir{s32(in[2]), s32(in[3]), static_cast<int64_t>(in[4])});
    return Row{static_cast<uint64_t>(o.u), static_cast<uint64_t>(o.v), o.iters, o.nonconv ? 1u : 0u};
  };
  b.ref = [](const Row& in) {
    double u = in[0] / 65536.0, v = in[1] / 65536.0, D = 0;
    const double su = s32(in[2]) / 65536.0, sv = s32(in[3]) / 65536.0, sh = double(in[4]) / 65536.0;
    for (int i = 0; i <= fmt::kIpxCap; ++i) {
      const double d = pom::tex_nearest_f(depth(), u, v) * 257 / 65536.0 - D;
      if (std::fabs(d) < fmt::kIpxEps / 65536.0 || i == fmt::kIpxCap) break;
      u -= d * su;
      v -= d * sv;
      D += d * sh;
    }
    return Row{vec::f64_bits(u - std::floor(u)), vec::f64_bits(v - std::floor(v))};
  };
  b.error = [](const Row&, const Row& out, const Row& ref) {
    ErrPoint e;
    auto wd = [](double x) { x = std::fabs(x); return std::min(x, 1 - x); };
    e.abs = std::max(wd(out[0] / 65536.0 - vec::bits_f64(ref[0])),
                     wd(out[1] / 65536.0 - vec::bits_f64(ref[1]))) * 65536.0;
    e.ulp = e.abs;  // uv LSB
    e.valid = out[3] == 0;
    return e;
  };
  b.latency_cycles = 3;  // 0 updates; a pixel takes iters + 3 cycles (data dependent)
  b.ii_cycles = 3;
  return b;
}

}  // namespace tu::blocks
