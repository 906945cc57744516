// Block "afvis" (afvis_block.cpp): its fixed maps and the C model of one row, for the RTL binding
// (testbench/cosim/afvis_rtl.cpp loads the same maps) and the cycle-model test.
#pragma once

#include "afvis/afvis.hpp"
#include "block.hpp"

namespace tu::blocks {

const tex::Texture& afvis_texture();  // bricks colour 256 x 256, repeat
const img::Gray8& afvis_depth();      // pom::map_bricks(64)
afvis::Out afvis_block_model(const Row& in);  // in: the block's in-fields

}  // namespace tu::blocks
