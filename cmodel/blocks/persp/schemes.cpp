#include "schemes.hpp"

namespace tu::persp {

namespace {
using sched::Graph;
}  // namespace

// One pixel of the back end (tu_persp_pixel, S2..S8) after the S1 op `acc_q` (the op producing q)
// and the S1 ops `acc_p` (p_u, p_v): guard + leading-one detect + normalise (registered), the
// reciprocal core (tu_recip_core: ROM, two multiply-adds, round; each stage registered), two
// multiplies p*R, shift/round/saturate (registered). `sfx` distinguishes the lanes. Convention as
// in the Gaussian graphs: a multiplier feeding an adder in the same stage is the registered op
// (latency 1), the adder after it chains combinationally (latency 0).
int add_reciprocal(Graph& g, int acc_q, const std::string& sfx) {
  const int nrm = g.add("guard_lzc_normalise" + sfx, "lzc", 1, {acc_q});
  const int rom = g.add("recip_rom" + sfx, "rom", 1, {nrm});
  const int m1 = g.add("recip_mul_c2_dx" + sfx, "mul", 1, {rom});
  const int a1 = g.add("recip_add_c1" + sfx, "add", 0, {m1});
  const int m2 = g.add("recip_mul_s_dx" + sfx, "mul", 1, {a1});
  const int a2 = g.add("recip_add_c0" + sfx, "add", 0, {m2});
  return g.add("recip_round_sat" + sfx, "add", 1, {a2});
}
std::pair<int, int> add_back_end(Graph& g, int acc_q, int acc_pu, int acc_pv, const std::string& sfx) {
  const int r = add_reciprocal(g, acc_q, sfx);
  const int mu = g.add("mul_pu_r" + sfx, "mul", 1, {r, acc_pu});
  const int mv = g.add("mul_pv_r" + sfx, "mul", 1, {r, acc_pv});
  return {g.add("shift_round_sat_u" + sfx, "shift", 1, {mu}), g.add("shift_round_sat_v" + sfx, "shift", 1, {mv})};
}
namespace {

// S1 of the incremental unit: n == 0 ? seed : acc + increment (registered accumulators).
// S1 of the direct unit: seed + n * increment (combinational multiply, registered sum).
// k lanes: lane j = n == 0 ? seed + j*inc : lane_j + K*inc (j*inc, K*inc by shift-and-add).
Graph build_persp(const std::string& name, bool direct, int lanes) {
  Graph g;
  g.name = name;
  g.description = direct ? "direct: seed + n*inc (3 multipliers), reciprocal, 2 multiplies"
                         : (lanes == 1 ? "incremental: 3 accumulators, reciprocal, 2 multiplies"
                                       : std::to_string(lanes) +
                                             "-lane incremental: per lane 3 accumulators, reciprocal, 2 multiplies");
  for (int j = 0; j < lanes; ++j) {
    const std::string sfx = lanes == 1 ? "" : "_lane" + std::to_string(j);
    int acc[3];
    const char* sig[3] = {"pu", "pv", "q"};
    for (int k = 0; k < 3; ++k) {
      if (direct) {
        const int m = g.add(std::string("mul_n_inc_") + sig[k] + sfx, "mul", 1);
        acc[k] = g.add(std::string("add_seed_") + sig[k] + sfx, "add", 0, {m});
      } else {
        acc[k] = g.add(std::string("acc_") + sig[k] + sfx, "add", 1);
      }
    }
    add_back_end(g, acc[2], acc[0], acc[1], sfx);
  }
  return g;
}

// Per-scanline set-up (tu_persp_setup): nine registered products (A, D, G times x0 and x1;
// B, E, H times y), then per accumulator and span end the sum A x + B y + C chained into the
// registered range check (the x0 sums are also the registered outputs).
Graph build_setup() {
  Graph g;
  g.name = "persp_setup";
  g.description = "set-up: 9 products, 6 three-input sums, range check (overflow flag)";
  const char* sig[3] = {"pu", "pv", "q"};
  for (int k = 0; k < 3; ++k) {
    const int by = g.add(std::string("mul_y_") + sig[k], "mul", 1);
    for (const char* end : {"x0", "x1"}) {
      const int ax = g.add(std::string("mul_") + end + "_" + sig[k], "mul", 1);
      const int s = g.add(std::string("add_") + sig[k] + "_" + end, "add", 0, {ax, by});
      g.add(std::string("range_check_") + sig[k] + "_" + end, "cmp", 1, {s});
    }
  }
  return g;
}

// Texel-depth variant (tu_texel_depth): S1 accumulators N (m == 0 ? 0 : N + q2) and
// D (m == 0 ? m2 q1 : D + (q2 - q1)), the load product m2 q1 registered with its select; the
// reciprocal of D; w = N R rounded; T = T1 + (T2 - T1) w rounded, for u and v.
Graph build_texel_depth() {
  Graph t;
  t.name = "texel_depth";
  t.description = "texel depth: N, D accumulators (D loads m2 q1), reciprocal of D, w = N R, T1 + (T2 - T1) w";
  const int n = t.add("acc_n", "add", 1);
  const int d = t.add("acc_d_select", "add", 0, {t.add("mul_m2_q1", "mul", 1)});
  const int r = add_reciprocal(t, d);
  const int w = t.add("round_w", "shift", 1, {t.add("mul_n_r", "mul", 1, {r, n})});
  for (const char* c : {"u", "v"})
    t.add(std::string("add_t1_round_") + c, "add", 1, {t.add(std::string("mul_dt_w_") + c, "mul", 1, {w})});
  return t;
}

std::vector<Graph> build() {
  return {build_persp("persp", false, 1), build_persp("persp_direct", true, 1),
          build_persp("persp_k4", false, 4), build_setup(), build_texel_depth()};
}
}  // namespace

const std::vector<sched::Graph>& schemes() {
  static const std::vector<sched::Graph> gs = build();
  return gs;
}

const sched::Graph& scheme(const std::string& name) { return sched::find(schemes(), name); }

const sched::Graph& texel_depth_scheme() { return scheme("texel_depth"); }

}  // namespace tu::persp
