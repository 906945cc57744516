// Rows of block objspace_sample (objspace_block.cpp) from and to the C model's types: shared by
// the vector sets and the RTL render (testbench/cosim/objspace_rtl.cpp).
#pragma once

#include "block.hpp"
#include "objspace/objspace.hpp"

namespace tu::blocks {
Row objspace_sample_in(const persp::Unit::Coefs& k, int i, int j);  // a..i, gi, gj
Row objspace_sample_out(const objspace::Splat& s);                  // x, y, w00, w10, w01, w11, guard
objspace::Splat objspace_sample_splat(const Row& out);              // the inverse of objspace_sample_out
}  // namespace tu::blocks
