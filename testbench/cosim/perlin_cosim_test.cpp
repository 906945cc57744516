// Perlin noise unit: both RTL schemes (pipelined tu_perlin{3,2}d, octave-serial
// tu_perlin{3,2}d_serial) on the golden, stiff and 100,000 random vectors of blocks perlin3d and
// perlin2d with 30% random stalls: bit-exact, one output per input in order, declared latency and
// II measured on Verilator. The 1,000,000-vector runs: docs/blocks/noise-appendix.md §4.
#include <gtest/gtest.h>

#include "cosim_checks.hpp"
#include "texunit/formats.hpp"

namespace {
using namespace tu;

class PerlinRtl : public ::testing::TestWithParam<std::tuple<std::string, bool>> {};

TEST_P(PerlinRtl, BitExactWithStallsAndDeclaredTiming) {
  const auto& [block, serial] = GetParam();
  const auto& b = blocks::find(block);
  for (const std::string set : {"golden", "stiff", "random"}) {
    const auto vf = blocks::generate(b, set, 100000, 2026);
    cosim::Options opt;
    opt.run.stall_prob = 0.3;
    opt.run.seed = 99;
    opt.rtl = serial ? block + "_serial" : "";
    const auto rep = cosim::run(vf, opt);
    SCOPED_TRACE(set);
    cosim::checks::expect_stream_clean(rep);
    EXPECT_TRUE(rep.ok()) << rep.json();
    EXPECT_EQ(rep.latency_cycles, static_cast<uint64_t>(serial ? fmt::kNoiseSerialLatency : b.latency_cycles));
    EXPECT_DOUBLE_EQ(rep.ii_cycles, serial ? fmt::kNoiseSerialIi : b.ii_cycles);
    std::printf("%s%s %s: %s\n", block.c_str(), serial ? " (octave-serial)" : "", set.c_str(), rep.json().c_str());
  }
}

TEST_P(PerlinRtl, DetectsACorruptedExpectedValue) {
  const auto& [block, serial] = GetParam();
  auto vf = blocks::generate(blocks::find(block), "random", 2000, 5);
  vf.rows[1234][static_cast<size_t>(vf.indices(vec::Role::Out)[0])] ^= 1;
  cosim::Options opt;
  opt.rtl = serial ? block + "_serial" : "";
  const auto rep = cosim::run(vf, opt);
  EXPECT_EQ(rep.mismatches, 1u);
  EXPECT_FALSE(rep.ok());
}

INSTANTIATE_TEST_SUITE_P(Schemes, PerlinRtl,
                         ::testing::Combine(::testing::Values("perlin3d", "perlin2d"), ::testing::Bool()),
                         [](const auto& info) {
                           return std::get<0>(info.param) + (std::get<1>(info.param) ? "_serial" : "_pipelined");
                         });
}  // namespace
