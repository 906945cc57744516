// `texunit report`: error / cycles / area / C-model speed per block variant (generic rows).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "planner/report_row.hpp"  // Row (and its JSON form)
#include "texunit/shard.hpp"

namespace tu::report {

struct Options {
  std::vector<std::string> blocks;  // report groups; empty: every group
  std::string json, plots, markdown;
  std::string root;                 // repository root; empty: repo_root("")
  std::string yosys_cache;          // JSON cache of Yosys results keyed by the RTL files' hash
                                    // (run(): empty = ROOT/docs/report/yosys_cache.json, read only
                                    // unless update_cache)
  bool yosys = true;                // false: area "not measured: " + no_yosys_why
  std::string no_yosys_why = "--no-yosys";
  bool yosys_cached_only = false;   // true: use matching cache entries, never synthesise (stale: not measured)
  std::string stdcell_cache;        // JSON cache of scripts/stdcell_flow.sh results (read only;
                                    // run(): empty = ROOT/docs/report/stdcell_cache.json)
  bool update_cache = false;        // the default (tracked) Yosys cache: synthesise stale entries and save
  uint64_t count = 20000;           // random vectors per registry block (plus its stiff set)
  Shard shard;                      // --shard K/N: the groups i with i % N == K (groups() order)
  std::string provenance;           // markdown header line; empty: "texunit report --count N"
};

// The files an RTL top needs, in Yosys/Verilator order: the sources of the rtl/manifest.json block
// that lists the top (packages first).
std::vector<std::string> rtl_files(const std::string& root, const std::string& top);

// FNV-1a (64 bits) of s, continuing from h: the caches' keys and a shard's vector-file hash.
uint64_t fnv1a(const std::string& s, uint64_t h = 1469598103934665603ull);

// Content hash of a top's RTL files and the flow script that measures it (the caches' key).
std::string rtl_hash(const std::string& root, const std::string& top, const std::string& script);

// The repository root: `given` if not empty, else the source directory texunit was configured
// from (when it still holds rtl/manifest.json), else ".": texunit works from any directory.
std::string repo_root(const std::string& given);

struct StdcellOptions {
  std::vector<std::string> tops;
  std::string root;          // empty: repo_root("")
  std::string cache;         // explicit cache file (read and written); empty: the defaults below
  std::string netlists;      // empty: ROOT/build/stdcell (flat) or ROOT/build/stdcell_hier
  std::string module_cache;  // hierarchical: module netlists; empty: ROOT/build/stdcell_modules
  bool force = false;
  bool update_cache = false;  // write the tracked ROOT/docs/report/ cache (default: ROOT/build/stdcell/)
  bool hier = false;          // scripts/stdcell_hier.py instead of scripts/stdcell_flow.sh
  int jobs = 1;               // hierarchical: modules mapped at once
};

// `texunit stdcell`: runs the flow script on every listed top whose cache entry is missing or
// stale and stores the result. Without an explicit cache it reads the tracked cache
// (docs/report/stdcell_cache.json, or stdcell_hier.json for the hierarchical flow) and the local
// one (build/stdcell/ of the same name) and writes the local one, or the tracked one with
// update_cache.
int stdcell(const StdcellOptions& opt);

// Report groups in output order (block names of the rows).
std::vector<std::string> groups();
std::vector<Row> rows(const Options& opt);
std::vector<Row> rows(const std::vector<std::string>& blocks, const std::string& root, bool yosys);
int run(const Options& opt);
// What identifies a `report --shard K/N` run (element 0 of its JSON array; `texunit merge` refuses
// shards whose identities differ, a gap and a repeat): the shard, --count, --blocks and the area source.
std::string shard_identity(const Options& opt);
// The table, JSON, plots and Markdown of measured rows (run() after measuring; texunit merge).
void write(const std::vector<Row>& rows, const Options& opt);
// `texunit merge` of report shards: rows of every file, put back in groups() order.
std::vector<Row> merge_rows(const std::vector<std::vector<Row>>& shards);

}  // namespace tu::report
