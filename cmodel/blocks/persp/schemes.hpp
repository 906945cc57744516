// Structural schemes of the perspective divide unit (B1) as dataflow graphs for the shared cycle
// estimator (texunit/sched.hpp, also used by the Gaussian blocks). Graph names are the names of the
// RTL bindings that implement them: "persp" (incremental, tu_persp), "persp_direct"
// (tu_persp_direct), "persp_k4" (tu_persp_klane, K = 4 lanes), "persp_setup" (tu_persp_setup),
// "texel_depth" (tu_texel_depth).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "texunit/sched.hpp"

namespace tu::persp {
const std::vector<sched::Graph>& schemes();
const sched::Graph& scheme(const std::string& name);  // throws std::invalid_argument
// Appends the per-pixel back end (tu_persp_pixel, S2..S8) after the ops producing q, p_u, p_v;
// `sfx` names a lane. Returns the two output ops (u, v). Also the object-space datapath's core.
std::pair<int, int> add_back_end(sched::Graph& g, int acc_q, int acc_pu, int acc_pv, const std::string& sfx = "");
// The back end's first part: guard + normalise of the op `acc_q`, the reciprocal core; returns R.
int add_reciprocal(sched::Graph& g, int acc_q, const std::string& sfx = "");
// Texel-depth variant (persp/texel_depth.hpp, rtl/persp/tu_texel_depth.sv), per pixel:
// accumulators N, D (D loads m2 q1), the reciprocal of D, w = N R (rounded),
// T = T1 + (T2 - T1) w for u and v: schemes()'s graph "texel_depth".
const sched::Graph& texel_depth_scheme();
}  // namespace tu::persp
