// The checked output path (texunit/output.hpp): all or none, every write checked, children run
// and reaped. Also in the ASan/UBSan build (the signal handler's registry is used by every call).
#include "texunit/output.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <iterator>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>

#include "texunit/image.hpp"

namespace fs = std::filesystem;
using tu::out::Outputs;

namespace {

struct TmpDir {
  fs::path p = fs::temp_directory_path() / ("tu_output_test_" + std::to_string(::getpid()));
  TmpDir() { fs::create_directories(p); }
  ~TmpDir() { fs::remove_all(p); }
  std::string operator/(const std::string& name) const { return (p / name).string(); }
};

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string message(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

size_t entries(const fs::path& dir) { return static_cast<size_t>(std::distance(fs::directory_iterator(dir), fs::directory_iterator())); }

TEST(Output, FullDeviceIsAnErrorNamingTheFile) {
  // /dev/full fails every write with ENOSPC: a full disk without privileges.
  EXPECT_EQ(message([] { tu::out::write_file("/dev/full", "x", "t.png"); }),
            "t.png: cannot write the file (No space left on device)");
  // A streamed file larger than the stream's buffer: the error is kept and reported.
  EXPECT_EQ(message([] {
              tu::out::write_stream("/dev/full", [](std::ostream& os) { os << std::string(300000, 'a'); }, "v.vec");
            }),
            "v.vec: cannot write the file (No space left on device)");
}

TEST(Output, CommitRenamesEveryFileAndLeavesNoTemporary) {
  TmpDir d;
  {
    Outputs o;
    o.make_dir(d / "sub/deeper");
    o.write(d / "sub/deeper/a.txt", "alpha");
    o.write(d / "b.txt", [](std::ostream& os) { os << "beta " << 42 << '\n'; });
    o.commit();
  }
  EXPECT_EQ(slurp(d / "sub/deeper/a.txt"), "alpha");
  EXPECT_EQ(slurp(d / "b.txt"), "beta 42\n");
  EXPECT_EQ(entries(d.p), 2u);  // sub, b.txt: no hidden temporary
}

TEST(Output, AFailureLeavesNothingNotEvenTheDirectoriesItCreated) {
  TmpDir d;
  std::ofstream(d / "old.txt") << "old";
  {
    Outputs o;
    o.make_dir(d / "new/dir");
    o.write(d / "new/dir/x.txt", "x");
    o.write(d / "old.txt", "new");
    EXPECT_THROW(o.write(d / "missing/y.txt", "y"), std::runtime_error);
  }  // not committed
  EXPECT_FALSE(fs::exists(d / "new"));
  EXPECT_EQ(slurp(d / "old.txt"), "old");
  EXPECT_EQ(entries(d.p), 1u);
}

TEST(Output, TargetsAreCheckedWithWordedMessages) {
  TmpDir d;
  EXPECT_EQ(message([&] { tu::out::check_target(d / "no/f.json"); }),
            d / "no/f.json" + ": cannot write the file (directory '" + d / "no" + "' does not exist)");
  EXPECT_EQ(message([&] { tu::out::check_target(d.p.string()); }), d.p.string() + ": cannot write the file (it is a directory)");
  EXPECT_EQ(message([] { tu::out::check_target(""); }), "empty output file name");
  EXPECT_EQ(entries(d.p), 0u);  // a check creates nothing
}

TEST(Output, PublishedFilesAreRemovedUnlessKeptAndAbsorbMovesOwnership) {
  TmpDir d;
  {
    Outputs o;
    o.write(d / "p.dat", "1 2\n");
    o.publish();
    EXPECT_EQ(slurp(d / "p.dat"), "1 2\n");  // in place for a reader (gnuplot)
  }
  EXPECT_FALSE(fs::exists(d / "p.dat"));
  {
    Outputs outer;
    {
      Outputs part;
      part.write(d / "q.dat", "q");
      part.publish();
      outer.absorb(part);
    }  // `part` owns nothing any more
    EXPECT_TRUE(fs::exists(d / "q.dat"));
    outer.commit();
  }
  EXPECT_EQ(slurp(d / "q.dat"), "q");
}

TEST(Output, PngBytesEqualTheLibraryWriterAndAreWhole) {
  TmpDir d;
  tu::img::Gray8 g(5, 3, 7);
  tu::img::write_png_gray(d / "g.png", g);
  EXPECT_EQ(slurp(d / "g.png"), tu::img::png_gray(g, "g.png"));
  EXPECT_TRUE(tu::out::png_complete(d / "g.png"));
  const std::string whole = slurp(d / "g.png");
  std::ofstream(d / "cut.png", std::ios::binary) << whole.substr(0, whole.size() - 4);
  EXPECT_FALSE(tu::out::png_complete(d / "cut.png"));
  EXPECT_FALSE(tu::out::png_complete(d / "none.png"));
}

TEST(Output, ChildrenRunInTheirOwnGroupAndAreReaped) {
  std::string out;
  EXPECT_EQ(tu::out::run_capture("echo hello; echo err >&2", out), 0);
  EXPECT_EQ(out, "hello\n");
  const int st = tu::out::run("exit 3");
  ASSERT_TRUE(WIFEXITED(st));
  EXPECT_EQ(WEXITSTATUS(st), 3);
  std::string pg;
  tu::out::run_capture("ps -o pgid= -p $$", pg);
  EXPECT_NE(std::stol(pg), static_cast<long>(::getpgrp()));  // killable as a group, apart from the caller
  EXPECT_EQ(tu::out::shell_quoted("a'b c"), "'a'\\''b c'");
}

}  // namespace
