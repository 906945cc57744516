// Co-simulation of a block's RTL against its C model on a vector file.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "block.hpp"
#include "generated/tu_glue.hpp"  // (build tree) drive_B / sample_B: ports by field name
#include "texture/texture.hpp"
#include "harness.hpp"
#include "vector_file.hpp"

namespace tu::cosim {

// One Verilated RTL block: run a stream of input rows, and time a stall-free stream.
struct RtlBlock {
  std::string name;
  std::string block;  // the registry block whose vectors it runs (make_rtl: its name; ewa_k4: ewa)
  std::function<RunResult(const std::vector<Row>&, const RunOptions&)> run;
  std::function<std::pair<uint64_t, double>(const std::vector<Row>&)> timing;
};

const RtlBlock& find_rtl(const std::string& name);  // throws std::invalid_argument
// The multi-texel EWA engine ("ewa_k4") reading texture t instead of the block's (wrap modes,
// non-square levels: the bank ports' broadcast and border routing; ewa_rtl.cpp).
RtlBlock rtl_ewa_k4_with(const tex::Texture& t);

// An RtlBlock for the Verilated model V from its `drive` and `sample` functions (and optionally
// the block's C++ surroundings, e.g. its texel RAM: Harness's Env).
template <class V, class Drive, class Sample>
RtlBlock make_rtl(const std::string& name, Drive drive, Sample sample, typename Harness<V>::MakeEnv make_env = {}) {
  RtlBlock b;
  b.name = name;
  b.block = name;
  b.run = [=](const std::vector<Row>& in, const RunOptions& o) {
    return Harness<V>(drive, sample, make_env).run(in, o);
  };
  b.timing = [=](const std::vector<Row>& in) {
    return Harness<V>(drive, sample, make_env).measure_timing(in);
  };
  return b;
}

struct Report {
  std::string block;
  uint64_t vectors = 0;
  uint64_t outputs = 0;
  uint64_t mismatches = 0;        // RTL output != expected output in the file
  uint64_t model_mismatches = 0;  // live C model != expected output in the file (stale file)
  uint64_t extra_outputs = 0;
  bool hung = false;
  bool in_order = true;
  double max_abs_err = 0, max_ulp_err = 0, rms_err = 0;  // RTL output vs float reference
  uint64_t err_points = 0;  // outputs in the statistics (not flagged)
  double err_sum_sq = 0;    // their sum of squared errors: what `texunit merge` needs for rms
  uint64_t flagged = 0;
  uint64_t latency_cycles = 0;
  double ii_cycles = 0;
  uint64_t sim_cycles = 0;
  double stall_prob = 0;
  double wall_s = 0;
  std::string first_mismatch;  // human-readable description of the first mismatch
  std::string err_metric;      // block's extra key for max_abs_err (empty: none)
  std::string shard;           // "K/N" for a `--shard` run (texunit merge combines them); empty: whole
  // A shard's identity, written with "shard": `texunit merge` refuses shards of different runs, a
  // gap or an overlap. The vector file's set and seed, the shard's first row in the set, the RTL
  // variant; when the run cut the file itself (`cosim --shard`), the file's rows and content hash.
  std::string set, rtl, file_hash;  // file_hash: 16 hex digits; empty: the file was itself a shard
  uint64_t seed = 0, first_vector = 0, file_vectors = 0;
  bool ok() const {
    return mismatches == 0 && model_mismatches == 0 && extra_outputs == 0 && !hung &&
           outputs == vectors;
  }
  std::string json() const;
};

struct Options {
  RunOptions run;
  size_t timing_vectors = 256;  // stall-free prefix used for latency and II
  std::string rtl;  // RTL variant on the file's vectors (e.g. perlin3d_serial); empty: the block's own
  uint64_t first_vector = 0;  // index of the file's first row in the whole set (a shard's offset)
};

// Throws std::invalid_argument when the file's block or fields do not match the block.
Report run(const vec::VectorFile& vf, const Options& opt);

}  // namespace tu::cosim
