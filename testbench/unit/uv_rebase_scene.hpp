// Test scenes of the uv rebase (testbench/unit/uv_rebase_test.cpp, testbench/cosim/uv_rebase_cosim_test.cpp):
// a camera-facing quad with uv far from 0.
#pragma once

#include <cstdio>
#include <string>

namespace tu::test {

inline std::string num(double x) {
  char b[64];
  std::snprintf(b, sizeof b, "%.17g", x);
  return b;
}

// A 48 x 32 camera looking down -z at a quad in the plane z = -depth covering [x0, x1] x [y0, y1]
// (world units), uv [u0, u0 + du] x [v0, v0 + du] on one `size`-texel checkerboard.
inline std::string quad_scene(int size, const std::string& wrap, const std::string& filter, double u0, double v0,
                       double depth = 2, double x0 = -1, double x1 = 1, double y0 = -0.7, double y1 = 0.7, double du = 1) {
  const std::string z = num(-depth);
  return R"({"texunit_scene": 1,
  "camera": {"position": [0, 0, 0], "look_at": [0, 0, -1], "width": 48, "height": 32},
  "textures": {"t": {"builtin": "checkerboard", "size": )" +
         std::to_string(size) + R"(, "cells": 8, "wrap": ")" + wrap + R"("}},
  "materials": {"m": {"texture": "t", "filter": ")" +
         filter + R"("}},
  "objects": [{"name": "q", "type": "quad", "material": "m",
    "vertices": [[)" + num(x0) + ", " + num(y0) + ", " + z + "], [" + num(x1) + ", " + num(y0) + ", " + z + "], [" + num(x1) + ", " +
         num(y1) + ", " + z + "], [" + num(x0) + ", " + num(y1) + ", " + z + R"(]],
    "uv": [[)" + num(u0) + ", " + num(v0) + "], [" + num(u0 + du) + ", " + num(v0) + "], [" + num(u0 + du) + ", " + num(v0 + du) +
         "], [" + num(u0) + ", " + num(v0 + du) + "]]}]}";
}

}  // namespace tu::test
