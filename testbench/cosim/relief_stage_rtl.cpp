// RTL binding of the relief stage (rtl/pom/tu_relief_stage.sv, Verilated as the top with SideW 20):
// its depth RAM is a SyncReadRam on d_* (1 << 21 words, the low 8 bits on d_data_i), and its view
// stream is offered beside the pixel: the pixel's view word is driven with it, and view_valid_i
// follows in_valid_i for relief pixels unless a random bubble holds it back, so the stage sees
// pixels waiting for their view word (the view word is accepted with its pixel: the scoreboard
// checks that through in_ready_o).
#include "relief_stage_rtl.hpp"

#include <memory>
#include <random>

#include "Vtu_relief_stage.h"
#include "harness.hpp"
#include "sync_read_ram.hpp"

namespace tu::cosim {

namespace {
constexpr uint32_t kSideMask = (1u << 20) - 1;  // the model's SideW (testbench/cosim/CMakeLists.txt)
constexpr uint64_t kRamWords = uint64_t(1) << 21;  // depth RAM (the default scene with its distance map: 1,114,112)

int64_t sext32(uint64_t x) { return static_cast<int32_t>(static_cast<uint32_t>(x)); }
}  // namespace

ReliefRun run_relief_stage(const std::vector<ReliefPixel>& px, const std::vector<uint32_t>& ram,
                           double stall_prob, double view_bubble_prob, uint64_t seed) {
  // The harness's input row is the pixel's index (it rides on the side port too).
  std::vector<size_t> rows(px.size());
  for (size_t i = 0; i < px.size(); ++i) rows[i] = i;
  std::mt19937_64 rng(seed ^ 0x5eedf00dull);
  std::bernoulli_distribution bubble(view_bubble_prob);
  bool held = false;  // this cycle's view word held back
  auto drive = [&](Vtu_relief_stage& d, size_t i) {
    const ReliefPixel& p = px[i];
    d.u_i = static_cast<uint32_t>(p.u);
    d.v_i = static_cast<uint32_t>(p.v);
    d.lw_i = static_cast<uint8_t>(p.lw);
    d.lh_i = static_cast<uint8_t>(p.lh);
    d.rel_i = p.rel;
    d.guard_i = p.guard;
    d.adaptive_i = p.adaptive;
    d.iter_i = p.iter;
    d.layers_i = static_cast<uint8_t>(p.layers);
    d.scale_i = static_cast<uint16_t>(p.scale);
    d.hbase_i = p.hbase;
    d.hlw_i = static_cast<uint8_t>(p.hlw);
    d.hlh_i = static_cast<uint8_t>(p.hlh);
    d.side_i = static_cast<uint32_t>(i & kSideMask);
    d.view_ok_i = p.ok;
    d.vx_i = static_cast<uint16_t>(p.view.vx);
    d.vy_i = static_cast<uint16_t>(p.view.vy);
    d.vz_i = static_cast<uint16_t>(p.view.vz);
    d.vc_i = static_cast<uint8_t>(p.vc);
    d.dm_i = p.dm;
    d.dlayers_i = static_cast<uint8_t>(p.dlayers);
    d.dbase_i = p.dbase;
    held = view_bubble_prob > 0 && bubble(rng);
  };
  auto sample = [](Vtu_relief_stage& d) {
    return ReliefOut{.u = sext32(d.u_o), .v = sext32(d.v_o), .n = d.n_o, .steps = d.steps_o, .flags = d.flags_o,
                     .index = d.side_o};
  };
  auto env = [&, image = std::make_shared<const SyncReadRam::Image>(ram)]() {
    Env<Vtu_relief_stage> e;
    e.settle.push_back([&](Vtu_relief_stage& d) { d.view_valid_i = d.in_valid_i && d.rel_i && !held; });
    attach_ram<Vtu_relief_stage>(e, std::make_shared<SyncReadRam>(image, kRamWords, 1, fmt::kTexAddrW, 8),
                                 [](Vtu_relief_stage& d) -> auto& { return d.d_req_o; },
                                 [](Vtu_relief_stage& d) -> auto& { return d.d_addr_o; },
                                 [](Vtu_relief_stage& d) -> auto& { return d.d_data_i; });
    return e;
  };
  Harness<Vtu_relief_stage, size_t, ReliefOut> h(drive, sample, env);
  RunOptions o;
  o.stall_prob = stall_prob;
  o.seed = seed;
  auto rr = h.run(rows, o);
  ReliefRun res;
  res.cycles = rr.sim_cycles;
  res.accepted = rr.accepted;
  res.extra_outputs = rr.extra_outputs;
  res.hung = rr.hung;
  res.out = std::move(rr.outputs);
  return res;
}

}  // namespace tu::cosim
