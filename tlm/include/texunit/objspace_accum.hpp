// SystemC model of the object-space pipeline's sample stream and pixel-buffer accumulation
// (docs/blocks/objspace.md "Accumulation: structural scheme"). Timing only: what each sample
// adds is the bit-accurate C model's (objspace::render_cmodel); this model says how many clocks
// the stream takes for a given structure:
//   S lanes of the per-sample datapath (tu_objspace_sample, latency L, II 1) take up to S samples
//   per clock, in order; the pixel buffer is banked by (x mod BankX, y mod BankY), each bank one
//   read-modify-write per clock (pipelined, with forwarding); a sample writes its four pixels
//   (x, y) .. (x + 1, y + 1), so a clock's samples must use disjoint banks: the issue stage stops
//   a clock's group at the first sample that would reuse a bank (a conflict clock) or at S.
//   BankX, BankY >= 2 so that one sample never conflicts with itself. After the last sample, a
//   resolve pass divides each covered pixel (I = sum w c / sum w), `resolve_per_clock` pixels per
//   clock, latency `resolve_latency`.
// Cycle 0 is the cycle the first sample is issued; the total is the cycle the last pixel is
// resolved. With S = 1 the stream takes exactly samples + L clocks (no conflict is possible): the
// figure the Verilator run of tu_objspace_sample measures (testbench/cosim/objspace_cosim_test.cpp).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace tu::sysmodel {

struct AccumScheme {
  int lanes = 1;              // S: samples per clock
  int bank_x = 2, bank_y = 2; // pixel-buffer banks per axis: powers of two, 2..8
  int datapath_latency = 0;   // L (objspace::sample_scheme)
  int resolve_per_clock = 1;  // normalising dividers
  int resolve_latency = 0;
  std::string name() const;   // e.g. "S=2, banks 4x2"
};

// One sample as the timing needs it: the low three bits of its top-left pixel x, y and the guard
// (a guarded sample takes a lane, writes nothing). One byte per sample: the default scene's
// 73 M samples fit in 73 MB.
struct AccumSample {
  uint8_t code = 0;  // bits 0-2: x mod 8, bits 3-5: y mod 8, bit 6: guard
  static AccumSample of(int64_t x, int64_t y, bool guard) {
    return {static_cast<uint8_t>((x & 7) | ((y & 7) << 3) | (guard ? 64 : 0))};
  }
};

struct AccumResult {
  uint64_t samples = 0;
  uint64_t issue_clocks = 0;     // clocks with at least one sample issued
  uint64_t conflict_clocks = 0;  // groups cut short by a bank conflict (fewer than S samples, more waiting)
  uint64_t stream_cycles = 0;    // cycle the last sample's bank writes are done
  uint64_t resolve_cycles = 0;   // the resolve pass
  uint64_t total_cycles = 0;
  double sim_seconds = 0;
};

// The SystemC simulation (a fresh context per call); throws std::invalid_argument on a malformed
// scheme (lanes < 1, banks not a power of two in 2..8, ...).
AccumResult simulate_accumulation(const AccumScheme& s, const std::vector<AccumSample>& samples,
                                  uint64_t covered_pixels);
// The same figure without SystemC (the structural estimate the SystemC run is tested against).
AccumResult estimate_accumulation(const AccumScheme& s, const std::vector<AccumSample>& samples,
                                  uint64_t covered_pixels);

}  // namespace tu::sysmodel
