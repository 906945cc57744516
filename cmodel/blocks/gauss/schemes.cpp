#include "schemes.hpp"

namespace tu::gauss {

namespace {
using sched::Graph;

// Degree-n Horner: acc = c_n; acc = c_k + floor(acc * a). `load` registers the operands first
// (FSM); the pipelined form multiplies straight from the input.
Graph horner(const std::string& name, int deg, bool shared) {
  Graph g;
  g.name = name;
  g.pipelined = !shared;
  int prev = g.add("abs_clamp", "add", 0);
  if (shared) {
    prev = g.add("load", "reg", 1, {prev});
    g.limits["mul"] = 1;
    g.description = "Horner, one shared multiplier (FSM)";
  } else {
    g.description = "Horner, fully pipelined";
  }
  for (int k = deg - 1; k >= 0; --k) {
    const int m = g.add("mul_c" + std::to_string(k + 1), "mul", 1, {prev});
    prev = g.add("add_c" + std::to_string(k), "add", 0, {m});
  }
  g.add("round_fold", "add", shared ? 0 : 1, {prev});
  return g;
}

std::vector<Graph> build() {
  std::vector<Graph> gs;
  {
    Graph g;
    g.name = "clip_p1";
    g.description = "comparators + segment table + one multiply-add";
    const int a = g.add("abs_clamp", "add", 0);
    const int c = g.add("compare", "cmp", 0, {a});
    const int r = g.add("seg_table", "rom", 0, {c});
    const int m = g.add("mul_c1", "mul", 1, {a, r});
    const int s = g.add("add_c0", "add", 0, {m});
    g.add("round_fold", "add", 1, {s});
    gs.push_back(g);
  }
  gs.push_back(horner("clip_horner", 3, false));
  {
    Graph g;
    g.name = "clip_estrin";
    g.description = "Estrin: a^2, c3*a, c1*a in parallel, then (c2 + c3 a) * a^2";
    const int a = g.add("abs_clamp", "add", 0);
    const int a2 = g.add("mul_a2", "mul", 1, {a});
    const int u = g.add("mul_c3", "mul", 1, {a});
    const int w = g.add("mul_c1", "mul", 1, {a});
    const int hi = g.add("add_c2", "add", 0, {u});
    const int lo = g.add("add_c0", "add", 0, {w});
    const int t = g.add("mul_hi_a2", "mul", 1, {hi, a2});
    const int s = g.add("add_lo_hi", "add", 0, {lo, t});
    g.add("round_fold", "add", 1, {s});
    gs.push_back(g);
  }
  gs.push_back(horner("clip_seq", 3, true));
  {
    Graph g;
    g.name = "gauss_weight";
    g.description = "t = 1 - Q/2, three squarings";
    const int t = g.add("one_minus_half_q", "add", 0);
    const int s1 = g.add("square1", "mul", 1, {t});
    const int s2 = g.add("square2", "mul", 1, {s1});
    g.add("square3_zero", "mul", 1, {s2});
    gs.push_back(g);
  }
  // Estimates without RTL: the other Horner degrees, the 16-segment table (the 1-D weight table
  // has RTL at N = 256, the 2-D table at N = 32, below).
  gs.push_back(horner("est_clip_horner_deg2", 2, false));
  gs.push_back(horner("est_clip_horner_deg4", 4, false));
  gs.push_back(horner("est_clip_seq_deg2", 2, true));
  {
    Graph g;
    g.name = "est_clip_tab16";
    g.description = "16-entry line table indexed by the top bits of a + one multiply-add";
    const int a = g.add("abs_clamp", "add", 0);
    const int r = g.add("seg_table", "rom", 0, {a});
    const int m = g.add("mul_c1", "mul", 1, {a, r});
    const int s = g.add("add_c0", "add", 0, {m});
    g.add("round_fold", "add", 1, {s});
    gs.push_back(g);
  }
  {
    Graph g;
    g.name = "weight_table_1d";
    g.description = "registered ROM read (2 entries per row), one lerp multiply, round";
    const int r = g.add("rom_read", "rom", 1);
    const int m = g.add("lerp_mul", "mul", 1, {r});
    g.add("add_round", "add", 1, {m});
    gs.push_back(g);
  }
  {
    Graph g;
    g.name = "weight_table_2d";
    g.description = "registered ROM read (4 cell corners per row), two x-lerp multiplies, "
                    "round + y-lerp multiply, round";
    const int r = g.add("rom_read", "rom", 1);
    const int m0 = g.add("lerp_x0", "mul", 1, {r});
    const int m1 = g.add("lerp_x1", "mul", 1, {r});
    const int m2 = g.add("lerp_y", "mul", 1, {m0, m1});
    g.add("add_round", "add", 1, {m2});
    gs.push_back(g);
  }
  return gs;
}
}  // namespace

const std::vector<sched::Graph>& schemes() {
  static const std::vector<sched::Graph> gs = build();
  return gs;
}

const sched::Graph& scheme(const std::string& name) { return sched::find(schemes(), name); }

}  // namespace tu::gauss
