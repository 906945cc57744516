// The EWA normalisation's carry-save tree (rtl/common/tu_csa.svh in tu_ewa_norm_tail) in
// Verilator, against the C model ewa::fx::normalise, on its own: tu_ewa_normalise with the tree,
// over random and extreme (acc, wsum). The engine models that hold it (Vtu_ewa, Vtu_ewa_k4,
// Vtu_afvis, Vtu_feline and the texture-unit top) are built with TU_SIM_PRODUCT_MUL, the same
// sum as one product, because the unrolled tree was about 90 % of their simulation time
// (docs/performance.md section 11); this test is what keeps the tree itself co-simulated (the
// osu018 netlists carry it; the engines are not in the Icarus block list).
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "Vtu_ewa_normalise.h"
#include "ewa/ewa_fx.hpp"
#include "texunit/formats.hpp"

namespace {
using namespace tu;

constexpr int kAccW = fmt::kEwaAccW;
constexpr int kWsumW = fmt::kEwaWsumW;

struct Case {
  uint64_t wsum;
  uint64_t acc[4];
};

// acc channel c at bits [c kAccW, (c + 1) kAccW) of the 4 kAccW-bit port
void set_acc(Vtu_ewa_normalise& m, const uint64_t (&acc)[4]) {
  for (int i = 0; i < (4 * kAccW + 31) / 32; ++i) m.acc_i[i] = 0;
  for (int c = 0; c < 4; ++c)
    for (int b = 0; b < kAccW; ++b)
      if ((acc[c] >> b) & 1) {
        const int bit = c * kAccW + b;
        m.acc_i[bit / 32] |= 1u << (bit % 32);
      }
}

void tick(Vtu_ewa_normalise& m) {
  m.clk_i = 0;
  m.eval();
  m.clk_i = 1;
  m.eval();
}

uint64_t mask(int w) { return w >= 64 ? ~uint64_t(0) : (uint64_t(1) << w) - 1; }

// One weight sum, then a stream of channel sums under it: wsum loads at a clock, the reciprocal's
// y is stable 3 clocks later, from then on each clock's acc_i gives rgba_o one clock later
// (tu_ewa_norm_tail: clock A pre-shift, clock B the carry-save pair, rgba_o combinational).
uint64_t run(Vtu_ewa_normalise& m, uint64_t wsum, const std::vector<Case>& accs, size_t* bad) {
  m.wsum_i = wsum;
  m.load_i = 1;
  tick(m);
  m.load_i = 0;
  for (int i = 0; i < 3; ++i) tick(m);
  uint64_t checked = 0;
  for (size_t i = 0; i <= accs.size(); ++i) {
    if (i < accs.size()) set_acc(m, accs[i].acc);
    tick(m);
    if (i == 0) continue;
    const auto& c = accs[i - 1];
    for (int ch = 0; ch < 4; ++ch) {
      const uint32_t want = ewa::fx::normalise(c.acc[ch], wsum);
      const uint32_t got = (m.rgba_o >> (8 * ch)) & 0xff;
      if (got != want && ++*bad <= 8)
        ADD_FAILURE() << "wsum " << wsum << " acc[" << ch << "] " << c.acc[ch] << ": RTL " << got << ", C model "
                      << want;
      ++checked;
    }
  }
  return checked;
}

TEST(EwaNormaliseRtl, CarrySaveTreeMatchesCModel) {
  Vtu_ewa_normalise m;
  std::mt19937_64 rng(2026);
  size_t bad = 0;
  uint64_t checked = 0;
  auto acc_for = [&](uint64_t wsum, int kind) -> uint64_t {
    switch (kind) {
      case 0: return rng() % (256 * wsum);                 // a weighted mean of 8-bit texels
      case 1: return rng() & mask(kAccW);                   // anything the port holds
      case 2: return 255 * wsum + rng() % (wsum + 1);       // around the saturation at 255
      default: return (rng() % 4 == 0) ? 0 : (mask(kAccW) >> (rng() % kAccW));
    }
  };
  // every leading-one position of the weight sum, extremes and random mantissas
  for (int p = 0; p < kWsumW; ++p) {
    const uint64_t top = uint64_t(1) << p;
    std::vector<uint64_t> sums = {top, top | (top - 1), top | (top >> 1)};
    for (int r = 0; r < 24; ++r) sums.push_back(top | (rng() & (top - 1)));
    for (const uint64_t wsum : sums) {
      std::vector<Case> accs(48);
      for (auto& c : accs)
        for (auto& a : c.acc) a = acc_for(wsum, static_cast<int>(rng() % 4)) & mask(kAccW);
      accs[0] = {wsum, {0, mask(kAccW), 255 * wsum, std::min(mask(kAccW), 256 * wsum - 1)}};
      checked += run(m, wsum, accs, &bad);
    }
  }
  EXPECT_EQ(bad, 0u);
  EXPECT_GT(checked, 150000u);
  std::printf("tu_ewa_normalise (carry-save tree) vs ewa::fx::normalise: %llu channels, %zu mismatches\n",
              static_cast<unsigned long long>(checked), bad);
}

}  // namespace
