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
  std::string root = ".";
  std::string yosys_cache;          // JSON cache of Yosys results keyed by the RTL files' hash
  bool yosys = true;                // false: area "not measured: " + no_yosys_why
  std::string no_yosys_why = "--no-yosys";
  bool yosys_cached_only = false;   // true: use matching cache entries, never synthesise (stale: not measured)
  std::string stdcell_cache;        // JSON cache of scripts/stdcell_flow.sh results (read only)
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

// `texunit stdcell`: runs scripts/stdcell_flow.sh on every listed top whose cache entry is
// missing or stale and stores the result in CACHE (netlists under NETLISTS/TOP.v).
int stdcell(const std::vector<std::string>& tops, const std::string& root, const std::string& cache,
            const std::string& netlists, bool force);

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
