#include "output.hpp"

#include <filesystem>
#include <stdexcept>
#include <system_error>
#include <unistd.h>

namespace fs = std::filesystem;

namespace tu::cli {

std::string fs_message(const std::string& path, const std::string& what, const std::error_code& ec) {
  return path + ": cannot " + what + " (" + ec.message() + ")";
}

Outputs::~Outputs() {
  if (committed_) return;
  std::error_code ec;
  for (const auto& [tmp, target] : files_) fs::remove(tmp, ec);
  for (auto it = created_dirs_.rbegin(); it != created_dirs_.rend(); ++it) fs::remove(*it, ec);  // only if empty
}

void Outputs::make_dir(const std::string& dir) {
  std::error_code ec;
  if (fs::is_directory(dir, ec)) return;
  if (fs::exists(dir, ec)) throw std::runtime_error(dir + ": cannot create the directory (a file of that name exists)");
  // Record each missing level, outermost first, so that a failure removes exactly those.
  std::vector<fs::path> missing;
  for (fs::path p = fs::path(dir).lexically_normal(); !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
    missing.insert(missing.begin(), p);
    if (p == p.parent_path()) break;
  }
  for (const auto& p : missing) {
    if (!fs::create_directory(p, ec) && ec) throw std::runtime_error(fs_message(p.string(), "create the directory", ec));
    created_dirs_.push_back(p.string());
  }
}

std::string Outputs::stage(const std::string& path) {
  if (path.empty()) throw std::runtime_error("empty output file name");
  std::error_code ec;
  const fs::path target(path);
  if (fs::is_directory(target, ec)) throw std::runtime_error(path + ": cannot write the file (it is a directory)");
  const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  if (!fs::is_directory(dir, ec))
    throw std::runtime_error(path + ": cannot write the file (directory '" + dir.string() + "' does not exist)");
  if (access(dir.c_str(), W_OK) != 0)
    throw std::runtime_error(path + ": cannot write the file (directory '" + dir.string() + "' is not writable)");
  const std::string tmp =
      (dir / ("." + target.filename().string() + ".texunit-" + std::to_string(getpid()) + "-" +
              std::to_string(files_.size()) + ".tmp"))
          .string();
  files_.emplace_back(tmp, path);
  return tmp;
}

void Outputs::commit() {
  for (const auto& [tmp, target] : files_) {
    std::error_code ec;
    if (!fs::exists(tmp, ec)) throw std::runtime_error(target + ": cannot write the file (nothing was written)");
    fs::rename(tmp, target, ec);
    if (ec) throw std::runtime_error(fs_message(target, "write the file", ec));
  }
  committed_ = true;
}

}  // namespace tu::cli
