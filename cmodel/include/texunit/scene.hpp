// Scenes: the documented JSON format (docs/scene-format.md) the render, dump and plan commands
// read. Loading validates everything up front: a malformed file, an unknown field, a wrong type,
// an out-of-range value or a missing texture file is a SceneError whose message names the file,
// the line (for syntax errors) or the field as a JSON pointer (e.g. `/objects/1/material`).
#pragma once

#include <array>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "persp/persp.hpp"
#include "texture/texture.hpp"
#include "texunit/schema.hpp"

namespace tu::scene {

struct SceneError : std::runtime_error {
  explicit SceneError(const std::string& what);  // control bytes quoted from the file escaped
};

enum class Filter { Nearest, Bilinear, Trilinear, Ewa, Feline };
using WeightSource = schema::WeightSource;  // EWA weight source: its RTL code is the enum value
enum class ReliefMethod { PomFixed, PomAdaptive, Iterative, DistanceMap, DistanceMapRefined };
// B2's Jacobian (docs/blocks/ellipse.md): analytic (tu_ellipse) or the seed's forward-difference
// recurrences (tu_ellipse_rec, unit configuration EllRecurrence). One per unit, so per scene.
enum class Footprint { Analytic, Recurrence };

struct Relief {
  std::string height_texture;  // its first channel is the height (255 = top)
  double scale = 0.05;         // depth of the relief in texture-space units (uv of the texture)
  ReliefMethod method = ReliefMethod::PomAdaptive;
  int layers = 16;             // PomFixed: N; PomAdaptive: Nmax (Nmin = 4); Iterative, DistanceMap*: cap
  int map_layers = 16;         // DistanceMap*: the distance map's layers D
  bool af_visibility = false;  // EWA keeps only the footprint texels visible over the relief (afvis)
};

// A procedural colour source (docs/scene-format.md "procedural"; docs/blocks/noise-appendix.md §5): the
// unit evaluates Perlin noise at the pixel's (u, v[, t]) instead of sampling the texture.
enum class ProceduralKind { Fbm, Smoke, Water };
struct Procedural {
  ProceduralKind kind = ProceduralKind::Fbm;
  int octaves = 4;          // K, 1..NoiseOctaves
  double frequency = 8;     // lattice cells per texture repeat
  int seed = 0;             // lattice shift (37 s, 91 s) mod 256 cells
  double time = 0;          // t of frame 0 (render --frames N --dt T adds frame * T)
  double speed = 0;         // time as the third noise dimension z = speed * t (0: 2-D noise)
  bool footprint_limit = true;  // fade out the octaves above the footprint's Nyquist frequency
  double threshold = 0.2, gain = 2;  // smoke: opacity = clamp((turbulence - threshold) * gain, 0, 1)
  double amplitude = 0.5;            // water: height amplitude (cells per unit of the octave sum)
  std::array<double, 3> light{0.4, 0.3, 0.866};  // water: tangent-space light direction
  std::array<double, 3> color0{0, 0, 0}, color1{255, 255, 255};  // value 0 -> color0, 1 -> color1
};

// The material's specular lobe for the shading stage (docs/blocks/brdf.md "In the unit").
struct Specular {
  std::string model = "auto";  // a brdf::name() model, or "auto": the unit's model (`texunit plan`)
  int n = 32;                  // exponent, 1..1000
  double color[3] = {1, 1, 1}; // ks per channel, 0..2
};

struct Material {
  std::string name;
  std::string texture;
  Filter filter = Filter::Ewa;
  WeightSource weights = WeightSource::Formula;
  // EWA sub-texel border weights (seed 003 §2): a gauss::clip variant name (docs/blocks/ewa.md
  // "Border weights"); empty: off (the all-or-nothing Q < 1 test).
  std::string clip;
  double max_aniso = 16;
  // Trilinear's GL LOD rule (texture/trilinear_lod.hpp): lambda + lod_bias clamped to
  // [min_lod, max_lod] (levels), then to the pyramid.
  double lod_bias = 0, min_lod = 0, max_lod = 12;
  // Feline (feline/feline_ref.hpp): at most this many trilinear probes per pixel (1..FelNMax).
  int feline_max_probes = 8;
  std::optional<Relief> relief;
  std::optional<Procedural> procedural;  // colour from noise; `texture` still fixes the uv grid
  std::optional<Specular> specular;  // absent: diffuse only (when the scene has a light)
  // GL TEXTURE_BASE_LEVEL / TEXTURE_MAX_LEVEL: the levels every engine samples
  // (tex::level_range; nearest and bilinear sample the base level).
  int base_level = 0, max_level = 1000;
};

struct TextureSpec {
  std::string name;
  std::string builtin;  // "checkerboard" | "bricks" | "" (PNG)
  std::string png;      // resolved path
  int size = 256;
  int cells = 8;
  tex::Addressing addressing;  // fields wrap (both axes), wrap_u, wrap_v, border
  // Storage format (texture/texel_format.hpp): the image is converted on load; srgb: the colour
  // channels are sRGB-encoded, decoded to linear before filtering (RTL: tu_texel_decode; bc1 is
  // C model and float reference only, --engine rtl refuses it naming the field).
  int format = 0;  // tex::TexelFormat code (kTexelFormatNames)
  bool srgb = false;
  int mip_filter = 0;  // tex::MipFilter code (kMipFilterNames)
};
// Scene names of the wrap modes, indexed by the tex::Wrap code.
inline constexpr const char* kWrapNames[] = {"repeat", "mirror", "clamp", "border", "mirror_once"};

struct Object {
  std::string name;
  std::string material;
  std::vector<persp::Triangle> triangles;  // uv in texture repeats (1 = the texture's width)
  // Per triangle, the normals at its three vertices (interpolated over it); empty: face normals.
  std::vector<std::array<std::array<double, 3>, 3>> normals;
};

// The scene's light (shading stage): a point light at `position` or a directional one shining
// along `direction`, its colour and the ambient level.
struct Light {
  bool positional = false;
  double position[3] = {0, 0, 0};
  double direction[3] = {0, -1, 0};
  double color[3] = {1, 1, 1};
  double ambient = 0.2;
};

// The object's triangles with uv in level-0 texels of a tex_width x tex_height texture.
std::vector<persp::Triangle> in_texels(const Object& o, int tex_width, int tex_height);

struct Budget {
  double max_texel_err = 1.0 / 16;  // texture-coordinate error, texels
  double min_psnr_db = 35;          // image quality against the float EWA reference
  double max_brdf_mad = 0.01;       // specular model: mean |F - F_Blinn| on the thesis grid (`plan`)
};

struct Scene {
  std::string source;  // file name or "<default>"
  persp::Camera camera;
  std::map<std::string, TextureSpec> textures;
  std::map<std::string, Material> materials;
  std::vector<Object> objects;
  Budget budget;
  std::vector<Light> lights;  // at most one (the shading stage's); empty: no shading
  Footprint footprint = Footprint::Analytic;  // "footprint": "analytic" | "recurrence"
  std::vector<std::string> warnings;  // e.g. zero-area triangles dropped (load() prints them)
};

// How messages name an object: "FILE: object 'NAME' (/objects/I)"; every set-up error (float
// reference, C model, RTL engine) starts with it.
std::string object_where(const Scene& s, size_t index);
std::string object_where(const Scene& s, const std::string& name, size_t index);

// Parse and validate; `source` names the file in messages, `base_dir` resolves relative PNG paths.
Scene parse(const std::string& json_text, const std::string& source, const std::string& base_dir);
Scene load(const std::string& path);  // also prints the scene's warnings to stderr
// The embedded default scene: a checkerboard ground plane receding to the horizon and a tilted
// brick wall with relief (grazing angles and strong anisotropy on purpose).
const std::string& default_scene_json();
Scene default_scene();
// docs/scenes/procedural.json embedded (the demo's procedural materials): the default scene's
// ground with fBm and its wall with smoke, 128 x 96.
const std::string& procedural_scene_json();
Scene procedural_scene();
// The same scene with every material's relief removed (the texture path alone).
Scene without_relief(Scene s);
// The same scene with every material's EWA border weights set to the clip variant `clip`
// ("off" or empty: none); throws std::invalid_argument for an unknown variant.
Scene with_clip(Scene s, const std::string& clip);

// Builds the texture named `name` (procedural or PNG) with its mip pyramid.
tex::Texture build_texture(const Scene& s, const std::string& name);

const char* to_string(Filter f);
const char* to_string(WeightSource w);
const char* to_string(ReliefMethod m);
const char* to_string(ProceduralKind k);
// The scene at time t: every procedural material's time set to its own time + t (frames).
Scene at_time(Scene s, double t);
const char* to_string(Footprint f);

}  // namespace tu::scene
