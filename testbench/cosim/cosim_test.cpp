// Co-simulation in the test suite: stiff, golden and 100,000 random vectors per block with 30%
// random stalls; 0 mismatches, one output per input in order, declared latency and II = 1.
// The full 1,000,000-vector run is `scripts/cosim_full.sh` (docs/blocks/<block>.md).
#include <gtest/gtest.h>

#include "cosim.hpp"

namespace {
using namespace tu;

void expect_clean(const cosim::Report& r, const blocks::Block& b) {
  EXPECT_EQ(r.mismatches, 0u) << r.first_mismatch;
  EXPECT_EQ(r.model_mismatches, 0u) << r.first_mismatch;
  EXPECT_EQ(r.outputs, r.vectors);
  EXPECT_EQ(r.extra_outputs, 0u);
  EXPECT_FALSE(r.hung);
  EXPECT_EQ(r.latency_cycles, static_cast<uint64_t>(b.latency_cycles));
  EXPECT_DOUBLE_EQ(r.ii_cycles, b.ii_cycles);
  EXPECT_TRUE(r.ok()) << r.json();
}

class Cosim : public ::testing::TestWithParam<std::string> {};

TEST_P(Cosim, StiffGoldenAndRandomWithStalls) {
  const auto& b = blocks::find(GetParam());
  for (const std::string set : {"golden", "stiff", "random"}) {
    const auto vf = blocks::generate(b, set, 100000, 2026);
    cosim::Options opt;
    opt.run.stall_prob = 0.3;
    opt.run.seed = 99;
    const auto rep = cosim::run(vf, opt);
    SCOPED_TRACE(set);
    expect_clean(rep, b);
    std::printf("%s %s: %s\n", b.name.c_str(), set.c_str(), rep.json().c_str());
    // With 30% stalls on both sides the run must take longer than one cycle per vector.
    if (vf.rows.size() > 1000) EXPECT_GT(rep.sim_cycles, vf.rows.size() * 13 / 10);
  }
}

TEST_P(Cosim, DetectsACorruptedExpectedValue) {
  // The scoreboard must fail when one expected output is wrong (the test can fail).
  const auto& b = blocks::find(GetParam());
  auto vf = blocks::generate(b, "random", 2000, 5);
  const int out0 = vf.indices(vec::Role::Out)[0];
  vf.rows[1234][static_cast<size_t>(out0)] ^= 1;
  cosim::Options opt;
  const auto rep = cosim::run(vf, opt);
  EXPECT_EQ(rep.mismatches, 1u);
  EXPECT_EQ(rep.model_mismatches, 1u);
  EXPECT_FALSE(rep.ok());
}

INSTANTIATE_TEST_SUITE_P(Blocks, Cosim, ::testing::Values("reciprocal", "clip_p1", "clip_horner", "clip_estrin", "clip_seq",
                                           "gauss_weight", "weight_table_1d", "weight_table_2d", "persp", "persp_k4", "persp_setup",
                                           "pom_layers", "ellipse"));
}  // namespace
