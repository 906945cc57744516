// The committed rtl/generated/ files must be exactly what the C model generates now.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "texunit/rtl_gen.hpp"

TEST(GeneratedRtl, IsFresh) {
  for (const auto& [rel, content] : tu::generated_rtl()) {
    std::ifstream in(std::string(TU_SOURCE_DIR) + "/" + rel, std::ios::binary);
    ASSERT_TRUE(in) << rel << " is missing: run `texunit gen-rtl`";
    std::ostringstream ss;
    ss << in.rdbuf();
    EXPECT_EQ(ss.str(), content) << rel << " is stale: run `texunit gen-rtl`";
  }
}
