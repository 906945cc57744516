// rtl/manifest.json against the tree: it lists every RTL file once, and each block's source list
// holds every module and package its files name (so a Verilator, Icarus or Yosys run of any top
// over that list elaborates).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "texunit/rtl_manifest.hpp"

namespace fs = std::filesystem;

namespace {
const std::string kRoot = TU_SOURCE_DIR;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Module / package name -> defining file, over every .sv under rtl/.
std::map<std::string, std::string> definitions() {
  std::map<std::string, std::string> def;
  const std::regex decl(R"((^|\n)\s*(module|package)\s+(\w+))");
  for (const auto& e : fs::recursive_directory_iterator(kRoot + "/rtl")) {
    if (e.path().extension() != ".sv") continue;
    const std::string t = slurp(e.path());
    for (auto it = std::sregex_iterator(t.begin(), t.end(), decl); it != std::sregex_iterator(); ++it)
      def[(*it)[3]] = fs::weakly_canonical(e.path()).string();
  }
  return def;
}
}  // namespace

TEST(RtlManifest, ListsEveryFileOnce) {
  const auto m = tu::rtl::Manifest::load(kRoot);
  std::map<std::string, int> listed;
  for (const auto& [name, f] : m.packages) ++listed[f];
  for (const auto& f : m.lint_only) ++listed[f];
  for (const auto& [name, b] : m.blocks)
    for (const auto& f : b.files) ++listed[f];
  for (const auto& [f, n] : listed) {
    EXPECT_EQ(n, 1) << f << " is listed " << n << " times in rtl/manifest.json";
    EXPECT_TRUE(fs::exists(m.rtl_dir + "/" + f)) << f << " (rtl/manifest.json) does not exist";
  }
  for (const auto& e : fs::recursive_directory_iterator(m.rtl_dir)) {
    if (e.path().extension() != ".sv") continue;
    const std::string rel = fs::relative(e.path(), m.rtl_dir).string();
    EXPECT_EQ(listed.count(rel), 1u) << "rtl/" << rel << " is in no block of rtl/manifest.json";
  }
  for (const auto& d : m.include_dirs) EXPECT_TRUE(fs::is_directory(m.rtl_dir + "/" + d)) << d;
}

TEST(RtlManifest, EveryBlockListHoldsWhatItsFilesName) {
  const auto m = tu::rtl::Manifest::load(kRoot);
  const auto def = definitions();
  const std::regex ident(R"(\btu_\w+)");
  size_t tops = 0;
  for (const auto& [name, b] : m.blocks) {
    std::set<std::string> have;
    for (const auto& f : m.sources(name)) have.insert(fs::weakly_canonical(f).string());
    for (const auto& t : b.tops) {
      ASSERT_TRUE(def.count(t)) << "blocks." << name << ".tops: no module " << t;
      EXPECT_TRUE(have.count(def.at(t))) << "blocks." << name << ": top " << t << " is not in its sources";
      ++tops;
    }
    for (const auto& f : b.files) {
      const std::string text = std::regex_replace(slurp(m.rtl_dir + "/" + f), std::regex("//[^\n]*"), "");
      for (auto it = std::sregex_iterator(text.begin(), text.end(), ident); it != std::sregex_iterator(); ++it)
        if (def.count(it->str()))
          EXPECT_TRUE(have.count(def.at(it->str())))
              << "blocks." << name << ": " << f << " names " << it->str() << ", whose file is not in the block's sources";
    }
    // Packages come first, tu_formats_pkg before the others.
    const auto src = m.sources(name);
    EXPECT_EQ(src.front(), m.rtl_dir + "/" + m.packages.at("tu_formats_pkg"));
  }
  EXPECT_GE(tops, 20u);
  EXPECT_EQ(m.block_of_top("tu_persp_setup"), "persp");
  EXPECT_THROW(m.block_of_top("tu_no_such_top"), std::invalid_argument);
}

TEST(RtlManifest, BadManifestNamesFileAndField) {
  const fs::path root = fs::temp_directory_path() / ("tu_manifest_test_" + std::to_string(::getpid()));
  fs::create_directories(root / "rtl");
  const std::string path = (root / "rtl/manifest.json").string();
  auto expect_error = [&](const std::string& body, const std::string& what) {
    std::ofstream(path) << body;
    try {
      tu::rtl::Manifest::load(root.string());
      ADD_FAILURE() << "accepted: " << body;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  const std::string pkgs = R"("packages": {"tu_formats_pkg": "0_pkg/tu_formats_pkg.sv"})";
  expect_error("{", "parse error");
  expect_error("{" + pkgs + R"(, "blocks": {"a": {"files": "x.sv"}}})", "blocks.a.files: expected an array");
  expect_error("{" + pkgs + R"(, "blocks": {"a": {"uses": ["b"]}}})", "blocks.a.uses: unknown block b");
  expect_error("{" + pkgs + R"(, "blocks": {"a": {"file": []}}})", "blocks.a.file: unknown field");
  expect_error(R"({"packages": {}, "blocks": {}})", "tu_formats_pkg missing");
  fs::remove_all(root);
}
