// Visibility engine co-simulation (rtl/ewa/tu_afvis.sv, docs/blocks/afvis.md §5): cycles per pixel
// depend on the box and the traces, so the engine is not in the fixed-latency Cosim suite: 0
// mismatches (colour, level, counts, flags, kept, traced, depth reads) with 30 % stalls on the
// golden, stiff and random sets, the scoreboard catches a corrupted value, and the cycle model
// (ewa::StreamModel with PixelCost::afv_walk = afvis::Out::clocks) equals Verilator's count on
// stall-free streams. The long run: scripts/cosim_full.sh afvis.
#include <gtest/gtest.h>

#include <cstdio>

#include "afvis_block.hpp"
#include "cosim_checks.hpp"
#include "ewa/ewa_cycles.hpp"

namespace {
using namespace tu;

cosim::Options with_stalls(double p) {
  cosim::Options opt;
  opt.run.stall_prob = p;
  opt.run.seed = 99;
  return opt;
}

TEST(AfvisCosim, GoldenStiffRandomWithStalls) {
  const auto& b = blocks::find("afvis");
  for (const std::string set : {"golden", "stiff", "random"}) {
    const auto vf = blocks::generate(b, set, 600, 2026);
    const auto rep = cosim::run(vf, with_stalls(0.3));
    SCOPED_TRACE(set);
    cosim::checks::expect_stream_clean(rep);
    std::printf("afvis %s: %s\n", set.c_str(), rep.json().c_str());
  }
}

TEST(AfvisCosim, DetectsACorruptedExpectedValue) { cosim::checks::expect_corruption_detected("afvis"); }

// Per-pixel cycle costs of a vector file's rows (the block's texture: top level 8).
std::vector<ewa::PixelCost> costs_of(const vec::VectorFile& vf) {
  const auto in_idx = vf.indices(vec::Role::In);
  std::vector<ewa::PixelCost> c;
  for (const auto& row : vf.rows) {
    const auto in = blocks::pick(row, in_idx);
    const afvis::Out o = blocks::afvis_block_model(in);
    ewa::fx::In px;
    px.b2.lod = static_cast<uint32_t>(in[7]);
    c.push_back(ewa::pixel_cost(px, o.ewa.level, o.ewa.flags, o.ewa.texels_visited, 8));
    c.back().afv_walk = o.clocks;
  }
  return c;
}

TEST(AfvisCosim, CyclesMatchPrediction) {
  for (const std::string set : {"golden", "stiff", "random"}) {
    const auto vf = blocks::generate(blocks::find("afvis"), set, 300, 7);
    const auto rep = cosim::run(vf, with_stalls(0));
    cosim::checks::expect_stream_clean(rep);
    const uint64_t predicted = ewa::stream_cycles(costs_of(vf));
    std::printf("afvis %s: %zu px, cycles measured %llu predicted %llu (%.2f cycles/px)\n", set.c_str(),
                vf.rows.size(), (unsigned long long)rep.sim_cycles, (unsigned long long)predicted,
                double(rep.sim_cycles) / double(vf.rows.size()));
    EXPECT_EQ(rep.sim_cycles, predicted) << set;
  }
}

}  // namespace
