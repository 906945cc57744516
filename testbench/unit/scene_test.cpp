// Scene format: the default scene, and every kind of bad input rejected with file + field.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <sys/stat.h>
#include <unistd.h>

#include "texture/texel_format.hpp"
#include "texunit/scene.hpp"

namespace {
using namespace tu::scene;

std::string error_of(const std::string& text) {
  try {
    parse(text, "s.json", ".");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

// The default scene with one substitution applied (must match exactly once).
std::string edited(const std::string& from, const std::string& to) {
  std::string s = default_scene_json();
  const auto at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  EXPECT_EQ(s.find(from, at + 1), std::string::npos) << from;
  return s.replace(at, from.size(), to);
}

TEST(Scene, DefaultSceneLoads) {
  const Scene s = default_scene();
  EXPECT_EQ(s.camera.width, 256);
  EXPECT_EQ(s.objects.size(), 2u);
  EXPECT_EQ(s.objects[0].triangles.size(), 2u);
  EXPECT_EQ(s.materials.at("wall").weights, WeightSource::Table1d);
  ASSERT_TRUE(s.materials.at("wall").relief.has_value());
  EXPECT_EQ(s.materials.at("wall").relief->method, ReliefMethod::PomAdaptive);
  EXPECT_FALSE(s.materials.at("ground").relief.has_value());
  EXPECT_DOUBLE_EQ(s.budget.max_texel_err, 0.0625);
  const auto t = build_texture(s, "checker");
  EXPECT_EQ(t.levels[0].width, 256);
  const auto tris = in_texels(s.objects[0], 256, 256);
  EXPECT_DOUBLE_EQ(tris[0].v[1].uv[0], 4 * 256.0);
}

TEST(Scene, BadInputNamesFileAndField) {
  EXPECT_EQ(error_of("{\n  \"texunit_scene\": 1,\n  \"camera\": {,\n}").rfind("s.json:3: malformed JSON", 0), 0u);
  EXPECT_EQ(error_of(edited("\"width\": 256", "\"width\": 0")),
            "s.json: /camera/width: value 0 is out of range [1, 4096]");
  EXPECT_EQ(error_of(edited("\"width\": 256", "\"widht\": 256")),
            "s.json: /camera: missing field 'width'");
  EXPECT_EQ(error_of(edited("\"fovy_deg\": 60,", "\"fovy_deg\": 60, \"zoom\": 2,")),
            "s.json: /camera/zoom: unknown field");
  EXPECT_EQ(error_of(edited("\"material\": \"wall\"", "\"material\": \"glass\"")),
            "s.json: /objects/1/material: unknown material 'glass'");
  EXPECT_EQ(error_of(edited("\"filter\": \"ewa\", \"weights\": \"formula\"",
                            "\"filter\": \"cubic\", \"weights\": \"formula\"")),
            "s.json: /materials/ground/filter: 'cubic' is not one of: nearest, bilinear, "
            "trilinear, ewa, feline");
  EXPECT_EQ(error_of(edited("\"filter\": \"ewa\", \"weights\": \"formula\"",
                            "\"filter\": \"feline\", \"feline_max_probes\": 17, \"weights\": \"formula\"")),
            "s.json: /materials/ground/feline_max_probes: value 17 is out of range [1, 16]");
  EXPECT_EQ(error_of(edited("\"size\": 256, \"cells\"", "\"size\": 200, \"cells\"")),
            "s.json: /textures/checker/size: must be a power of two");
  EXPECT_EQ(error_of(edited("\"builtin\": \"bricks\"", "\"png\": \"missing.png\"")),
            "s.json: /textures/bricks/png: file './missing.png' does not exist");
  EXPECT_EQ(error_of(edited("[[0, 0], [4, 0], [4, 16], [0, 16]]", "[[0, 0], [4, 0], [4, 16]]")),
            "s.json: /objects/0/uv: expected 4 uv pairs for a quad");
  EXPECT_EQ(error_of(edited("\"scale\": 0.04", "\"scale\": -1")),
            "s.json: /materials/wall/relief/scale: value -1 is out of range [0, 1]");
  EXPECT_EQ(error_of(edited("\"texunit_scene\": 1", "\"texunit_scene\": 2")),
            "s.json: /texunit_scene: value 2 is out of range [1, 1]");
  EXPECT_EQ(error_of("[1, 2]"), "s.json: /: expected an object");
}

// "filter": "feline" with its probe cap (default 8).
TEST(Scene, FelineFilterAndProbeCap) {
  EXPECT_EQ(default_scene().materials.at("ground").feline_max_probes, 8);
  const Scene s = parse(edited("\"filter\": \"ewa\", \"weights\": \"formula\"",
                               "\"filter\": \"feline\", \"feline_max_probes\": 4, \"weights\": \"formula\""),
                        "s.json", ".");
  EXPECT_EQ(s.materials.at("ground").filter, Filter::Feline);
  EXPECT_EQ(s.materials.at("ground").feline_max_probes, 4);
  EXPECT_STREQ(to_string(Filter::Feline), "feline");
}

// Sampler LOD state: base_level 0..12, max_level 0..1000 (GL defaults 0, 1000); min_lod > max_lod
// and base_level > max_level are accepted (documented behaviour: min_lod wins, the base level alone).
TEST(Scene, LodStateFields) {
  EXPECT_EQ(default_scene().materials.at("ground").base_level, 0);
  EXPECT_EQ(default_scene().materials.at("ground").max_level, 1000);
  const std::string from = "\"filter\": \"ewa\", \"weights\": \"formula\"";
  const Scene s = parse(edited(from, from + ", \"base_level\": 3, \"max_level\": 1, \"min_lod\": 4, \"max_lod\": 2"),
                        "s.json", ".");
  const auto& m = s.materials.at("ground");
  EXPECT_EQ(m.base_level, 3);
  EXPECT_EQ(m.max_level, 1);
  EXPECT_EQ(m.min_lod, 4);
  EXPECT_EQ(m.max_lod, 2);
  EXPECT_EQ(error_of(edited(from, from + ", \"base_level\": 13")),
            "s.json: /materials/ground/base_level: value 13 is out of range [0, 12]");
  EXPECT_EQ(error_of(edited(from, from + ", \"max_level\": -1")),
            "s.json: /materials/ground/max_level: value -1 is out of range [0, 1000]");
  EXPECT_EQ(error_of(edited(from, from + ", \"base_level\": 1.5")),
            "s.json: /materials/ground/base_level: expected an integer");
}

// Texture storage format and sRGB: converted on load (texture/texel_format.hpp).
TEST(Scene, TextureFormatAndSrgb) {
  EXPECT_EQ(default_scene().textures.at("checker").format, 0);
  const std::string from = "\"checker\": {\"builtin\": \"checkerboard\", \"size\": 256, \"cells\": 8, \"wrap\": \"repeat\"";
  const Scene s = parse(edited(from, from + ", \"format\": \"rgb565\", \"srgb\": true"), "s.json", ".");
  EXPECT_EQ(s.textures.at("checker").format, static_cast<int>(tu::tex::TexelFormat::Rgb565));
  EXPECT_TRUE(s.textures.at("checker").srgb);
  const auto t = build_texture(s, "checker");
  const auto plain = build_texture(default_scene(), "checker");
  const auto& lin = tu::tex::srgb_decode_table();
  ASSERT_EQ(t.levels.size(), plain.levels.size());
  for (size_t k = 0; k < t.levels[0].px.size(); ++k) {  // every base texel: the rgb565 code, decoded to linear
    const auto& p = plain.levels[0].px[k];
    const auto& q = t.levels[0].px[k];
    const auto d = tu::tex::decode_texel(tu::tex::TexelFormat::Rgb565, tu::tex::encode_texel(tu::tex::TexelFormat::Rgb565, p));
    EXPECT_EQ(q.r, lin[d.r]);
    EXPECT_EQ(q.g, lin[d.g]);
    EXPECT_EQ(q.b, lin[d.b]);
    EXPECT_EQ(q.a, 255);
  }
  EXPECT_EQ(error_of(edited(from, from + ", \"format\": \"bc7\"")),
            "s.json: /textures/checker/format: 'bc7' is not one of: rgba8, rgb565, rgba5551, rgba4444, l8, la8, a8, bc1");
  EXPECT_EQ(error_of(edited(from, from + ", \"srgb\": 1")), "s.json: /textures/checker/srgb: expected true or false");
}

// Mip generation per texture: "mip_filter" (default box), box | box_linear | lanczos2.
TEST(Scene, TextureMipFilter) {
  EXPECT_EQ(default_scene().textures.at("checker").mip_filter, 0);
  const std::string from = "\"checker\": {\"builtin\": \"checkerboard\", \"size\": 256, \"cells\": 8, \"wrap\": \"repeat\"";
  const Scene s = parse(edited(from, from + ", \"mip_filter\": \"lanczos2\""), "s.json", ".");
  EXPECT_EQ(s.textures.at("checker").mip_filter, static_cast<int>(tu::tex::MipFilter::Lanczos2));
  const auto t = build_texture(s, "checker"), plain = build_texture(default_scene(), "checker");
  EXPECT_EQ(t.levels[0].px, plain.levels[0].px);
  EXPECT_NE(t.levels[4].px, plain.levels[4].px);  // 16 x 16: the 8-texel cells seen through 8 x 8 taps
  EXPECT_EQ(error_of(edited(from, from + ", \"mip_filter\": \"kaiser\"")),
            "s.json: /textures/checker/mip_filter: 'kaiser' is not one of: box, box_linear, lanczos2");
}

// The B2 variant: "footprint" (default analytic), one of analytic | recurrence.
TEST(Scene, FootprintVariant) {
  EXPECT_EQ(default_scene().footprint, Footprint::Analytic);
  const Scene r = parse(edited("\"texunit_scene\": 1", "\"texunit_scene\": 1, \"footprint\": \"recurrence\""), "s.json", ".");
  EXPECT_EQ(r.footprint, Footprint::Recurrence);
  EXPECT_STREQ(to_string(r.footprint), "recurrence");
  EXPECT_EQ(error_of(edited("\"texunit_scene\": 1", "\"texunit_scene\": 1, \"footprint\": \"ewa\"")),
            "s.json: /footprint: 'ewa' is not one of: analytic, recurrence");
}

// Wrap modes: `wrap` for both axes, `wrap_u` / `wrap_v` per axis, `border` an RGBA colour.
TEST(Scene, WrapModesPerAxisAndBorder) {
  const Scene d = default_scene();
  EXPECT_EQ(d.textures.at("checker").addressing.u, tu::tex::Wrap::Repeat);
  const std::string at = "\"builtin\": \"bricks\", \"size\": 256, \"wrap\": \"repeat\"";
  const Scene s = parse(edited(at, "\"builtin\": \"bricks\", \"size\": 256, \"wrap\": \"mirror\", \"wrap_v\": \"border\", "
                               "\"border\": [1, 2, 3, 4]"),
                        "s.json", ".");
  const auto& a = s.textures.at("bricks").addressing;
  EXPECT_EQ(a.u, tu::tex::Wrap::Mirror);
  EXPECT_EQ(a.v, tu::tex::Wrap::Border);
  EXPECT_EQ(a.border, (tu::img::Rgba8{1, 2, 3, 4}));
  EXPECT_EQ(build_texture(s, "bricks").addressing.v, tu::tex::Wrap::Border);
  EXPECT_EQ(error_of(edited(at, "\"builtin\": \"bricks\", \"size\": 256, \"wrap_u\": \"spiral\"")),
            "s.json: /textures/bricks/wrap_u: 'spiral' is not one of: repeat, mirror, clamp, border, mirror_once");
  EXPECT_EQ(error_of(edited(at, "\"builtin\": \"bricks\", \"size\": 256, \"border\": [0, 0, 300, 0]")),
            "s.json: /textures/bricks/border/2: expected an integer in [0, 255]");
  EXPECT_EQ(error_of(edited(at, "\"builtin\": \"bricks\", \"size\": 256, \"border\": [0, 0.5, 0, 0]")),
            "s.json: /textures/bricks/border/1: expected an integer in [0, 255]");
}

TEST(Scene, MissingFileAndPngTextureRelativeToTheScene) {
  EXPECT_THROW(load("/nonexistent/scene.json"), SceneError);
  const auto dir = std::filesystem::temp_directory_path() / "tu_scene_test";
  std::filesystem::create_directories(dir);
  tu::img::write_png_rgba((dir / "t.png").string(), tu::img::Rgba8Image(32, 16, {1, 2, 3, 255}));
  std::ofstream(dir / "s.json") << edited("\"builtin\": \"bricks\", \"size\": 256", "\"png\": \"t.png\"");
  const Scene s = load((dir / "s.json").string());
  const auto t = build_texture(s, "bricks");
  EXPECT_EQ(t.levels[0].width, 32);
  EXPECT_EQ(t.levels[0].height, 16);
  // A non-power-of-two PNG fails when built, naming the scene, the texture and the file.
  tu::img::write_png_rgba((dir / "t.png").string(), tu::img::Rgba8Image(30, 16));
  try {
    build_texture(s, "bricks");
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("/textures/bricks"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("not a power of two"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}
// A texture path that is a directory, a FIFO or a device, and a scene path that is a directory,
// are named as what they are (not "does not exist", not "malformed JSON"); a FIFO is never opened.
TEST(Scene, TextureAndScenePathsThatAreNotFiles) {
  const auto dir = std::filesystem::temp_directory_path() / ("tu_scene_nonfiles_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir / "d.png");
  ASSERT_EQ(::mkfifo((dir / "f.png").c_str(), 0600), 0);
  const std::string scene = (dir / "s.json").string();
  auto error_with = [&](const std::string& png) {
    std::ofstream(scene) << edited("\"builtin\": \"bricks\", \"size\": 256", "\"png\": \"" + png + "\"");
    try {
      load(scene);
    } catch (const SceneError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  const std::string at = scene + ": /textures/bricks/png: ";
  const std::string not_regular = "' is not a regular file (a FIFO, a device or a socket), not a PNG file";
  EXPECT_EQ(error_with("d.png"), at + "'" + (dir / "d.png").string() + "' is a directory, not a PNG file");
  EXPECT_EQ(error_with("f.png"), at + "'" + (dir / "f.png").string() + not_regular);
  EXPECT_EQ(error_with("/dev/zero"), at + "'/dev/zero" + not_regular);
  EXPECT_EQ(error_with("none.png"), at + "file '" + (dir / "none.png").string() + "' does not exist");
  try {
    load(dir.string());
    ADD_FAILURE() << "loaded a directory";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()), dir.string() + ": is a directory, not a scene file");
  }
  std::filesystem::remove_all(dir);
}

// Colour ranges name their real bounds ([0, 2] for light and specular colours, [0, 255] for a
// procedural material's); af_visibility, which keeps texels of the EWA footprint, needs filter ewa.
TEST(Scene, ColourBoundsAndAfVisibilityOnANonEwaMaterial) {
  const std::string ground = "\"max_aniso\": 16},";
  EXPECT_EQ(error_of(edited(ground, "\"max_aniso\": 16, \"specular\": {\"color\": [1, 3, 1]}},")),
            "s.json: /materials/ground/specular/color/1: value 3 is out of range [0, 2]");
  EXPECT_EQ(error_of(edited(ground, "\"max_aniso\": 16, \"procedural\": {\"kind\": \"fbm\", \"color0\": [0, 0, 300]}},")),
            "s.json: /materials/ground/procedural/color0/2: value 300 is out of range [0, 255]");
  EXPECT_EQ(error_of(edited(ground, "\"max_aniso\": 16, \"procedural\": {\"kind\": \"fbm\", \"color1\": [-1, 0, 0]}},")),
            "s.json: /materials/ground/procedural/color1/0: value -1 is out of range [0, 255]");
  const std::string wall = "\"filter\": \"ewa\", \"weights\": \"table1d\"";
  const std::string relief = "\"layers\": 32}";
  for (const char* f : {"trilinear", "feline", "bilinear", "nearest"}) {
    std::string t = edited(wall, std::string("\"filter\": \"") + f + "\", \"weights\": \"table1d\"");
    t.replace(t.find(relief), relief.size(), "\"layers\": 32, \"af_visibility\": true}");
    EXPECT_EQ(error_of(t), std::string("s.json: /materials/wall/relief/af_visibility: needs filter ewa (the visibility "
                                       "rule keeps EWA footprint texels); the material's filter is ") + f);
    t.replace(t.find("\"af_visibility\": true"), 21, "\"af_visibility\": false");
    EXPECT_EQ(error_of(t), "");  // off: any filter
  }
}

// Bad input found by testing as a new user would (issue 13 §5): each names the file and the
// line or the field.
TEST(Scene, NumberOutsideDoubleRangeNamesTheLine) {
  EXPECT_EQ(error_of("{\n  \"texunit_scene\": 1,\n  \"camera\": {\"fovy_deg\": 1e400}\n}"),
            "s.json:3: number 1e400 is outside double's range");
}

TEST(Scene, DuplicateKeyIsAnError) {
  EXPECT_EQ(error_of(edited("\"fovy_deg\": 60,", "\"fovy_deg\": 60, \"fovy_deg\": 90,")),
            "s.json: /camera/fovy_deg: duplicate key (a key appears once per object)");
  EXPECT_EQ(error_of(edited("\"material\": \"wall\"", "\"material\": \"wall\", \"material\": \"ground\"")),
            "s.json: /objects/1/material: duplicate key (a key appears once per object)");
}

TEST(Scene, NulByteInAKeyIsShownEscaped) {
  // what() is a C string: the NUL would have cut the message.
  EXPECT_EQ(error_of(edited("\"fovy_deg\": 60,", "\"fovy_deg\": 60, \"zo\\u0000om\": 2,")),
            "s.json: /camera/zo\\x00om: unknown field");
}

TEST(Scene, CameraUpZeroOrAlongTheViewIsRejected) {
  EXPECT_EQ(error_of(edited("\"up\": [0, 1, 0]", "\"up\": [0, 0, 0]")), "s.json: /camera/up: is the zero vector");
  // look_at - position = (0.6, -0.5, -10).
  EXPECT_EQ(error_of(edited("\"up\": [0, 1, 0]", "\"up\": [1.2, -1, -20]")),
            "s.json: /camera/up: is parallel to the view direction (look_at - position)");
}

TEST(Scene, HugeMagnitudesAreOutOfRange) {
  EXPECT_EQ(error_of(edited("[[0, 0], [4, 0], [4, 16], [0, 16]]", "[[0, 0], [1e18, 0], [4, 16], [0, 16]]")),
            "s.json: /objects/0/uv/1/0: value 1e+18 is out of range [-65536, 65536]");
  EXPECT_EQ(error_of(edited("[-20, 0, -0.5], [20, 0, -0.5]", "[-20, 0, -0.5], [1e308, 0, -0.5]")),
            "s.json: /objects/0/vertices/1/0: value 1e+308 is out of range [-1e+06, 1e+06]");
  EXPECT_EQ(error_of(edited("\"position\": [0, 1.5, 0]", "\"position\": [0, 1.5e7, 0]")),
            "s.json: /camera/position/1: value 15000000.0 is out of range [-1e+06, 1e+06]");
}

TEST(Scene, ZeroAreaTriangleIsDroppedWithAWarningNamingTheObject) {
  // Quad (0,1,2) + (0,2,3): vertex 3 = vertex 0 makes the second triangle degenerate.
  const Scene s = parse(edited("[[2.5, 0, -1.5], [3.5, 0, -40], [3.5, 4, -40], [2.5, 4, -1.5]]",
                               "[[2.5, 0, -1.5], [3.5, 0, -40], [3.5, 4, -40], [2.5, 0, -1.5]]"),
                        "s.json", ".");
  ASSERT_EQ(s.objects[1].triangles.size(), 1u);
  EXPECT_EQ(s.objects[1].triangles[0].name, "wall#0");
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_EQ(s.warnings[0], "s.json: object 'wall' (/objects/1): triangle 'wall#1' has zero area "
                           "(collinear or repeated vertices): dropped");
  // Collinear vertices too.
  const Scene c = parse(edited("[[2.5, 0, -1.5], [3.5, 0, -40], [3.5, 4, -40], [2.5, 4, -1.5]]",
                               "[[0, 0, -2], [1, 0, -3], [2, 0, -4], [2.5, 4, -1.5]]"),
                        "s.json", ".");
  EXPECT_EQ(c.objects[1].triangles.size(), 1u);
  EXPECT_EQ(c.warnings.size(), 1u);
  EXPECT_TRUE(default_scene().warnings.empty());
}
}  // namespace

namespace {
// Shading fields (docs/scene-format.md): lights, the material's specular block, vertex normals.
TEST(Scene, LightsSpecularAndNormals) {
  const std::string lit = edited("\"error_budget\":", "\"lights\": [{\"position\": [1, 5, -3], \"color\": [1, 0.5, 0.25]}],\n  \"error_budget\":");
  const Scene s = parse(lit, "s.json", ".");
  ASSERT_EQ(s.lights.size(), 1u);
  EXPECT_TRUE(s.lights[0].positional);
  EXPECT_DOUBLE_EQ(s.lights[0].color[2], 0.25);
  EXPECT_DOUBLE_EQ(s.lights[0].ambient, 0.2);
  EXPECT_FALSE(s.materials.at("ground").specular.has_value());
  EXPECT_TRUE(default_scene().lights.empty());
  auto with = [&](const std::string& from, const std::string& to) {
    std::string t = lit;
    const auto at = t.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return error_of(t.replace(at, from.size(), to));
  };
  EXPECT_EQ(with("\"position\": [1, 5, -3]", "\"position\": [1, 5, -3], \"direction\": [0, -1, 0]"),
            "s.json: /lights/0: give exactly one of 'position' or 'direction'");
  EXPECT_EQ(with("\"position\": [1, 5, -3]", "\"direction\": [0, 0, 0]"), "s.json: /lights/0/direction: is the zero vector");
  EXPECT_EQ(with("\"color\": [1, 0.5, 0.25]", "\"color\": [1, -0.5, 0.25]"),
            "s.json: /lights/0/color/1: value -0.5 is out of range [0, 2]");
  EXPECT_EQ(with("\"color\": [1, 0.5, 0.25]}", "\"color\": [1, 0.5, 0.25]}, {\"direction\": [0, -1, 0]}"),
            "s.json: /lights: expected an array of at most one light (one shading pass)");
  const std::string spec = "\"max_aniso\": 16},";
  EXPECT_EQ(with(spec, "\"max_aniso\": 16, \"specular\": {\"model\": \"phong\"}},"),
            "s.json: /materials/ground/specular/model: 'phong' is not one of: auto, blinn, schlick, msh, dsh, scos2, st16, qr");
  EXPECT_EQ(with(spec, "\"max_aniso\": 16, \"specular\": {\"n\": 1001}},"),
            "s.json: /materials/ground/specular/n: value 1001 is out of range [1, 1000]");
  const Scene sp = parse(lit.substr(0, lit.find(spec)) + "\"max_aniso\": 16, \"specular\": {\"model\": \"st16\", \"n\": 7}}," +
                             lit.substr(lit.find(spec) + spec.size()), "s.json", ".");
  EXPECT_EQ(sp.materials.at("ground").specular->model, "st16");
  EXPECT_EQ(sp.materials.at("ground").specular->n, 7);
  const std::string uv = "\"uv\": [[0, 0], [4, 0], [4, 16], [0, 16]]";
  EXPECT_EQ(with(uv, uv + ", \"normals\": [[0, 1, 0], [0, 1, 0], [0, 1, 0]]"),
            "s.json: /objects/0/normals: expected 4 normals for a quad");
  EXPECT_EQ(with(uv, uv + ", \"normals\": [[0, 1, 0], [0, 0, 0], [0, 1, 0], [0, 1, 0]]"),
            "s.json: /objects/0/normals/1: is the zero vector");
  std::string t = lit;
  t.replace(t.find(uv), uv.size(), uv + ", \"normals\": [[0, 1, 0], [1, 1, 0], [0, 1, 1], [0, 2, 0]]");
  const Scene n = parse(t, "s.json", ".");
  ASSERT_EQ(n.objects[0].normals.size(), 2u);  // per triangle (0, 1, 2) and (0, 2, 3)
  EXPECT_DOUBLE_EQ(n.objects[0].normals[1][2][1], 2.0);
  EXPECT_TRUE(n.objects[1].normals.empty());
}
}  // namespace
