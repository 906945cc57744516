// RTL binding of the relief stage (rtl/pom/tu_relief_stage.sv, Verilated as the top with SideW 20):
// its depth RAM is a SyncReadRam on d_* (1 << 21 words, the low 8 bits on d_data_i), and its view
// stream is offered beside the pixel: the row carries the pixel's view word, and view_valid_i
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
enum Col { kU, kV, kLw, kLh, kRel, kGuard, kAdaptive, kIter, kLayers, kScale, kHbase, kHlw, kHlh, kSide,
           kOk, kVx, kVy, kVz, kVc, kDm, kDlayers, kDbase, kCols };
constexpr uint32_t kSideMask = (1u << 20) - 1;  // the model's SideW (testbench/cosim/CMakeLists.txt)
constexpr uint64_t kRamWords = uint64_t(1) << 21;  // depth RAM (the default scene with its distance map: 1,114,112)

int64_t sext32(uint64_t x) { return static_cast<int32_t>(static_cast<uint32_t>(x)); }
}  // namespace

ReliefRun run_relief_stage(const std::vector<ReliefPixel>& px, const std::vector<uint32_t>& ram,
                           double stall_prob, double view_bubble_prob, uint64_t seed) {
  std::vector<Row> rows;
  for (size_t i = 0; i < px.size(); ++i) {
    const auto& p = px[i];
    Row r(kCols);
    r[kU] = static_cast<uint32_t>(p.u);
    r[kV] = static_cast<uint32_t>(p.v);
    r[kLw] = static_cast<uint64_t>(p.lw);
    r[kLh] = static_cast<uint64_t>(p.lh);
    r[kRel] = p.rel;
    r[kGuard] = p.guard;
    r[kAdaptive] = p.adaptive;
    r[kIter] = p.iter;
    r[kLayers] = static_cast<uint64_t>(p.layers);
    r[kScale] = p.scale;
    r[kHbase] = p.hbase;
    r[kHlw] = static_cast<uint64_t>(p.hlw);
    r[kHlh] = static_cast<uint64_t>(p.hlh);
    r[kSide] = i & kSideMask;
    r[kOk] = p.ok;
    r[kVx] = static_cast<uint16_t>(p.view.vx);
    r[kVy] = static_cast<uint16_t>(p.view.vy);
    r[kVz] = static_cast<uint16_t>(p.view.vz);
    r[kVc] = p.vc;
    r[kDm] = p.dm;
    r[kDlayers] = static_cast<uint64_t>(p.dlayers);
    r[kDbase] = p.dbase;
    rows.push_back(std::move(r));
  }
  std::mt19937_64 rng(seed ^ 0x5eedf00dull);
  std::bernoulli_distribution bubble(view_bubble_prob);
  bool held = false;  // this cycle's view word held back
  auto drive = [&](Vtu_relief_stage& d, const Row& r) {
    d.u_i = static_cast<uint32_t>(r[kU]);
    d.v_i = static_cast<uint32_t>(r[kV]);
    d.lw_i = static_cast<uint8_t>(r[kLw]);
    d.lh_i = static_cast<uint8_t>(r[kLh]);
    d.rel_i = static_cast<uint8_t>(r[kRel]);
    d.guard_i = static_cast<uint8_t>(r[kGuard]);
    d.adaptive_i = static_cast<uint8_t>(r[kAdaptive]);
    d.iter_i = static_cast<uint8_t>(r[kIter]);
    d.layers_i = static_cast<uint8_t>(r[kLayers]);
    d.scale_i = static_cast<uint16_t>(r[kScale]);
    d.hbase_i = static_cast<uint32_t>(r[kHbase]);
    d.hlw_i = static_cast<uint8_t>(r[kHlw]);
    d.hlh_i = static_cast<uint8_t>(r[kHlh]);
    d.side_i = static_cast<uint32_t>(r[kSide]);
    d.view_ok_i = static_cast<uint8_t>(r[kOk]);
    d.vx_i = static_cast<uint16_t>(r[kVx]);
    d.vy_i = static_cast<uint16_t>(r[kVy]);
    d.vz_i = static_cast<uint16_t>(r[kVz]);
    d.vc_i = static_cast<uint8_t>(r[kVc]);
    d.dm_i = static_cast<uint8_t>(r[kDm]);
    d.dlayers_i = static_cast<uint8_t>(r[kDlayers]);
    d.dbase_i = static_cast<uint32_t>(r[kDbase]);
    held = view_bubble_prob > 0 && bubble(rng);
  };
  auto sample = [](Vtu_relief_stage& d) { return Row{d.u_o, d.v_o, d.n_o, d.side_o, d.steps_o, d.flags_o}; };
  auto env = [&, image = std::make_shared<const SyncReadRam::Image>(ram)]() {
    Env<Vtu_relief_stage> e;
    e.settle.push_back([&](Vtu_relief_stage& d) { d.view_valid_i = d.in_valid_i && d.rel_i && !held; });
    attach_ram<Vtu_relief_stage>(e, std::make_shared<SyncReadRam>(image, kRamWords, 1, fmt::kTexAddrW, 8),
                                 [](Vtu_relief_stage& d) -> auto& { return d.d_req_o; },
                                 [](Vtu_relief_stage& d) -> auto& { return d.d_addr_o; },
                                 [](Vtu_relief_stage& d) -> auto& { return d.d_data_i; });
    return e;
  };
  Harness<Vtu_relief_stage> h(drive, sample, {}, env);
  RunOptions o;
  o.stall_prob = stall_prob;
  o.seed = seed;
  const auto rr = h.run(rows, o);
  ReliefRun res;
  res.cycles = rr.sim_cycles;
  res.accepted = rr.accepted;
  res.extra_outputs = rr.extra_outputs;
  res.hung = rr.hung;
  for (const Row& q : rr.outputs)
    res.out.push_back({sext32(q[0]), sext32(q[1]), static_cast<uint32_t>(q[2]), static_cast<uint32_t>(q[4]),
                       static_cast<uint32_t>(q[5]), static_cast<uint32_t>(q[3])});
  return res;
}

}  // namespace tu::cosim
