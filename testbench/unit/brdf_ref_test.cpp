// Float references of the seed-004 BRDF models against the thesis's numbers, as the note
// (shared/spec/notes/seed-004-brdf.md) verified them: Table 2.1, the MADs against Blinn on the
// thesis grid (deg 0..90 x n 1..1000), Fig. 2.14, Fig. 3.8, the normalising-coefficient tables,
// the epicentre errors, the golden values of §7 and the Table 4.2 sphere render.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "brdf/brdf_common.hpp"
#include "brdf/brdf_ref.hpp"

namespace {
using namespace tu::brdf;

TEST(BrdfRef, Table21MshSearchRows) {
  // Table 2.1 (b1 b2 b3 b5, a1 a2 a3 a5) and the note's recomputed MADs (thesis: 2 digits).
  const struct {
    ref::MshTemplate t;
    double mad;
  } rows[] = {{{2, 2, 1, 2, 2, 1.25, 1, 1.25}, 0.00630}, {{3, 2, 1, 3, 2, 1.25, 1, 1.25}, 0.00622},
              {{1, 2, 1, 1, 2, 1.25, 1, 1.25}, 0.00655}, {{2, 2, 1, 3, 2, 1.25, 1, 1.25}, 0.00663},
              {{1, 2, 1, 2, 2, 1.25, 1, 1.25}, 0.00702}};
  for (const auto& r : rows) {
    const double mad = ref::mad_vs_blinn([&](double c, int n) { return ref::msh_template(r.t, c, n); });
    EXPECT_NEAR(mad, r.mad, 5e-6);
  }
  // Row 2 is F_MSH itself.
  EXPECT_NEAR(ref::msh_template(rows[2].t, 0.7, 37), ref::msh(0.7, 37), 1e-15);
}

TEST(BrdfRef, MadAgainstBlinnOnTheThesisGrid) {
  EXPECT_NEAR(ref::mad_vs_blinn(ref::msh), 0.00655, 5e-6);
  EXPECT_NEAR(ref::mad_vs_blinn(ref::schlick), 0.02879, 5e-6);
  EXPECT_NEAR(ref::mad_vs_blinn([](double c, int n) { return ref::st(c, n, 16); }), 0.001143, 5e-7);
  // Fig. 3.8 printed 0.0004738259334582657 (a = 268) and 0.00047382616505358354 (a = 267).
  EXPECT_NEAR(ref::mad_vs_blinn([](double c, int n) { return ref::st(c, n, 268); }),
              0.0004738259334582657, 1e-12);
  EXPECT_NEAR(ref::mad_vs_blinn([](double c, int n) { return ref::st(c, n, 267); }),
              0.00047382616505358354, 1e-12);
  // a = 268 beats its neighbours and a = 16 (the thesis's choice for cost).
  const double m268 = ref::mad_vs_blinn([](double c, int n) { return ref::st(c, n, 268); });
  for (int a : {16, 200, 267, 269, 500})
    EXPECT_LT(m268, ref::mad_vs_blinn([a](double c, int n) { return ref::st(c, n, a); })) << a;
  // §7: F_dsh (averaged) 0.00251, F_SCOS 0.00683, F_SCOS2 0.00487, F_QR 0.00819.
  EXPECT_NEAR(ref::mad_vs_blinn(ref::dsh), 0.0025051413, 1e-9);
  EXPECT_NEAR(ref::mad_vs_blinn(ref::scos), 0.00683, 5e-6);
  EXPECT_NEAR(ref::mad_vs_blinn(ref::scos2), 0.00487, 5e-6);
  EXPECT_NEAR(ref::mad_vs_blinn(ref::qr), 0.00819, 5e-6);
}

TEST(BrdfRef, Fig214DshModelsOnlyAsTheClampedAverage) {
  // Printed order: powers b1..b6, coefficients a1..a5 (a4 = a3), constants c1..c3; the note's MADs.
  const struct {
    ref::DshTemplate t;
    double mad;
  } rows[] = {
      {{16, 2, 1, 16, 1, 2, 1.25, 1.25, 1.25, 0, 0, 0.1}, 0.0074218930},
      {{4, 1, 1, 8, 2, 1.25, 0.5, 2.5, 2.5, 0.2, 1.1, 0.25}, 0.0034289783},
      {{8, 1, 1, 16, 2, 1.5, 0.5, 3, 3, 0.15, 2.25, 0.5}, 0.0033047454},
      {{8, 2, 1, 8, 1, 2, 1.25, 1.25, 1.25, 0.1, 1.5, 0.25}, 0.0025051413},
      {{2, 1, 1, 4, 2, 1.5, 0.5, 3, 3, 0.25, 0.5, 0.25}, 0.0029209517}};
  for (const auto& r : rows)
    EXPECT_NEAR(ref::mad_vs_blinn([&](double c, int n) { return ref::dsh_template(r.t, c, n); }),
                r.mad, 2e-10);
  EXPECT_NEAR(ref::dsh_template(rows[3].t, 0.93, 40), ref::dsh(0.93, 40), 1e-15);
  // The printed plain sum (2.26) peaks at 1.9915 and misses the MAD by two orders of magnitude.
  EXPECT_NEAR(ref::dsh_printed_sum(1.0, 100), 1.9915, 5e-5);
  EXPECT_GT(ref::mad_vs_blinn(ref::dsh_printed_sum), 0.2);
}

TEST(BrdfRef, GoldenValuesOfTheNote) {
  // §7 golden values (6 significant digits).
  const struct {
    int n;
    double c, b, sh, msh, dsh, scos, scos2, st16, qr;
  } g[] = {{1, 0.5, 0.5, 0.5, 0.632099, 0.133415, 0.5625, 0.401111, 0.60171, 0.3035},
           {10, 0.9, 0.348678, 0.473684, 0.318893, 0.293774, 0.25, 0.368622, 0.356074, 0.1926},
           {50, 0.99, 0.605006, 0.66443, 0.524693, 0.572587, 0.5625, 0.605635, 0.60171, 0.60093},
           {1000, 0.999, 0.367695, 0.49975, 0.316084, 0.354926, 0.25, 0.400801, 0.356074, 0.213786}};
  for (const auto& r : g) {
    auto near = [](double got, double want) { EXPECT_NEAR(got, want, 5e-6 * std::max(1.0, want)); };
    near(ref::blinn(r.c, r.n), r.b);
    near(ref::schlick(r.c, r.n), r.sh);
    near(ref::msh(r.c, r.n), r.msh);
    near(ref::dsh(r.c, r.n), r.dsh);
    near(ref::scos(r.c, r.n), r.scos);
    near(ref::scos2(r.c, r.n), r.scos2);
    near(ref::st(r.c, r.n, 16), r.st16);
    near(ref::qr(r.c, r.n), r.qr);
  }
  EXPECT_NEAR(ref::msh(1, 7), 1.024, 1e-12);  // overshoot for every n
  EXPECT_NEAR(ref::dsh(1, 7), 0.995768, 5e-7);
  EXPECT_NEAR(ref::st(0, 1, 16), 0.356074, 5e-7);  // grazing bias for n < a
}

// Max relative error |F - F_B| / F_B at the epicentre c = 0.3^(1/n) over n in [lo, 1000].
double epicentre_delta(double (*f)(double, int), int lo) {
  double worst = 0;
  for (int n = lo; n <= 1000; ++n) {
    const double c = std::pow(0.3, 1.0 / n);
    worst = std::max(worst, std::fabs(f(c, n) - 0.3) / 0.3);
  }
  return worst;
}

TEST(BrdfRef, EpicentreRelativeErrors) {
  EXPECT_NEAR(epicentre_delta(ref::msh, 2), 0.1566, 5e-4);      // thesis: <= 16 %
  EXPECT_NEAR(epicentre_delta(ref::schlick, 2), 0.5119, 5e-4);  // thesis: <= 52 %
  EXPECT_NEAR(epicentre_delta(ref::dsh, 9), 0.2132, 5e-4);      // thesis: <= 22 % (n >= 9)
}

TEST(BrdfRef, NormalisingCoefficientOfMsh) {
  // Fig. 2.9 (3 decimals), the closed form against quadrature of the lobe.
  const struct {
    int n;
    double coef;
  } fig29[] = {{1, 0.419}, {2, 0.6},   {3, 0.765},  {5, 1.073},  {7, 1.367}, {9, 1.653},
               {10, 1.793}, {30, 4.476}, {40, 5.779}, {50, 7.071}, {70, 9.634}};
  for (const auto& r : fig29) {
    EXPECT_NEAR(ref::msh_coef_exact(r.n), r.coef, 5.1e-4) << r.n;
    const double quad = 1 / ref::lobe_energy([&](double c) { return ref::msh(c, r.n); },
                                             std::numbers::pi / 2);
    EXPECT_NEAR(quad, ref::msh_coef_exact(r.n), 1e-9 * quad) << r.n;
  }
  EXPECT_NEAR(ref::msh_coef_exact(1000), 125.9796, 1e-4);
  // (2.24): max |coef_fit / coef - 1| on n in [2, 1000] is 0.04234 at n = 2 (thesis: <= 0.042);
  // 0.147 at n = 1, outside the stated range.
  double worst = 0;
  int at = 0;
  for (int n = 2; n <= 1000; ++n) {
    const double e = std::fabs(ref::msh_coef_fit(n) / ref::msh_coef_exact(n) - 1);
    if (e > worst) worst = e, at = n;
  }
  EXPECT_NEAR(worst, 0.04234, 5e-5);
  EXPECT_EQ(at, 2);
  EXPECT_NEAR(ref::msh_coef_fit(1) / ref::msh_coef_exact(1) - 1, 0.147, 5e-4);
}

TEST(BrdfRef, NormalisingCoefficientOfQr) {
  // Fig. 3.10 reproduces with the zero constant 2.545e-3 (OCR: 2.5e-3), except n = 320 (printed
  // 80.466, a transposition of 80.446).
  const struct {
    int n;
    double coef;
  } fig310[] = {{1, 0.593},    {20, 5.222},   {40, 10.223},  {60, 15.227},  {80, 20.232},
                {120, 30.245}, {140, 35.254}, {160, 40.265}, {180, 45.278}, {200, 50.293},
                {220, 55.31},  {240, 60.331}, {260, 65.354}, {280, 70.381}, {300, 75.412},
                {320, 80.446}, {340, 85.484}};
  for (const auto& r : fig310) EXPECT_NEAR(ref::qr_coef_thesis(r.n), r.coef, 6e-4) << r.n;
  // The exact closed form (note §4.3) against quadrature up to the true zero.
  for (int n : {2, 5, 20, 100, 1000}) {
    const double zero = std::acos(1 - 1 / (0.786 * n));
    const double quad = 1 / ref::lobe_energy([n](double c) { return ref::qr(c, n); }, zero);
    EXPECT_NEAR(ref::qr_coef_exact(n), quad, 1e-8 * quad) << n;
  }
  EXPECT_NEAR(ref::qr_coef_exact(1), 0.5942, 5e-5);
  EXPECT_NEAR(ref::qr_coef_exact(1000), 250.4039, 5e-4);
  // (3.25) on [1, 20]: max error 0.0577 (n = 3); 0.255 n on [21, 1000]: 0.0213 (n = 21).
  double lo = 0, hi = 0;
  for (int n = 1; n <= 1000; ++n) {
    const double e = std::fabs(ref::qr_coef_fit(n) / ref::qr_coef_exact(n) - 1);
    (n <= 20 ? lo : hi) = std::max(n <= 20 ? lo : hi, e);
  }
  EXPECT_NEAR(lo, 0.0577, 5e-4);
  EXPECT_NEAR(hi, 0.0213, 5e-4);
}

TEST(BrdfRef, CutOffsMatchTheClosedForms) {
  const double one = std::ldexp(1.0, tu::fmt::kBrdfCF);
  for (int q : {3, 8, 9})
    for (int n : {1, 2, 10, 100, 1000}) {
      const double s = std::pow(2.0, q);
      // (2.8) Schlick: c = n / (2^q + n - 1); (2.12) Blinn: c = 2^(-q/n);
      // (3.14) simplified, F_SCOS2: c = n (10 r + 1) / (20 + n + 10 r n - 20 r), r = 2^(-q/2).
      const double r = std::pow(2.0, -q / 2.0);
      const double want[] = {n / (s + n - 1), std::pow(2.0, -static_cast<double>(q) / n),
                             n * (10 * r + 1) / (20 + n + 10 * r * n - 20 * r)};
      const Model m[] = {Model::Schlick, Model::Blinn, Model::Scos2};
      for (int i = 0; i < 3; ++i)
        EXPECT_NEAR(static_cast<double>(cut_code(m[i], n, q)), std::ceil(want[i] * one), 1.0)
            << name(m[i]) << " n=" << n << " q=" << q;
    }
}

TEST(BrdfRef, MonotoneInC) {
  for (Model m : kModels)
    for (int n : {1, 2, 9, 16, 50, 268, 1000}) {
      double prev = -1;
      for (int i = 0; i <= 100000; ++i) {
        const double v = ref_value(m, i / 100000.0, n);
        ASSERT_GE(v, prev) << name(m) << " n=" << n << " c=" << i / 100000.0;
        prev = v;
      }
    }
}

TEST(BrdfRef, Table42SphereRender) {
  // Mean Manhattan grey distance against Phong; thesis Table 4.2. The note's re-render differs by
  // up to 0.1 (n = 5 Schlick: 1.125 vs 1.22; exact normals instead of the 20x20 tessellation).
  const struct {
    int n;
    double sch, msh;
  } t42[] = {{5, 1.22, 0.65},  {10, 1.24, 0.52}, {15, 0.77, 0.19},  {20, 0.71, 0.17},
             {50, 0.41, 0.07}, {100, 0.26, 0.04}, {250, 0.14, 0.02}, {500, 0.08, 0.01}};
  for (const auto& r : t42) {
    const auto phong = ref::sphere_render(ref::blinn, r.n);
    EXPECT_NEAR(ref::manhattan(phong, ref::sphere_render(ref::schlick, r.n)), r.sch, 0.2) << r.n;
    EXPECT_NEAR(ref::manhattan(phong, ref::sphere_render(ref::msh, r.n)), r.msh, 0.2) << r.n;
  }
  // n = 50 in the tool's formula mode: F_dsh 0.009 (averaged; the printed sum gives 0.101) and
  // F_SCOS2 0.19 (the tool clamps the result, not the base).
  const auto phong = ref::sphere_render(ref::blinn, 50);
  EXPECT_NEAR(ref::manhattan(phong, ref::sphere_render(ref::dsh, 50)), 0.009, 0.005);
  EXPECT_NEAR(ref::manhattan(phong, ref::sphere_render(
                                        [](double c, int n) {
                                          const double b = (-1.1 / (-n + n * c - 2 * c)) * n * (c - 1) + 1;
                                          return std::max(0.0, b * b);
                                        },
                                        50)),
              0.19, 0.02);
}

}  // namespace
