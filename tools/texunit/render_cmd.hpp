#pragma once

#include <CLI/CLI.hpp>
#include <string>

namespace tu::cli {

struct RenderArgs {
  std::string scene, out_dir, dump, engine = "ref", filter;
};

CLI::App* add_render(CLI::App& app, RenderArgs& a);
int run_render(const RenderArgs& a);  // throws on bad scenes and unwritable outputs

}  // namespace tu::cli
