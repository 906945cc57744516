#include "feline/feline_cycles.hpp"

#include <algorithm>

#include "texunit/formats.hpp"

namespace tu::feline {

int setup_cycles(const PixelWork& w, int cord_unroll) {
  if (w.guard) return 1;          // ACCEPT -> HAND
  if (w.probes <= 1) return 2;    // ACCEPT PRE -> HAND: no line
  return 3 + 2 * (fmt::kEwaCordIter / cord_unroll);  // ACCEPT PRE, the CORDIC, the half step
}

EngineModel::Times EngineModel::add(const PixelWork& w, uint64_t ready) {
  const uint64_t a = std::max(setup_free_, ready);
  const uint64_t h = std::max(a + static_cast<uint64_t>(setup_cycles(w, unroll_)), prober_free_);
  const int p = w.one_level || w.guard ? kProbeCyclesOne : kProbeCycles;
  const uint64_t last = h + static_cast<uint64_t>(std::max(1, w.probes)) * static_cast<uint64_t>(p);
  setup_free_ = h + 1;
  prober_free_ = last;  // the next record is taken with the last probe's output
  return {a, last + static_cast<uint64_t>(w.guard ? kGuardOutCycles : kOutCycles)};
}

}  // namespace tu::feline
