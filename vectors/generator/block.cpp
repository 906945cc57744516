#include "block.hpp"

#include <algorithm>
#include <stdexcept>

#include "texunit/parallel.hpp"

namespace tu::blocks {

Block make_reciprocal();  // reciprocal_block.cpp
std::vector<Block> make_gauss_blocks();  // gauss_blocks.cpp
Block make_pom_layers();  // pom_layers_block.cpp
Block make_pom_march();   // pom_march_block.cpp
Block make_iter_parallax();  // iter_parallax_block.cpp
std::vector<Block> make_pom_unit_blocks();  // pom_unit_block.cpp
Block make_persp();       // persp_block.cpp
Block make_persp_k4();    // persp_block.cpp
Block make_persp_setup(); // persp_block.cpp
Block make_persp_texel_depth();  // persp_block.cpp (C model from B1's seeds)
Block make_texel_depth();  // persp_block.cpp (RTL tu_texel_depth)
Block make_ellipse();     // ellipse_block.cpp
Block make_ellipse_rec(); // ellipse_block.cpp
Block make_ewa();         // ewa_block.cpp
Block make_ewa_border();  // ewa_border_block.cpp
Block make_feline();      // feline_block.cpp
Block make_afvis();       // afvis_block.cpp
Block make_objspace_sample();  // objspace_block.cpp
Block make_texel_addr();  // texel_addr_block.cpp
Block make_texel_decode();  // texel_decode_block.cpp
Block make_bc1_decode();  // bc1_decode_block.cpp
std::vector<Block> make_brdf_blocks();  // brdf_block.cpp
std::vector<Block> make_perlin_blocks();  // perlin_block.cpp

const std::vector<Block>& all() {
  static const std::vector<Block> blocks = [] {
    std::vector<Block> b;
    b.push_back(make_reciprocal());
    for (auto& g : make_gauss_blocks()) b.push_back(std::move(g));
    b.push_back(make_pom_layers());
    b.push_back(make_pom_march());
    b.push_back(make_iter_parallax());
    for (auto& p : make_pom_unit_blocks()) b.push_back(std::move(p));
    b.push_back(make_persp());
    b.push_back(make_persp_k4());
    b.push_back(make_persp_setup());
    b.push_back(make_persp_texel_depth());
    b.push_back(make_texel_depth());
    b.push_back(make_ellipse());
    b.push_back(make_ellipse_rec());
    b.push_back(make_ewa());
    b.push_back(make_ewa_border());
    b.push_back(make_feline());
    b.push_back(make_afvis());
    b.push_back(make_objspace_sample());
    b.push_back(make_texel_addr());
    b.push_back(make_texel_decode());
    b.push_back(make_bc1_decode());
    for (auto& m : make_brdf_blocks()) b.push_back(std::move(m));
    for (auto& p : make_perlin_blocks()) b.push_back(std::move(p));
    return b;
  }();
  return blocks;
}

const Block& find(const std::string& name) {
  for (const auto& b : all())
    if (b.name == name) return b;
  std::string known;
  for (const auto& b : all()) known += (known.empty() ? "" : ", ") + b.name;
  throw std::invalid_argument("unknown block '" + name + "' (known: " + known + ")");
}

Row pick(const Row& row, const std::vector<int>& idx) {
  Row r;
  r.reserve(idx.size());
  for (int i : idx) r.push_back(row[static_cast<size_t>(i)]);
  return r;
}

std::pair<uint64_t, uint64_t> shard_rows(const Block& b, const std::vector<Row>& rows,
                                         const std::vector<int>& in_idx, Shard s) {
  const auto starts = [&](uint64_t i) {
    return i >= rows.size() || !b.starts_run || b.starts_run(in_idx.empty() ? rows[i] : pick(rows[i], in_idx));
  };
  auto [first, last] = s.range(rows.size());
  while (!starts(first)) ++first;
  while (!starts(last)) ++last;
  return {first, last};
}

vec::VectorFile generate(const Block& b, const std::string& set, uint64_t count, uint64_t seed,
                         int threads, Shard shard) {
  if (std::find(b.sets.begin(), b.sets.end(), set) == b.sets.end())
    throw std::invalid_argument("block '" + b.name + "' has no set '" + set + "'");
  vec::VectorFile v;
  v.block = b.name;
  v.set = set;
  v.seed = seed;
  v.fields = b.fields;
  const auto in_idx = v.indices(vec::Role::In);
  const auto out_idx = v.indices(vec::Role::Out);
  const auto ref_idx = v.indices(vec::Role::Ref);
  // The inputs come from one seeded stream (serial); model and reference are pure functions of
  // a row, so chunks of rows run on every thread, each into its own slots.
  std::vector<Row> ins = b.inputs(set, count, seed);
  if (!shard.whole()) {
    const auto [first, last] = shard_rows(b, ins, {}, shard);
    v.shard = shard.str();
    v.first_vector = first;
    ins = std::vector<Row>(ins.begin() + static_cast<std::ptrdiff_t>(first),
                           ins.begin() + static_cast<std::ptrdiff_t>(last));
  }
  v.rows.resize(ins.size());
  constexpr size_t kChunk = 512;
  const int chunks = static_cast<int>((ins.size() + kChunk - 1) / kChunk);
  par::for_each_index(chunks, threads, [&](int c) {
    const size_t end = std::min(ins.size(), (static_cast<size_t>(c) + 1) * kChunk);
    for (size_t r = static_cast<size_t>(c) * kChunk; r < end; ++r) {
      const Row& in = ins[r];
      Row row(v.fields.size());
      const Row out = b.model(in);
      const Row ref = b.ref(in);
      for (size_t i = 0; i < in_idx.size(); ++i) row[static_cast<size_t>(in_idx[i])] = in[i];
      for (size_t i = 0; i < out_idx.size(); ++i) row[static_cast<size_t>(out_idx[i])] = out[i];
      for (size_t i = 0; i < ref_idx.size(); ++i) row[static_cast<size_t>(ref_idx[i])] = ref[i];
      v.rows[r] = std::move(row);
    }
  });
  return v;
}

}  // namespace tu::blocks
