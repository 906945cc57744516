#include "objspace/schemes.hpp"

#include "persp/schemes.hpp"

namespace tu::objspace {

namespace {
// S1: per accumulator two products of a coefficient and a grid index (i, j), summed with the
// constant (registered); B1's back end (S2..S8); S9: the four weight products (registered), the
// floor (a bit select) beside them.
sched::Graph build() {
  sched::Graph g;
  g.name = "objspace_sample";
  g.description = "object-space sample: 2-D map (6 multipliers), B1 back end, 4 weight multiplies";
  int acc[3];
  const char* sig[3] = {"pu", "pv", "q"};
  for (int k = 0; k < 3; ++k) {
    const int mi = g.add(std::string("mul_i_") + sig[k], "mul", 1);
    const int mj = g.add(std::string("mul_j_") + sig[k], "mul", 1);
    acc[k] = g.add(std::string("add_map_") + sig[k], "add", 0, {mi, mj});
  }
  const auto [u, v] = persp::add_back_end(g, acc[2], acc[0], acc[1]);
  for (const char* w : {"w00", "w10", "w01", "w11"}) g.add(std::string("mul_") + w, "mul", 1, {u, v});
  return g;
}
}  // namespace

const sched::Graph& sample_scheme() {
  static const sched::Graph g = build();
  return g;
}

}  // namespace tu::objspace
