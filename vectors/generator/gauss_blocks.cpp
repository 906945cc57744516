// Vector sets for the Gaussian pixel-model blocks (docs/blocks/gaussian.md): the clip-volume
// schemes (d s13.12 -> v u16.16, error |v - Phi(clamp(d)/0.2)|) and the weight (Q u16.14 ->
// w u17.16, error |w - (1 - Q/2)^8|).
#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "block.hpp"
#include "gauss/clip.hpp"
#include "gauss/weight.hpp"

namespace tu::blocks {

namespace {
// |w - ref| for a weight output with `frac` fraction bits (ref: f64 bits).
auto weight_error(int frac) {
  return [frac](const Row&, const Row& out, const Row& ref) {
    ErrPoint e;
    e.abs = std::fabs(std::ldexp(static_cast<double>(out[0]), -frac) - vec::bits_f64(ref[0]));
    e.ulp = e.abs / std::ldexp(1.0, -frac);
    return e;
  };
}

std::vector<Row> clip_inputs(const std::string& set, uint64_t count, uint64_t seed) {
  const int w = fmt::kClipInW;
  const uint64_t mask = (uint64_t(1) << w) - 1;
  auto code = [&](int64_t d) { return Row{static_cast<uint64_t>(d) & mask}; };
  std::vector<Row> rows;
  const int64_t h = clip::kHalfCode;
  if (set == "golden") {
    for (int64_t d : {int64_t(0), int64_t(1), int64_t(-1), h / 2, -h / 2, h, -h, int64_t(689),
                      int64_t(1244), int64_t(-1000), int64_t(4095), int64_t(-4096)})
      rows.push_back(code(d));
  } else if (set == "stiff") {
    // Domain edges, clamping, sign, every seed and minimax breakpoint +-1, extremes.
    for (int64_t d : {int64_t(0), int64_t(1), int64_t(-1), h - 1, h, h + 1, -h + 1, -h, -h - 1,
                      int64_t(4095), int64_t(-4096), int64_t(-4095)})
      rows.push_back(code(d));
    for (int64_t b : {int64_t(676), int64_t(1249), int64_t(689), int64_t(1244)})
      for (int64_t e = -1; e <= 1; ++e) {
        rows.push_back(code(b + e));
        rows.push_back(code(-(b + e)));
      }
  } else {
    std::mt19937_64 rng(seed);
    for (uint64_t i = 0; i < count; ++i) {
      // 90% inside the domain, 10% anywhere.
      const int64_t d = (rng() % 10) ? static_cast<int64_t>(rng() % (2 * h + 1)) - h
                                     : static_cast<int64_t>(rng() & mask) - (int64_t(1) << (w - 1));
      rows.push_back(code(d));
    }
  }
  return rows;
}

Block make_clip(const std::string& name, const std::string& variant, const std::string& desc,
                int latency, int ii) {
  Block b;
  b.name = name;
  b.description = desc;
  b.fields = {field("d", vec::Role::In, "s13.12"), field("v", vec::Role::Out, "u16.16"),
              field("ref", vec::Role::Ref, "f64")};
  b.sets = {"golden", "stiff", "random"};
  b.inputs = clip_inputs;
  const clip::Variant* v = &clip::variant(variant);
  b.model = [v](const Row& in) {
    return Row{clip::eval(*v, static_cast<int32_t>(vec::sext(in[0], fmt::kClipInW)))};
  };
  b.ref = [](const Row& in) {
    const double d = std::ldexp(static_cast<double>(vec::sext(in[0], fmt::kClipInW)), -fmt::kClipInF);
    return Row{vec::f64_bits(clip::reference(d))};
  };
  b.error = [](const Row&, const Row& out, const Row& ref) {
    ErrPoint e;
    e.abs = std::fabs(std::ldexp(static_cast<double>(out[0]), -fmt::kClipOutF) - vec::bits_f64(ref[0]));
    e.ulp = e.abs / std::ldexp(1.0, -fmt::kClipOutF);
    return e;
  };
  b.latency_cycles = latency;
  b.ii_cycles = ii;
  return b;
}
}  // namespace

std::vector<Block> make_gauss_blocks() {
  std::vector<Block> bs;
  bs.push_back(make_clip("clip_p1", "mm_p1",
                         "clip volume, 3-segment minimax lines: comparators + table + 1 MAC",
                         fmt::kClipP1Latency, 1));
  bs.push_back(make_clip("clip_horner", "mm_p3", "clip volume, degree-3 minimax, Horner pipelined",
                         fmt::kClipHornerLatency, 1));
  bs.push_back(make_clip("clip_estrin", "mm_p3_estrin",
                         "clip volume, degree-3 minimax, Estrin (a^2 beside c1*a)",
                         fmt::kClipEstrinLatency, 1));
  bs.push_back(make_clip("clip_seq", "mm_p3", "clip volume, degree-3 minimax, one shared multiplier",
                         fmt::kClipSeqLatency, fmt::kClipSeqIi));
  Block w;
  w.name = "gauss_weight";
  w.description = "Gaussian weight (1 - Q/2)^8, three squarings, II = 1";
  w.fields = {field("q", vec::Role::In, "u16.14"), field("w", vec::Role::Out, "u17.16"),
              field("ref", vec::Role::Ref, "f64")};
  w.sets = {"golden", "stiff", "random"};
  w.inputs = [](const std::string& set, uint64_t count, uint64_t seed) {
    std::vector<Row> rows;
    const uint64_t one = uint64_t(1) << fmt::kGaussQF;
    if (set == "golden") {
      for (uint64_t q : {uint64_t(0), one / 2, one, one + 1, one / 4, uint64_t(12345), uint64_t(0xffff)})
        rows.push_back({q});
    } else if (set == "stiff") {
      for (uint64_t q : {uint64_t(0), uint64_t(1), one - 1, one, one + 1, 2 * one, uint64_t(0xffff),
                         uint64_t(0xfffe)})
        rows.push_back({q});
    } else {
      std::mt19937_64 rng(seed);
      for (uint64_t i = 0; i < count; ++i)
        rows.push_back({(rng() % 5) ? rng() % (one + 1) : rng() & 0xffff});
    }
    return rows;
  };
  w.model = [](const Row& in) { return Row{gauss::weight(static_cast<uint32_t>(in[0]))}; };
  w.ref = [](const Row& in) {
    return Row{vec::f64_bits(gauss::weight_ref(std::ldexp(static_cast<double>(in[0]), -fmt::kGaussQF)))};
  };
  w.error = weight_error(fmt::kGaussSqF);
  w.latency_cycles = fmt::kGaussLatency;
  w.ii_cycles = 1;
  bs.push_back(w);
  // 1-D weight table by Q at the RTL size (N = 256), linear interpolation; error against the
  // computed reference (1 - Q/2)^8 of the same Q.
  Block t = w;
  t.name = "weight_table_1d";
  t.description = "Gaussian weight from a 1-D table by Q (N = 256), linear interpolation, II = 1";
  t.fields = {field("q", vec::Role::In, "u16.14"), field("w", vec::Role::Out, "u16.16"),
              field("ref", vec::Role::Ref, "f64")};
  t.inputs = [](const std::string& set, uint64_t count, uint64_t seed) {
    std::vector<Row> rows;
    const uint64_t one = uint64_t(1) << fmt::kGaussQF;
    const uint64_t step = one >> gauss::kWtabRtlLog2N;  // table node spacing in Q codes
    if (set == "golden") {
      for (uint64_t q : {uint64_t(0), one / 2, one, one + 1, one / 4, uint64_t(12345), uint64_t(0xffff),
                         step / 2, one - step / 2})
        rows.push_back({q});
    } else if (set == "stiff") {
      // every table node and its neighbours (both interpolation ends), the end of the table,
      // just outside, the largest codes
      for (uint64_t k = 0; k <= one; k += step)
        for (uint64_t q : {k, k + 1, k + step - 1, k + step / 2})
          if (q <= one + 1) rows.push_back({q});
      for (uint64_t q : {one + 1, one + step, 2 * one, uint64_t(0xfffe), uint64_t(0xffff)}) rows.push_back({q});
    } else {
      std::mt19937_64 rng(seed);
      for (uint64_t i = 0; i < count; ++i)
        rows.push_back({(rng() % 5) ? rng() % (one + 1) : rng() & 0xffff});
    }
    return rows;
  };
  t.model = [](const Row& in) {
    static const gauss::Table1D tab(gauss::kWtabRtlLog2N);
    return Row{tab.lookup(static_cast<uint32_t>(in[0]))};
  };
  t.error = weight_error(fmt::kWtabEntryW);
  t.latency_cycles = gauss::kWtabRtlLatency;
  t.ii_cycles = 1;
  bs.push_back(t);
  // 2-D quarter-symmetric weight table by (|xi|, |eta|) at the RTL size (N = 32), bilinear
  // interpolation; error against the exact weight (1 - (xi^2 + eta^2)/2)^8 of the input codes.
  Block t2;
  t2.name = "weight_table_2d";
  t2.description = "Gaussian weight from a 2-D table by (|xi|, |eta|) (N = 32), bilinear, II = 1";
  t2.fields = {field("xi", vec::Role::In, "s16.14"), field("eta", vec::Role::In, "s16.14"),
               field("w", vec::Role::Out, "u16.16"), field("ref", vec::Role::Ref, "f64")};
  t2.sets = {"golden", "stiff", "random"};
  t2.inputs = [](const std::string& set, uint64_t count, uint64_t seed) {
    static_assert(gauss::kXiW == 16);
    std::vector<Row> rows;
    const int64_t one = int64_t(1) << gauss::kXiF;
    const int64_t step = one >> gauss::kWtab2dRtlLog2N;  // table node spacing in xi codes
    auto add = [&](int64_t x, int64_t y) {
      rows.push_back({static_cast<uint64_t>(x) & 0xffff, static_cast<uint64_t>(y) & 0xffff});
    };
    if (set == "golden") {
      for (const auto& [x, y] : std::vector<std::pair<int64_t, int64_t>>{
               {0, 0}, {one / 2, 0}, {0, -one / 2}, {one / 2, one / 2}, {-one / 3, one / 4}, {one, 0},
               {0, one}, {one + 1, 0}, {step / 2, step / 2}, {-12345, 3456}, {32767, -32768}})
        add(x, y);
    } else if (set == "stiff") {
      // every table node (both signs), cell centres, both interpolation ends of every cell
      for (int64_t j = 0; j <= one; j += step)
        for (int64_t i = 0; i <= one; i += step) {
          add(i, j);
          add(-(i + step / 2), j + 1);
          add(i + step - 1, -(j + step - 1));
        }
      // the edges |xi| or |eta| = 1 and just past, outside the disc inside the square, extremes
      for (int64_t v : {int64_t(0), one / 2, one - 1, one})
        for (int64_t e : {one - 1, one, one + 1, int64_t(32767), int64_t(-32768)}) {
          add(e, v);
          add(v, e);
          add(-e, -v);
        }
      add(-32768, -32768);
      add(32767, 32767);
      add(one, one);
      add(-one, -one);
    } else {
      std::mt19937_64 rng(seed);
      for (uint64_t i = 0; i < count; ++i) {
        // 80% in [-1.01, 1.01]^2, 20% anywhere
        if (rng() % 5) {
          const int64_t r = one + one / 100;
          add(static_cast<int64_t>(rng() % (2 * r + 1)) - r, static_cast<int64_t>(rng() % (2 * r + 1)) - r);
        } else {
          add(static_cast<int64_t>(rng() & 0xffff), static_cast<int64_t>(rng() & 0xffff));
        }
      }
    }
    return rows;
  };
  t2.model = [](const Row& in) {
    static const gauss::Table2D tab(gauss::kWtab2dRtlLog2N);
    return Row{tab.lookup(static_cast<int32_t>(vec::sext(in[0], gauss::kXiW)),
                          static_cast<int32_t>(vec::sext(in[1], gauss::kXiW)))};
  };
  t2.ref = [](const Row& in) {
    const double x = std::ldexp(static_cast<double>(vec::sext(in[0], gauss::kXiW)), -gauss::kXiF);
    const double y = std::ldexp(static_cast<double>(vec::sext(in[1], gauss::kXiW)), -gauss::kXiF);
    return Row{vec::f64_bits(gauss::weight_ref(x * x + y * y))};
  };
  t2.error = weight_error(fmt::kWtabEntryW);
  t2.latency_cycles = gauss::kWtab2dRtlLatency;
  t2.ii_cycles = 1;
  bs.push_back(t2);
  return bs;
}

}  // namespace tu::blocks
