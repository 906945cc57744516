// Verilator co-simulation harness shared by every block.
//
// The DUT has the uniform handshake ports clk_i, rst_ni, in_valid_i, in_ready_o, out_valid_o,
// out_ready_i; a block supplies `drive` (put one input row on its data ports) and `sample`
// (read one output row). A row is a vector of fields (Row, a vector file's row) by default, or
// the block's own record type with named fields (Harness<V, In, Out>). The harness:
//   * holds in_valid and the data until accepted (valid/ready rule), inserting random input
//     bubbles and random output back-pressure with probability stall_prob each;
//   * keeps a scoreboard: each output is paired with the oldest accepted input not yet answered,
//     so it proves one output per input, in order, nothing lost and nothing duplicated (extra
//     outputs during the drain phase are counted as errors);
//   * counts cycles, and measures latency and II on a stall-free prefix.
// What a block's bench adds around it (a RAM on its read ports: sync_read_ram.hpp; an input that
// follows other inputs) is C++ too, in the optional Env: the block itself is the Verilator top.
#pragma once

#include <verilated.h>
#include <verilated_fst_c.h>

#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace tu::cosim {

using Row = std::vector<uint64_t>;

struct RunOptions {
  double stall_prob = 0.3;
  uint64_t seed = 1;
  std::string fst_path;        // empty: no waveform
  uint64_t max_idle = 100000;  // cycles without progress before declaring a hang
  uint64_t drain_cycles = 64;  // extra cycles after the last output, watching for extras
  // No eval at the falling clock edge (without a waveform): it only propagates what the update
  // hooks drove after the rising edge (RAM read data, stream words), which the next cycle's
  // pre-edge eval propagates anyway, so the outputs and cycles are the same; for a DUT with no
  // negedge-clk logic (the texture unit: docs/performance.md section 10).
  bool skip_fall_eval = false;
};

template <class Out = Row>
struct BasicRunResult {
  std::vector<Out> outputs;      // in arrival order
  uint64_t accepted = 0;         // inputs accepted
  uint64_t extra_outputs = 0;    // outputs with no pending input (duplicates / spurious)
  uint64_t sim_cycles = 0;       // cycles from reset release to the last output
  bool hung = false;
};
using RunResult = BasicRunResult<Row>;

// The C++ surroundings of a block (what a simulation wrapper around it would hold), fresh for every
// run. The harness calls, on every clock and every evaluation:
//   settle(d)  before each eval: inputs that follow other inputs combinationally;
//   edge(d)    just before each rising clock edge, on the ports as evaluated for this cycle (what a
//              register samples: e.g. a RAM's read enable and address);
//   update(d)  just after the edge: registered values onto the block's inputs (the RAM's read data;
//              the clock's falling-edge eval propagates them, so they cost no extra eval).
template <class V>
struct Env {
  std::vector<std::function<void(V&)>> settle, edge, update;
};

template <class V, class In = Row, class Out = Row>
class Harness {
 public:
  using Drive = std::function<void(V&, const In&)>;
  using Sample = std::function<Out(V&)>;
  // The block's surroundings, built afresh for each run (Env); what they hold (a RAM's image, a
  // stream's words) is there from the start: no clock is spent loading it.
  using MakeEnv = std::function<Env<V>()>;

  Harness(Drive drive, Sample sample, MakeEnv make_env = {})
      : drive_(std::move(drive)), sample_(std::move(sample)), make_env_(std::move(make_env)) {}

  // fanout[i] (default 1): outputs input i produces (e.g. the pixels of a span).
  BasicRunResult<Out> run(const std::vector<In>& inputs, const RunOptions& opt,
                          const std::vector<uint64_t>& fanout = {}) {
    uint64_t expected = inputs.size();
    if (!fanout.empty()) {
      expected = 0;
      for (uint64_t n : fanout) expected += n;
    }
    auto ctx = std::make_unique<VerilatedContext>();
    ctx->traceEverOn(!opt.fst_path.empty());
    V dut(ctx.get());
    std::unique_ptr<VerilatedFstC> tfp;
    if (!opt.fst_path.empty()) {
      // Models carry tracing only where configured (testbench/cosim/CMakeLists.txt TU_COSIM_TRACE).
      if constexpr (requires(VerilatedFstC* f) { dut.trace(f, 99); }) {
        tfp = std::make_unique<VerilatedFstC>();
        dut.trace(tfp.get(), 99);
        tfp->open(opt.fst_path.c_str());
      } else {
        throw std::invalid_argument("--fst: this block's co-simulation model is built without FST tracing; "
                                    "reconfigure with cmake --preset default -DTU_COSIM_TRACE=ON");
      }
    }
    const Env<V> env = make_env_ ? make_env_() : Env<V>{};
    auto eval = [&]() {
      for (const auto& f : env.settle) f(dut);
      dut.eval();
    };
    uint64_t t = 0;
    auto tick = [&]() {
      for (const auto& f : env.edge) f(dut);
      dut.clk_i = 1;
      eval();
      for (const auto& f : env.update) f(dut);
      if (tfp) {
        if (!env.update.empty()) eval();  // the waveform shows the registered values propagated
        tfp->dump(t * 10 + 5);
      }
      dut.clk_i = 0;
      if (tfp || !opt.skip_fall_eval) eval();
      if (tfp) tfp->dump(t * 10 + 10);
      ++t;
    };
    // Reset.
    dut.clk_i = 0;
    dut.rst_ni = 0;
    dut.in_valid_i = 0;
    dut.out_ready_i = 0;
    if (!inputs.empty()) drive_(dut, inputs[0]);
    eval();
    for (int i = 0; i < 4; ++i) tick();
    dut.rst_ni = 1;
    eval();

    std::mt19937_64 rng(opt.seed);
    std::bernoulli_distribution stall(opt.stall_prob);
    BasicRunResult<Out> res;
    res.outputs.reserve(expected);
    size_t next = 0;        // next input to offer
    uint64_t pending = 0;   // accepted, not yet answered
    bool offering = false;  // in_valid held high for inputs[next]
    uint64_t idle = 0;
    const uint64_t t0 = t;
    while (res.outputs.size() < expected) {
      // Decide this cycle's input offer: once offered, hold until accepted.
      if (!offering && next < inputs.size() && !stall(rng)) offering = true;
      dut.in_valid_i = offering ? 1 : 0;
      if (offering) drive_(dut, inputs[next]);
      dut.out_ready_i = stall(rng) ? 0 : 1;
      eval();
      const bool fire_in = offering && dut.in_ready_o;
      const bool fire_out = dut.out_valid_o && dut.out_ready_i;
      Out out{};
      if (fire_out) out = sample_(dut);
      tick();
      bool progress = false;
      if (fire_in) {
        pending += fanout.empty() ? 1 : fanout[next];
        ++next;
        offering = false;
        progress = true;
      }
      if (fire_out) {
        if (pending == 0) ++res.extra_outputs;
        else --pending;
        res.outputs.push_back(std::move(out));
        progress = true;
      }
      idle = progress ? 0 : idle + 1;
      if (idle > opt.max_idle) {
        res.hung = true;
        break;
      }
    }
    res.sim_cycles = t - t0;
    // Drain: nothing more may come out.
    dut.in_valid_i = 0;
    dut.out_ready_i = 1;
    for (uint64_t i = 0; i < opt.drain_cycles; ++i) {
      eval();
      if (dut.out_valid_o) ++res.extra_outputs;
      tick();
    }
    res.accepted = next;
    if (tfp) tfp->close();
    dut.final();
    return res;
  }

  // Latency (acceptance to output, in cycles) and II (cycles between acceptances) with no stalls.
  std::pair<uint64_t, double> measure_timing(const std::vector<In>& inputs) {
    auto ctx = std::make_unique<VerilatedContext>();
    V dut(ctx.get());
    const Env<V> env = make_env_ ? make_env_() : Env<V>{};
    auto eval = [&]() {
      for (const auto& f : env.settle) f(dut);
      dut.eval();
    };
    auto tick = [&]() {
      for (const auto& f : env.edge) f(dut);
      dut.clk_i = 1;
      eval();
      for (const auto& f : env.update) f(dut);
      dut.clk_i = 0;
      eval();
    };
    dut.clk_i = 0;
    dut.rst_ni = 0;
    dut.in_valid_i = 0;
    dut.out_ready_i = 1;
    if (!inputs.empty()) drive_(dut, inputs[0]);
    eval();
    for (int i = 0; i < 4; ++i) tick();
    dut.rst_ni = 1;
    eval();
    uint64_t cyc = 0, first_accept = 0, last_accept = 0, first_out = 0;
    size_t next = 0, outs = 0;
    bool got_first_out = false;
    while (outs < inputs.size() && cyc < 1000000) {
      dut.in_valid_i = next < inputs.size();
      if (next < inputs.size()) drive_(dut, inputs[next]);
      dut.out_ready_i = 1;
      eval();
      const bool fire_in = dut.in_valid_i && dut.in_ready_o;
      const bool fire_out = dut.out_valid_o;
      tick();
      if (fire_in) {
        if (next == 0) first_accept = cyc;
        last_accept = cyc;
        ++next;
      }
      if (fire_out) {
        if (!got_first_out) first_out = cyc;
        got_first_out = true;
        ++outs;
      }
      ++cyc;
    }
    dut.final();
    const double ii = next > 1 ? static_cast<double>(last_accept - first_accept) / (next - 1) : 1;
    return {first_out - first_accept, ii};
  }

 private:
  Drive drive_;
  Sample sample_;
  MakeEnv make_env_;
};

}  // namespace tu::cosim
