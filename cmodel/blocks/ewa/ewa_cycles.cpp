#include "ewa_cycles.hpp"

#include <algorithm>
#include <deque>
#include <stdexcept>

namespace tu::ewa {

PixelCost pixel_cost(const fx::In& in, int level, uint32_t flags, uint64_t box, int top_level) {
  // First level tried: the integer lod (the sampler's level, a unit disc too) clamped to the top.
  const int l0 = std::min(static_cast<int>(in.b2.lod >> fmt::kEllLodF), top_level);
  return {level - l0 + 1, box, (flags & fx::kNoWeight) != 0};
}

int setup_cycles(const PixelCost& c, const EngineParams& p) {
  if (c.guard) return 1;  // ACCEPT -> HAND
  const int levels = c.levels;
  const int cordic = 2 * (fmt::kEwaCordIter / p.cord_unroll);
  const int per_level = 6 + p.root_w / p.sqrt_step;  // AX EXP MUL SQ ROOT.. BOX CAP
  return 2 + cordic + levels * per_level + 2;         // ACCEPT PRE ... START1 START2
}

int rtl_clip_code(const std::string& variant) {
  for (size_t i = 0; i < kRtlClipVariants.size(); ++i)
    if (variant == kRtlClipVariants[i]) return static_cast<int>(i);
  return -1;
}

int border_latency(int clip_code) {
  const int clip = clip_code == 1 ? fmt::kClipHornerLatency : clip_code == 2 ? fmt::kClipEstrinLatency : fmt::kClipP1Latency;
  return 1 + 1 + fmt::kEwaRootW + 1 + fmt::kClipInF + 1 + clip + 1;
}

int walk_cycles(const PixelCost& c, const EngineParams& p) {
  if (c.guard) return 3;  // hand-over, read, data
  // hand-over clock, one clock per texel, 5 drain clocks (weight pipeline + accumulate; border
  // weights: + the border pipeline), then normalisation (6: mantissa + 4 reciprocal stages +
  // round) or the nearest texel (1 + 2).
  const int drain = fmt::kEwaDrainCycles + (c.clip ? border_latency(p.clip_variant) : 0);
  return 1 + static_cast<int>(c.box) + drain + (c.no_weight ? 3 : fmt::kEwaNormCycles);
}

int lane_walk_latency(const EngineParams& p) {
  return fmt::kEwaDrainCycles + fmt::kEwaNormCycles + 1 + (p.lane_clip ? border_latency(p.clip_variant) : 0);
}

StreamModel::Times StreamModel::add(const PixelCost& c, uint64_t avail) {
  // An engine switch waits for the other engine's last output.
  const bool afv = !c.noise && c.afv_walk > 0;
  const bool other = last_noise_ != c.noise || (c.noise ? last_water_ != c.water
                                                          : last_engine_ != c.engine || last_afv_ != afv || last_fmt_ != c.texfmt);
  const uint64_t drained = any_ && other ? last_out_ + 1 : 0;
  const uint64_t ready = std::max(drained, avail);
  uint64_t a = 0;
  if (c.noise) {
    const int issues = (c.water ? fmt::kWaterPasses : 1) * p_.noise_slots;
    a = std::max(noise_free_, ready) + static_cast<uint64_t>(issues - 1);  // the last issue (the pixel's acceptance)
    last_out_ = a + static_cast<uint64_t>(c.water ? fmt::kNoiseWaterLatency : fmt::kNoiseUnitLatency);
    noise_free_ = a + 1;
    any_ = last_noise_ = true;
    last_water_ = c.water;
    return {a, last_out_};
  }
  last_noise_ = false;
  last_afv_ = afv;
  last_fmt_ = c.texfmt;
  if (afv) {  // tu_afvis: its own set-up and visibility walker, joined as tu_ewa's
    a = std::max(afv_setup_free_, ready);
    const uint64_t h = std::max(a + static_cast<uint64_t>(setup_cycles(c, p_)), afv_walker_free_);
    last_out_ = h + c.afv_walk;
    afv_setup_free_ = h + 1;
    afv_walker_free_ = last_out_ + 1;
    any_ = true;
    last_engine_ = c.engine;
    return {a, last_out_};
  }
  switch (c.engine) {
    case Engine::Bilinear:
      a = std::max(bil_free_, ready);
      last_out_ = a + 6;
      bil_free_ = a + 7;
      break;
    case Engine::Nearest:
      a = std::max(nst_free_, ready);
      last_out_ = a + 3;
      nst_free_ = a + 4;
      break;
    case Engine::Trilinear:
      a = std::max(tri_free_, ready);
      last_out_ = a + (c.one_level ? 8 : 15);
      tri_free_ = last_out_ + 1;
      break;
    case Engine::Feline: {
      const auto t = fel_.add({c.probes, c.one_level, c.guard}, ready);
      a = t.accept;
      last_out_ = t.out;
      break;
    }
    case Engine::Ewa: {
      if (p_.lanes > 1) {
        const size_t units = static_cast<size_t>(std::clamp(p_.setup_units, 1, kMaxSetupUnits));
        a = std::max({ready, unit_free_[unit_next_], ewa_any_ ? ewa_accept_ + 1 : 0});
        const uint64_t credit = lane_outs_.size() >= static_cast<size_t>(p_.out_depth) ? lane_outs_.front() + 1 : 0;
        const uint64_t h = std::max({a + static_cast<uint64_t>(setup_cycles(c, p_)), lane_free_, credit});
        const uint64_t f = c.guard ? 1 : c.blocks;
        const uint64_t o = h + f + static_cast<uint64_t>(lane_walk_latency(p_));
        unit_free_[unit_next_] = h + 1;
        unit_next_ = (unit_next_ + 1) % units;
        ewa_accept_ = a;
        ewa_any_ = true;
        lane_free_ = h + f;
        lane_outs_.push_back(o);
        if (lane_outs_.size() > static_cast<size_t>(p_.out_depth)) lane_outs_.pop_front();
        last_out_ = o;
        break;
      }
      a = std::max(setup_free_, ready);                                               // accept
      const uint64_t h = std::max(a + static_cast<uint64_t>(setup_cycles(c, p_)), walker_free_);
      const uint64_t o = h + static_cast<uint64_t>(walk_cycles(c, p_));                   // output valid and taken
      setup_free_ = h + 1;
      walker_free_ = o + 1;
      last_out_ = o;
      break;
    }
  }
  any_ = true;
  last_engine_ = c.engine;
  return {a, last_out_};
}

uint64_t stream_cycles(const std::vector<PixelCost>& px, uint64_t first_arrival, const EngineParams& p) {
  StreamModel m(p);
  for (const PixelCost& c : px) m.add(c, first_arrival);
  return m.cycles();
}

uint64_t texture_unit_cycles(const std::vector<PixelCost>& px, const std::vector<relief::StagePixel>& relief_px,
                             const EngineParams& p) {
  if (px.size() != relief_px.size()) throw std::invalid_argument("ewa::texture_unit_cycles: one relief entry per pixel");
  // Front: span set-up (2) and the expander register (1); the spans wait at the input, so the
  // expander offers a pixel every clock from then on.
  constexpr uint64_t kExpander = 3;
  constexpr size_t kFilterFifo = 4;  // tu_texture_unit FifoDepth
  using Pipe = std::vector<int>;     // pixel index per stage, -1: empty (tu_pipe_valid)
  Pipe b1(fmt::kPerspLatency, -1), b2(fmt::kEllLatency, -1);
  auto advance = [](Pipe& p, int in) {
    for (size_t k = p.size() - 1; k > 0; --k) p[k] = p[k - 1];
    p[0] = in;
  };
  relief::StageModel stage(relief_px);
  StreamModel filter(p);
  std::deque<uint64_t> pops;  // acceptance cycles of the pixels in the filter FIFO, oldest first
  size_t in_fifo = 0, ex_next = 0;
  const uint64_t limit = 1000 + 5000 * static_cast<uint64_t>(px.size());
  for (uint64_t t = 0; stage.outputs() < px.size(); ++t) {
    if (t > limit) throw std::logic_error("ewa::texture_unit_cycles: no progress");
    while (!pops.empty() && pops.front() < t) pops.pop_front(), --in_fifo;  // popped before this clock
    const bool out_ready = in_fifo < kFilterFifo;
    // B1 / B2 join in front of the relief stage; the fork feeds both pipelines at once.
    const bool pj_valid = b1.back() >= 0 && b2.back() >= 0;
    const bool pj_ready = stage.in_ready(out_ready);
    const bool b1_en = b1.back() < 0 || (pj_ready && b2.back() >= 0);
    const bool b2_en = b2.back() < 0 || (pj_ready && b1.back() >= 0);
    const bool ex_fire = t >= kExpander && ex_next < px.size() && b1_en && b2_en;
    const size_t out_index = stage.outputs();
    const auto fired = stage.step(pj_valid, out_ready);
    if (fired.out) {  // into the filter FIFO: at its head from the next clock
      const auto times = filter.add(px[out_index], t + 1);
      pops.push_back(times.accept);
      ++in_fifo;
    }
    const int in = ex_fire ? static_cast<int>(ex_next++) : -1;
    if (b1_en) advance(b1, in);
    if (b2_en) advance(b2, in);
  }
  return filter.cycles();
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
