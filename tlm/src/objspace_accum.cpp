// SystemC model of the object-space sample stream and pixel-buffer accumulation
// (texunit/objspace_accum.hpp): issue (S lanes, bank-conflict-free groups) -> datapath latency ->
// bank writes -> resolve pass.
#include "texunit/objspace_accum.hpp"

#include <systemc>

#include <chrono>
#include <stdexcept>

#include "sc_context.hpp"

namespace tu::sysmodel {

namespace {
using sc_core::sc_time;
using sc_core::SC_NS;
const sc_time kClk(1, SC_NS);
constexpr std::size_t kStack = std::size_t(1) << 20;  // thread stacks (the ASan build's frames are large)
uint64_t cycles(const sc_time& t) { return static_cast<uint64_t>(std::llround(t / kClk)); }

bool pow2_in_range(int b) { return b >= 2 && b <= 8 && (b & (b - 1)) == 0; }
void validate(const AccumScheme& s) {
  if (s.lanes < 1 || s.lanes > 64) throw std::invalid_argument("accumulation scheme: lanes must be 1..64");
  if (!pow2_in_range(s.bank_x) || !pow2_in_range(s.bank_y))
    throw std::invalid_argument("accumulation scheme: banks per axis must be 2, 4 or 8");
  if (s.datapath_latency < 0 || s.resolve_latency < 0 || s.resolve_per_clock < 1)
    throw std::invalid_argument("accumulation scheme: negative latency or no divider");
}

// The four banks a sample writes, as a bit mask over bank_x * bank_y banks (0: guarded).
uint64_t bank_mask(const AccumScheme& s, AccumSample a) {
  if (a.code & 64) return 0;
  const int x = a.code & 7, y = (a.code >> 3) & 7;
  uint64_t m = 0;
  for (int dy = 0; dy < 2; ++dy)
    for (int dx = 0; dx < 2; ++dx)
      m |= uint64_t(1) << (((y + dy) % s.bank_y) * s.bank_x + (x + dx) % s.bank_x);
  return m;
}

// The issue rule: the samples [pos, end) one clock takes, and whether a bank conflict cut it short.
size_t next_group(const AccumScheme& s, const std::vector<AccumSample>& v, size_t pos, bool* conflict) {
  uint64_t used = 0;
  size_t end = pos;
  *conflict = false;
  while (end < v.size() && end - pos < static_cast<size_t>(s.lanes)) {
    const uint64_t m = bank_mask(s, v[end]);
    if (used & m) {
      *conflict = true;
      break;
    }
    used |= m;
    ++end;
  }
  return end;
}

uint64_t resolve_cycles(const AccumScheme& s, uint64_t covered) {
  const uint64_t r = static_cast<uint64_t>(s.resolve_per_clock);
  return (covered + r - 1) / r + static_cast<uint64_t>(s.resolve_latency);
}

struct Group {
  uint64_t samples = 0;
  sc_time issued;
  bool operator==(const Group& o) const { return samples == o.samples && issued == o.issued; }
};
std::ostream& operator<<(std::ostream& os, const Group& g) { return os << g.samples << " samples"; }

// Issue stage: the S datapath lanes' input, one group of conflict-free samples per clock.
struct Issue : sc_core::sc_module {
  sc_core::sc_fifo_out<Group> out;
  const AccumScheme& s;
  const std::vector<AccumSample>& v;
  AccumResult& r;
  SC_HAS_PROCESS(Issue);
  Issue(sc_core::sc_module_name n, const AccumScheme& sc, const std::vector<AccumSample>& samples, AccumResult& res)
      : sc_module(n), s(sc), v(samples), r(res) {
    SC_THREAD(run);
    set_stack_size(kStack);
  }
  void run() {
    for (size_t pos = 0; pos < v.size();) {
      bool conflict = false;
      const size_t end = next_group(s, v, pos, &conflict);
      r.conflict_clocks += conflict;
      ++r.issue_clocks;
      out.write(Group{end - pos, sc_core::sc_time_stamp()});
      pos = end;
      wait(kClk);
    }
  }
};

// Datapath latency + bank writes, then the resolve pass over the covered pixels.
struct Accumulate : sc_core::sc_module {
  sc_core::sc_fifo_in<Group> in;
  const AccumScheme& s;
  uint64_t total, covered;
  AccumResult& r;
  SC_HAS_PROCESS(Accumulate);
  Accumulate(sc_core::sc_module_name n, const AccumScheme& sc, uint64_t samples, uint64_t cov, AccumResult& res)
      : sc_module(n), s(sc), total(samples), covered(cov), r(res) {
    SC_THREAD(run);
    set_stack_size(kStack);
  }
  void wait_until(const sc_time& t) {
    if (t > sc_core::sc_time_stamp()) wait(t - sc_core::sc_time_stamp());
  }
  void run() {
    uint64_t done = 0;
    while (done < total) {
      const Group g = in.read();
      wait_until(g.issued + s.datapath_latency * kClk);  // the lanes' outputs reach the banks
      done += g.samples;
      r.samples += g.samples;
    }
    r.stream_cycles = total ? cycles(sc_core::sc_time_stamp()) + 1 : 0;  // clocks 0 .. last write
    // Resolve: resolve_per_clock pixels a clock from the next clock on, each done after the latency.
    const uint64_t per = static_cast<uint64_t>(s.resolve_per_clock);
    for (uint64_t p = 0; p < covered; p += per) wait(kClk);
    wait(s.resolve_latency * kClk);
    r.resolve_cycles = cycles(sc_core::sc_time_stamp()) + (total ? 1 : 0) - r.stream_cycles;
    r.total_cycles = r.stream_cycles + r.resolve_cycles;
  }
};
}  // namespace

std::string AccumScheme::name() const {
  return "S=" + std::to_string(lanes) + ", banks " + std::to_string(bank_x) + "x" + std::to_string(bank_y);
}

AccumResult estimate_accumulation(const AccumScheme& s, const std::vector<AccumSample>& v, uint64_t covered) {
  validate(s);
  AccumResult r;
  r.samples = v.size();
  for (size_t pos = 0; pos < v.size();) {
    bool conflict = false;
    pos = next_group(s, v, pos, &conflict);
    ++r.issue_clocks;
    r.conflict_clocks += conflict;
  }
  r.stream_cycles = v.empty() ? 0 : r.issue_clocks + static_cast<uint64_t>(s.datapath_latency);
  r.resolve_cycles = resolve_cycles(s, covered);
  r.total_cycles = r.stream_cycles + r.resolve_cycles;
  return r;
}

AccumResult simulate_accumulation(const AccumScheme& s, const std::vector<AccumSample>& v, uint64_t covered) {
  validate(s);
  AccumResult r;
  Context ctx;
  {
    sc_core::sc_fifo<Group> link("lanes", s.datapath_latency + 2);  // the lanes' pipeline registers
    Issue issue("issue", s, v, r);
    Accumulate acc("accumulate", s, v.size(), covered, r);
    issue.out(link);
    acc.in(link);
    const auto t0 = std::chrono::steady_clock::now();
    sc_core::sc_start();
    r.sim_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  if (r.samples != v.size()) throw std::logic_error("accumulation model: not every sample reached the banks");
  return r;
}

}  // namespace tu::sysmodel
