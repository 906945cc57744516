// Structural schemes of the perspective divide unit (B1) as dataflow graphs for the shared cycle
// estimator (texunit/sched.hpp, also used by the Gaussian blocks). Graph names are the names of the
// RTL bindings that implement them: "persp" (incremental, tu_persp), "persp_direct"
// (tu_persp_direct), "persp_k4" (tu_persp_klane, K = 4 lanes).
#pragma once

#include <string>
#include <vector>

#include "texunit/sched.hpp"

namespace tu::persp {
const std::vector<sched::Graph>& schemes();
const sched::Graph& scheme(const std::string& name);  // throws std::invalid_argument
}  // namespace tu::persp
