// Checks shared by every co-simulation test (fixed-latency suite and data-dependent engines).
#pragma once

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "cosim.hpp"

namespace tu::cosim::checks {

// One output per input, in order, bit-exact against the file and the live C model.
inline void expect_stream_clean(const Report& r) {
  EXPECT_EQ(r.mismatches, 0u) << r.first_mismatch;
  EXPECT_EQ(r.model_mismatches, 0u) << r.first_mismatch;
  EXPECT_EQ(r.outputs, r.vectors);
  EXPECT_EQ(r.extra_outputs, 0u);
  EXPECT_FALSE(r.hung);
}

// The suite's stall pattern: an input bubble and output back-pressure with probability p per
// cycle (seed 99).
inline Options with_stalls(double p) {
  Options opt;
  opt.run.stall_prob = p;
  opt.run.seed = 99;
  return opt;
}

// Golden, stiff and `random` random vectors (seed 2026) with 30% random stalls (seed 99), on the
// block's RTL or the named one (Options::rtl); `check` receives each set's vector file and report
// after the stream checks.
template <class Check>
void for_each_set_with_stalls(const blocks::Block& b, Check check, size_t random = 100000, const std::string& rtl = "") {
  for (const std::string set : {"golden", "stiff", "random"}) {
    const auto vf = blocks::generate(b, set, random, 2026);
    Options opt = with_stalls(0.3);
    opt.rtl = rtl;
    const auto rep = run(vf, opt);
    SCOPED_TRACE(set);
    expect_stream_clean(rep);
    check(vf, rep);
    std::printf("%s %s: %s\n", rtl.empty() ? b.name.c_str() : rtl.c_str(), set.c_str(), rep.json().c_str());
  }
}

// The scoreboard must fail when one expected output is wrong (the test can fail).
inline void expect_corruption_detected(const std::string& block) {
  const auto& b = blocks::find(block);
  auto vf = blocks::generate(b, "random", 2000, 5);
  const int out0 = vf.indices(vec::Role::Out)[0];
  vf.rows[1234][static_cast<size_t>(out0)] ^= 1;
  const auto rep = run(vf, Options{});
  EXPECT_EQ(rep.mismatches, 1u);
  EXPECT_EQ(rep.model_mismatches, 1u);
  EXPECT_FALSE(rep.ok());
}

}  // namespace tu::cosim::checks
