// Cycle model of the Feline RTL engine (rtl/top/tu_feline.sv, docs/blocks/feline.md "RTL"):
// exact clock counts of its pixel stream with no back-pressure, from the C model's per-pixel
// probe count and level. The engine is a set-up unit and a prober joined by a one-record
// hand-over, then the EWA's normalisation:
//   set-up : accepted at a, record ready at a + S, S = 1 (B1 guard), 2 (N = 1), 3 + 2 I/U (N >= 2)
//   hand   : h = max(a + S, the previous pixel's last probe output); the set-up accepts again at h + 1
//   probes : one tu_trilinear pass each, P = 16 clocks (9 with one level: the lod at the top level,
//            or a guard pixel), back to back from h + 1: the last output at h + N P
//   output : 7 clocks after the last probe output (normalisation, 6 clocks, and the register;
//            guard: 1, the probe's colour as is), taken at once
// (I = EwaCordIter CORDIC iterations, U = iterations per clock: tu_feline CordUnroll.)
#pragma once

#include <cstdint>

namespace tu::feline {

inline constexpr int kProbeCycles = 16;     // tu_trilinear: accepted at t, output at t + 15, free at t + 16
inline constexpr int kProbeCyclesOne = 9;   // one level: output at t + 8
inline constexpr int kOutCycles = 7;        // last probe output -> pixel out (tu_ewa_normalise + register)
inline constexpr int kGuardOutCycles = 1;

struct PixelWork {
  int probes = 1;          // N (1 for a guard pixel)
  bool one_level = false;  // the probes blend one level (lod at the top, or guard)
  bool guard = false;      // B1 guard: one probe through tu_trilinear's guard pass
};

// Set-up clocks from acceptance to the record (tu_feline_setup); cord_unroll = CordUnroll.
int setup_cycles(const PixelWork& w, int cord_unroll = 2);

// The engine's state across a pixel stream (the texture unit's StreamModel holds one).
class EngineModel {
 public:
  explicit EngineModel(int cord_unroll = 2) : unroll_(cord_unroll) {}
  struct Times {
    uint64_t accept = 0, out = 0;
  };
  // Pixel w at the engine's input from cycle `ready` on.
  Times add(const PixelWork& w, uint64_t ready);

 private:
  int unroll_;
  uint64_t setup_free_ = 0, prober_free_ = 0;
};

}  // namespace tu::feline
