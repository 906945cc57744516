// Bit-accurate BRDF models (cmodel/blocks/brdf): guards, the error bound of each header, monotone in
// c, every c code for a spread of n (the full n = 1..1000 sweep is the long test
// brdf_long_test.cpp), MAD against Blinn and the epicentre error on the thesis grid.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "brdf/brdf_common.hpp"
#include "brdf/brdf_error.hpp"
#include "brdf/brdf_ref.hpp"

namespace {
using namespace tu;
using namespace tu::brdf;

constexpr uint64_t kOne = uint64_t(1) << fmt::kBrdfCF;
uint64_t neg(int64_t v) { return static_cast<uint64_t>(v) & ((uint64_t(1) << fmt::kBrdfCW) - 1); }

// The bound stated in each model's header comment, in output LSB against its own float formula.
double bound_lsb(Model) { return 0.501; }

TEST(BrdfFx, GuardsAtTheEdges) {
  for (Model m : kModels) {
    SCOPED_TRACE(name(m));
    for (int n : {1, 2, 15, 16, 17, 1000}) {
      const uint64_t cut = cut_code(m, n);
      const Result at0 = eval(m, {0, uint64_t(n), cut});
      // c <= 0 (back-facing) is F(0): the same code as c = 0, no flag.
      for (int64_t c : {int64_t(-1), int64_t(-(1 << 20)), -(int64_t(1) << (fmt::kBrdfCW - 1))}) {
        const Result r = eval(m, {neg(c), uint64_t(n), cut});
        EXPECT_EQ(r.f, at0.f);
        EXPECT_FALSE(r.flag);
      }
      // F(0) is 0 except F_ST16 for n < 16, (1 - n/16)^16.
      const double f0 = ref_value(m, 0, n);
      EXPECT_NEAR(value(at0.f), f0, 0.5 / 256 + 1e-12) << n;
      // c = 1: u = 0 exactly; 1 for every model except F_MSH 1.024 (code 262), F_dsh 0.99577 (255).
      const Result r1 = eval(m, {kOne, uint64_t(n), cut});
      const uint64_t want1 = m == Model::Msh ? 262 : m == Model::Dsh ? 255 : 256;
      EXPECT_EQ(r1.f, want1) << n;
      EXPECT_FALSE(r1.flag);
      // c > 1 clamps to 1 and flags.
      const Result big = eval(m, {kOne + 1, uint64_t(n), cut});
      EXPECT_EQ(big.f, want1);
      EXPECT_TRUE(big.flag);
      const Result big2 = eval(m, {(uint64_t(1) << (fmt::kBrdfCW - 1)) - 1, uint64_t(n), cut});
      EXPECT_EQ(big2.f, want1);
      // Beyond the cut-off the output is 0.
      if (cut > 0 && cut <= kOne) {
        EXPECT_EQ(eval(m, {cut - 1, uint64_t(n), cut}).f, 0u) << n;
      }
    }
    // n = 0 behaves as n = 1, n > 1000 as n = 1000; both flag.
    const uint64_t c = 1019000;
    const Result n0 = eval(m, {c, 0, cut_code(m, 1)});
    EXPECT_EQ(n0.f, eval(m, {c, 1, cut_code(m, 1)}).f);
    EXPECT_TRUE(n0.flag);
    const Result n1023 = eval(m, {kOne - 100, 1023, cut_code(m, 1000)});
    EXPECT_EQ(n1023.f, eval(m, {kOne - 100, 1000, cut_code(m, 1000)}).f);
    EXPECT_TRUE(n1023.flag);
  }
}

TEST(BrdfFx, EveryCCodeForASpreadOfN) {
  // All 2^20 + 1 codes (below the cut-off: F = 0) for n at the corners of every model.
  for (Model m : kModels) {
    SweepStats all;
    for (int n : {1, 16, 1000}) {
      const auto s = sweep(m, n, cut_code(m, n), true);
      EXPECT_TRUE(s.monotone) << name(m) << " n=" << n;
      merge(all, s);
    }
    EXPECT_EQ(all.nonzero_below_cut, 0u) << name(m);
    EXPECT_LT(all.max_own_lsb, bound_lsb(m)) << name(m) << " worst code " << all.worst_own_code;
    std::printf("%-8s max err vs own formula %.4f LSB, vs Blinn %.2f LSB (%llu codes)\n",
                name(m).c_str(), all.max_own_lsb, all.max_blinn_lsb,
                static_cast<unsigned long long>(all.codes));
  }
}

TEST(BrdfFx, StiffPointsOnTheBound) {
  // Cut-off neighbours, c one code below 1, the epicentre and the zero of each model, every n step.
  for (Model m : kModels)
    for (int n = 1; n <= 1000; n += 37) {
      const uint64_t cut = cut_code(m, n);
      for (uint64_t k : {cut, cut + 1, kOne - 1, kOne - 2, input_of(m, std::pow(0.3, 1.0 / n), n).c}) {
        if (k > kOne) continue;
        const double c = std::ldexp(static_cast<double>(k), -fmt::kBrdfCF);
        const double err = std::fabs(value(eval(m, {k, uint64_t(n), cut}).f) - ref_value(m, c, n)) * 256;
        EXPECT_LT(err, bound_lsb(m)) << name(m) << " n=" << n << " code " << k;
      }
    }
}

TEST(BrdfFx, MadAndEpicentreOnTheThesisGrid) {
  // On the thesis grid the fixed-point models keep the float MADs of §7: rounding to 2^-8 moves a
  // MAD by less than half an output LSB.
  const struct {
    Model m;
    double mad;
  } want[] = {{Model::Schlick, 0.02879}, {Model::Msh, 0.00655}, {Model::Dsh, 0.00251},
              {Model::Scos2, 0.00487}, {Model::St16, 0.00114}, {Model::Qr, 0.00819}};
  for (const auto& w : want) {
    const double mad = vs_blinn_fx(w.m).mad;
    const double mad_float = ref::mad_vs_blinn([&](double c, int n) { return ref_value(w.m, c, n); });
    EXPECT_NEAR(mad, mad_float, 0.5 / 256) << name(w.m);
    EXPECT_NEAR(mad_float, w.mad, 5e-6) << name(w.m);
  }
  EXPECT_LT(vs_blinn_fx(Model::Blinn).mad, 0.5 / 256);
  // Epicentre (F_B = 0.3): float 15.66 % (F_MSH), 51.19 % (Schlick), 21.32 % (F_dsh, n >= 9).
  EXPECT_NEAR(epicentre_rel_fx(Model::Msh, 2), 0.1566, 0.01);
  EXPECT_NEAR(epicentre_rel_fx(Model::Schlick, 2), 0.5119, 0.01);
  EXPECT_NEAR(epicentre_rel_fx(Model::Dsh, 9), 0.2132, 0.01);
  EXPECT_LT(epicentre_rel_fx(Model::Blinn, 2), 0.01);
}

}  // namespace
