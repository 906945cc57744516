// rtl/manifest.json: the one RTL file list (docs/architecture.md, "RTL manifest"). Read by
// `texunit rtl-files`, the report's Yosys runs and the RtlManifest tests; rtl/CMakeLists.txt reads
// the same file for the Verilator builds.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace tu::rtl {

struct Block {
  std::vector<std::string> uses;      // blocks whose files come first
  std::vector<std::string> packages;  // packages beyond tu_formats_pkg (names)
  std::vector<std::string> files;     // own files, relative to rtl/
  std::vector<std::string> tops;      // modules co-simulated or synthesised on their own
};

struct Manifest {
  std::string rtl_dir;                           // ROOT/rtl
  std::vector<std::string> include_dirs;         // relative to rtl/
  std::map<std::string, std::string> packages;   // package name -> file relative to rtl/
  std::vector<std::string> lint_only;            // Verilator configuration files (whole-tree lint)
  std::map<std::string, Block> blocks;

  // Throws std::runtime_error naming the file and the field on a malformed manifest.
  static Manifest load(const std::string& root);
  // The block whose "tops" list `top`; throws std::invalid_argument when none does.
  const std::string& block_of_top(const std::string& top) const;
  // Complete source list of a block in compile order, paths ROOT/rtl/...: packages (tu_formats_pkg,
  // then the block's and its dependencies'), then the files of the used blocks depth first, then
  // its own; each file once.
  std::vector<std::string> sources(const std::string& block) const;
  // sources(block_of_top(top)).
  std::vector<std::string> top_sources(const std::string& top) const;
  // Every block's tops, in block-name order.
  std::vector<std::string> tops() const;
  // The whole tree: every package, then every block file sorted (each file once), paths ROOT/rtl/...
  std::vector<std::string> all_sources() const;
  // Every `include file (*.svh) of the include directories, sorted, paths ROOT/rtl/...
  std::vector<std::string> headers() const;
};

}  // namespace tu::rtl
