// Perspective divide: the direct-evaluation RTL variant (tu_persp_direct) on the same vectors as
// the incremental unit (block persp), bit-for-bit against the C model, with 30% stalls.
#include <gtest/gtest.h>

#include "cosim.hpp"

namespace tu::cosim {
RtlBlock rtl_persp_direct();  // persp_rtl.cpp
}

namespace {
using namespace tu;

TEST(PerspDirectRtl, MatchesTheCModelWithStalls) {
  const auto& b = blocks::find("persp");
  const auto rtl = cosim::rtl_persp_direct();
  for (const std::string set : {"golden", "stiff", "random"}) {
    const auto vf = blocks::generate(b, set, 30000, 77);
    const auto in_idx = vf.indices(vec::Role::In), out_idx = vf.indices(vec::Role::Out);
    std::vector<blocks::Row> in;
    for (const auto& r : vf.rows) in.push_back(blocks::pick(r, in_idx));
    cosim::RunOptions o;
    o.stall_prob = 0.3;
    o.seed = 5;
    const auto rr = rtl.run(in, o);
    ASSERT_EQ(rr.outputs.size(), vf.rows.size()) << set;
    EXPECT_FALSE(rr.hung);
    uint64_t bad = 0;
    for (size_t i = 0; i < vf.rows.size(); ++i) bad += rr.outputs[i] != blocks::pick(vf.rows[i], out_idx);
    EXPECT_EQ(bad, 0u) << set;
    const auto [lat, ii] = rtl.timing(std::vector<blocks::Row>(in.begin(), in.begin() + std::min<size_t>(in.size(), 256)));
    EXPECT_EQ(lat, static_cast<uint64_t>(b.latency_cycles));
    EXPECT_DOUBLE_EQ(ii, 1.0);
  }
}
}  // namespace
