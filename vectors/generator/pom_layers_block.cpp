// Vector sets for the adaptive POM layer counter. Inputs: vz (s16.14), complexity code c (u8),
// Nmin, Nmax (u6). Outputs: n (u6), neg (u1). Reference: the seed's float formula at the real
// |vz| (double, F = (1-|vz|)^0.8), floored and clamped like the unit. Error unit: layers.
#include <cmath>
#include <random>

#include "block.hpp"
#include "pom/pom_layers.hpp"

namespace tu::blocks {

namespace {
constexpr int kVzW = fmt::kPomVzW;
const uint64_t kVzMask = (uint64_t(1) << kVzW) - 1;
uint64_t vzc(int64_t v) { return static_cast<uint64_t>(v) & kVzMask; }
const int kCodes[24] = {0,   11,  22,  33,  44,  55,  66,  77,  88,  99,  110, 121,
                        133, 144, 155, 166, 177, 188, 199, 210, 221, 232, 243, 255};

std::vector<Row> golden_inputs() {
  // The note's §1.4.3 table: 14 view angles x the 24 complexity codes, Nmin/Nmax = 4/32.
  std::vector<Row> rows;
  for (int ang : {0, 10, 20, 30, 40, 45, 50, 60, 70, 75, 80, 85, 89, 90}) {
    const int64_t v = std::llround(std::cos(ang * M_PI / 180.0) * (1 << fmt::kPomVzF));
    for (int c : kCodes) rows.push_back({vzc(v), uint64_t(c), 4, 32});
  }
  return rows;
}

std::vector<Row> stiff_inputs() {
  std::vector<Row> rows;
  const int64_t one = int64_t(1) << fmt::kPomVzF;
  std::vector<int64_t> vzs = {0, 1, -1, 2, -2, 3, 4, 5, -4, one, -one, one - 1, one + 1, -one - 1,
                              -(int64_t(1) << (kVzW - 1)), (int64_t(1) << (kVzW - 1)) - 1};
  const int sh = fmt::kPomVzF - fmt::kPomIdxF;
  for (int64_t k : {int64_t(1), int64_t(100), int64_t(1024), int64_t(2047)})  // index rounding edges
    for (int64_t d : {int64_t(-1), int64_t(0)}) {
      vzs.push_back((k << sh) - (int64_t(1) << (sh - 1)) + d);
      vzs.push_back(-((k << sh) - (int64_t(1) << (sh - 1)) + d));
    }
  const std::vector<std::pair<uint64_t, uint64_t>> cfg = {
      {4, 32}, {0, 0}, {1, 1}, {63, 63}, {0, 63}, {63, 0}, {16, 8}, {1, 50}, {8, 16}, {32, 4}};
  for (auto [lo, hi] : cfg)
    for (int64_t v : vzs)
      for (uint64_t c : {uint64_t(0), uint64_t(1), uint64_t(128), uint64_t(254), uint64_t(255)})
        rows.push_back({vzc(v), c, lo, hi});
  return rows;
}

std::vector<Row> random_inputs(uint64_t count, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<Row> rows;
  rows.reserve(count);
  for (uint64_t i = 0; i < count; ++i) {
    const uint64_t r = rng();
    const bool dflt = (r >> 60) < 11;  // ~70% default configuration
    rows.push_back({r & kVzMask, (r >> 16) & 0xff, dflt ? 4 : (r >> 24) & 63,
                    dflt ? 32 : (r >> 30) & 63});
  }
  return rows;
}
}  // namespace

Block make_pom_layers() {
  Block b;
  b.name = "pom_layers";
  b.description = "adaptive POM layer count N = floor(Nmin + field(|Vz|)*(...)), F ROM, II = 1";
  b.fields = {field("vz", vec::Role::In, "s16.14"),  field("c", vec::Role::In, "u8.0"),
              field("nmin", vec::Role::In, "u6.0"),  field("nmax", vec::Role::In, "u6.0"),
              field("n", vec::Role::Out, "u6.0"),    field("neg", vec::Role::Out, "u1.0"),
              field("ref", vec::Role::Ref, "f64")};
  b.sets = {"golden", "stiff", "random"};
  b.inputs = standard_sets(golden_inputs, stiff_inputs, random_inputs);
  b.model = [](const Row& in) {
    const auto r = pom::layers(static_cast<int32_t>(vec::sext(in[0], kVzW)),
                               static_cast<uint32_t>(in[1]), static_cast<uint32_t>(in[2]),
                               static_cast<uint32_t>(in[3]));
    return Row{r.n, r.neg ? 1u : 0u};
  };
  b.ref = [](const Row& in) {
    const double a = std::ldexp(static_cast<double>(vec::sext(in[0], kVzW)), -fmt::kPomVzF);
    return Row{vec::f64_bits(pom::layers_ref(a, static_cast<double>(in[1]) / 255.0,
                                             static_cast<uint32_t>(in[2]),
                                             static_cast<uint32_t>(in[3])))};
  };
  b.error = [](const Row&, const Row& out, const Row& ref) {
    ErrPoint e;
    e.abs = std::fabs(static_cast<double>(out[0]) - vec::bits_f64(ref[0]));
    e.ulp = e.abs;  // one layer = one LSB
    return e;
  };
  b.latency_cycles = fmt::kPomLayersLatency;
  b.ii_cycles = 1;
  return b;
}

}  // namespace tu::blocks
