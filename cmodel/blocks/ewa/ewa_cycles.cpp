#include "ewa_cycles.hpp"

#include <algorithm>

namespace tu::ewa {

PixelCost pixel_cost(const fx::In& in, int level, uint32_t flags, uint64_t box, int top_level) {
  // First level tried: the unit disc starts at 0, otherwise the integer lod clamped to the top.
  int l0 = 0;
  if (!(flags & fx::kUnitDisc)) l0 = std::min(static_cast<int>(in.b2.lod >> fmt::kEllLodF), top_level);
  return {level - l0 + 1, box, (flags & fx::kNoWeight) != 0};
}

int setup_cycles(const PixelCost& c, const EngineParams& p) {
  if (c.guard) return 1;  // ACCEPT -> HAND
  const int levels = c.levels;
  const int cordic = 2 * (fmt::kEwaCordIter / p.cord_unroll);
  const int per_level = 6 + p.root_w / p.sqrt_step;  // AX EXP MUL SQ ROOT.. BOX CAP
  return 2 + cordic + levels * per_level + 2;         // ACCEPT PRE ... START1 START2
}

int walk_cycles(const PixelCost& c) {
  if (c.guard) return 3;  // hand-over, read, data
  // hand-over clock, one clock per texel, 5 drain clocks (weight pipeline + accumulate), then
  // normalisation (6: mantissa + 4 reciprocal stages + round) or the nearest texel (1 + 2).
  return 1 + static_cast<int>(c.box) + fmt::kEwaDrainCycles + (c.no_weight ? 3 : fmt::kEwaNormCycles);
}

uint64_t stream_cycles(const std::vector<PixelCost>& px, uint64_t first_arrival,
                       const EngineParams& p) {
  uint64_t setup_free = first_arrival, walker_free = 0, last_out = 0;
  uint64_t bil_free = first_arrival, tri_free = first_arrival, nst_free = first_arrival;
  for (size_t i = 0; i < px.size(); ++i) {
    const PixelCost& c = px[i];
    // An engine switch waits for the other engine's last output.
    const uint64_t drained = i > 0 && px[i - 1].engine != c.engine ? last_out + 1 : 0;
    switch (c.engine) {
      case Engine::Bilinear: {
        const uint64_t a = std::max(bil_free, drained);
        last_out = a + 6;
        bil_free = a + 7;
        break;
      }
      case Engine::Nearest: {
        const uint64_t a = std::max(nst_free, drained);
        last_out = a + 3;
        nst_free = a + 4;
        break;
      }
      case Engine::Trilinear: {
        const uint64_t a = std::max(tri_free, drained);
        last_out = a + (c.one_level ? 8 : 15);
        tri_free = last_out + 1;
        break;
      }
      case Engine::Ewa: {
        const uint64_t a = std::max(setup_free, drained);                // accept
        const uint64_t h = std::max(a + static_cast<uint64_t>(setup_cycles(c, p)), walker_free);
        const uint64_t o = h + static_cast<uint64_t>(walk_cycles(c));    // output valid and taken
        setup_free = h + 1;
        walker_free = o + 1;
        last_out = o;
        break;
      }
    }
  }
  return px.empty() ? 0 : last_out + 1;
}

uint64_t bilinear_stream_cycles(uint64_t pixels, uint64_t first_arrival) {
  PixelCost c;
  c.engine = Engine::Bilinear;
  return stream_cycles(std::vector<PixelCost>(pixels, c), first_arrival);
}

int texture_unit_front_latency(bool relief_stage, bool ell_recurrence) {
  return 2 + 1 + std::max(fmt::kPerspLatency, ell_recurrence ? fmt::kEllRecLatency : 0) + 1 +
         (relief_stage ? kReliefStagePassLatency : 0);
}

}  // namespace tu::ewa
