// Cycle estimator: a structural scheme described once as a small dataflow graph (operators with
// latencies in cycles and the functional unit they occupy) plus resource limits; a list scheduler
// predicts the latency and the initiation interval (II). Every block reuses it; the co-simulation
// test compares the prediction with the Verilator measurement (docs/blocks/gaussian.md).
//
// Timing model (matches the RTL conventions of tu_pipe_valid and the FSM schemes):
//   * an input accepted in cycle 0 is on the ports in cycle 0; an op with latency L >= 1 starts
//     when all its predecessors have finished and finishes L cycles later (its result registered);
//     latency-0 ops (adders, muxes, shifts, comparators) chain combinationally in the cycle their
//     inputs are ready;
//   * a unit with a limit (e.g. "mul": 1) is busy for max(L, 1) cycles per op;
//   * latency = the finish time of the last op (cycle of the output handshake after acceptance);
//   * II: pipelined schemes -> max over limited units of ceil(busy cycles / limit), at least 1;
//     non-pipelined (one item in flight, FSM) -> the latency (the next input is accepted in the
//     cycle the output leaves).
#pragma once

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace tu::sched {

struct Op {
  std::string name;
  std::string unit;        // functional-unit type, e.g. "mul", "add", "rom", "reg"
  int latency = 0;         // cycles
  std::vector<int> preds;  // indices of earlier ops
};

struct Graph {
  std::string name;  // the block name of the RTL that implements it
  std::string description;
  std::vector<Op> ops;
  std::map<std::string, int> limits;  // unit -> number of instances (absent: unlimited)
  bool pipelined = true;
  int add(std::string n, std::string unit, int lat, std::vector<int> preds = {}) {
    ops.push_back(Op{std::move(n), std::move(unit), lat, std::move(preds)});
    return static_cast<int>(ops.size()) - 1;
  }
};

struct Schedule {
  std::vector<int> start;
  int latency = 0;
  int ii = 1;
  std::map<std::string, int> units_used;  // ops per unit type (e.g. multipliers in a pipeline)
};

// The graph called `name` in a block's list of schemes (throws std::invalid_argument).
inline const Graph& find(const std::vector<Graph>& gs, const std::string& name) {
  for (const auto& g : gs)
    if (g.name == name) return g;
  throw std::invalid_argument("no scheme graph '" + name + "'");
}

inline Schedule schedule(const Graph& g) {
  const size_t n = g.ops.size();
  for (size_t i = 0; i < n; ++i)
    for (int p : g.ops[i].preds)
      if (p < 0 || static_cast<size_t>(p) >= i)
        throw std::invalid_argument(g.name + ": op " + g.ops[i].name + " has a bad predecessor");
  // Priority: longest latency path from the op to a sink (critical path first).
  std::vector<int> prio(n, 0);
  for (size_t i = n; i-- > 0;) {
    prio[i] = std::max(prio[i], g.ops[i].latency);
    for (int p : g.ops[i].preds)
      prio[static_cast<size_t>(p)] =
          std::max(prio[static_cast<size_t>(p)], g.ops[static_cast<size_t>(p)].latency + prio[i]);
  }
  Schedule s;
  s.start.assign(n, -1);
  std::map<std::string, std::map<int, int>> busy;  // unit -> cycle -> ops busy
  size_t done = 0;
  for (int t = 0; done < n; ++t) {
    if (t > 100000) throw std::runtime_error(g.name + ": schedule does not converge");
    bool progress = true;
    while (progress) {  // latency-0 ops may chain within cycle t
      progress = false;
      std::vector<size_t> ready;
      for (size_t i = 0; i < n; ++i) {
        if (s.start[i] >= 0) continue;
        bool ok = true;
        for (int p : g.ops[i].preds) {
          const auto pi = static_cast<size_t>(p);
          ok = ok && s.start[pi] >= 0 && s.start[pi] + g.ops[pi].latency <= t;
        }
        if (ok) ready.push_back(i);
      }
      std::stable_sort(ready.begin(), ready.end(), [&](size_t a, size_t b) { return prio[a] > prio[b]; });
      for (size_t i : ready) {
        const Op& op = g.ops[i];
        const auto lim = g.limits.find(op.unit);
        const int occ = std::max(op.latency, 1);
        if (lim != g.limits.end()) {
          bool free = true;
          for (int c = t; c < t + occ; ++c) free = free && busy[op.unit][c] < lim->second;
          if (!free) continue;
          for (int c = t; c < t + occ; ++c) ++busy[op.unit][c];
        }
        s.start[i] = t;
        ++done;
        progress = true;
      }
    }
  }
  for (size_t i = 0; i < n; ++i) {
    s.latency = std::max(s.latency, s.start[i] + g.ops[i].latency);
    ++s.units_used[g.ops[i].unit];
  }
  if (!g.pipelined) {
    s.ii = s.latency;
  } else {
    s.ii = 1;
    for (const auto& [unit, lim] : g.limits) {
      int cycles = 0;
      for (const auto& op : g.ops)
        if (op.unit == unit) cycles += std::max(op.latency, 1);
      s.ii = std::max(s.ii, (cycles + lim - 1) / lim);
    }
  }
  return s;
}

}  // namespace tu::sched
