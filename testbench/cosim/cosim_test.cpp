// Co-simulation in the test suite: stiff, golden and 100,000 random vectors per block with 30%
// random stalls; 0 mismatches, one output per input in order, declared latency and II = 1.
// The full 1,000,000-vector run is `scripts/cosim_full.sh` (docs/blocks/<block>.md).
#include <gtest/gtest.h>

#include "cosim_checks.hpp"

namespace {
using namespace tu;

void expect_clean(const cosim::Report& r, const blocks::Block& b) {
  cosim::checks::expect_stream_clean(r);
  EXPECT_EQ(r.latency_cycles, static_cast<uint64_t>(b.latency_cycles));
  EXPECT_DOUBLE_EQ(r.ii_cycles, b.ii_cycles);
  EXPECT_TRUE(r.ok()) << r.json();
}

class Cosim : public ::testing::TestWithParam<std::string> {};

TEST_P(Cosim, StiffGoldenAndRandomWithStalls) {
  const auto& b = blocks::find(GetParam());
  cosim::checks::for_each_set_with_stalls(b, [&](const vec::VectorFile& vf, const cosim::Report& rep) {
    expect_clean(rep, b);
    // With 30% stalls on both sides the run must take longer than one cycle per vector.
    if (vf.rows.size() > 1000) EXPECT_GT(rep.sim_cycles, vf.rows.size() * 13 / 10);
  });
}

TEST_P(Cosim, DetectsACorruptedExpectedValue) {
  cosim::checks::expect_corruption_detected(GetParam());
}

INSTANTIATE_TEST_SUITE_P(Blocks, Cosim, ::testing::Values("reciprocal", "clip_p1", "clip_horner", "clip_estrin", "clip_seq",
                                           "gauss_weight", "weight_table_1d", "weight_table_2d", "persp", "persp_k4", "persp_setup", "texel_depth",
                                           "pom_layers", "ellipse", "ellipse_rec", "brdf_blinn", "brdf_schlick", "brdf_msh",
                                           "brdf_msh_seq", "brdf_dsh", "brdf_scos2", "brdf_st16", "brdf_qr",
                                           "ewa_border", "objspace_sample", "texel_addr", "texel_decode", "bc1_decode"));
}  // namespace
