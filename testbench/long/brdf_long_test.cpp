// Long test (label `long`, outside CI): every c code above each n's cut-off for every n in
// 1..1000 and every bit-accurate BRDF model; the error bound of each header, monotone in c, and
// F = 0 below the cut-off. Run: ctest --test-dir build/default -L long (docs/blocks/brdf.md).
#include <gtest/gtest.h>

#include <cstdio>

#include "brdf/brdf_error.hpp"

namespace {
using namespace tu::brdf;

class BrdfLong : public ::testing::TestWithParam<Model> {};

TEST_P(BrdfLong, EveryNEveryCCodeAboveTheCutOff) {
  const Model m = GetParam();
  SweepStats all;
  for (int n = 1; n <= tu::fmt::kBrdfNMax; ++n) {
    const auto s = sweep(m, n, cut_code(m, n), n % 50 == 1);
    EXPECT_TRUE(s.monotone) << "n=" << n;
    merge(all, s);
  }
  EXPECT_EQ(all.nonzero_below_cut, 0u);
  EXPECT_LT(all.max_own_lsb, 0.501);  // the bound in each model's header
  std::printf("%s: %llu codes, max err vs own formula %.6f LSB (code %llu), vs Blinn %.2f LSB\n",
              name(m).c_str(), static_cast<unsigned long long>(all.codes), all.max_own_lsb,
              static_cast<unsigned long long>(all.worst_own_code), all.max_blinn_lsb);
}

INSTANTIATE_TEST_SUITE_P(Models, BrdfLong, ::testing::ValuesIn(kModels),
                         [](const auto& info) { return name(info.param); });
}  // namespace
