// Vector sets for the BC1 (DXT1) texel decode (tu_bc1_decode, tex::bc1_decode): a 64-bit block
// and a texel's place in it -> RGBA8. Stiff set: every endpoint word c0 (2^16) against three
// partners c1 (c0 itself: the 3-colour mode with equal endpoints; a scrambled word; its bitwise
// complement, so that each c0 meets both c0 > c1 and c0 <= c1 across the set), each with the four
// indices at four texel places (the index pattern 0, 1, 2, 3 repeated, so texel t has index t mod 4).
// Random: random blocks, random texels. Reference: the palette on real values of the exact
// expansions (tex::bc1_decode_ref). Error unit: 8-bit codes, the largest over the four channels.
#include <algorithm>
#include <cmath>
#include <random>

#include "block.hpp"
#include "texture/texel_format.hpp"

namespace tu::blocks {

namespace {
constexpr uint64_t kIdx0123 = 0xe4e4e4e4ull;  // texel t: index t mod 4 (2 bits each, texel 0 lowest)

Row row(uint32_t c0, uint32_t c1, uint64_t idx, int texel) {
  return {uint64_t(c0 & 0xffff) | uint64_t(c1 & 0xffff) << 16 | (idx & 0xffffffffull) << 32, uint64_t(texel)};
}

std::vector<Row> golden_inputs() {
  // Hand-made blocks: pure red / blue endpoints in both modes, black / white, every texel.
  std::vector<Row> rows;
  const std::pair<uint32_t, uint32_t> ends[] = {{0xf800, 0x001f}, {0x001f, 0xf800}, {0xffff, 0x0000},
                                                {0x0000, 0xffff}, {0x7bef, 0x7bef}};
  for (const auto& [c0, c1] : ends)
    for (int t = 0; t < 16; ++t) rows.push_back(row(c0, c1, kIdx0123, t));
  return rows;
}

std::vector<Row> stiff_inputs() {
  std::vector<Row> rows;
  for (uint32_t c0 = 0; c0 < (1u << 16); ++c0)
    for (const uint32_t c1 : {c0, (c0 * 40503u + 12345u) & 0xffffu, ~c0 & 0xffffu})
      for (int t : {0, 5, 10, 15}) rows.push_back(row(c0, c1, kIdx0123, t));  // indices 0, 1, 2, 3
  return rows;
}

std::vector<Row> random_inputs(uint64_t count, uint64_t seed) {
  return random_rows(count, seed, [](std::mt19937_64& rng) {
    const uint64_t b = rng();
    return row(static_cast<uint32_t>(b), static_cast<uint32_t>(b >> 16), b >> 32, int(rng() % 16));
  });
}
}  // namespace

Block make_bc1_decode() {
  Block b;
  b.name = "bc1_decode";
  b.description = "BC1 (DXT1) texel decode: 64-bit block + texel place -> RGBA8 (4-colour and 3-colour + transparent modes)";
  b.fields = {field("block", vec::Role::In, "u64.0"),   field("texel", vec::Role::In, "u4.0"),
              field("rgba", vec::Role::Out, "u32.0"),   field("ref_r", vec::Role::Ref, "f64"),
              field("ref_g", vec::Role::Ref, "f64"),    field("ref_b", vec::Role::Ref, "f64"),
              field("ref_a", vec::Role::Ref, "f64")};
  b.sets = {"golden", "stiff", "random"};
  b.inputs = standard_sets(golden_inputs, stiff_inputs, random_inputs);
  b.model = [](const Row& r) {
    const img::Rgba8 c = tex::bc1_decode(r[0], static_cast<int>(r[1]));
    return Row{uint64_t(c.r) | uint64_t(c.g) << 8 | uint64_t(c.b) << 16 | uint64_t(c.a) << 24};
  };
  b.ref = [](const Row& r) {
    const auto c = tex::bc1_decode_ref(r[0], static_cast<int>(r[1]));
    return Row{vec::f64_bits(c[0]), vec::f64_bits(c[1]), vec::f64_bits(c[2]), vec::f64_bits(c[3])};
  };
  b.error = [](const Row&, const Row& out, const Row& ref) {
    ErrPoint e;
    for (int k = 0; k < 4; ++k)
      e.abs = std::max(e.abs, std::fabs(double((out[0] >> (8 * k)) & 0xff) - vec::bits_f64(ref[static_cast<size_t>(k)])));
    e.ulp = e.abs;
    return e;
  };
  b.latency_cycles = 1;  // tu_bc1_decode_sim's output register (the decode is combinational)
  b.ii_cycles = 1;
  return b;
}

}  // namespace tu::blocks
