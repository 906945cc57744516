// Structural schemes of the Gaussian pixel-model blocks as dataflow graphs for the cycle
// estimator (texunit/sched.hpp). Graph names are the block names of the RTL that implements
// them; "est_*" graphs have no RTL yet (estimates only).
#pragma once

#include <vector>

#include "texunit/sched.hpp"

namespace tu::gauss {
const std::vector<sched::Graph>& schemes();
const sched::Graph& scheme(const std::string& name);  // throws std::invalid_argument
}  // namespace tu::gauss
