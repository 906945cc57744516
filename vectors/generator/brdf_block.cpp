// Vector sets of the BRDF specular models (docs/blocks/brdf.md): one block per model, brdf_<model>,
// plus brdf_msh_seq (the shared-multiplier F_MSH RTL, the same C model). Inputs c = N.H (s22.20),
// n (u10.0) and the per-material cut-off code ccut = cut_code(model, n) (u21.20); outputs F (u9.8)
// and flag. Error unit: F itself (0..1.024); 1 ULP = 2^-8. Reference: the model's float formula
// at the clamped c.
#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include "block.hpp"
#include "brdf/brdf_common.hpp"

namespace tu::blocks {

namespace {
using brdf::Model;
constexpr uint64_t kOne = uint64_t(1) << fmt::kBrdfCF;
constexpr uint64_t kCMask = (uint64_t(1) << fmt::kBrdfCW) - 1;

uint64_t ccode(int64_t c) { return static_cast<uint64_t>(c) & kCMask; }

// Cut-off codes of every model for n = 0..1023 (out-of-range n clamps as the front end does).
uint64_t cut_of(Model m, uint64_t n) {
  static const auto tab = [] {
    std::array<std::array<uint64_t, 1024>, std::size(brdf::kModels)> t{};
    for (Model mm : brdf::kModels)
      for (int k = 0; k < 1024; ++k)
        t[static_cast<size_t>(mm)][static_cast<size_t>(k)] =
            brdf::cut_code(mm, std::clamp(k, 1, static_cast<int>(fmt::kBrdfNMax)));
    return t;
  }();
  return tab[static_cast<size_t>(m)][n & 1023];
}

Row row(Model m, int64_t c, uint64_t n) { return {ccode(c), n, cut_of(m, n)}; }
int64_t code_of(double c) { return std::llround(std::ldexp(c, fmt::kBrdfCF)); }

std::vector<Row> golden(Model m) {
  // The note's golden table (§7): n in {1, 10, 50, 1000} x c in {0, .5, .9, .99, .999, 1}, and
  // one back-facing and one over-range c.
  std::vector<Row> rows;
  for (uint64_t n : {1u, 10u, 50u, 1000u}) {
    for (double c : {0.0, 0.5, 0.9, 0.99, 0.999, 1.0}) rows.push_back(row(m, code_of(c), n));
    rows.push_back(row(m, code_of(-0.5), n));
    rows.push_back(row(m, code_of(1.5), n));
  }
  return rows;
}

std::vector<Row> stiff(Model m) {
  std::vector<Row> rows;
  const int64_t cmin = -(int64_t(1) << (fmt::kBrdfCW - 1)), cmax = (int64_t(1) << (fmt::kBrdfCW - 1)) - 1;
  for (uint64_t n : {0u, 1u, 2u, 9u, 15u, 16u, 17u, 268u, 999u, 1000u, 1001u, 1023u})
    for (int64_t c : {cmin, int64_t(-1), int64_t(0), int64_t(1), int64_t(kOne) - 2,
                      int64_t(kOne) - 1, int64_t(kOne), int64_t(kOne) + 1, cmax})
      rows.push_back(row(m, c, n));
  // Cut-off neighbours and the epicentre (F_B = 0.3) for n across the range.
  for (uint64_t n = 1; n <= fmt::kBrdfNMax; n += 13) {
    const auto cut = static_cast<int64_t>(cut_of(m, n));
    for (int64_t d : {-2, -1, 0, 1, 2}) rows.push_back(row(m, std::min<int64_t>(cut + d, kOne), n));
    rows.push_back(row(m, code_of(std::pow(0.3, 1.0 / static_cast<double>(n))), n));
  }
  return rows;
}

std::vector<Row> random(Model m, uint64_t count, uint64_t seed) {
  return random_rows(count, seed, [m](std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u01(0, 1);
    const double pick_n = u01(rng);
    const uint64_t n = pick_n < 0.02 ? (rng() % 2 ? 0 : 1001 + rng() % 23) : 1 + rng() % 1000;
    const auto cut = static_cast<int64_t>(cut_of(m, n));
    const double pick = u01(rng);
    int64_t c;
    if (pick < 0.5) {  // above the cut-off, uniform
      c = cut + static_cast<int64_t>(rng() % (kOne - std::min<uint64_t>(cut, kOne) + 1));
    } else if (pick < 0.8) {  // the highlight: within 16/n of c = 1
      const double w = std::min(1.0, 16.0 / static_cast<double>(std::max<uint64_t>(n, 1)));
      c = code_of(1 - w * u01(rng));
    } else if (pick < 0.9) {  // near the cut-off
      c = cut + static_cast<int64_t>(rng() % 129) - 64;
    } else {  // any code, back-facing and over-range included
      c = static_cast<int64_t>(rng() & kCMask);
    }
    return row(m, c, n);
  });
}

Block make(Model m, const std::string& name, const std::string& desc, int latency, int ii) {
  Block b;
  b.name = name;
  b.description = desc;
  b.fields = {field("c", vec::Role::In, "s22.20"),   field("n", vec::Role::In, "u10.0"),
              field("ccut", vec::Role::In, "u21.20"), field("f", vec::Role::Out, "u9.8"),
              field("flag", vec::Role::Out, "u1.0"),  field("ref", vec::Role::Ref, "f64")};
  b.sets = {"golden", "stiff", "random"};
  b.inputs = [m](const std::string& set, uint64_t count, uint64_t seed) {
    if (set == "golden") return golden(m);
    if (set == "stiff") return stiff(m);
    return random(m, count, seed);
  };
  b.model = [m](const Row& in) {
    const auto r = brdf::eval(m, {in[0], in[1], in[2]});
    return Row{r.f, r.flag ? 1u : 0u};
  };
  b.ref = [m](const Row& in) {
    const brdf::Front f = brdf::front({in[0], in[1], in[2]});
    return Row{vec::f64_bits(brdf::ref_value(m, f.c.to_double(), f.n))};
  };
  b.error = [](const Row&, const Row& out, const Row& ref) {
    ErrPoint e;
    e.abs = std::fabs(brdf::value(out[0]) - vec::bits_f64(ref[0]));
    e.ulp = e.abs * (1 << fmt::kBrdfOutF);
    return e;
  };
  b.latency_cycles = latency;
  b.ii_cycles = ii;
  return b;
}
}  // namespace

std::vector<Block> make_brdf_blocks() {
  return {
      make(Model::Blinn, "brdf_blinn", "Blinn c^n, square-and-multiply over the 10 bits of n, II = 1",
           fmt::kBrdfBlinnLatency, 1),
      make(Model::Schlick, "brdf_schlick", "Schlick c/(u+c), reciprocal core, II = 1",
           fmt::kBrdfSchlickLatency, 1),
      make(Model::Msh, "brdf_msh", "F_MSH 1.6c/(u+1.25c)^2, reciprocal core + square, II = 1",
           fmt::kBrdfMshLatency, 1),
      make(Model::Msh, "brdf_msh_seq", "F_MSH on one shared multiplier (FSM), same C model",
           fmt::kBrdfMshSeqLatency, fmt::kBrdfMshSeqIi),
      make(Model::Dsh, "brdf_dsh", "F_dsh clamped average, two reciprocals + six squarings, II = 1",
           fmt::kBrdfDshLatency, 1),
      make(Model::Scos2, "brdf_scos2", "F_SCOS2 ((2c-0.1u)/(u+2c))^2, reciprocal core, II = 1",
           fmt::kBrdfScos2Latency, 1),
      make(Model::St16, "brdf_st16", "F_ST16 (1-u/16)^16, four squarings, II = 1",
           fmt::kBrdfSt16Latency, 1),
      make(Model::Qr, "brdf_qr", "F_QR c(1-0.786u), two multiplies, II = 1", fmt::kBrdfQrLatency, 1),
  };
}

}  // namespace tu::blocks
