// Vector sets for the POM march engine (rtl/pom/tu_pom_march.sv, docs/blocks/relief-appendix.md §6).
// Inputs: T = (u, v), dT = (du, dv) (s32.16 uv), N (u6, 1..63). Depth map: pom::map_bricks(64)
// (the engine's ROM). Outputs: T_k (s32.16), k (u6), refinement operands a, den (u16).
// Reference: the same loop in double (the loop is exact, so the error is 0 by construction; the
// check that matters is RTL == C model). Inputs are limited to |T|, |dT| < 2^22 so that T_k
// stays inside 32 bits.
#include <cmath>
#include <random>

#include "block.hpp"
#include "pom_vec_common.hpp"

namespace tu::blocks {

namespace {
using namespace pomvec;

std::vector<Row> golden_inputs() {
  std::vector<Row> rows;
  // texel centres of a brick face, bevel, mortar; head-on (dT = 0); dT one texel; N = 1, 4, 32, 63
  for (int64_t u : {int64_t(0), int64_t(20 << 10) + 512, int64_t(31 << 10) + 100, int64_t(65535)})
    for (std::pair<int64_t, int64_t> d : {std::pair<int64_t, int64_t>{0, 0}, {1024, 0}, {-700, 300},
                                          {5000, -5000}})
      for (uint64_t n : {1u, 4u, 32u, 63u})
        rows.push_back({c32(u), c32(u / 3 + 4096), c32(d.first), c32(d.second), n});
  return rows;
}

std::vector<Row> stiff_inputs() {
  std::vector<Row> rows;
  const int64_t big = (int64_t(1) << 22) - 1;
  for (int64_t u : {-big, int64_t(-1), int64_t(0), int64_t(1023), int64_t(1024), big})
    for (int64_t du : {-big, int64_t(-1), int64_t(0), int64_t(1), int64_t(1024), big})
      for (uint64_t n : {1u, 2u, 63u}) rows.push_back({c32(u), c32(-u), c32(du), c32(du / 2), n});
  return rows;
}

std::vector<Row> random_inputs(uint64_t count, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<Row> rows;
  rows.reserve(count);
  for (uint64_t i = 0; i < count; ++i) {
    const uint64_t r = rng(), s = rng();
    const int sh = static_cast<int>((r >> 40) % 12);  // step magnitude 2^(10..21)
    auto step = [&](uint64_t bits) {
      const int64_t m = static_cast<int64_t>(bits & ((uint64_t(1) << (10 + sh)) - 1));
      return (bits >> 30) & 1 ? -m : m;
    };
    rows.push_back({r & 0xffff, (r >> 16) & 0xffff, c32(step(s)), c32(step(s >> 32)),
                    1 + (r >> 48) % 63});
  }
  return rows;
}

}  // namespace

Block make_pom_march() {
  Block b;
  b.name = "pom_march";
  b.description = "POM march engine: exact rule 255*i < h*N, one layer step per clock, bricks ROM";
  const auto F = field;  // block.hpp
  b.fields = {F("u", vec::Role::In, "s32.16"),     F("v", vec::Role::In, "s32.16"),
              F("du", vec::Role::In, "s32.16"),    F("dv", vec::Role::In, "s32.16"),
              F("n", vec::Role::In, "u6.0"),       F("tu", vec::Role::Out, "s32.16"),
              F("tv", vec::Role::Out, "s32.16"),   F("steps", vec::Role::Out, "u6.0"),
              F("a", vec::Role::Out, "u16.0"),     F("den", vec::Role::Out, "u16.0"),
              F("ref_steps", vec::Role::Ref, "f64")};
  b.ports = {{"tu", "u"}, {"tv", "v"}};  // tu_pom_march's u_o / v_o (u_i / v_i are the start)
  b.sets = {"golden", "stiff", "random"};
  b.inputs = standard_sets(golden_inputs, stiff_inputs, random_inputs);
  b.model = [](const Row& in) {
    const auto c = pom::march_core(depth(), s32(in[0]), s32(in[1]), s32(in[2]), s32(in[3]),
                                   static_cast<uint32_t>(in[4]));
    return Row{c32(c.u), c32(c.v), c.steps, c.a, c.den};
  };
  b.ref = [](const Row& in) {
    const double n = static_cast<double>(in[4]);
    const double u = s32(in[0]) / 65536.0, v = s32(in[1]) / 65536.0;
    const double du = s32(in[2]) / 65536.0, dv = s32(in[3]) / 65536.0;
    int i = 0;
    while (i / n < pom::tex_nearest_f(depth(), u - i * du, v - i * dv) / 255.0) ++i;
    return Row{vec::f64_bits(static_cast<double>(i))};
  };
  b.error = [](const Row&, const Row& out, const Row& ref) {
    ErrPoint e;
    e.abs = std::fabs(static_cast<double>(out[2]) - vec::bits_f64(ref[0]));
    e.ulp = e.abs;  // steps
    return e;
  };
  b.latency_cycles = 2;  // k = 0 (output in cycle k + 2); a stream takes k + 1 cycles per pixel
  b.ii_cycles = 1;
  return b;
}

}  // namespace tu::blocks
