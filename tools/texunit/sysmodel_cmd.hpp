#pragma once

#include <CLI/CLI.hpp>
#include <string>

namespace tu::cli {

struct SysmodelArgs {
  std::string scene, compare;
  bool json = false;
  bool relief = false;
  int fifo_depth = 4;
  int cord_unroll = 2, sqrt_step = 4;  // tu_ewa CordUnroll, SqrtStep (what-if: the RTL uses 2, 4)
  uint32_t cache_size = 0, cache_line = 64, cache_ways = 4, miss_penalty = 0;  // texel cache (0: none)
};

// `texunit sysmodel SCENE|default [--engine-compare rtl] [--json]` (docs/systemc.md).
CLI::App* add_sysmodel(CLI::App& app, SysmodelArgs& a);
int run_sysmodel(const SysmodelArgs& a);

}  // namespace tu::cli
