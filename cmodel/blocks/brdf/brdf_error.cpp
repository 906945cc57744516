#include "brdf_error.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "brdf_ref.hpp"

namespace tu::brdf {

namespace {
constexpr double kLsb = 1.0 / (1 << fmt::kBrdfOutF);
uint64_t code_of(double c) {
  return static_cast<uint64_t>(std::llround(std::ldexp(c, fmt::kBrdfCF)));
}
}  // namespace

In input_of(Model m, double c, int n) {
  return {code_of(c), static_cast<uint64_t>(n), cut_code(m, n)};
}

SweepStats sweep(Model m, int n, uint64_t from, bool check_below) {
  SweepStats s;
  const uint64_t one = uint64_t(1) << fmt::kBrdfCF;
  const uint64_t ccut = cut_code(m, n);
  if (check_below)
    for (uint64_t k = 0; k < std::min(from, ccut); ++k)
      if (eval(m, {k, static_cast<uint64_t>(n), ccut}).f != 0) ++s.nonzero_below_cut;
  uint64_t prev = 0;
  for (uint64_t k = from; k <= one; ++k) {
    const uint64_t f = eval(m, {k, static_cast<uint64_t>(n), ccut}).f;
    const double c = std::ldexp(static_cast<double>(k), -fmt::kBrdfCF);
    const double got = value(f);
    const double own = std::fabs(got - ref_value(m, c, n)) / kLsb;
    if (own > s.max_own_lsb) s.max_own_lsb = own, s.worst_own_code = k;
    s.max_blinn_lsb = std::max(s.max_blinn_lsb, std::fabs(got - ref::blinn(c, n)) / kLsb);
    if (k > from && f < prev) s.monotone = false;
    prev = f;
    ++s.codes;
  }
  return s;
}

void merge(SweepStats& into, const SweepStats& s) {
  if (s.max_own_lsb > into.max_own_lsb) into.max_own_lsb = s.max_own_lsb, into.worst_own_code = s.worst_own_code;
  into.max_blinn_lsb = std::max(into.max_blinn_lsb, s.max_blinn_lsb);
  into.monotone = into.monotone && s.monotone;
  into.codes += s.codes;
  into.nonzero_below_cut += s.nonzero_below_cut;
}

GridStats vs_blinn_fx(Model m, int deg_step, int n_step) {
  GridStats g;
  double sum = 0;
  long count = 0;
  for (int n = 1; n <= fmt::kBrdfNMax; n += n_step) {
    const uint64_t ccut = cut_code(m, n);
    for (int deg = 0; deg <= 90; deg += deg_step) {
      const double c = std::cos(deg * std::numbers::pi / 180);
      const Result r = eval(m, {code_of(c), static_cast<uint64_t>(n), ccut});
      const double e = std::fabs(value(r.f) - ref::blinn(c, n));
      sum += e;
      g.max_abs = std::max(g.max_abs, e);
      ++count;
    }
  }
  g.mad = sum / static_cast<double>(count);
  return g;
}

double epicentre_rel_fx(Model m, int n_lo) {
  double worst = 0;
  for (int n = n_lo; n <= fmt::kBrdfNMax; ++n) {
    const Result r = eval(m, input_of(m, std::pow(0.3, 1.0 / n), n));
    worst = std::max(worst, std::fabs(value(r.f) - 0.3) / 0.3);
  }
  return worst;
}

}  // namespace tu::brdf
