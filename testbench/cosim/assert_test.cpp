// The valid/ready assertions of rtl/common/tu_assert.svh fire under Verilator --assert (the flag
// every co-simulation build uses): a producer that drops valid while the consumer stalls stops the
// simulation with the assertion's name; a legal one runs on.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "Vtu_assert_probe.h"

namespace {
struct Outcome {
  bool error = false;  // an assertion failed
  int cycles = 0;      // clocks run before the simulation stopped (or all of them)
  std::string log;     // what the simulation printed
};

// Clocks with out_ready low after a reset.
Outcome stall(bool drop, int cycles) {
  auto ctx = std::make_unique<VerilatedContext>();
  ctx->fatalOnError(false);  // report through gotError() instead of aborting the test
  Vtu_assert_probe m(ctx.get());
  testing::internal::CaptureStdout();
  m.drop_i = drop;
  m.out_ready_i = 0;
  m.clk_i = 0;
  m.rst_ni = 0;
  m.eval();
  m.rst_ni = 1;
  Outcome o;
  for (; o.cycles < cycles && !ctx->gotFinish(); ++o.cycles) {
    m.clk_i = 1;
    m.eval();
    m.clk_i = 0;
    m.eval();
  }
  o.error = ctx->gotError();
  o.log = testing::internal::GetCapturedStdout();
  return o;
}
}  // namespace

TEST(RtlAssert, LegalStallRunsOn) {
  const Outcome o = stall(false, 32);
  EXPECT_FALSE(o.error) << o.log;
  EXPECT_EQ(o.cycles, 32);
}

TEST(RtlAssert, ValidDroppedWhileStalledStops) {
  const Outcome o = stall(true, 32);
  EXPECT_TRUE(o.error);
  EXPECT_LT(o.cycles, 32);
  EXPECT_NE(o.log.find("OutHandshake_hold"), std::string::npos) << o.log;
  EXPECT_NE(o.log.find("dropped or data_o changed while not out_ready_i"), std::string::npos) << o.log;
}
