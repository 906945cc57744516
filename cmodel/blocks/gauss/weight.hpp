// Gaussian pixel-model weight (seed 003 §1, docs/blocks/gaussian.md):
//     w = (1 - Q/2)^8 for 0 <= Q <= 1, 0 outside,   Q = (Ae U^2 + Be U V + Ce V^2) / Fe.
// Computed: t = 1 - Q/2 (exact, u16.15), then three squarings, each rounded half up to u17.16.
// Tables instead of arithmetic (seed 003 §3): a 1-D table indexed by Q (no square root) and a 2-D
// quarter-symmetric table indexed by (|xi|, |eta|), linear / bilinear interpolation.
#pragma once

#include <cstdint>
#include <vector>

#include "texunit/fixed.hpp"
#include "texunit/formats.hpp"

namespace tu::gauss {

using Q = UFixed<fmt::kGaussQW, fmt::kGaussQF>;
using T = UFixed<fmt::kGaussTW, fmt::kGaussTF>;
using Sq = UFixed<fmt::kGaussSqW, fmt::kGaussSqF>;

// Q code (u16.14) -> w code (u17.16). Q > 1 gives 0. Inline: the EWA walk calls it per texel.
inline uint32_t weight(uint32_t q_code) {
  if (q_code > (uint32_t(1) << fmt::kGaussQF)) return 0;
  // t = 1 - Q/2: Q/2 has GaussQF + 1 = GaussTF fraction bits with the same raw code.
  static_assert(fmt::kGaussTF == fmt::kGaussQF + 1);
  const T t = T::from_raw((int64_t(1) << fmt::kGaussTF) - q_code);
  const Sq t2 = (t * t).as<Sq, Round::HalfUp, Ovf::Sat>();
  const Sq t4 = (t2 * t2).as<Sq, Round::HalfUp, Ovf::Sat>();
  return static_cast<uint32_t>((t4 * t4).as<Sq, Round::HalfUp, Ovf::Sat>().raw());
}
double weight_ref(double q);  // (1 - q/2)^8 on [0, 1], else 0

struct WeightStats {
  double max_abs = 0, rms = 0, max_ulp = 0;
  bool monotonic = true;  // non-increasing in Q
};
WeightStats weight_exhaustive();  // every Q code

// ---- weight tables ----------------------------------------------------------------------------
// Entries are u16.16 codes of w (1.0 saturates to 0xffff), N + 1 entries per axis covering [0, 1].
struct Table1D {
  int log2n;
  std::vector<uint32_t> e;  // e[k] = w(k / N)
  explicit Table1D(int log2n);
  uint32_t lookup(uint32_t q_code) const;  // Q code u16.14 -> w code u16.16, linear interpolation
  uint64_t memory_bits() const { return e.size() * fmt::kWtabEntryW; }
};

// The 1-D table built in RTL (rtl/gauss/tu_weight_table_1d.sv, generated ROM tu_wtab1d_rom from
// Table1D(kWtabRtlLog2N).e): N = 256 (4 kbit; the NMSE saturates there, gaussian.md), latency 3
// (registered ROM read, lerp multiply, round), II = 1.
inline constexpr int kWtabRtlLog2N = 8;
inline constexpr int kWtabRtlLatency = 3;

// Coordinates in the ellipse frame: xi, eta signed s16.14 (Q = xi^2 + eta^2).
inline constexpr int kXiW = fmt::kGaussXiW, kXiF = fmt::kGaussXiF;
struct Table2D {
  int log2n;
  std::vector<uint32_t> e;  // (N+1) x (N+1), e[j*(N+1)+i] = w(i/N, j/N), 0 outside the disc
  explicit Table2D(int log2n);
  uint32_t lookup(int32_t xi_code, int32_t eta_code) const;  // bilinear on |xi|, |eta|
  uint64_t memory_bits() const { return e.size() * fmt::kWtabEntryW; }
};

// The 2-D table built in RTL (rtl/gauss/tu_weight_table_2d.sv, generated ROM tu_wtab2d_rom from
// Table2D(kWtab2dRtlLog2N).e): N = 32 per axis (33 x 33 entries, 17 kbit; gaussian.md), latency 4
// (registered ROM read of the 4 cell corners, two x-lerp multiplies, y-lerp multiply, round), II = 1.
inline constexpr int kWtab2dRtlLog2N = 5;
inline constexpr int kWtab2dRtlLatency = 4;

// Q code of xi^2 + eta^2 for xi, eta codes (s16.14), rounded half up, saturated.
uint32_t q_of(int32_t xi_code, int32_t eta_code);

struct TableStats {
  double nmse = 0;     // sum (w_tab - w)^2 / sum w^2 over the sample grid
  double rms = 0;      // sqrt(mean (w_tab - w)^2)
  double max_abs = 0;  // max |w_tab - w| (includes the 2^-8 step of w at the ellipse boundary)
  double max_abs_inner = 0;  // the same over samples with Q <= 0.9 (away from the step)
  uint64_t samples = 0;
  uint64_t memory_bits = 0;
};
// Sample grid: xi, eta codes k * step_code in [-1.25, 1.25] (step 37 codes = 2.26e-3 by default:
// odd, so samples never sit on table nodes), reference w(xi^2 + eta^2) in double.
// kind: 0 = 1-D table, 1 = 2-D table, 2 = computed weight (three squarings).
TableStats table_stats(int kind, int log2n, int step_code = 37);

}  // namespace tu::gauss
