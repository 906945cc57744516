// Block descriptions shared by the vector generator, the co-simulation and the report:
// field layout, input sets, the bit-accurate model, the float reference and the error metric.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "texture/texture.hpp"
#include "texunit/shard.hpp"
#include "vector_file.hpp"

namespace tu::blocks {

using Row = std::vector<uint64_t>;

// Low w bits (1..64) of a two's-complement value: a signed field's code in a vector row.
inline uint64_t field_bits(int64_t v, int w) {
  return static_cast<uint64_t>(v) & (w == 64 ? ~0ull : ((1ull << w) - 1));
}

// Error of one output against the float reference, in the block's own units.
struct ErrPoint {
  double abs = 0;  // absolute error in the block's documented unit
  double ulp = 0;  // the same in units of the output's last place
  bool valid = true;  // false for flagged/saturated outputs (excluded from the statistics)
};

// A vector-file field from its name, role and format ("s24.16", "u1.0", "f64").
inline vec::Field field(const std::string& name, vec::Role role, const std::string& format) {
  return vec::Field{name, role, vec::FieldFormat::parse(format)};
}

struct Block {
  std::string name;
  std::string description;
  std::vector<vec::Field> fields;  // in, out and ref fields, in file order
  // RTL port base names where they differ from the field's name (port = base + "_i" / "_o"): a
  // file cannot hold an in- and an out-field of one name, a port list can (the generated glue).
  std::map<std::string, std::string> ports;
  std::vector<std::string> sets;   // e.g. golden, stiff, random
  // Input rows (one raw code per in-field) for a set; count/seed used by random sets.
  std::function<std::vector<Row>(const std::string& set, uint64_t count, uint64_t seed)> inputs;
  std::function<Row(const Row& in)> model;  // out-field codes
  std::function<Row(const Row& in)> ref;    // ref-field bits (f64)
  std::function<ErrPoint(const Row& in, const Row& out, const Row& ref)> error;
  // Rows where an independent run of the RTL may start, i.e. a `--shard` boundary (e.g. the first
  // pixel of a span for the incremental divide, whose later pixels continue the span's state);
  // empty: every row is independent.
  std::function<bool(const Row& in)> starts_run;
  int latency_cycles = 0;  // declared by the structural scheme
  int ii_cycles = 1;
  // Optional extra JSON key for max_abs_err in the block's own unit (e.g. "max_texel_err").
  std::string err_metric;
};

const std::vector<Block>& all();
const Block& find(const std::string& name);  // throws std::invalid_argument listing known names

// A full vector file: inputs, C-model outputs and the reference, for a set of a block. Model and
// reference rows on `threads` threads (<= 0: every core); the same file for any count. A shard
// holds the rows [first, last) of the whole set (Shard::range): the inputs stream is drawn in
// full (cheap) and the model and reference run on the shard's rows only.
vec::VectorFile generate(const Block& b, const std::string& set, uint64_t count, uint64_t seed,
                         int threads = 0, Shard shard = {});

// Rows [first, last) of shard s of `rows` (vector-file rows whose inputs are at `in_idx`, or input
// rows when in_idx is empty): Shard::range with each boundary moved forward to the next row where
// b.starts_run holds, so the shards still tile the rows in order.
std::pair<uint64_t, uint64_t> shard_rows(const Block& b, const std::vector<Row>& rows,
                                         const std::vector<int>& in_idx, Shard s);

// Block ewa: the 2 x 2 blocks of an input row's box (ewa::fx::Out::lane_blocks: the K = 4 walk's
// clocks, ewa::PixelCost::blocks) with the block's texture (ewa_block.cpp).
uint64_t ewa_lane_blocks(const Row& in);
// Block ewa: the C model's out codes of an input row with texture t instead of the block's.
Row ewa_model_with(const Row& in, const tex::Texture& t);
// Split/join a file row by role.
Row pick(const Row& row, const std::vector<int>& idx);

// `count` rows from one generator call each (gen(rng) -> Row), seeded with `seed`.
template <class Gen>
std::vector<Row> random_rows(uint64_t count, uint64_t seed, Gen gen) {
  std::mt19937_64 rng(seed);
  std::vector<Row> rows;
  rows.reserve(count);
  while (rows.size() < count) rows.push_back(gen(rng));
  return rows;
}

// Block::inputs for the three standard sets: golden() and stiff() are fixed, random(count, seed).
template <class Golden, class Stiff, class Random>
auto standard_sets(Golden golden, Stiff stiff, Random random) {
  return [=](const std::string& set, uint64_t count, uint64_t seed) -> std::vector<Row> {
    if (set == "golden") return golden();
    if (set == "stiff") return stiff();
    return random(count, seed);
  };
}

}  // namespace tu::blocks
