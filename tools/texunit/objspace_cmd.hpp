#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>

namespace tu::cli {

struct ObjspaceArgs {
  std::string scene;
  int ss = 16;                        // ground truth: samples per pixel side
  double spacing = 1;                 // object-space sample spacing (pixels at the plane's distance)
  uint64_t max_samples = 1ull << 28;  // object-space sample cap
};

// `texunit objspace-compare SCENE|default` (docs/blocks/objspace.md).
CLI::App* add_objspace(CLI::App& app, ObjspaceArgs& a);
int run_objspace(const ObjspaceArgs& a);

}  // namespace tu::cli
