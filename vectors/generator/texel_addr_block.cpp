// Vector sets for the texel addressing every filter engine uses (tu_texel_addr, tex::texel_addr):
// wrap modes per axis (repeat, mirror, clamp, border, mirror once), level bases, the border word.
// Reference: the OpenGL wrap rules in double (tex::wrap_index_ref) and the layout written out in
// double (levels from base, border word at base - 1), modulo 2^TexAddrW. Error unit: words; the
// addressing is exact, so every vector must have error 0.
#include <algorithm>
#include <climits>
#include <cmath>
#include <random>

#include "block.hpp"
#include "texture/texture.hpp"

namespace tu::blocks {

namespace {
constexpr int kAW = fmt::kTexAddrW;
constexpr int kWW = schema::kWrapW;
constexpr int kModes = 5;
const uint64_t kAMask = (uint64_t(1) << kAW) - 1;

struct In {
  uint64_t base;
  int lw, lh, wu, wv, level;
  int64_t x, y;
};
Row row(const In& i) {
  return {i.base & kAMask, uint64_t(i.lw), uint64_t(i.lh), uint64_t(i.wu | i.wv << kWW), uint64_t(i.level),
          static_cast<uint64_t>(i.x) & 0xffffffffu, static_cast<uint64_t>(i.y) & 0xffffffffu};
}
In unrow(const Row& r) {
  return {r[0], int(r[1]), int(r[2]), int(r[3] & ((1u << kWW) - 1)), int(r[3] >> kWW), int(r[4]),
          vec::sext(r[5], 32), vec::sext(r[6], 32)};
}

// Coordinates around the edges of an axis of 2^l texels, and the int32 extremes.
std::vector<int64_t> edge_coords(int l) {
  const int64_t n = int64_t(1) << l;
  std::vector<int64_t> c = {INT32_MIN, INT32_MIN + 1, -2 * n - 1, -2 * n, -n - 1, -n, -1, 0, n - 1, n,
                            2 * n - 1, 2 * n, 3 * n, INT32_MAX};
  std::sort(c.begin(), c.end());
  c.erase(std::unique(c.begin(), c.end()), c.end());
  return c;
}

std::vector<Row> golden_inputs() {
  // An 8 x 4 texture at word 100, each mode along u then v, around both edges, levels 0 and 1.
  std::vector<Row> rows;
  for (int m = 0; m < kModes; ++m)
    for (int level : {0, 1})
      for (int64_t x : {-9, -1, 0, 7, 8, 16}) rows.push_back(row({100, 3, 2, m, 0, level, x, 1}));
  for (int m = 0; m < kModes; ++m)
    for (int64_t y : {-5, -1, 4}) rows.push_back(row({100, 3, 2, 0, m, 0, 2, y}));
  return rows;
}

std::vector<Row> stiff_inputs() {
  // Every mode pair, square / long / one-texel textures, the base at 0 (border word wraps to
  // 2^TexAddrW - 1) and at the top of the address space, the finest and the top level.
  std::vector<Row> rows;
  const std::pair<int, int> sizes[] = {{0, 0}, {12, 12}, {3, 0}, {0, 5}, {12, 1}};
  for (int wu = 0; wu < kModes; ++wu)
    for (int wv = 0; wv < kModes; ++wv)
      for (const auto& [lw, lh] : sizes)
        for (int level : {0, std::max(lw, lh)}) {
          const uint64_t base = (wu + wv) % 2 ? kAMask : 0;
          const int wl = std::max(0, lw - level), hl = std::max(0, lh - level);
          const int64_t nh = int64_t(1) << hl;
          for (int64_t x : edge_coords(wl))
            for (int64_t y : {int64_t(INT32_MIN), int64_t(-1), nh - 1, nh, int64_t(INT32_MAX)})
              rows.push_back(row({base, lw, lh, wu, wv, level, x, y}));
        }
  return rows;
}

std::vector<Row> random_inputs(uint64_t count, uint64_t seed) {
  return random_rows(count, seed, [](std::mt19937_64& rng) {
    In i;
    i.base = rng() & kAMask;
    i.lw = int(rng() % 13);
    i.lh = int(rng() % 13);
    i.level = int(rng() % (std::max(i.lw, i.lh) + 1));
    i.wu = int(rng() % kModes);
    i.wv = int(rng() % kModes);
    auto coord = [&](int l) -> int64_t {  // mostly within a few repeats, some far, some anywhere
      const uint64_t pick = rng() % 10;
      const int64_t span = pick < 7 ? (int64_t(8) << l) : pick < 9 ? (int64_t(1) << 20) : (int64_t(1) << 32);
      return static_cast<int32_t>(static_cast<int64_t>(rng() % static_cast<uint64_t>(span)) - span / 2);
    };
    i.x = coord(std::max(0, i.lw - i.level));
    i.y = coord(std::max(0, i.lh - i.level));
    return row(i);
  });
}

// The address in double from the GL rules: levels one after another from base, border at base - 1.
double ref_addr(const In& i) {
  const int wl = std::max(0, i.lw - i.level), hl = std::max(0, i.lh - i.level);
  const int64_t xi = tex::wrap_index_ref(double(i.x), 1 << wl, tex::Wrap(i.wu));
  const int64_t yi = tex::wrap_index_ref(double(i.y), 1 << hl, tex::Wrap(i.wv));
  const double m = std::ldexp(1.0, kAW);
  double a = double(i.base) - 1;
  if (xi >= 0 && yi >= 0) {
    a = double(i.base) + double(yi) * std::ldexp(1.0, wl) + double(xi);
    for (int k = 0; k < i.level; ++k) a += std::ldexp(1.0, std::max(0, i.lw - k)) * std::ldexp(1.0, std::max(0, i.lh - k));
  }
  return a - m * std::floor(a / m);
}
}  // namespace

Block make_texel_addr() {
  Block b;
  b.name = "texel_addr";
  b.description = "texel address: per-axis wrap (repeat, mirror, clamp, border, mirror once), level base, border word";
  b.fields = {field("base", vec::Role::In, "u26.0"), field("lw", vec::Role::In, "u4.0"),
              field("lh", vec::Role::In, "u4.0"), field("wrap", vec::Role::In, "u6.0"),
              field("level", vec::Role::In, "u4.0"), field("x", vec::Role::In, "s32.0"),
              field("y", vec::Role::In, "s32.0"), field("addr", vec::Role::Out, "u26.0"),
              field("ref", vec::Role::Ref, "f64")};
  b.sets = {"golden", "stiff", "random"};
  b.inputs = standard_sets(golden_inputs, stiff_inputs, random_inputs);
  b.model = [](const Row& r) {
    const In i = unrow(r);
    return Row{tex::texel_addr(i.base, i.lw, i.lh, {tex::Wrap(i.wu), tex::Wrap(i.wv), {}}, i.level, i.x, i.y)};
  };
  b.ref = [](const Row& r) { return Row{vec::f64_bits(ref_addr(unrow(r)))}; };
  b.error = [](const Row&, const Row& out, const Row& ref) {
    ErrPoint e;
    e.abs = e.ulp = std::fabs(double(out[0]) - vec::bits_f64(ref[0]));
    return e;
  };
  b.latency_cycles = 1;  // tu_texel_addr_sim's output register (the addressing is combinational)
  b.ii_cycles = 1;
  return b;
}

}  // namespace tu::blocks
