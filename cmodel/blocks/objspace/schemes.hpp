// Structural scheme of the object-space per-sample datapath (rtl/objspace/tu_objspace_sample.sv)
// as a dataflow graph for the shared cycle estimator (texunit/sched.hpp): graph "objspace_sample",
// the name of its RTL binding; testbench/cosim/objspace_cosim_test.cpp checks the prediction
// against Verilator.
#pragma once

#include "texunit/sched.hpp"

namespace tu::objspace {
const sched::Graph& sample_scheme();
}  // namespace tu::objspace
