#include "texunit/scene.hpp"

#include "gauss/clip.hpp"
#include "texture/texel_format.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "texunit/formats.hpp"
#include "texunit/text.hpp"

namespace tu::scene {

using json = nlohmann::json;

SceneError::SceneError(const std::string& what) : std::runtime_error(printable(what)) {}

namespace {

// Line (1-based) of byte offset `at` in `text`.
size_t line_of(const std::string& text, size_t at) {
  at = std::min(at, text.size());
  return 1 + static_cast<size_t>(std::count(text.begin(), text.begin() + static_cast<long>(at ? at - 1 : 0), '\n'));
}

// nlohmann's DOM builder behind a SAX filter that is stricter than json::parse: a key repeated
// in one object is an error naming it (json::parse keeps the last), and every parse error names
// the line, a number outside double's range included (json::parse throws that one without a
// position).
class StrictSax {
 public:
  using Dom = nlohmann::detail::json_sax_dom_parser<json>;
  StrictSax(json& root, const std::string& text, const std::string& source)
      : dom_(root), text_(text), source_(source) {}
  bool null() { return value(), dom_.null(); }
  bool boolean(bool b) { return value(), dom_.boolean(b); }
  bool number_integer(json::number_integer_t x) { return value(), dom_.number_integer(x); }
  bool number_unsigned(json::number_unsigned_t x) { return value(), dom_.number_unsigned(x); }
  bool number_float(json::number_float_t x, const std::string& s) { return value(), dom_.number_float(x, s); }
  bool string(std::string& s) { return value(), dom_.string(s); }
  bool binary(json::binary_t& b) { return value(), dom_.binary(b); }
  bool start_object(std::size_t n) {
    value();
    frames_.push_back({false, 0, {}, {}});
    return dom_.start_object(n);
  }
  bool key(std::string& k) {
    Frame& f = frames_.back();
    if (!f.keys.insert(k).second) {
      f.key = k;
      throw SceneError(source_ + ": " + pointer() + ": duplicate key (a key appears once per object)");
    }
    f.key = k;
    return dom_.key(k);
  }
  bool end_object() { return frames_.pop_back(), dom_.end_object(); }
  bool start_array(std::size_t n) {
    value();
    frames_.push_back({true, 0, {}, {}});
    return dom_.start_array(n);
  }
  bool end_array() { return frames_.pop_back(), dom_.end_array(); }
  bool parse_error(std::size_t at, const std::string& token, const nlohmann::detail::exception& e) {
    const std::string where = source_ + ":" + std::to_string(line_of(text_, at)) + ": ";
    if (e.id == 406) throw SceneError(where + "number " + token + " is outside double's range");
    throw SceneError(where + "malformed JSON (" + e.what() + ")");
  }

 private:
  struct Frame {
    bool array;
    size_t index;  // arrays: elements seen so far
    std::string key;  // objects: the current key
    std::set<std::string> keys;
  };
  void value() {
    if (!frames_.empty() && frames_.back().array) ++frames_.back().index;
  }
  std::string pointer() const {
    std::string p;
    for (const auto& f : frames_) p += "/" + (f.array ? std::to_string(f.index - 1) : f.key);
    return p;
  }
  Dom dom_;
  const std::string& text_;
  const std::string& source_;
  std::vector<Frame> frames_;
};

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
  bool boolean(const std::string& k) {
    const json& v = raw(k);
    if (!v.is_boolean()) fail_at(k, "expected true or false");
    return v.get<bool>();
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
  // A fixed-length array of numbers, each of magnitude <= max_abs.
  std::vector<double> vec(const std::string& k, size_t n, double max_abs,
                          std::optional<std::vector<double>> def = {}) {
    if (!has(k) && def) return used_.insert(k), *def;
    return numbers(raw(k), k, n, max_abs);
  }
  // The same for an array element `json_at` of field k (k names it in messages, e.g. "uv/2").
  std::vector<double> numbers(const json& v, const std::string& k, size_t n, double max_abs) const {
    if (!v.is_array() || v.size() != n)
      fail_at(k, "expected an array of " + std::to_string(n) + " numbers");
    std::vector<double> out;
    for (size_t i = 0; i < n; ++i) {
      if (!v[i].is_number()) fail_at(k, "expected an array of " + std::to_string(n) + " numbers");
      out.push_back(v[i].get<double>());
      if (!(std::fabs(out.back()) <= max_abs))
        fail_at(k + "/" + std::to_string(i),
                "value " + v[i].dump() + " is out of range [-" + fmt(max_abs) + ", " + fmt(max_abs) + "]");
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

// Validated magnitudes (docs/scene-format.md): world coordinates and uv stay where double
// arithmetic of the set-up and of the float reference is exact enough and every float->int
// conversion is defined.
constexpr double kMaxCoord = 1e6;  // |x|, |y|, |z| of camera and vertices, world units
constexpr double kMaxUv = 65536;   // |u|, |v|, texture repeats
// Vectors a, b with |a x b| <= kParallel |a| |b| count as parallel (sin of the angle; a triangle
// with edges this close to collinear has zero area).
constexpr double kParallel = 1e-12;

void parse_camera(Node n, persp::Camera& c) {
  const auto p = n.vec("position", 3, kMaxCoord), l = n.vec("look_at", 3, kMaxCoord);
  const auto u = n.vec("up", 3, kMaxCoord, {{0, 1, 0}});
  for (int i = 0; i < 3; ++i) c.pos[i] = p[i], c.look_at[i] = l[i], c.up[i] = u[i];
  if (p == l) n.fail_at("look_at", "equals the position");
  // The camera basis is right = normalize(view x up): up must be non-zero and not along the view.
  const double d[3] = {l[0] - p[0], l[1] - p[1], l[2] - p[2]};
  const double x[3] = {d[1] * u[2] - d[2] * u[1], d[2] * u[0] - d[0] * u[2], d[0] * u[1] - d[1] * u[0]};
  const double dn = std::hypot(d[0], d[1], d[2]), un = std::hypot(u[0], u[1], u[2]);
  if (!(un > 0)) n.fail_at("up", "is the zero vector");
  if (!(std::hypot(x[0], x[1], x[2]) > kParallel * dn * un))
    n.fail_at("up", "is parallel to the view direction (look_at - position)");
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
  // `wrap` sets both axes; `wrap_u` / `wrap_v` override one.
  const std::vector<std::string> modes(std::begin(kWrapNames), std::end(kWrapNames));
  auto wrap_of = [&](const std::string& k, tex::Wrap def) {
    if (!n.has(k)) return def;
    const std::string m = n.str(k, {}, modes);
    return static_cast<tex::Wrap>(std::find(modes.begin(), modes.end(), m) - modes.begin());
  };
  const tex::Wrap both = wrap_of("wrap", tex::Wrap::Repeat);
  const std::vector<std::string> formats(std::begin(tex::kTexelFormatNames), std::end(tex::kTexelFormatNames));
  const std::string fm = n.str("format", std::string("rgba8"), formats);
  t.format = static_cast<int>(std::find(formats.begin(), formats.end(), fm) - formats.begin());
  t.srgb = n.has("srgb") ? n.boolean("srgb") : false;
  const std::vector<std::string> mips(std::begin(tex::kMipFilterNames), std::end(tex::kMipFilterNames));
  const std::string mf = n.str("mip_filter", std::string("box"), mips);
  t.mip_filter = static_cast<int>(std::find(mips.begin(), mips.end(), mf) - mips.begin());
  t.addressing.u = wrap_of("wrap_u", both);
  t.addressing.v = wrap_of("wrap_v", both);
  if (n.has("border")) {
    const auto c = n.vec("border", 4, 1e300);  // (the range check below names [0, 255])
    uint8_t* ch[4] = {&t.addressing.border.r, &t.addressing.border.g, &t.addressing.border.b, &t.addressing.border.a};
    for (size_t i = 0; i < 4; ++i) {
      if (c[i] < 0 || c[i] > 255 || c[i] != std::floor(c[i]))
        n.fail_at("border/" + std::to_string(i), "expected an integer in [0, 255]");
      *ch[i] = static_cast<uint8_t>(c[i]);
    }
  }
  n.finish();
  return t;
}

Procedural parse_procedural(Node p) {
  Procedural pr;
  const auto kind = p.str("kind", {}, {"fbm", "smoke", "water"});
  pr.kind = kind == "smoke" ? ProceduralKind::Smoke : kind == "water" ? ProceduralKind::Water : ProceduralKind::Fbm;
  pr.octaves = p.integer("octaves", 1, fmt::kNoiseOctaves, fmt::kNoiseOctaves);
  // f / texture width < 256 keeps the frequency code in u32.24 (docs/blocks/noise-appendix.md §5).
  pr.frequency = p.num("frequency", 1.0 / 256, 128, 8.0);
  pr.seed = p.integer("seed", 0, 255, 0);
  pr.time = p.num("time", -1e6, 1e6, 0.0);
  pr.speed = p.num("speed", 0, 256, pr.kind == ProceduralKind::Smoke ? 1.0 : 0.0);
  pr.footprint_limit = p.has("footprint_limit") ? p.boolean("footprint_limit") : true;
  if (pr.kind == ProceduralKind::Smoke) {
    pr.threshold = p.num("threshold", 0, 0.99, pr.threshold);
    pr.gain = p.num("gain", 0, 255, pr.gain);
  }
  if (pr.kind == ProceduralKind::Water) {
    pr.amplitude = p.num("amplitude", 0, 16, pr.amplitude);
    if (p.has("light")) {
      const auto l = p.vec("light", 3, 1e6);
      if (!(std::hypot(l[0], l[1], l[2]) > 0)) p.fail_at("light", "is the zero vector");
      for (size_t i = 0; i < 3; ++i) pr.light[i] = l[i];
    }
  }
  for (const char* k : {"color0", "color1"}) {
    if (!p.has(k)) continue;
    const auto c = p.vec(k, 3, 255);
    for (size_t i = 0; i < 3; ++i)
      if (c[i] < 0) p.fail_at(std::string(k) + "/" + std::to_string(i), "value is out of range [0, 255]");
    auto& dst = std::string(k) == "color0" ? pr.color0 : pr.color1;
    for (size_t i = 0; i < 3; ++i) dst[i] = c[i];
  }
  p.finish();
  return pr;
}

Material parse_material(Node n, const std::string& name, const Scene& s) {
  Material m;
  m.name = name;
  m.texture = n.str("texture");
  if (!s.textures.count(m.texture)) n.fail_at("texture", "unknown texture '" + m.texture + "'");
  const auto f = n.str("filter", std::string("ewa"), {"nearest", "bilinear", "trilinear", "ewa", "feline"});
  m.filter = f == "nearest" ? Filter::Nearest : f == "bilinear" ? Filter::Bilinear
             : f == "trilinear" ? Filter::Trilinear : f == "feline" ? Filter::Feline : Filter::Ewa;
  m.feline_max_probes = n.integer("feline_max_probes", 1, fmt::kFelNMax, 8);
  const auto w = n.str("weights", std::string("formula"), {"formula", "table1d", "table2d"});
  m.weights = w == "table1d" ? WeightSource::Table1d : w == "table2d" ? WeightSource::Table2d
                                                                      : WeightSource::Formula;
  std::vector<std::string> clips{"off"};
  for (const auto& v : clip::variants()) clips.push_back(v.name);
  m.clip = n.str("clip", std::string("off"), clips);
  if (m.clip == "off") m.clip.clear();
  m.max_aniso = n.num("max_aniso", 1, 64, 16.0);
  m.lod_bias = n.num("lod_bias", -16, 16, 0.0);
  m.min_lod = n.num("min_lod", 0, 12, 0.0);
  m.max_lod = n.num("max_lod", 0, 12, 12.0);
  // min_lod > max_lod and base_level > max_level are allowed (GL allows them): min_lod wins, the
  // base level alone is sampled (tex::trilinear_lod, tex::level_range).
  m.base_level = n.integer("base_level", 0, 12, 0);
  m.max_level = n.integer("max_level", 0, 1000, 1000);
  if (n.has("relief")) {
    Node r = n.obj("relief");
    Relief rel;
    rel.height_texture = r.str("height");
    if (!s.textures.count(rel.height_texture))
      r.fail_at("height", "unknown texture '" + rel.height_texture + "'");
    rel.scale = r.num("scale", 0, 1, 0.05);
    const auto meth = r.str("method", std::string("pom_adaptive"),
                            {"pom_fixed", "pom_adaptive", "iterative", "distance_map", "distance_map_refined"});
    rel.method = meth == "pom_fixed" ? ReliefMethod::PomFixed
                 : meth == "iterative" ? ReliefMethod::Iterative
                 : meth == "distance_map" ? ReliefMethod::DistanceMap
                 : meth == "distance_map_refined" ? ReliefMethod::DistanceMapRefined : ReliefMethod::PomAdaptive;
    rel.layers = r.integer("layers", 1, 256, 32);
    rel.map_layers = r.integer("map_layers", 1, 255, 16);
    if (r.has("af_visibility")) rel.af_visibility = r.boolean("af_visibility");
    r.finish();
    m.relief = rel;
  }
  if (n.has("procedural")) m.procedural = parse_procedural(n.obj("procedural"));
  if (n.has("specular")) {
    Node sp = n.obj("specular");
    Specular spec;
    spec.model = sp.str("model", std::string("auto"), {"auto", "blinn", "schlick", "msh", "dsh", "scos2", "st16", "qr"});
    spec.n = sp.integer("n", 1, 1000, 32);
    const auto c = sp.vec("color", 3, 2, {{1, 1, 1}});
    for (int k = 0; k < 3; ++k) {
      if (c[static_cast<size_t>(k)] < 0) sp.fail_at("color/" + std::to_string(k), "is negative");
      spec.color[k] = c[static_cast<size_t>(k)];
    }
    sp.finish();
    m.specular = spec;
  }
  n.finish();
  return m;
}

Object parse_object(Node n, const Scene& s, int index, std::vector<std::string>* warnings) {
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
  std::array<std::array<double, 3>, 4> normal{};
  const bool has_normals = n.has("normals");
  if (has_normals) {
    const json& ns = n.raw("normals");
    if (!ns.is_array() || ns.size() != nv)
      n.fail_at("normals", "expected " + std::to_string(nv) + " normals for a " + type);
    for (size_t i = 0; i < nv; ++i) {
      const auto q = n.numbers(ns[i], "normals/" + std::to_string(i), 3, kMaxCoord);
      if (!(std::hypot(q[0], q[1], q[2]) > 0)) n.fail_at("normals/" + std::to_string(i), "is the zero vector");
      for (size_t k = 0; k < 3; ++k) normal[i][k] = q[k];
    }
  }
  persp::Vertex v[4];
  for (size_t i = 0; i < nv; ++i) {
    const auto p = n.numbers(vs[i], "vertices/" + std::to_string(i), 3, kMaxCoord);
    const auto uv = n.numbers(uvs[i], "uv/" + std::to_string(i), 2, kMaxUv);
    for (int k = 0; k < 3; ++k) v[i].p[k] = p[static_cast<size_t>(k)];
    for (int k = 0; k < 2; ++k) v[i].uv[k] = uv[static_cast<size_t>(k)];  // texture repeats; see in_texels()
  }
  // A zero-area triangle (collinear or repeated vertices) covers no pixel: dropped with a
  // warning, as GPUs drop it (its set-up would divide by its zero normal).
  auto tri = [&](int a, int b, int c, const char* suffix) {
    persp::Triangle t;
    t.name = o.name + suffix;
    t.v[0] = v[a], t.v[1] = v[b], t.v[2] = v[c];
    double e1[3], e2[3];
    for (int k = 0; k < 3; ++k) e1[k] = v[b].p[k] - v[a].p[k], e2[k] = v[c].p[k] - v[a].p[k];
    const double cr = std::hypot(e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                                 e1[0] * e2[1] - e1[1] * e2[0]);
    if (!(cr > kParallel * std::hypot(e1[0], e1[1], e1[2]) * std::hypot(e2[0], e2[1], e2[2]))) {
      warnings->push_back(object_where(s, o.name, static_cast<size_t>(index)) + ": triangle '" + t.name +
                          "' has zero area (collinear or repeated vertices): dropped");
      return;
    }
    o.triangles.push_back(t);
    if (has_normals) o.normals.push_back({normal[static_cast<size_t>(a)], normal[static_cast<size_t>(b)], normal[static_cast<size_t>(c)]});
  };
  if (nv == 3) tri(0, 1, 2, "");
  else tri(0, 1, 2, "#0"), tri(0, 2, 3, "#1");
  n.finish();
  return o;
}

}  // namespace

Scene parse(const std::string& text, const std::string& source, const std::string& base_dir) {
  json j;
  StrictSax sax(j, text, source);
  json::sax_parse(text, &sax);
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
                                     static_cast<int>(i), &s.warnings));
  if (root.has("error_budget")) {
    Node b = root.obj("error_budget");
    s.budget.max_texel_err = b.num("max_texel_err", 1e-6, 16, s.budget.max_texel_err);
    s.budget.min_psnr_db = b.num("min_psnr_db", 0, 100, s.budget.min_psnr_db);
    s.budget.max_brdf_mad = b.num("max_brdf_mad", 1e-6, 1, s.budget.max_brdf_mad);
    b.finish();
  }
  if (root.has("lights")) {
    const json& ls = root.raw("lights");
    if (!ls.is_array() || ls.size() > 1) root.fail_at("lights", "expected an array of at most one light (one shading pass)");
    for (size_t i = 0; i < ls.size(); ++i) {
      Node l(ls[i], "/lights/" + std::to_string(i), s.source);
      Light light;
      if (l.has("position") == l.has("direction")) l.fail("give exactly one of 'position' or 'direction'");
      light.positional = l.has("position");
      const auto p = light.positional ? l.vec("position", 3, kMaxCoord) : l.vec("direction", 3, kMaxCoord);
      if (!light.positional && !(std::hypot(p[0], p[1], p[2]) > 0)) l.fail_at("direction", "is the zero vector");
      for (int k = 0; k < 3; ++k) (light.positional ? light.position : light.direction)[k] = p[static_cast<size_t>(k)];
      const auto c = l.vec("color", 3, 2, {{1, 1, 1}});
      for (int k = 0; k < 3; ++k) {
        if (c[static_cast<size_t>(k)] < 0) l.fail_at("color/" + std::to_string(k), "is negative");
        light.color[k] = c[static_cast<size_t>(k)];
      }
      light.ambient = l.num("ambient", 0, 2, 0.2);
      l.finish();
      s.lights.push_back(light);
    }
  }
  s.footprint = root.str("footprint", std::string("analytic"), {"analytic", "recurrence"}) == "recurrence"
                    ? Footprint::Recurrence
                    : Footprint::Analytic;
  root.finish();
  return s;
}

Scene load(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path + ": cannot open file");
  std::ostringstream ss;
  ss << in.rdbuf();
  Scene s = parse(ss.str(), path, std::filesystem::path(path).parent_path().string());
  for (const auto& w : s.warnings) std::cerr << "warning: " << w << "\n";
  return s;
}

std::string object_where(const Scene& s, const std::string& name, size_t index) {
  return s.source + ": object '" + name + "' (/objects/" + std::to_string(index) + ")";
}
std::string object_where(const Scene& s, size_t index) {
  return object_where(s, s.objects.at(index).name, index);
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

const std::string& procedural_scene_json() {
  // docs/scenes/procedural.json, byte for byte (NoiseProc.DocsSceneIsTheEmbeddedOne).
  static const std::string text = R"({
  "texunit_scene": 1,
  "camera": {"position": [0, 1.5, 0], "look_at": [0.6, 1.0, -10], "up": [0, 1, 0],
             "fovy_deg": 60, "width": 128, "height": 96, "z_near": 0.1},
  "textures": {
    "grid": {"builtin": "checkerboard", "size": 256, "cells": 8, "wrap": "repeat"}
  },
  "materials": {
    "marble": {"texture": "grid",
               "procedural": {"kind": "fbm", "octaves": 4, "frequency": 8, "seed": 3,
                              "color0": [40, 30, 20], "color1": [240, 220, 190]}},
    "smoke": {"texture": "grid",
              "procedural": {"kind": "smoke", "octaves": 4, "frequency": 4, "seed": 7, "time": 0,
                             "speed": 0.5, "threshold": 0.15, "gain": 2.5,
                             "color0": [30, 40, 90], "color1": [230, 230, 230]}}
  },
  "objects": [
    {"name": "ground", "type": "quad", "material": "marble",
     "vertices": [[-20, 0, -0.5], [20, 0, -0.5], [20, 0, -160], [-20, 0, -160]],
     "uv": [[0, 0], [4, 0], [4, 16], [0, 16]]},
    {"name": "smoke", "type": "quad", "material": "smoke",
     "vertices": [[2.5, 0, -1.5], [3.5, 0, -40], [3.5, 4, -40], [2.5, 4, -1.5]],
     "uv": [[0, 1], [8, 1], [8, 0], [0, 0]]}
  ],
  "error_budget": {"max_texel_err": 0.0625, "min_psnr_db": 35}
}
)";
  return text;
}

Scene procedural_scene() { return parse(procedural_scene_json(), "<procedural scene>", "."); }

Scene without_relief(Scene s) {
  for (auto& [name, m] : s.materials) m.relief.reset();
  return s;
}

Scene with_clip(Scene s, const std::string& clip) {
  const std::string c = clip == "off" ? std::string() : clip;
  if (!c.empty()) clip::variant(c);  // validates the name
  for (auto& [name, m] : s.materials) m.clip = c;
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
    const auto f = static_cast<tex::TexelFormat>(t.format);  // converted on load (texel_format.hpp)
    const auto mip = static_cast<tex::MipFilter>(t.mip_filter);
    if (t.builtin == "checkerboard")
      return tex::build_stored(where, tex::checkerboard(t.size, t.cells), t.addressing, f, t.srgb, mip);
    if (t.builtin == "bricks") return tex::build_stored(where, tex::bricks(t.size).color, t.addressing, f, t.srgb, mip);
    return tex::build_stored(where + " (" + t.png + ")", img::read_png_rgba(t.png), t.addressing, f, t.srgb, mip);
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
    case Filter::Feline: return "feline";
  }
  return "?";
}
const char* to_string(WeightSource w) {
  return w == WeightSource::Formula ? "formula" : w == WeightSource::Table1d ? "table1d" : "table2d";
}
const char* to_string(ProceduralKind k) {
  return k == ProceduralKind::Smoke ? "smoke" : k == ProceduralKind::Water ? "water" : "fbm";
}

Scene at_time(Scene s, double t) {
  for (auto& [name, m] : s.materials)
    if (m.procedural) m.procedural->time += t;
  return s;
}
const char* to_string(Footprint f) { return f == Footprint::Recurrence ? "recurrence" : "analytic"; }

const char* to_string(ReliefMethod m) {
  return m == ReliefMethod::PomFixed ? "pom_fixed" : m == ReliefMethod::PomAdaptive ? "pom_adaptive"
         : m == ReliefMethod::Iterative ? "iterative" : m == ReliefMethod::DistanceMap ? "distance_map"
                                                                                        : "distance_map_refined";
}

}  // namespace tu::scene
