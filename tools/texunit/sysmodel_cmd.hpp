#pragma once

#include <CLI/CLI.hpp>
#include <string>

namespace tu::cli {

struct SysmodelArgs {
  std::string scene, compare;
  bool json = false;
  int fifo_depth = 4;
};

// `texunit sysmodel SCENE|default [--engine-compare rtl] [--json]` (docs/systemc.md).
CLI::App* add_sysmodel(CLI::App& app, SysmodelArgs& a);
int run_sysmodel(const SysmodelArgs& a);

}  // namespace tu::cli
