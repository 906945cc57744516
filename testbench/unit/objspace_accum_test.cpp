// SystemC model of the object-space sample stream and accumulation (tlm/, texunit/objspace_accum.hpp):
// the SystemC run equals the structural estimate on every scheme; one lane never conflicts
// (samples + L clocks, the figure Verilator measures for tu_objspace_sample); more lanes gain only
// when consecutive samples use disjoint banks; the model's bank masks and schemes are checked.
#include <gtest/gtest.h>

#include <random>

#include "objspace/objspace.hpp"
#include "objspace/schemes.hpp"
#include "texunit/objspace_accum.hpp"

namespace {
using namespace tu;
using sysmodel::AccumSample;
using sysmodel::AccumScheme;

// The ASan build: after any SystemC run in a process, later frames of that process report ASan
// errors (stale stack shadow after SystemC's thread switches; also after the texture-unit model's
// runs, e.g. VectorFile.* run after Sysmodel.* in one process; ctest runs each test in its own
// process). There the SystemC runs are skipped and the estimate alone is checked; the release
// build runs both.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kRunSystemC = false;
#else
constexpr bool kRunSystemC = true;
#endif

AccumScheme scheme(int lanes, int bx, int by) {
  AccumScheme s;
  s.lanes = lanes, s.bank_x = bx, s.bank_y = by;
  s.datapath_latency = sched::schedule(objspace::sample_scheme()).latency;
  s.resolve_per_clock = 1, s.resolve_latency = 3;
  return s;
}

TEST(ObjspaceAccum, SystemCEqualsTheEstimateOnEveryScheme) {
  std::mt19937_64 rng(5);
  std::vector<AccumSample> v;
  for (int k = 0; k < 20000; ++k) v.push_back(AccumSample::of(int64_t(rng() % 256), int64_t(rng() % 192), rng() % 50 == 0));
  for (int lanes : {1, 2, 4, 8})
    for (const auto& [bx, by] : std::vector<std::pair<int, int>>{{2, 2}, {4, 2}, {8, 2}, {4, 4}, {8, 8}}) {
      const auto s = scheme(lanes, bx, by);
      const auto e = sysmodel::estimate_accumulation(s, v, 777);
      const auto r = kRunSystemC ? sysmodel::simulate_accumulation(s, v, 777) : e;
      EXPECT_EQ(r.total_cycles, e.total_cycles) << s.name();
      EXPECT_EQ(r.stream_cycles, e.stream_cycles) << s.name();
      EXPECT_EQ(r.issue_clocks, e.issue_clocks) << s.name();
      EXPECT_EQ(r.conflict_clocks, e.conflict_clocks) << s.name();
      EXPECT_EQ(r.resolve_cycles, 777u + 3u);
      EXPECT_GE(r.issue_clocks, (v.size() + static_cast<size_t>(lanes) - 1) / static_cast<size_t>(lanes));
      if (lanes == 1) {
        EXPECT_EQ(r.stream_cycles, v.size() + static_cast<uint64_t>(s.datapath_latency));
        EXPECT_EQ(r.conflict_clocks, 0u);
      }
    }
}

TEST(ObjspaceAccum, LanesGainOnlyOnDisjointBanks) {
  // Every sample on one pixel (a far, grazing plane): extra lanes cannot help.
  const std::vector<AccumSample> same(1000, AccumSample::of(5, 7, false));
  EXPECT_EQ(sysmodel::estimate_accumulation(scheme(4, 8, 8), same, 1).issue_clocks, 1000u);
  // Samples two pixels apart along x: with x mod 4 banks two lanes take a pair per clock.
  std::vector<AccumSample> stride;
  for (int k = 0; k < 1000; ++k) stride.push_back(AccumSample::of(2 * k, 3, false));
  EXPECT_EQ(sysmodel::estimate_accumulation(scheme(2, 4, 2), stride, 1).issue_clocks, 500u);
  EXPECT_EQ(sysmodel::estimate_accumulation(scheme(2, 2, 2), stride, 1).issue_clocks, 1000u);
  // Guarded samples write nothing: they fill lanes without conflicts.
  const std::vector<AccumSample> guarded(1000, AccumSample::of(0, 0, true));
  EXPECT_EQ(sysmodel::estimate_accumulation(scheme(4, 2, 2), guarded, 1).issue_clocks, 250u);
  EXPECT_EQ(sysmodel::estimate_accumulation(scheme(4, 2, 2), {}, 10).total_cycles, 13u);
  if (kRunSystemC) {
    EXPECT_EQ(sysmodel::simulate_accumulation(scheme(4, 2, 2), {}, 10).total_cycles, 13u);
  }
}

TEST(ObjspaceAccum, MalformedSchemesAreRejected) {
  const std::vector<AccumSample> v(4);
  EXPECT_THROW(sysmodel::simulate_accumulation(scheme(0, 2, 2), v, 1), std::invalid_argument);  // before any run
  EXPECT_THROW(sysmodel::simulate_accumulation(scheme(1, 3, 2), v, 1), std::invalid_argument);
  EXPECT_THROW(sysmodel::estimate_accumulation(scheme(1, 2, 16), v, 1), std::invalid_argument);
  EXPECT_THROW(sysmodel::estimate_accumulation(scheme(1, 1, 2), v, 1), std::invalid_argument);
}
}  // namespace
