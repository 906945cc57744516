// Shared by the tests of walks that must equal the sequential EWA walk (ewa_lanes_test.cpp,
// afvis_test.cpp): the vector set's texture and the comparison of two walk outputs.
#pragma once

#include <gtest/gtest.h>

#include "ewa/ewa_fx.hpp"

namespace tu::test {

// The ewa block's texture: the builtin bricks colour texture, 256 x 256, repeat.
inline const tex::Texture& bricks_texture() {
  static const tex::Texture t = tex::Texture::build("bricks", tex::bricks(256).color, tex::Wrap::Repeat);
  return t;
}

// Colour, level, texels visited and inside, flags identical.
inline void expect_same_walk(const ewa::fx::Out& a, const ewa::fx::Out& b) {
  EXPECT_EQ(a.color, b.color);
  EXPECT_EQ(a.level, b.level);
  EXPECT_EQ(a.texels_visited, b.texels_visited);
  EXPECT_EQ(a.texels_inside, b.texels_inside);
  EXPECT_EQ(a.flags, b.flags);
}

}  // namespace tu::test
