// Vector sets for the Perlin noise unit (docs/blocks/noise.md): blocks perlin3d (inputs x, y, z)
// and perlin2d (x, y), codes s32.16; output fbm u17.16 (K = NoiseOctaves octaves, normalised to
// [0,1] by the analytic bound); ref = fbm_ref at the decoded point. Error unit: the fbm value
// (1 ULP = 2^-16).
#include <cmath>
#include <random>

#include "block.hpp"
#include "noise/noise_fbm.hpp"
#include "noise/noise_ref.hpp"

namespace tu::blocks {

namespace {
constexpr int kW = fmt::kNoiseCoordW;
constexpr int64_t kOne = int64_t(1) << fmt::kNoiseTF;
const uint64_t kMask = (uint64_t(1) << kW) - 1;

uint64_t code(int64_t c) { return static_cast<uint64_t>(c) & kMask; }
int64_t code_of(double v) { return static_cast<int64_t>(std::llround(v * static_cast<double>(kOne))); }

Row point(int dims, int64_t x, int64_t y, int64_t z) {
  return dims == 3 ? Row{code(x), code(y), code(z)} : Row{code(x), code(y)};
}

std::vector<Row> golden_inputs(int dims) {
  std::vector<Row> rows;
  const double pts[][3] = {{3.14, 42, 7},  {0.5, 0.5, 0.5},     {-0.25, 1.75, -3.5}, {10.1, -20.2, 30.3},
                           {0, 0, 0},       {1.5, 2.25, 0.125},  {255.9, 256.1, -0.1}, {-1000.3, 77.7, 5.55},
                           {0.355, 0.481, 0.5}, {12.5, -7.25, 100.75}};
  for (const auto& p : pts) rows.push_back(point(dims, code_of(p[0]), code_of(p[1]), code_of(p[2])));
  return rows;
}

std::vector<Row> stiff_inputs(int dims) {
  std::vector<Row> rows;
  const int64_t cmax = (int64_t(1) << (kW - 1)) - 1, cmin = -(int64_t(1) << (kW - 1));
  // Lattice points (noise 0 at every octave: fbm = 1/2), negative and large ones included.
  for (int64_t k : {int64_t(0), int64_t(1), int64_t(-1), int64_t(255), int64_t(256), int64_t(-256), int64_t(1000),
                    int64_t(-32768), int64_t(32767)})
    rows.push_back(point(dims, k * kOne, (k + 3) * kOne, (k - 7) * kOne));
  // Cell borders: one LSB either side of a lattice line on each axis in turn (continuity).
  for (int axis = 0; axis < dims; ++axis)
    for (int64_t k : {int64_t(0), int64_t(1), int64_t(-1), int64_t(128), int64_t(255), int64_t(256), int64_t(-129)})
      for (int64_t d : {int64_t(-1), int64_t(0), int64_t(1)}) {
        int64_t c[3] = {code_of(0.3) + 5 * kOne, code_of(0.6) - 2 * kOne, code_of(0.45) + 9 * kOne};
        c[axis] = k * kOne + d;
        rows.push_back(point(dims, c[0], c[1], c[2]));
      }
  // Extreme codes and the period wrap (x and x + 256 give the same output).
  for (int64_t c : {cmin, cmax, cmin + 1, cmax - 1, int64_t(-1), int64_t(1)})
    rows.push_back(point(dims, c, cmax - (c & 0xffff), c ^ 0x5a5a5a));
  for (int64_t k : {int64_t(0), int64_t(256), int64_t(-256), int64_t(512), int64_t(-32512)})
    rows.push_back(point(dims, code_of(3.7) + k * kOne, code_of(-1.2) + k * kOne, code_of(8.9) + k * kOne));
  // Near the worst-case local point of the bound (t = (0.3553, 0.4815, 0.5) and a permutation).
  for (int64_t cell = 0; cell < 16; ++cell) {
    rows.push_back(point(dims, code_of(0.355257) + cell * kOne, code_of(0.481492) + 3 * cell * kOne,
                         code_of(0.5) + 7 * cell * kOne));
    rows.push_back(point(dims, code_of(0.5) - cell * kOne, code_of(0.355257) + 5 * cell * kOne,
                         code_of(0.481492) - 11 * cell * kOne));
  }
  // Fraction extremes: t = 2^-16 and 1 - 2^-16 (fade's ends) in every axis at once.
  for (int64_t k : {int64_t(0), int64_t(-1), int64_t(37)}) {
    rows.push_back(point(dims, k * kOne + 1, k * kOne + 1, k * kOne + 1));
    rows.push_back(point(dims, k * kOne - 1, k * kOne - 1, k * kOne - 1));
  }
  return rows;
}

std::vector<Row> random_inputs(int dims, uint64_t count, uint64_t seed) {
  return random_rows(count, seed, [dims](std::mt19937_64& rng) {
    const uint64_t pick = rng() % 10;
    int64_t c[3];
    for (auto& v : c) {
      if (pick < 5) v = static_cast<int64_t>(rng() % (1024 * uint64_t(kOne))) - 512 * kOne;  // [-512, 512)
      else if (pick < 8) v = vec::sext(rng() & kMask, kW);                                  // every code
      else v = (static_cast<int64_t>(rng() % 600) - 300) * kOne + static_cast<int64_t>(rng() % 33) - 16;  // borders
    }
    return point(dims, c[0], c[1], c[2]);
  });
}

Block make_perlin(int dims) {
  Block b;
  b.name = dims == 3 ? "perlin3d" : "perlin2d";
  b.description = std::to_string(dims) + "-D improved-noise fBm, " + std::to_string(fmt::kNoiseOctaves) +
                  " octaves normalised to [0,1] by the analytic bound; pipelined, one core per octave, II = 1";
  const std::string cf = "s" + std::to_string(kW) + "." + std::to_string(fmt::kNoiseTF);
  b.fields = {field("x", vec::Role::In, cf), field("y", vec::Role::In, cf)};
  if (dims == 3) b.fields.push_back(field("z", vec::Role::In, cf));
  b.fields.push_back(field("fbm", vec::Role::Out, "u" + std::to_string(fmt::kNoiseOutW) + "." + std::to_string(fmt::kNoiseTF)));
  b.fields.push_back(field("ref", vec::Role::Ref, "f64"));
  b.sets = {"golden", "stiff", "random"};
  b.inputs = standard_sets([dims] { return golden_inputs(dims); }, [dims] { return stiff_inputs(dims); },
                           [dims](uint64_t n, uint64_t s) { return random_inputs(dims, n, s); });
  auto decode = [dims](const Row& in, int k) { return k < dims ? vec::sext(in[static_cast<size_t>(k)], kW) : 0; };
  b.model = [dims, decode](const Row& in) {
    return Row{noise::fbm_fx(dims, decode(in, 0), decode(in, 1), decode(in, 2))};
  };
  b.ref = [dims, decode](const Row& in) {
    const double v = noise::fbm_ref(dims, fmt::kNoiseOctaves, noise::coord_value(decode(in, 0)),
                                    noise::coord_value(decode(in, 1)), noise::coord_value(decode(in, 2)));
    return Row{vec::f64_bits(v)};
  };
  b.error = [](const Row&, const Row& out, const Row& ref) {
    ErrPoint e;
    e.abs = std::fabs(noise::out_value(static_cast<uint32_t>(out[0])) - vec::bits_f64(ref[0]));
    e.ulp = std::ldexp(e.abs, fmt::kNoiseTF);
    return e;
  };
  b.latency_cycles = fmt::kNoisePipeLatency;
  b.ii_cycles = 1;
  return b;
}
}  // namespace

std::vector<Block> make_perlin_blocks() { return {make_perlin(3), make_perlin(2)}; }

}  // namespace tu::blocks
