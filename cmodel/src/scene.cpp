#include "texunit/scene.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

namespace tu::scene {

using json = nlohmann::json;

namespace {

// A JSON object being validated: every access records the field, finish() rejects the rest.
class Node {
 public:
  Node(const json& j, std::string path, const std::string& source)
      : j_(j), path_(std::move(path)), source_(source) {
    if (!j_.is_object()) fail("expected an object");
  }
  [[noreturn]] void fail(const std::string& why) const {
    throw SceneError(source_ + ": " + (path_.empty() ? "/" : path_) + ": " + why);
  }
  [[noreturn]] void fail_at(const std::string& key, const std::string& why) const {
    throw SceneError(source_ + ": " + path_ + "/" + key + ": " + why);
  }
  bool has(const std::string& k) const { return j_.contains(k); }
  const json& raw(const std::string& k) {
    used_.insert(k);
    if (!j_.contains(k)) fail("missing field '" + k + "'");
    return j_.at(k);
  }
  Node obj(const std::string& k) { return Node(raw(k), path_ + "/" + k, source_); }
  double num(const std::string& k, double lo, double hi, std::optional<double> def = {}) {
    if (!has(k) && def) return used_.insert(k), *def;
    const json& v = raw(k);
    if (!v.is_number()) fail_at(k, "expected a number");
    const double x = v.get<double>();
    if (!(x >= lo && x <= hi))
      fail_at(k, "value " + v.dump() + " is out of range [" + fmt(lo) + ", " + fmt(hi) + "]");
    return x;
  }
  int integer(const std::string& k, int lo, int hi, std::optional<int> def = {}) {
    if (!has(k) && def) return used_.insert(k), *def;
    const json& v = raw(k);
    if (!v.is_number_integer()) fail_at(k, "expected an integer");
    const auto x = v.get<int64_t>();
    if (x < lo || x > hi)
      fail_at(k, "value " + v.dump() + " is out of range [" + std::to_string(lo) + ", " +
                     std::to_string(hi) + "]");
    return static_cast<int>(x);
  }
  std::string str(const std::string& k, std::optional<std::string> def = {},
                  const std::vector<std::string>& allowed = {}) {
    if (!has(k) && def) return used_.insert(k), *def;
    const json& v = raw(k);
    if (!v.is_string()) fail_at(k, "expected a string");
    const auto s = v.get<std::string>();
    if (!allowed.empty()) {
      bool ok = false;
      std::string list;
      for (const auto& a : allowed) {
        ok |= a == s;
        list += (list.empty() ? "" : ", ") + a;
      }
      if (!ok) fail_at(k, "'" + s + "' is not one of: " + list);
    }
    return s;
  }
  // A fixed-length array of numbers.
  std::vector<double> vec(const std::string& k, size_t n, std::optional<std::vector<double>> def = {}) {
    if (!has(k) && def) return used_.insert(k), *def;
    const json& v = raw(k);
    if (!v.is_array() || v.size() != n)
      fail_at(k, "expected an array of " + std::to_string(n) + " numbers");
    std::vector<double> out;
    for (size_t i = 0; i < n; ++i) {
      if (!v[i].is_number()) fail_at(k + "/" + std::to_string(i), "expected a number");
      out.push_back(v[i].get<double>());
      if (!std::isfinite(out.back())) fail_at(k + "/" + std::to_string(i), "not finite");
    }
    return out;
  }
  void finish() const {
    for (const auto& [k, v] : j_.items())
      if (!used_.count(k)) fail_at(k, "unknown field");
  }
  const std::string& path() const { return path_; }

 private:
  static std::string fmt(double x) {
    std::ostringstream os;
    os << x;
    return os.str();
  }
  const json& j_;
  std::string path_;
  const std::string& source_;
  std::set<std::string> used_;
};

bool pow2(int x) { return x > 0 && (x & (x - 1)) == 0; }

void parse_camera(Node n, persp::Camera& c) {
  const auto p = n.vec("position", 3), l = n.vec("look_at", 3), u = n.vec("up", 3, {{0, 1, 0}});
  for (int i = 0; i < 3; ++i) c.pos[i] = p[i], c.look_at[i] = l[i], c.up[i] = u[i];
  if (p == l) n.fail_at("look_at", "equals the position");
  c.fovy_deg = n.num("fovy_deg", 1, 170, 60.0);
  c.width = n.integer("width", 1, 4096);
  c.height = n.integer("height", 1, 4096);
  c.z_near = n.num("z_near", 1e-6, 1e6, 0.1);
  n.finish();
}

TextureSpec parse_texture(Node n, const std::string& name, const std::string& base_dir) {
  TextureSpec t;
  t.name = name;
  const bool has_png = n.has("png"), has_builtin = n.has("builtin");
  if (has_png == has_builtin) n.fail("give exactly one of 'png' or 'builtin'");
  if (has_builtin) {
    t.builtin = n.str("builtin", {}, {"checkerboard", "bricks"});
    t.size = n.integer("size", 1, 4096, 256);
    if (!pow2(t.size)) n.fail_at("size", "must be a power of two");
    if (t.builtin == "checkerboard") t.cells = n.integer("cells", 1, 4096, 8);
  } else {
    const std::string p = n.str("png");
    const std::filesystem::path fp = std::filesystem::path(p).is_absolute()
                                         ? std::filesystem::path(p)
                                         : std::filesystem::path(base_dir) / p;
    if (!std::filesystem::is_regular_file(fp))
      n.fail_at("png", "file '" + fp.string() + "' does not exist");
    t.png = fp.string();
  }
  t.wrap = n.str("wrap", std::string("repeat"), {"repeat", "clamp"}) == "clamp" ? tex::Wrap::Clamp
                                                                                : tex::Wrap::Repeat;
  n.finish();
  return t;
}

Material parse_material(Node n, const std::string& name, const Scene& s) {
  Material m;
  m.name = name;
  m.texture = n.str("texture");
  if (!s.textures.count(m.texture)) n.fail_at("texture", "unknown texture '" + m.texture + "'");
  const auto f = n.str("filter", std::string("ewa"), {"nearest", "bilinear", "trilinear", "ewa"});
  m.filter = f == "nearest" ? Filter::Nearest : f == "bilinear" ? Filter::Bilinear
             : f == "trilinear" ? Filter::Trilinear : Filter::Ewa;
  const auto w = n.str("weights", std::string("formula"), {"formula", "table1d", "table2d"});
  m.weights = w == "table1d" ? WeightSource::Table1d : w == "table2d" ? WeightSource::Table2d
                                                                      : WeightSource::Formula;
  m.max_aniso = n.num("max_aniso", 1, 64, 16.0);
  m.lod_bias = n.num("lod_bias", -16, 16, 0.0);
  m.min_lod = n.num("min_lod", 0, 12, 0.0);
  m.max_lod = n.num("max_lod", 0, 12, 12.0);
  if (m.min_lod > m.max_lod) n.fail_at("max_lod", "below min_lod");
  if (n.has("relief")) {
    Node r = n.obj("relief");
    Relief rel;
    rel.height_texture = r.str("height");
    if (!s.textures.count(rel.height_texture))
      r.fail_at("height", "unknown texture '" + rel.height_texture + "'");
    rel.scale = r.num("scale", 0, 1, 0.05);
    const auto meth = r.str("method", std::string("pom_adaptive"),
                            {"pom_fixed", "pom_adaptive", "iterative"});
    rel.method = meth == "pom_fixed" ? ReliefMethod::PomFixed
                 : meth == "iterative" ? ReliefMethod::Iterative : ReliefMethod::PomAdaptive;
    rel.layers = r.integer("layers", 1, 256, 32);
    r.finish();
    m.relief = rel;
  }
  n.finish();
  return m;
}

Object parse_object(Node n, const Scene& s, int index) {
  Object o;
  o.name = n.str("name", "object" + std::to_string(index));
  o.material = n.str("material");
  const auto mit = s.materials.find(o.material);
  if (mit == s.materials.end()) n.fail_at("material", "unknown material '" + o.material + "'");
  const auto type = n.str("type", {}, {"triangle", "quad"});
  const size_t nv = type == "quad" ? 4 : 3;
  const json& vs = n.raw("vertices");
  const json& uvs = n.raw("uv");
  if (!vs.is_array() || vs.size() != nv)
    n.fail_at("vertices", "expected " + std::to_string(nv) + " vertices for a " + type);
  if (!uvs.is_array() || uvs.size() != nv)
    n.fail_at("uv", "expected " + std::to_string(nv) + " uv pairs for a " + type);
  persp::Vertex v[4];
  for (size_t i = 0; i < nv; ++i) {
    const auto bad = [&](const char* f, size_t k) {
      n.fail_at(std::string(f) + "/" + std::to_string(i), "expected an array of " +
                                                              std::to_string(k) + " numbers");
    };
    if (!vs[i].is_array() || vs[i].size() != 3) bad("vertices", 3);
    if (!uvs[i].is_array() || uvs[i].size() != 2) bad("uv", 2);
    for (int k = 0; k < 3; ++k) {
      if (!vs[i][k].is_number()) bad("vertices", 3);
      v[i].p[k] = vs[i][k].get<double>();
    }
    for (int k = 0; k < 2; ++k) {
      if (!uvs[i][k].is_number()) bad("uv", 2);
      v[i].uv[k] = uvs[i][k].get<double>();  // texture repeats; see in_texels()
    }
  }
  auto tri = [&](int a, int b, int c, const char* suffix) {
    persp::Triangle t;
    t.name = o.name + suffix;
    t.v[0] = v[a], t.v[1] = v[b], t.v[2] = v[c];
    o.triangles.push_back(t);
  };
  if (nv == 3) tri(0, 1, 2, "");
  else tri(0, 1, 2, "#0"), tri(0, 2, 3, "#1");
  n.finish();
  return o;
}

}  // namespace

Scene parse(const std::string& text, const std::string& source, const std::string& base_dir) {
  json j;
  try {
    j = json::parse(text);
  } catch (const json::parse_error& e) {
    // Byte offset -> line number.
    const size_t at = std::min(e.byte, text.size());
    const auto line = 1 + std::count(text.begin(), text.begin() + static_cast<long>(at ? at - 1 : 0), '\n');
    throw SceneError(source + ":" + std::to_string(line) + ": malformed JSON (" + e.what() + ")");
  }
  Scene s;
  s.source = source;
  Node root(j, "", s.source);
  if (root.integer("texunit_scene", 1, 1) != 1) root.fail("unsupported version");
  parse_camera(root.obj("camera"), s.camera);
  {
    Node texs = root.obj("textures");
    for (const auto& [name, v] : root.raw("textures").items()) {
      s.textures[name] = parse_texture(texs.obj(name), name, base_dir);
    }
    texs.finish();
    if (s.textures.empty()) texs.fail("declares no texture");
  }
  {
    Node mats = root.obj("materials");
    for (const auto& [name, v] : root.raw("materials").items())
      s.materials[name] = parse_material(mats.obj(name), name, s);
    mats.finish();
  }
  const json& objs = root.raw("objects");
  if (!objs.is_array() || objs.empty()) root.fail_at("objects", "expected a non-empty array");
  for (size_t i = 0; i < objs.size(); ++i)
    s.objects.push_back(parse_object(Node(objs[i], "/objects/" + std::to_string(i), s.source), s,
                                     static_cast<int>(i)));
  if (root.has("error_budget")) {
    Node b = root.obj("error_budget");
    s.budget.max_texel_err = b.num("max_texel_err", 1e-6, 16, s.budget.max_texel_err);
    s.budget.min_psnr_db = b.num("min_psnr_db", 0, 100, s.budget.min_psnr_db);
    b.finish();
  }
  root.finish();
  return s;
}

Scene load(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path + ": cannot open file");
  std::ostringstream ss;
  ss << in.rdbuf();
  return parse(ss.str(), path, std::filesystem::path(path).parent_path().string());
}

const std::string& default_scene_json() {
  static const std::string text = R"({
  "texunit_scene": 1,
  "camera": {"position": [0, 1.5, 0], "look_at": [0.6, 1.0, -10], "up": [0, 1, 0],
             "fovy_deg": 60, "width": 256, "height": 192, "z_near": 0.1},
  "textures": {
    "checker": {"builtin": "checkerboard", "size": 256, "cells": 8, "wrap": "repeat"},
    "bricks": {"builtin": "bricks", "size": 256, "wrap": "repeat"}
  },
  "materials": {
    "ground": {"texture": "checker", "filter": "ewa", "weights": "formula", "max_aniso": 16},
    "wall": {"texture": "bricks", "filter": "ewa", "weights": "table1d", "max_aniso": 16,
             "relief": {"height": "bricks", "scale": 0.04, "method": "pom_adaptive", "layers": 32}}
  },
  "objects": [
    {"name": "ground", "type": "quad", "material": "ground",
     "vertices": [[-20, 0, -0.5], [20, 0, -0.5], [20, 0, -160], [-20, 0, -160]],
     "uv": [[0, 0], [4, 0], [4, 16], [0, 16]]},
    {"name": "wall", "type": "quad", "material": "wall",
     "vertices": [[2.5, 0, -1.5], [3.5, 0, -40], [3.5, 4, -40], [2.5, 4, -1.5]],
     "uv": [[0, 1], [8, 1], [8, 0], [0, 0]]}
  ],
  "error_budget": {"max_texel_err": 0.0625, "min_psnr_db": 35}
}
)";
  return text;
}

Scene default_scene() { return parse(default_scene_json(), "<default scene>", "."); }

Scene without_relief(Scene s) {
  for (auto& [name, m] : s.materials) m.relief.reset();
  return s;
}

std::vector<persp::Triangle> in_texels(const Object& o, int tex_width, int tex_height) {
  std::vector<persp::Triangle> out = o.triangles;
  for (auto& t : out)
    for (auto& v : t.v) v.uv[0] *= tex_width, v.uv[1] *= tex_height;
  return out;
}

tex::Texture build_texture(const Scene& s, const std::string& name) {
  const auto it = s.textures.find(name);
  if (it == s.textures.end()) throw SceneError(s.source + ": unknown texture '" + name + "'");
  const TextureSpec& t = it->second;
  const std::string where = s.source + ": /textures/" + name;
  try {
    if (t.builtin == "checkerboard")
      return tex::Texture::build(where, tex::checkerboard(t.size, t.cells), t.wrap);
    if (t.builtin == "bricks") return tex::Texture::build(where, tex::bricks(t.size).color, t.wrap);
    return tex::Texture::build(where + " (" + t.png + ")", img::read_png_rgba(t.png), t.wrap);
  } catch (const std::invalid_argument& e) {
    throw SceneError(e.what());
  } catch (const std::runtime_error& e) {
    throw SceneError(where + ": " + e.what());
  }
}

const char* to_string(Filter f) {
  switch (f) {
    case Filter::Nearest: return "nearest";
    case Filter::Bilinear: return "bilinear";
    case Filter::Trilinear: return "trilinear";
    case Filter::Ewa: return "ewa";
  }
  return "?";
}
const char* to_string(WeightSource w) {
  return w == WeightSource::Formula ? "formula" : w == WeightSource::Table1d ? "table1d" : "table2d";
}
const char* to_string(ReliefMethod m) {
  return m == ReliefMethod::PomFixed ? "pom_fixed" : m == ReliefMethod::PomAdaptive ? "pom_adaptive"
                                                                                    : "iterative";
}

}  // namespace tu::scene
