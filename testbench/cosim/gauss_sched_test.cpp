// Cycle estimator vs Verilator: for every Gaussian-model scheme with RTL, the list scheduler's
// predicted latency and II equal the measured ones exactly (docs/blocks/gaussian.md).
#include <gtest/gtest.h>

#include "cosim.hpp"
#include "cosim_checks.hpp"
#include "gauss/schemes.hpp"

namespace {
using namespace tu;

TEST(GaussSched, PredictionEqualsVerilatorMeasurement) {
  int checked = 0;
  for (const auto& g : gauss::schemes()) {
    if (g.name.rfind("est_", 0) == 0) continue;
    const auto pred = sched::schedule(g);
    const auto& b = blocks::find(g.name);
    std::vector<cosim::Row> in;
    for (const auto& r : b.inputs("random", 64, 3)) in.push_back(r);
    const auto [lat, ii] = cosim::find_rtl(g.name).timing(in);
    EXPECT_EQ(static_cast<uint64_t>(pred.latency), lat) << g.name;
    EXPECT_DOUBLE_EQ(static_cast<double>(pred.ii), ii) << g.name;
    std::printf("%-14s predicted latency %d II %d, measured latency %llu II %.2f\n", g.name.c_str(),
                pred.latency, pred.ii, static_cast<unsigned long long>(lat), ii);
    ++checked;
  }
  EXPECT_EQ(checked, 7);
}

// tu_gauss_weight's first stage forms t^2 = (2^15 - q)^2 as the multiply-add q^2 - 2^16 q + 2^30
// (no subtractor in front of the multiplier): every one of the 2^16 Q codes through the RTL, with
// 30% stalls, against the file's and the live C model's w (gauss::weight: t = 1 - Q/2, t^2).
TEST(GaussWeightRtl, EveryQCodeEqualsCModel) {
  const auto& b = blocks::find("gauss_weight");
  vec::VectorFile vf = blocks::generate(b, "golden", 0, 1);
  const auto in = vf.indices(vec::Role::In);
  const auto out = vf.indices(vec::Role::Out);
  const auto ref = vf.indices(vec::Role::Ref);
  ASSERT_EQ(in.size(), 1u);
  ASSERT_EQ(out.size(), 1u);
  vf.rows.clear();
  for (uint64_t q = 0; q < (uint64_t(1) << fmt::kGaussQW); ++q) {
    blocks::Row row(vf.fields.size());
    const blocks::Row x{q};
    row[static_cast<size_t>(in[0])] = q;
    row[static_cast<size_t>(out[0])] = b.model(x)[0];
    for (size_t k = 0; k < ref.size(); ++k) row[static_cast<size_t>(ref[k])] = b.ref(x)[k];
    vf.rows.push_back(row);
  }
  const auto rep = cosim::run(vf, cosim::checks::with_stalls(0.3));
  cosim::checks::expect_stream_clean(rep);
  EXPECT_EQ(rep.vectors, uint64_t(1) << fmt::kGaussQW);
  EXPECT_TRUE(rep.ok()) << rep.json();
}
}  // namespace
