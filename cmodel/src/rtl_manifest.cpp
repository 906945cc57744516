#include "texunit/rtl_manifest.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <set>
#include <stdexcept>

namespace tu::rtl {

namespace {
using json = nlohmann::json;

std::vector<std::string> strings(const json& j, const std::string& key, const std::string& where) {
  std::vector<std::string> out;
  if (!j.contains(key)) return out;
  if (!j.at(key).is_array()) throw std::runtime_error(where + "." + key + ": expected an array of strings");
  for (const auto& s : j.at(key)) {
    if (!s.is_string()) throw std::runtime_error(where + "." + key + ": expected an array of strings");
    out.push_back(s.get<std::string>());
  }
  return out;
}
}  // namespace

Manifest Manifest::load(const std::string& root) {
  Manifest m;
  m.rtl_dir = root + "/rtl";
  const std::string path = m.rtl_dir + "/manifest.json";
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open the RTL manifest");
  json j;
  try {
    j = json::parse(in);
  } catch (const json::parse_error& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
  if (!j.is_object() || !j.contains("blocks") || !j.at("blocks").is_object() || !j.contains("packages") ||
      !j.at("packages").is_object())
    throw std::runtime_error(path + ": expected an object with \"packages\" and \"blocks\" objects");
  m.include_dirs = strings(j, "include_dirs", path);
  m.lint_only = strings(j, "lint_only", path);
  for (const auto& [name, file] : j.at("packages").items()) {
    if (!file.is_string()) throw std::runtime_error(path + ": packages." + name + ": expected a file name");
    m.packages[name] = file.get<std::string>();
  }
  if (!m.packages.count("tu_formats_pkg")) throw std::runtime_error(path + ": packages: tu_formats_pkg missing");
  for (const auto& [name, b] : j.at("blocks").items()) {
    const std::string where = path + ": blocks." + name;
    if (!b.is_object()) throw std::runtime_error(where + ": expected an object");
    for (const auto& [key, v] : b.items())
      if (key != "uses" && key != "packages" && key != "files" && key != "tops")
        throw std::runtime_error(where + "." + key + ": unknown field (uses, packages, files, tops)");
    Block blk{strings(b, "uses", where), strings(b, "packages", where), strings(b, "files", where),
              strings(b, "tops", where)};
    for (const auto& p : blk.packages)
      if (!m.packages.count(p)) throw std::runtime_error(where + ".packages: unknown package " + p);
    m.blocks[name] = std::move(blk);
  }
  for (const auto& [name, b] : m.blocks)
    for (const auto& u : b.uses)
      if (!m.blocks.count(u)) throw std::runtime_error(path + ": blocks." + name + ".uses: unknown block " + u);
  return m;
}

const std::string& Manifest::block_of_top(const std::string& top) const {
  for (const auto& [name, b] : blocks)
    if (std::find(b.tops.begin(), b.tops.end(), top) != b.tops.end()) return name;
  throw std::invalid_argument("RTL top '" + top + "' is in no block's \"tops\" in " + rtl_dir + "/manifest.json");
}

std::vector<std::string> Manifest::sources(const std::string& block) const {
  std::vector<std::string> pkgs = {"tu_formats_pkg"}, files;
  std::set<std::string> seen, visiting;
  std::function<void(const std::string&)> visit = [&](const std::string& name) {
    const auto it = blocks.find(name);
    if (it == blocks.end()) throw std::invalid_argument("no RTL block '" + name + "' in " + rtl_dir + "/manifest.json");
    if (!visiting.insert(name).second) throw std::runtime_error(rtl_dir + "/manifest.json: blocks." + name + ": uses itself");
    for (const auto& u : it->second.uses) visit(u);
    for (const auto& p : it->second.packages)
      if (std::find(pkgs.begin(), pkgs.end(), p) == pkgs.end()) pkgs.push_back(p);
    for (const auto& f : it->second.files)
      if (seen.insert(f).second) files.push_back(f);
    visiting.erase(name);
  };
  visit(block);
  std::vector<std::string> out;
  for (const auto& p : pkgs) out.push_back(rtl_dir + "/" + packages.at(p));
  for (const auto& f : files) out.push_back(rtl_dir + "/" + f);
  return out;
}

std::vector<std::string> Manifest::top_sources(const std::string& top) const { return sources(block_of_top(top)); }

std::vector<std::string> Manifest::tops() const {
  std::vector<std::string> out;
  for (const auto& [name, b] : blocks) out.insert(out.end(), b.tops.begin(), b.tops.end());
  return out;
}

std::vector<std::string> Manifest::all_sources() const {
  std::vector<std::string> out;
  for (const auto& [name, file] : packages) out.push_back(rtl_dir + "/" + file);
  std::set<std::string> files;
  for (const auto& [name, b] : blocks) files.insert(b.files.begin(), b.files.end());
  for (const auto& f : files) out.push_back(rtl_dir + "/" + f);
  return out;
}

std::vector<std::string> Manifest::headers() const {
  std::vector<std::string> out;
  for (const auto& d : include_dirs)
    for (const auto& e : std::filesystem::directory_iterator(rtl_dir + "/" + d))
      if (e.path().extension() == ".svh") out.push_back(rtl_dir + "/" + d + "/" + e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace tu::rtl
