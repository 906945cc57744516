// Verilator drive/sample glue generated from the vector blocks' field lists, so that a block's
// RTL binding maps fields to ports by name (field `x` -> port `x_i` / `x_o`) from the one
// description of its fields (Block::fields) instead of by position in hand-written code.
#pragma once

#include <string>

namespace tu::blocks {

// The content of the generated header tu_glue.hpp (written at build time by tu_gen_glue).
std::string generated_glue();

}  // namespace tu::blocks
