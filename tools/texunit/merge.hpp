// `texunit merge`: combines the JSON of `--shard K/N` runs into the unsharded run's result.
//   cosim shards (`cosim --json`): counts summed, maxima taken, rms from the summed squares,
//     latency/II from shard 0 (the unsharded run measures them on the same first vectors);
//     every shard 0..N-1 must be present once.
//   report shards (`report --json`): rows put back in the report's block order, then the same
//     table, JSON, Markdown and Pareto plots as `texunit report` writes.
#pragma once

#include <string>
#include <vector>

#include "report.hpp"

namespace tu::cli {

struct MergeArgs {
  std::vector<std::string> files;
  tu::report::Options report;  // json / markdown / plots outputs (report shards)
};

int run_merge(const MergeArgs& a);

}  // namespace tu::cli
