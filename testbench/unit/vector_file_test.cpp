// Vector file format: round trip, and every malformed input rejected with file:line and reason.
#include <gtest/gtest.h>

#include <filesystem>

#include "block.hpp"
#include "vector_file.hpp"

namespace {
using namespace tu;

const char* kGood =
    "# texunit-vectors 1\n# block: reciprocal\n# set: golden\n# seed: 7\n"
    "# fields: q:in:s24.16 mant:out:u25.24 shift:out:u5.0 flag:out:u1.0 ref:ref:f64\n"
    "010000 1000000 10 0 3ff0000000000000\n";

std::string error_of(const std::string& text) {
  try {
    vec::parse(text, "t.vec");
  } catch (const vec::FormatError& e) {
    return e.what();
  }
  return "";
}

TEST(VectorFile, ParsesAndRoundTrips) {
  const auto v = vec::parse(kGood, "t.vec");
  EXPECT_EQ(v.block, "reciprocal");
  EXPECT_EQ(v.seed, 7u);
  ASSERT_EQ(v.rows.size(), 1u);
  EXPECT_EQ(v.rows[0][0], 0x10000u);
  EXPECT_EQ(vec::bits_f64(v.rows[0][4]), 1.0);
  EXPECT_EQ(vec::serialise(v), kGood);
}

TEST(VectorFile, RejectsMalformedInputWithLine) {
  const std::string head =
      "# texunit-vectors 1\n# block: reciprocal\n# set: golden\n# seed: 7\n"
      "# fields: q:in:s24.16 mant:out:u25.24 shift:out:u5.0 flag:out:u1.0 ref:ref:f64\n";
  EXPECT_EQ(error_of(""), "t.vec:1: empty file or missing header '# texunit-vectors 1'");
  EXPECT_EQ(error_of("010000\n"), "t.vec:1: expected header '# texunit-vectors 1' as the first line");
  EXPECT_EQ(error_of(head + "010000 1000000 10 0\n"), "t.vec:6: expected 5 fields, found 4");
  EXPECT_EQ(error_of(head + "0100000 1000000 10 0 0\n"),
            "t.vec:6: field 'q': '0100000' has more than 6 hex digits");
  EXPECT_EQ(error_of(head + "01000g 1000000 10 0 0\n"),
            "t.vec:6: field 'q': '01000g' is not hexadecimal");
  EXPECT_EQ(error_of(head + "010000 1000000 20 0 0\n"),
            "t.vec:6: field 'shift': 20 does not fit in 5 bits");
  EXPECT_EQ(error_of("# texunit-vectors 1\n# block: x\n# set: s\n# seed: 1\n# fields: a:bad:u8.0\n"),
            "t.vec:5: field 'a': role 'bad' is not in/out/ref");
  EXPECT_EQ(error_of("# texunit-vectors 1\n# block: x\n# set: s\n# seed: 1\n# fields: a:in:q8\n"),
            "t.vec:5: field 'a': format 'q8' is not sW.F, uW.F or f64");
  EXPECT_EQ(error_of("# texunit-vectors 1\n# block: x\n# seed: z\n"),
            "t.vec:3: seed 'z' is not an unsigned integer");
  EXPECT_EQ(error_of("# texunit-vectors 1\n# block: x\n00\n"),
            "t.vec:3: data line before the header declared block, set, seed and fields");
}

TEST(VectorFile, MissingFileNamesThePath) {
  try {
    vec::read("/nonexistent/x.vec");
    FAIL();
  } catch (const vec::FormatError& e) {
    EXPECT_STREQ(e.what(), "/nonexistent/x.vec:0: cannot open file");
  }
}

// `--shard K/N` (texunit/shard.hpp): the N shards' rows tile every block's sets in order, the
// header round-trips, and a malformed shard header names the line.
TEST(VectorFile, ShardsTileTheSetAndRoundTrip) {
  for (const auto& b : blocks::all()) {
    for (const auto& set : b.sets) {
      const auto whole = blocks::generate(b, set, 301, 9);
      std::vector<std::vector<uint64_t>> joined;
      for (uint64_t k = 0; k < 3; ++k) {
        const auto part = blocks::generate(b, set, 301, 9, 1, Shard{k, 3});
        EXPECT_EQ(part.shard, std::to_string(k) + "/3");
        EXPECT_EQ(part.first_vector, joined.size()) << b.name << " " << set;
        const auto back = vec::parse(vec::serialise(part), "mem");
        EXPECT_EQ(back.shard, part.shard);
        EXPECT_EQ(back.first_vector, part.first_vector);
        joined.insert(joined.end(), part.rows.begin(), part.rows.end());
      }
      EXPECT_EQ(joined, whole.rows) << b.name << " " << set;
    }
  }
  const std::string head = "# texunit-vectors 1\n# block: reciprocal\n# set: golden\n# seed: 7\n";
  EXPECT_EQ(error_of(head + "# shard: 3/3 first 0\n"),
            "t.vec:5: shard '3/3 first 0' is not 'K/N first F' (0 <= K < N, F a decimal row index)");
  EXPECT_EQ(error_of(head + "# shard: 1/3\n"),
            "t.vec:5: shard '1/3' is not 'K/N first F' (0 <= K < N, F a decimal row index)");
  EXPECT_EQ(Shard::parse("2/3").range(10), (std::pair<uint64_t, uint64_t>(6, 10)));
  EXPECT_EQ(Shard::parse("1/4").range(~0ull).first, 0x3fffffffffffffffull);  // no 64-bit overflow
  EXPECT_THROW(Shard::parse("1/0"), std::invalid_argument);
  EXPECT_THROW(Shard::parse("-1/4"), std::invalid_argument);
  EXPECT_EQ(Shard::parse("15/16").str(), "15/16");
}

TEST(VectorFile, GeneratedSetsRoundTripAndMatchTheModel) {
  for (const auto& b : blocks::all()) {
    for (const auto& set : b.sets) {
      const auto v = blocks::generate(b, set, 500, 3);
      ASSERT_FALSE(v.rows.empty()) << b.name << " " << set;
      const auto back = vec::parse(vec::serialise(v), "mem");
      EXPECT_EQ(back.rows, v.rows);
      const auto in = v.indices(vec::Role::In), out = v.indices(vec::Role::Out);
      for (const auto& r : v.rows) EXPECT_EQ(b.model(blocks::pick(r, in)), blocks::pick(r, out));
    }
  }
}

TEST(VectorFile, CommittedGoldenSetsAreCurrent) {
  // vectors/golden/<block>.vec must equal what the generator writes today.
  for (const auto& b : blocks::all()) {
    const std::string path = std::string(TU_SOURCE_DIR) + "/vectors/golden/" + b.name + ".vec";
    ASSERT_TRUE(std::filesystem::exists(path))
        << path << " missing: texunit vectors --block " << b.name << " --set golden --out " << path;
    const auto committed = vec::read(path);
    const auto fresh = blocks::generate(b, "golden", 0, committed.seed);
    EXPECT_EQ(vec::serialise(committed), vec::serialise(fresh)) << path << " is stale";
  }
}
}  // namespace
