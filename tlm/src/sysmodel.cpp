// SystemC kernel side of the system model: Source -> Stage ... Stage over sc_fifos.
#include <systemc>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <deque>
#include <memory>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "sc_context.hpp"
#include "texunit/sysmodel.hpp"

namespace tu::sysmodel {

namespace {
using sc_core::sc_time;
using sc_core::SC_NS;
using sc_core::SC_ZERO_TIME;

const sc_time kClk(1, SC_NS);

uint64_t cycles(const sc_time& t) { return static_cast<uint64_t>(std::llround(t / kClk)); }

// A span (stage 0 up to the expanding stage) or a pixel (after it). `ready`: the earliest cycle
// the consumer may take it (the producer's handshake plus the link's registers).
struct Token {
  uint32_t idx = 0;
  bool span = false;
  sc_time ready;
  bool operator==(const Token& o) const { return idx == o.idx && span == o.span && ready == o.ready; }
};
std::ostream& operator<<(std::ostream& os, const Token& t) {
  return os << (t.span ? "span " : "pixel ") << t.idx;
}

struct Source : sc_core::sc_module {
  sc_core::sc_fifo_out<Token> out;
  const Workload& wl;
  SC_HAS_PROCESS(Source);
  Source(sc_core::sc_module_name n, const Workload& w) : sc_module(n), wl(w) { SC_THREAD(run); }
  void run() {
    for (uint32_t i = 0; i < wl.spans.size(); ++i) out.write(Token{i, true, SC_ZERO_TIME});
  }
};

// One block. Pipelines (capacity > 1): an accept thread (waits for room and input, issues an item
// every ii cycles) and an emit thread (hands each item downstream in order once its latency has
// passed, waiting for room). A one-item block does both in one thread (fewer context switches,
// the same times).
struct Stage : sc_core::sc_module {
  sc_core::sc_fifo_in<Token> in;
  sc_core::sc_fifo_out<Token> out;
  const StageSpec spec;
  const Workload& wl;
  BlockStats& st;
  sc_time next_link;  // registers between this stage and the next
  bool next_direct;   // the link to the next stage has no buffer
  bool last;          // the unit's output: nobody reads `out`, we count the pixels here
  uint64_t n_in, n_out;  // items it will accept and hand on: its threads return after them
  uint64_t delivered = 0, last_cycle = 0;
  std::deque<std::pair<Token, sc_time>> flight;
  sc_core::sc_event pushed, freed;

  SC_HAS_PROCESS(Stage);
  Stage(sc_core::sc_module_name n, const StageSpec& s, const Workload& w, BlockStats& stats,
        const StageSpec* next, uint64_t items_in, uint64_t items_out)
      : sc_module(n), spec(s), wl(w), st(stats),
        next_link((next ? next->link_latency : 0) * kClk), next_direct(next && next->direct),
        last(!next), n_in(items_in), n_out(items_out) {
    SC_THREAD(accept);
    if (spec.capacity > 1) SC_THREAD(emit);
  }

  void wait_until(const sc_time& t) {
    if (t > sc_core::sc_time_stamp()) wait(t - sc_core::sc_time_stamp());
  }

  // Latency and ii of one item; accounts it in the statistics.
  Timing account(const Token& t) {
    int lat = spec.lat0, ii = spec.ii0;
    if (!t.span) {
      const PixelWork& p = wl.pixels[t.idx];
      const auto w = static_cast<int>(work_of(p, spec.work));
      if (spec.relief_only && !p.relief) {
        lat = spec.bypass_latency, ii = 1;
      } else {
        if (spec.timing) {
          const Timing tm = spec.timing(p);
          lat = tm.latency, ii = tm.ii;
        } else {
          lat += spec.lat_per_work * w, ii += spec.ii_per_work * w;
        }
        st.work += static_cast<uint64_t>(w);
      }
    }
    ii = std::max(ii, 1);  // a block takes at most one item per clock
    ++st.items;
    st.busy += static_cast<uint64_t>(ii);
    return {lat, ii};
  }

  // Hands t downstream (the item's output handshake), then waits out the slot's release.
  void hand(Token t) {
    if (last) {
      // In order, one output per pixel: anything else is a model error, not a measurement.
      if (t.span || t.idx != delivered)
        throw std::logic_error("sysmodel: unit output " + std::string(t.span ? "span " : "pixel ") +
                               std::to_string(t.idx) + ", expected pixel " + std::to_string(delivered));
      ++delivered;
      last_cycle = cycles(sc_core::sc_time_stamp());
      return;
    }
    t.ready = sc_core::sc_time_stamp() + next_link;
    const sc_time t0 = sc_core::sc_time_stamp();
    out.write(t);
    // A direct link has no storage: the item is ours until the consumer has read it.
    while (next_direct && out->num_free() == 0) wait(out->data_read_event());
    st.stalled += cycles(sc_core::sc_time_stamp() - t0);
    if (spec.release > 0) wait(spec.release * kClk);
  }

  void issue(const Token& t) {
    const Timing tm = account(t);
    const sc_time start = sc_core::sc_time_stamp();
    if (spec.capacity == 1) {
      wait_until(start + tm.latency * kClk);
      hand(t);
    } else {
      while (static_cast<int>(flight.size()) >= spec.capacity) wait(freed);
      flight.emplace_back(t, start + tm.latency * kClk);
      pushed.notify();  // immediate: the emit thread re-checks the queue, nothing is lost
    }
    wait_until(start + tm.ii * kClk);
  }

  // Every thread returns once its items are through (no process is left blocked: a clean end,
  // and no coroutine frames are abandoned under AddressSanitizer).
  void accept() {
    for (uint64_t n = 0; n < n_in; ++n) {
      while (static_cast<int>(flight.size()) >= spec.capacity) wait(freed);
      const sc_time t0 = sc_core::sc_time_stamp();
      Token t = in.read();
      wait_until(t.ready);
      st.starved += cycles(sc_core::sc_time_stamp() - t0);
      if (spec.expand && t.span) {
        const Span& s = wl.spans[t.idx];
        for (uint32_t k = 0; k < s.count; ++k) {
          while (static_cast<int>(flight.size()) >= spec.capacity) wait(freed);
          issue(Token{s.first + k, false, SC_ZERO_TIME});
        }
      } else {
        issue(t);
      }
    }
  }

  void emit() {
    for (uint64_t n = 0; n < n_out; ++n) {
      while (flight.empty()) wait(pushed);
      wait_until(flight.front().second);
      hand(flight.front().first);
      flight.pop_front();
      freed.notify();
    }
  }
};

void validate(const Pipeline& p, const Workload& w) {
  if (p.stages.empty()) throw std::invalid_argument(p.name + ": pipeline has no stages");
  int expanders = 0;
  for (const auto& s : p.stages) {
    const std::string where = p.name + ": stage '" + s.name + "': ";
    if (s.capacity < 1) throw std::invalid_argument(where + "capacity must be >= 1");
    if (s.fifo_depth < 1) throw std::invalid_argument(where + "fifo_depth must be >= 1");
    if (s.direct && s.fifo_depth != 1) throw std::invalid_argument(where + "a direct link has fifo_depth 1");
    if (s.ii0 < 0 || s.lat0 < 0 || s.lat_per_work < 0 || s.ii_per_work < 0 || s.link_latency < 0 ||
        s.bypass_latency < 0 || s.release < 0)
      throw std::invalid_argument(where + "negative latency or ii");
    expanders += s.expand ? 1 : 0;
  }
  if (expanders != 1) throw std::invalid_argument(p.name + ": exactly one stage must expand spans");
  uint64_t n = 0;
  for (const auto& s : w.spans) {
    if (s.count == 0 || s.first != n) throw std::invalid_argument("workload: spans must be non-empty and consecutive");
    n += s.count;
  }
  if (n != w.pixels.size()) throw std::invalid_argument("workload: span pixels != pixel records");
}

}  // namespace

uint32_t work_of(const PixelWork& w, Work kind) {
  switch (kind) {
    case Work::None: return 0;
    case Work::Texels: return w.texels;
    case Work::Levels: return w.levels;
    case Work::Steps: return w.steps;
  }
  return 0;
}

Result simulate(const Pipeline& p, const Workload& w) {
  validate(p, w);
  Result r;
  r.pixels = w.pixels.size();
  r.blocks.resize(p.stages.size());
  for (size_t i = 0; i < p.stages.size(); ++i) r.blocks[i].name = p.stages[i].name;
  size_t expander = 0;
  while (!p.stages[expander].expand) ++expander;
  Context ctx;
  {
    std::vector<std::unique_ptr<sc_core::sc_fifo<Token>>> fifos;
    std::vector<std::unique_ptr<Stage>> stages;
    Source src("source", w);
    for (size_t i = 0; i < p.stages.size(); ++i)
      fifos.push_back(std::make_unique<sc_core::sc_fifo<Token>>(
          ("fifo_" + p.stages[i].name).c_str(), p.stages[i].fifo_depth));
    // Bound only to satisfy the port: the last stage counts its outputs instead of writing them.
    fifos.push_back(std::make_unique<sc_core::sc_fifo<Token>>("fifo_out", 1));
    src.out(*fifos[0]);
    for (size_t i = 0; i < p.stages.size(); ++i) {
      const StageSpec* next = i + 1 < p.stages.size() ? &p.stages[i + 1] : nullptr;
      // Spans up to the expanding stage, pixels from its output on.
      const uint64_t n_in = i <= expander ? w.spans.size() : w.pixels.size();
      const uint64_t n_out = i < expander ? w.spans.size() : w.pixels.size();
      stages.push_back(std::make_unique<Stage>(p.stages[i].name.c_str(), p.stages[i], w, r.blocks[i], next,
                                               n_in, n_out));
      stages.back()->in(*fifos[i]);
      stages.back()->out(*fifos[i + 1]);
    }
    const auto t0 = std::chrono::steady_clock::now();
    sc_core::sc_start();  // runs until no process can move: every pixel has left the unit
    r.sim_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const Stage& out = *stages.back();
    if (out.delivered != w.pixels.size())
      throw std::logic_error("sysmodel: " + std::to_string(out.delivered) + " of " +
                             std::to_string(w.pixels.size()) + " pixels left the unit");
    r.total_cycles = out.last_cycle;
  }
  return r;
}

std::string table(const Result& r) {
  std::ostringstream os;
  char buf[200];
  std::snprintf(buf, sizeof buf, "%-16s %9s %10s %7s %10s %10s %12s\n", "block", "items", "busy",
                "util%", "stalled", "starved", "work");
  os << buf;
  for (const auto& b : r.blocks) {
    const double u = r.total_cycles ? 100.0 * static_cast<double>(b.busy) / static_cast<double>(r.total_cycles) : 0;
    std::snprintf(buf, sizeof buf, "%-16s %9llu %10llu %7.2f %10llu %10llu %12llu\n", b.name.c_str(),
                  static_cast<unsigned long long>(b.items), static_cast<unsigned long long>(b.busy), u,
                  static_cast<unsigned long long>(b.stalled), static_cast<unsigned long long>(b.starved),
                  static_cast<unsigned long long>(b.work));
    os << buf;
  }
  std::snprintf(buf, sizeof buf, "total %llu cycles for %llu pixels (%.3f cycles/pixel), SystemC %.3f s\n",
                static_cast<unsigned long long>(r.total_cycles), static_cast<unsigned long long>(r.pixels),
                r.pixels ? static_cast<double>(r.total_cycles) / static_cast<double>(r.pixels) : 0.0,
                r.sim_seconds);
  os << buf;
  return os.str();
}

nlohmann::json to_json(const Result& r) {
  nlohmann::json j;
  j["total_cycles"] = r.total_cycles;
  j["pixels"] = r.pixels;
  j["sim_seconds"] = r.sim_seconds;
  for (const auto& b : r.blocks) {
    j["blocks"].push_back({{"name", b.name}, {"items", b.items}, {"busy", b.busy},
                           {"utilisation", r.total_cycles ? static_cast<double>(b.busy) / static_cast<double>(r.total_cycles) : 0.0},
                           {"stalled", b.stalled}, {"starved", b.starved}, {"work", b.work}});
  }
  return j;
}

}  // namespace tu::sysmodel
