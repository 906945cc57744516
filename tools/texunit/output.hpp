// A command's output files, written all or none. Each output is written to a temporary file
// beside its target (stage()) and renamed into place by commit() once every output and every
// check has succeeded; a command that throws before commit() leaves nothing behind (the
// destructor removes the temporaries and any directory make_dir() created). Targets are checked
// up front (their directory exists, they are not a directory), so an impossible output fails the
// command before the work, with a worded message.
#pragma once

#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace tu::cli {

class Outputs {
 public:
  Outputs() = default;
  Outputs(const Outputs&) = delete;
  Outputs& operator=(const Outputs&) = delete;
  ~Outputs();
  // Creates `dir` (and missing parents) unless it exists; removed again on failure.
  void make_dir(const std::string& dir);
  // Returns the temporary path to write `path` to (throws a worded std::runtime_error when the
  // target cannot be written: missing directory, the target is a directory).
  std::string stage(const std::string& path);
  // Renames every staged file into place, in stage() order.
  void commit();

 private:
  std::vector<std::pair<std::string, std::string>> files_;  // temporary, target
  std::vector<std::string> created_dirs_;                   // outermost first
  bool committed_ = false;
};

// A file-system error as a sentence: "PATH: cannot WHAT (reason)", without the library's
// "filesystem error: ..." text.
std::string fs_message(const std::string& path, const std::string& what, const std::error_code& ec);

}  // namespace tu::cli
