// Structural schemes of the ellipse/LOD units (rtl/ellipse/tu_ellipse.sv, tu_ellipse_rec.sv) for the cycle
// estimator (texunit/sched.hpp); testbench/cosim/ellipse_sched_test.cpp compares the prediction
// with the Verilator measurement.
#pragma once

#include "texunit/sched.hpp"

namespace tu::ellipse {

// The analytic unit's operations, after `after` (the recurrence front's last op, or none).
inline void add_analytic(sched::Graph& g, std::vector<int> after) {
  std::vector<int> prods;
  for (const char* n : {"nvx^2", "nvy^2", "nux^2", "nuy^2", "nux*nvx", "nuy*nvy"})
    prods.push_back(g.add(n, "mul", 1, after));                      // S0
  const int recip = g.add("recip_core(q mantissa)", "recip", 4, after);  // S0..S3 (tu_recip_core)
  const int lq = g.add("log2 q", "log", 1, after);                    // S0
  prods.push_back(lq);
  const int norm = g.add("s, d, Be' normalise; Ae'..Ce' codes", "shift", 1, prods);  // S1
  const int sq = g.add("isqrt(d^2 + Be'^2)", "sqrt", 1, {norm});                    // S2
  const int ll = g.add("log2 lam", "log", 1, {sq});                                 // S3
  const int fd = g.add("det3 * R", "mul", 0, {recip});                              // S4
  const int lf = g.add("log2 |f|", "log", 0, {fd});
  g.add("minor, clamp, lod, flags", "reg", 1, {ll, lf});
}

inline sched::Graph scheme() {
  sched::Graph g;
  g.name = "ellipse";
  g.description = "analytic (q^4-scaled) ellipse, axes, anisotropy clamp, LOD; II = 1";
  add_analytic(g, {});
  return g;
}

// The recurrence variant (rtl/ellipse/tu_ellipse_rec.sv): the Jacobian front, then the analytic
// unit on J (q := 1).
inline sched::Graph scheme_rec() {
  sched::Graph g;
  g.name = "ellipse_rec";
  g.description = "seed recurrences: J = n / (q (q+G)), n / (q (q+H)), then the analytic unit on J; II = 1";
  const int dx = g.add("q (q+G), q (q+H), leading ones", "mul", 0);
  const int rc = g.add("recip_core x2", "recip", 4, {dx});               // F0..F3
  const int jac = g.add("J = n R, round, saturate (4 mul)", "mul", 1, {rc});  // F4
  const int det = g.add("det J, normalise", "mul", 1, {jac});             // F5
  add_analytic(g, {det});
  return g;
}

}  // namespace tu::ellipse
