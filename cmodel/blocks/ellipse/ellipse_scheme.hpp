// Structural scheme of the analytic ellipse/LOD unit (rtl/ellipse/tu_ellipse.sv) for the cycle
// estimator (texunit/sched.hpp); testbench/cosim/ellipse_sched_test.cpp compares the prediction
// with the Verilator measurement.
#pragma once

#include "texunit/sched.hpp"

namespace tu::ellipse {

inline sched::Graph scheme() {
  sched::Graph g;
  g.name = "ellipse";
  g.description = "analytic (q^4-scaled) ellipse, axes, anisotropy clamp, LOD; II = 1";
  std::vector<int> prods;
  for (const char* n : {"nvx^2", "nvy^2", "nux^2", "nuy^2", "nux*nvx", "nuy*nvy"})
    prods.push_back(g.add(n, "mul", 1));                             // S0
  const int recip = g.add("recip_core(q mantissa)", "recip", 4);      // S0..S3 (tu_recip_core)
  const int lq = g.add("log2 q", "log", 1);                           // S0
  prods.push_back(lq);
  const int norm = g.add("s, d, Be' normalise; Ae'..Ce' codes", "shift", 1, prods);  // S1
  const int sq = g.add("isqrt(d^2 + Be'^2)", "sqrt", 1, {norm});                    // S2
  const int ll = g.add("log2 lam", "log", 1, {sq});                                 // S3
  const int fd = g.add("det3 * R", "mul", 0, {recip});                              // S4
  const int lf = g.add("log2 |f|", "log", 0, {fd});
  g.add("minor, clamp, lod, flags", "reg", 1, {ll, lf});
  return g;
}

}  // namespace tu::ellipse
