// Vector sets for the reciprocal unit. Input q is s24.16 (the unit itself is agnostic to the
// fraction bits; 16 makes the reference value readable). Error unit: the normalised mantissa,
// |R - 2^(p-F)/q| (so 1 ULP = 2^-RecipOutF whatever the exponent).
#include <cmath>
#include <random>

#include "block.hpp"
#include "reciprocal/reciprocal.hpp"

namespace tu::blocks {

namespace {
constexpr int kFrac = 16;
constexpr int kW = fmt::kRecipInW;
const uint64_t kMask = (uint64_t(1) << kW) - 1;

uint64_t code(int64_t q) { return static_cast<uint64_t>(q) & kMask; }

std::vector<Row> stiff_inputs() {
  std::vector<Row> rows;
  const int64_t qmax = (int64_t(1) << (kW - 1)) - 1;
  const int64_t qmin = -(int64_t(1) << (kW - 1));
  for (int64_t q : {int64_t(0), int64_t(-1), int64_t(-2), qmin, qmin + 1, int64_t(1), int64_t(2),
                    int64_t(3), qmax, qmax - 1})
    rows.push_back({code(q)});
  // Every power of two and its neighbours (exponent boundaries of the normaliser).
  for (int p = 0; p < kW - 1; ++p) {
    const int64_t b = int64_t(1) << p;
    for (int64_t d : {int64_t(-1), int64_t(0), int64_t(1)})
      if (b + d > 0 && b + d <= qmax) rows.push_back({code(b + d)});
  }
  // Segment boundaries of the ROM at full precision (msb at bit kW-2): M = 1 + k/2^IdxW +- 1 LSB.
  const int dxw = fmt::kRecipDxW;
  for (int64_t k = 0; k < (int64_t(1) << fmt::kRecipIdxW); ++k) {
    const int64_t base = (int64_t(1) << (kW - 2)) + (k << dxw);
    for (int64_t d : {int64_t(-1), int64_t(0), int64_t(1)})
      if (base + d > 0 && base + d <= qmax) rows.push_back({code(base + d)});
  }
  return rows;
}

std::vector<Row> random_inputs(uint64_t count, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<Row> rows;
  rows.reserve(count);
  std::uniform_int_distribution<int> exp_dist(0, kW - 2);
  std::uniform_real_distribution<double> u01(0, 1);
  for (uint64_t i = 0; i < count; ++i) {
    const double pick = u01(rng);
    if (pick < 0.02) {  // out of range: q <= 0
      rows.push_back({code(-static_cast<int64_t>(rng() % (uint64_t(1) << (kW - 1))))});
    } else if (pick < 0.5) {  // uniform over the codes
      rows.push_back({code(static_cast<int64_t>(1 + rng() % ((uint64_t(1) << (kW - 1)) - 1)))});
    } else {  // log-uniform: every exponent equally often
      const int p = exp_dist(rng);
      const int64_t lo = int64_t(1) << p;
      rows.push_back({code(lo + static_cast<int64_t>(rng() % static_cast<uint64_t>(lo)))});
    }
  }
  return rows;
}

std::vector<Row> golden_inputs() {
  // A small readable set committed under vectors/golden/: powers, thirds, extremes, q <= 0.
  std::vector<Row> rows;
  for (int64_t q : {int64_t(1) << kFrac, int64_t(3) << kFrac, int64_t(1), int64_t(0x7fffff),
                    int64_t(0x555555), int64_t(0x400000), int64_t(0x3fffff), int64_t(12345),
                    int64_t(0), int64_t(-65536), int64_t(98304), int64_t(65537)})
    rows.push_back({code(q)});
  return rows;
}
}  // namespace

Block make_reciprocal() {
  Block b;
  b.name = "reciprocal";
  b.description = "1/q, piecewise-quadratic ROM + Horner, faithful (< 1 ULP), II = 1";
  b.fields = {field("q", vec::Role::In, "s24.16"), field("mant", vec::Role::Out, "u25.24"),
              field("shift", vec::Role::Out, "u5.0"), field("flag", vec::Role::Out, "u1.0"),
              field("ref", vec::Role::Ref, "f64")};
  b.sets = {"golden", "stiff", "random"};
  b.inputs = standard_sets(golden_inputs, stiff_inputs, random_inputs);
  b.model = [](const Row& in) {
    const auto r = recip::eval(static_cast<int32_t>(vec::sext(in[0], kW)));
    return Row{r.mant, r.shift, r.flag ? 1u : 0u};
  };
  b.ref = [](const Row& in) {
    const int64_t q = vec::sext(in[0], kW);
    const double v = q > 0 ? std::ldexp(1.0, kFrac) / static_cast<double>(q) : INFINITY;
    return Row{vec::f64_bits(v)};
  };
  b.error = [](const Row& in, const Row& out, const Row& ref) {
    ErrPoint e;
    const int64_t q = vec::sext(in[0], kW);
    const double r = vec::bits_f64(ref[0]);
    if (q <= 0) {  // must be flagged and saturated
      const bool ok = out[2] == 1 && out[0] == static_cast<uint64_t>(recip::Out::kMaxRaw) &&
                      out[1] == 0 && std::isinf(r);
      e.valid = !ok;  // a correct guard is excluded from the statistics; a wrong one is infinite
      e.abs = e.ulp = ok ? 0 : INFINITY;
      return e;
    }
    // Normalised: compare R with 1/M = r * 2^(p - F).
    const double exact = std::ldexp(r, static_cast<int>(out[1]) - kFrac);
    const double got = std::ldexp(static_cast<double>(out[0]), -fmt::kRecipOutF);
    e.abs = std::fabs(got - exact);
    e.ulp = e.abs / std::ldexp(1.0, -fmt::kRecipOutF);
    return e;
  };
  b.latency_cycles = fmt::kRecipLatency;
  b.ii_cycles = 1;
  return b;
}

}  // namespace tu::blocks
