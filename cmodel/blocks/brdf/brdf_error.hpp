// Error measures of the bit-accurate BRDF models (docs/blocks/brdf.md): exhaustive sweeps over the
// c codes of one n, the thesis's MAD against Blinn, the relative error at the highlight epicentre.
// Used by the unit tests, the long exhaustive test and `texunit report --blocks brdf`.
#pragma once

#include <cstdint>

#include "brdf_common.hpp"

namespace tu::brdf {

struct SweepStats {
  double max_own_lsb = 0;    // |F_fx - F_ref(c)| in output LSB, F_ref the model's own formula
  double max_blinn_lsb = 0;  // |F_fx - c^n| in output LSB
  uint64_t worst_own_code = 0;
  bool monotone = true;      // F_fx non-decreasing in the c code
  uint64_t codes = 0;        // c codes evaluated
  uint64_t nonzero_below_cut = 0;  // must stay 0
};
// Every c code from `from` to 1.0 for one n (the cut-off code from cut_code); codes below `from`
// down to 0 are only checked to give F = 0 when `check_below` is set.
SweepStats sweep(Model m, int n, uint64_t from, bool check_below = false);
void merge(SweepStats& into, const SweepStats& s);

// Input of the model for a real c (rounded to nearest code) and n, with its cut-off.
In input_of(Model m, double c, int n);

// Against Blinn on the thesis grid (deg 0..90 x n 1..1000, c rounded to BrdfCF bits): the MAD
// (mean |F_fx - c^n|) and the largest |F_fx - c^n|.
struct GridStats {
  double mad = 0, max_abs = 0;
};
GridStats vs_blinn_fx(Model m, int deg_step = 1, int n_step = 1);
// Max |F_fx - 0.3| / 0.3 at the epicentre c = 0.3^(1/n), n in [n_lo, 1000].
double epicentre_rel_fx(Model m, int n_lo);

}  // namespace tu::brdf
