// List-scheduler cycle estimator (texunit/sched.hpp): generic properties and the Gaussian schemes'
// predictions against their declared latency / II (the co-simulation test compares with Verilator).
#include <gtest/gtest.h>

#include "block.hpp"
#include "gauss/schemes.hpp"
#include "texunit/sched.hpp"

namespace {
using namespace tu;

TEST(Sched, ChainAndParallel) {
  sched::Graph g;
  const int a = g.add("a", "mul", 1);
  const int b = g.add("b", "mul", 1);
  const int c = g.add("c", "add", 0, {a, b});
  g.add("d", "mul", 2, {c});
  auto s = sched::schedule(g);
  EXPECT_EQ(s.latency, 3);  // a, b in parallel, c chained, d 2 cycles
  EXPECT_EQ(s.ii, 1);
  g.limits["mul"] = 1;  // a and b now serialise; the unit is busy 4 cycles per item
  s = sched::schedule(g);
  EXPECT_EQ(s.latency, 4);
  EXPECT_EQ(s.ii, 4);
  g.pipelined = false;
  EXPECT_EQ(sched::schedule(g).ii, 4);
}

TEST(Sched, RejectsForwardEdges) {
  sched::Graph g;
  g.ops.push_back({"x", "add", 0, {1}});
  g.ops.push_back({"y", "add", 0, {}});
  EXPECT_THROW(sched::schedule(g), std::invalid_argument);
}

TEST(Sched, GaussSchemesMatchTheDeclaredBlocks) {
  for (const auto& g : gauss::schemes()) {
    if (g.name.rfind("est_", 0) == 0) continue;
    const auto s = sched::schedule(g);
    const auto& b = blocks::find(g.name);
    EXPECT_EQ(s.latency, b.latency_cycles) << g.name;
    EXPECT_EQ(s.ii, b.ii_cycles) << g.name;
  }
  EXPECT_EQ(sched::schedule(gauss::scheme("clip_horner")).units_used.at("mul"), 3);
  EXPECT_EQ(sched::schedule(gauss::scheme("clip_estrin")).units_used.at("mul"), 4);
}
}  // namespace
