// Sphere tracing through a distance map (docs/blocks/relief.md §13), bit-accurate and float.
//
// Ray (POM's): from the surface point T (depth 0) along -V, position T - D P at depth D, with
// P = pom::parallax(view) (a = max(|Vz|, PomVzMin): the Vz -> 0 guard; Vz < 0 mirrored). In map
// texels the point is (W (T - D P), D Z), Z = S W, so one unit of D is
// lambda = sqrt((W Pu)^2 + (W Pv)^2 + Z^2) texels of ray.
//
// Bit-accurate (formats.hpp, prefix Dm):
//   set-up  L2 = (W Pu)^2 + (W Pv)^2 + (S W)^2   exact, 2^-32 texel^2 (uint64: W <= 512, |P| < 64)
//           lambda_c = ceil(sqrt(L2))            exact integer square root, 2^-16 texel (DmLambdaW)
//           K = floor(2^44 / lambda_c)           DmKW bits, DmKF fraction bits (exact division)
//   loop    D_0 = 0; i = 0..cap-1:
//             x = T - round_half_up(D_i P / 2^DmDF)          uv, PomUvF bits
//             c = map[floor(x W) mod W, floor(y W) mod W, min(floor(D_i layers), layers - 1)]
//             c == 0: stop (converged: within the margin of the surface)
//             D_{i+1} = min(D_i + floor(c K / 2^DmKF), 2^DmDF)   (bottom reached: `bottom` flag)
//   out     x at the last D; steps = map reads that moved the ray; capped = the cap was hit.
// The step's ray length floor(c K / 2^8) * lambda * 2^-24 <= c * 2^-4 texel (K rounded down,
// lambda_c >= lambda), and x's rounding (<= 2^-17 repeats, <= 2^-8 texel for W <= 512, per axis)
// is within eta = 2^-6 texel: the map's safety proof applies, so a step never enters the solid.
// Float reference: the same loop in double, unquantised P and lambda, the unquantised safe
// distance (Map::safe) and threshold "safe < one quantum" (where the code is 0).
//
// Finish (optional, `finish` > 0, the "linear + binary" refinement of relief mapping): from the
// stop depth, linear steps of one layer (2^DmDF / layers) against the nearest-sampled depth map
// (D >= code / 255, POM's rule, exact: 255 D >= code 2^DmDF) for at most `finish` steps, then 4
// bisection steps between the last point above and the first point at or below; out = the point
// at or below. The same search from D = 0 with N linear steps of 1/N is the method `linbin`.
#pragma once

#include <cstdint>

#include "distmap/distance_map.hpp"
#include "pom/pom_march.hpp"

namespace tu::dm {

struct TraceOut {
  int64_t u = 0, v = 0;   // PomUvF bits, not wrapped (T - D P)
  uint32_t d = 0;         // D, DmDF bits
  uint32_t steps = 0;     // map reads that moved the ray
  uint32_t finish_steps = 0;  // depth reads of the finish
  bool capped = false, bottom = false, clamped = false, back = false;
};

struct Setup {
  int64_t pu = 0, pv = 0;  // P
  uint64_t lambda = 0;     // ceil(lambda), 2^-16 texel
  uint64_t k = 0;          // step factor
  bool clamped = false, back = false;
};
Setup setup(const Map& m, const pom::View& view);
uint64_t isqrt_ceil(uint64_t x);

TraceOut trace(const Map& m, const img::Gray8& depth, int64_t u, int64_t v, const pom::View& view,
               uint32_t cap, uint32_t finish = 0);

struct TraceRef {
  double u = 0, v = 0, d = 0;
  uint32_t steps = 0, finish_steps = 0;
  bool capped = false;
};
TraceRef trace_ref(const Map& m, const img::Gray8& depth, double u, double v, double vx, double vy,
                   double vz, double scale, uint32_t cap, uint32_t finish = 0);

// Linear search (n steps of 1/n in D, POM's exact hit rule) + 4 bisection steps, fixed point:
// the relief-mapping method of Policarpo et al., the "beyond the seeds" method of the comparison.
TraceOut linbin(const img::Gray8& depth, int64_t u, int64_t v, const pom::View& view, uint32_t n);

}  // namespace tu::dm
