// texunit formats: the ONE description of word lengths, fraction bits and constants shared by the
// C model and the RTL. `texunit gen-rtl` writes rtl/generated/tu_formats_pkg.sv from this list;
// the test GeneratedRtl.IsFresh fails when the committed package differs from this file.
//
// Naming: <Block><Signal><W|F>; W = word length, F = fraction bits. Signedness is in the comment
// and in the C-model type that uses the constant.
#pragma once

// X(name, value, description). Values may use earlier names (prefixed k) as constant expressions.
#define TU_FORMAT_PARAMS(X)                                                                      \
  /* Reciprocal unit (docs/blocks/reciprocal.md) */                                             \
  X(RecipInW, 24, "input code q: signed, caller-defined fraction bits")                          \
  X(RecipMantW, 24, "normalised mantissa M in [1,2): unsigned, RecipMantW-1 fraction bits")     \
  X(RecipIdxW, 8, "segment index: top fraction bits of M")                                      \
  X(RecipDxW, kRecipMantW - 1 - kRecipIdxW, "offset in segment: unsigned, RecipMantW-1 frac")   \
  X(RecipShiftW, 5, "exponent p = msb position of q, 0..RecipInW-2")                             \
  X(RecipC2W, 14, "quadratic coefficient c2: unsigned")                                         \
  X(RecipC2F, 12, "")                                                                           \
  X(RecipT1W, 18, "t1 = c2*dx, truncated: unsigned")                                            \
  X(RecipT1F, 22, "")                                                                           \
  X(RecipC1W, 25, "linear coefficient c1: signed")                                              \
  X(RecipC1F, 22, "")                                                                           \
  X(RecipSW, 25, "s = c1 + t1: signed")                                                         \
  X(RecipT2W, 26, "t2 = s*dx, truncated: signed")                                               \
  X(RecipT2F, 30, "")                                                                           \
  X(RecipC0W, 32, "constant coefficient c0: unsigned")                                          \
  X(RecipC0F, 30, "")                                                                           \
  X(RecipOutW, 25, "reciprocal mantissa R in (0.5,1]: unsigned, RecipOutF fraction bits")       \
  X(RecipOutF, 24, "")                                                                          \
  X(RecipLatency, 5, "pipeline latency in cycles, II = 1")

namespace tu::fmt {
#define TU_X_DECLARE(name, value, desc) inline constexpr int k##name = (value);
TU_FORMAT_PARAMS(TU_X_DECLARE)
#undef TU_X_DECLARE
}  // namespace tu::fmt
