#include "texture_unit_rtl.hpp"

#include <chrono>
#include <cmath>
#include <algorithm>
#include <array>
#include <map>
#include <stdexcept>
#include <type_traits>

#include "Vtu_texture_unit.h"
#include "Vtu_texture_unit_bil.h"
#include "Vtu_texture_unit_corridor.h"
#include "Vtu_texture_unit_rec.h"
#if TU_COSIM_K4_UNIT
#include "Vtu_texture_unit_k4.h"
#endif
#if TU_COSIM_CLIP_VARIANTS
#include "Vtu_texture_unit_clip1.h"
#include "Vtu_texture_unit_clip2.h"
#endif
#include "afvis/afvis.hpp"
#include "ellipse/ellipse_fx.hpp"
#include "ewa/ewa_cycles.hpp"
#include "harness.hpp"
#include "noise/noise_proc.hpp"
#include "pom/relief.hpp"
#include "stream_source.hpp"
#include "sync_read_ram.hpp"
#include "texel_ram.hpp"
#include "texture/texel_format.hpp"
#include "texture/trilinear_lod.hpp"

namespace tu::cosim {

namespace {
static_assert(static_cast<int>(tex::TexelFormat::Bc1) == 7, "tu_texture_unit TexFmtBc1 is 3'd7");
// The unit's memories (2^TexRamLog2Words texel words: tu_texel_addr's address space; the depth RAM
// twice that, since it also holds the distance maps: the default scene's wall 1,114,112 words).
constexpr uint64_t kRamWords = uint64_t(1) << fmt::kTexRamLog2Words;
constexpr uint64_t kDepthWords = 2 * kRamWords;

uint64_t lo(i128 v) { return static_cast<uint64_t>(v); }
uint64_t hi(i128 v) { return static_cast<uint64_t>(v >> 64); }
uint64_t code(i128 v, int w) { return static_cast<uint64_t>(v) & (w >= 64 ? ~0ull : (1ull << w) - 1); }

constexpr size_t kProcWords = (schema::kProcW + 63) / 64;  // tu_proc_t, least significant first

// The span fields that go to one input port each, by the port's name without _i
// (rtl/top/tu_texture_unit.sv): B1 coefficient codes a .. i, the span x0 .. x1 on row y, the
// per-triangle footprint constants, the colour texture, the filter, the relief and afvis fields.
#define TU_SPAN_PORTS(X)                                                                             \
  X(a) X(b) X(c) X(d) X(e) X(f) X(g) X(h) X(i) X(x0) X(x1) X(y)                                      \
  X(dm) X(dexp) X(laniso) X(maxlod) X(lbias) X(lminlod) X(lmaxlod) X(lbase) X(ltop)                \
  X(tbase) X(tlw) X(tlh) X(twrap) X(tfmt) X(tsrgb) X(wsrc) X(cap) X(filt) X(fnmax) X(clip)          \
  X(rel) X(radapt) X(riter) X(rlayers) X(rscale) X(hbase) X(hlw) X(hlh) X(rdm) X(dlayers) X(dbase)  \
  X(afv) X(admin) X(abias) X(arule)
// The 112-bit exact numerator constants of the footprint (ellipse::fx), one port each.
#define TU_SPAN_WIDE_PORTS(X) X(kux) X(kvx) X(kuy) X(kvy) X(m) X(nn)

// One span on the unit's input ports: every field a code of its port's width.
struct Span {
#define TU_X_FIELD(name) uint64_t name = 0;
  TU_SPAN_PORTS(TU_X_FIELD)
#undef TU_X_FIELD
#define TU_X_FIELD(name) i128 name = 0;
  TU_SPAN_WIDE_PORTS(TU_X_FIELD)
#undef TU_X_FIELD
  std::array<uint64_t, kProcWords> proc{};  // proc_i: a procedural material's tu_proc_t
};

// One output pixel of the unit, by output port (without _o).
struct UnitPixel {
  uint64_t x, y, rgba, level, visited, inside, flags, eflags, rn, rsteps, rflags;
};

// One word of the view port: the pixel's quantised tangent-space view and the complexity texel.
struct ViewWord {
  uint64_t ok, vx, vy, vz, c;
};
using ShadeWord = std::array<uint32_t, brdf::shade::kWordWords>;  // the shade port's word
static_assert(32 * brdf::shade::kWordWords == fmt::kShadeWordW, "shade_i is whole 32-bit words");

// A procedural material's tu_proc_t bits (schema.hpp TU_REC_PROC: first field most significant).
std::array<uint64_t, kProcWords> pack_proc(const noise::ProcCodes& c) {
  using namespace schema;
  auto rgb = [](const std::array<uint8_t, 3>& k) { return uint64_t(k[0]) | uint64_t(k[1]) << 8 | uint64_t(k[2]) << 16; };
  const uint64_t value[] = {1, c.smoke, c.limit, static_cast<uint64_t>(c.octaves), c.freq,
                            code(c.lfreq, fmt::kEllLogW), code(c.sx, fmt::kNoiseCoordW), code(c.sy, fmt::kNoiseCoordW),
                            code(c.z, fmt::kNoiseCoordW), c.norm, code(c.mean_abs, fmt::kNoiseValW), c.thr, c.gain,
                            rgb(c.c0), rgb(c.c1), c.water, c.amp, code(c.light[0], fmt::kWaterLightW),
                            code(c.light[1], fmt::kWaterLightW), code(c.light[2], fmt::kWaterLightW)};
#define TU_X_W(field, width, desc) (width),
  constexpr int width[] = {TU_REC_PROC(TU_X_W)};
#undef TU_X_W
  static_assert(std::size(width) == sizeof value / sizeof value[0], "one value per field");
  std::array<uint64_t, kProcWords> w{};
  int bit = 0;
  for (size_t f = std::size(width); f-- > 0;)  // the last field is least significant
    for (int b = 0; b < width[f]; ++b, ++bit)
      if (value[f] >> b & 1) w[static_cast<size_t>(bit / 64)] |= uint64_t(1) << (bit % 64);
  return w;
}

template <class P>
void set_wide(P& port, i128 v) {
  const uint64_t l = lo(v), h = hi(v);
  port[0] = static_cast<uint32_t>(l);
  port[1] = static_cast<uint32_t>(l >> 32);
  port[2] = static_cast<uint32_t>(h);
  port[3] = static_cast<uint32_t>(h >> 32) & 0xffffu;  // 112 bits
}

template <class V>
void drive(V& d, const Span& s) {
#define TU_X_DRIVE(name) d.name##_i = static_cast<std::remove_reference_t<decltype(d.name##_i)>>(s.name);
  TU_SPAN_PORTS(TU_X_DRIVE)
#undef TU_X_DRIVE
#define TU_X_DRIVE(name) set_wide(d.name##_i, s.name);
  TU_SPAN_WIDE_PORTS(TU_X_DRIVE)
#undef TU_X_DRIVE
  for (size_t j = 0; j < (schema::kProcW + 31) / 32; ++j)  // the VlWide words of proc_i
    d.proc_i[j] = static_cast<uint32_t>(s.proc[j / 2] >> (32 * (j % 2)));
}

template <class V>
UnitPixel sample(V& d) {
  return {.x = d.x_o, .y = d.y_o, .rgba = d.rgba_o, .level = d.level_o, .visited = d.visited_o,
          .inside = d.inside_o, .flags = d.flags_o, .eflags = d.eflags_o, .rn = d.rn_o, .rsteps = d.rsteps_o,
          .rflags = d.rflags_o};
}

// What the unit reads besides its spans, preloaded (no clock spent loading): the texel RAM's
// words (64 bits: a BC1 block, or a texel in the low bits), the depth RAM's (a depth or distance
// code in the low 8 bits), the view and the shade words in pixel order.
struct UnitImages {
  std::shared_ptr<const SyncReadRam64::Image> texels;
  std::shared_ptr<const SyncReadRam::Image> depth;
  std::shared_ptr<const StreamSource<ViewWord>::Words> views;
  std::shared_ptr<const StreamSource<ShadeWord>::Words> shades;
  int ewa_lanes = 1;  // the model's EwaLanes: texel RAM read ports (tex_* and, above 1, texk_*)
};

// The unit's surroundings in C++ (fresh per run), so that tu_texture_unit is the Verilator top:
//   * the texel RAM on tex_* (port 0) and texk_* (bank ports 1 .. EwaLanes - 1; each port only
//     reads its parity class of texels, so four single-port banks serve the same traffic: one
//     image here), words of the texel port's width (64 with HasBc1, else TexelW: the Verilated
//     port's C++ type holds exactly that many bits for TexelW 32);
//   * the depth RAM on d_* and, for the visibility engine (HasAfvis; a_req_o stays low without
//     it), its second read port a_* (a dual-port RAM);
//   * the view stream on view_* / vx_i ... and the shade stream on shade_*.
template <class V>
Env<V> unit_env(const UnitImages& im) {
  Env<V> e;
  constexpr int kTpw = 8 * static_cast<int>(sizeof(std::declval<V&>().tex_data_i));
  static_assert(kTpw == 32 || kTpw == 64, "texel port: TexelW = 32, or 64 bits with HasBc1");
  attach_ram<V>(e, std::make_shared<SyncReadRam64>(im.texels, kRamWords, 1, fmt::kTexAddrW, kTpw),
                [](V& d) -> auto& { return d.tex_req_o; }, [](V& d) -> auto& { return d.tex_addr_o; },
                [](V& d) -> auto& { return d.tex_data_i; });
  if (im.ewa_lanes > 1) {
    if (8 * sizeof(std::declval<V&>().texk_data_i) != static_cast<size_t>((im.ewa_lanes - 1) * kTpw))
      throw std::logic_error("render_rtl: the model's texk_data_i is not EwaLanes - 1 = " +
                             std::to_string(im.ewa_lanes - 1) + " texel ports");
    attach_ram<V>(e, std::make_shared<SyncReadRam64>(im.texels, kRamWords, im.ewa_lanes - 1, fmt::kTexAddrW, kTpw),
                  [](V& d) -> auto& { return d.texk_req_o; }, [](V& d) -> auto& { return d.texk_addr_o; },
                  [](V& d) -> auto& { return d.texk_data_i; });
  }
  attach_ram<V>(e, std::make_shared<SyncReadRam>(im.depth, kDepthWords, 1, fmt::kTexAddrW, 8),
                [](V& d) -> auto& { return d.d_req_o; }, [](V& d) -> auto& { return d.d_addr_o; },
                [](V& d) -> auto& { return d.d_data_i; });
  attach_ram<V>(e, std::make_shared<SyncReadRam>(im.depth, kDepthWords, 1, fmt::kTexAddrW, 8),
                [](V& d) -> auto& { return d.a_req_o; }, [](V& d) -> auto& { return d.a_addr_o; },
                [](V& d) -> auto& { return d.a_data_i; });
  attach_stream<V>(e, std::make_shared<StreamSource<ViewWord>>(im.views),
                   [](V& d) -> auto& { return d.view_valid_i; }, [](V& d) { return d.view_ready_o; },
                   [](V& d, const ViewWord& w) {
                     d.view_ok_i = static_cast<uint8_t>(w.ok);
                     d.vx_i = static_cast<uint16_t>(w.vx);
                     d.vy_i = static_cast<uint16_t>(w.vy);
                     d.vz_i = static_cast<uint16_t>(w.vz);
                     d.vc_i = static_cast<uint8_t>(w.c);
                   });
  attach_stream<V>(e, std::make_shared<StreamSource<ShadeWord>>(im.shades),
                   [](V& d) -> auto& { return d.shade_valid_i; }, [](V& d) { return d.shade_ready_o; },
                   [](V& d, const ShadeWord& w) {
                     for (size_t j = 0; j < w.size(); ++j) d.shade_i[j] = w[j];
                   });
  return e;
}
}  // namespace

RtlRender render_rtl(const scene::Scene& s, const RtlRenderOptions& o) {
  using Coefs = persp::Unit::Coefs;
  const int w = s.camera.width;
  // Each material's filter engine on this unit.
  std::map<std::string, ewa::Engine> engine_of;
  for (const auto& [name, m] : s.materials) {
    const scene::Filter f = o.filter.value_or(m.filter);
    if (f != scene::Filter::Bilinear && !o.has_ewa)
      throw std::invalid_argument(s.source + ": /materials/" + name + "/filter: " + std::string(scene::to_string(f)) +
                                  ", but the unit is bilinear-only");
    engine_of[name] = render::engine_of(f);
  }
  // The corridor unit (its plan: EWA with the 1-D weight table on every material, iterative
  // parallax) has neither the bilinear, trilinear and nearest engines, the other weight sources,
  // nor the POM march.
  for (const auto& [name, m] : o.corridor_unit ? s.materials : decltype(s.materials){}) {
    if (engine_of.at(name) != ewa::Engine::Ewa)
      throw std::invalid_argument(s.source + ": /materials/" + name + "/filter: " +
                                  std::string(scene::to_string(o.filter.value_or(m.filter))) +
                                  ", but the corridor unit has the EWA engine only (--filter ewa)");
    if (o.weights.value_or(m.weights) != scene::WeightSource::Table1d)
      throw std::invalid_argument(s.source + ": /materials/" + name +
                                  "/weights: the corridor unit has the 1-D weight table only (--weights table1d)");
    if (o.relief && m.relief && m.relief->method != scene::ReliefMethod::Iterative)
      throw std::invalid_argument(s.source + ": /materials/" + name +
                                  "/relief/method: the corridor unit's relief stage has the iterative engine only");
  }
  // Stored formats: the texel RAM holds each texture's packed words, tu_texel_decode expands them;
  // BC1 textures as 64-bit blocks (HasBc1: tu_texel_port), the other formats one texel per word
  // in its low bits (the corridor unit's plan keeps rgba8 only; the other units every format).
  for (const auto& [name, t] : o.corridor_unit ? s.textures : decltype(s.textures){})
    if (t.format != 0 || t.srgb)
      throw std::invalid_argument(s.source + ": /textures/" + name + (t.srgb ? "/srgb" : "/format") +
                                  ": the corridor unit decodes rgba8 texels only (its plan's TexFormats" +
                                  (t.format == static_cast<int>(tex::TexelFormat::Bc1) ? "; no BC1 block fetch, HasBc1 = 0)" : ")"));
  if (o.relief && !o.has_ewa)
    throw std::invalid_argument("render_rtl: relief needs the full unit (the bilinear-only unit has no relief stage)");
  // The noise unit (HasNoise, with HasWater) is in the full unit: fbm, smoke and water.
  for (const auto& [name, m] : s.materials)
    if (m.procedural && (!o.has_ewa || o.corridor_unit))
      throw std::invalid_argument(s.source + ": /materials/" + name +
                                  "/procedural: this unit has no noise unit (the full unit has); render it with --engine cmodel or ref");
  // AF with parallax visibility (docs/blocks/afvis.md): the full unit's tu_afvis (HasAfvis), with
  // the trace on the depth map itself (no coarse pyramid) and no border weights.
  auto afv_on = [&](const scene::Material& m) {
    return o.relief && m.relief && m.relief->af_visibility && o.filter.value_or(m.filter) == scene::Filter::Ewa;
  };
  for (const auto& [name, m] : s.materials) {
    if (afv_on(m) && (o.corridor_unit || s.footprint == scene::Footprint::Recurrence))
      throw std::invalid_argument(s.source + ": /materials/" + name + "/relief/af_visibility: the " +
                                  (o.corridor_unit ? "corridor unit" : "recurrence-ellipse unit") +
                                  " has no visibility engine (the full unit has); render it with --engine cmodel or ref");
    if (afv_on(m) && !m.clip.empty())
      throw std::invalid_argument(s.source + ": /materials/" + name +
                                  "/relief/af_visibility: with clip, but the visibility engine has no border weights "
                                  "(render with --clip off, or with --engine cmodel)");
  }
  // The full unit shades (HasShading); a light needs it, and a model the materials name must be its.
  const bool shade_unit = o.has_ewa && !o.corridor_unit;  // the corridor plan has no lights
  if (!shade_unit && !s.lights.empty())
    throw std::invalid_argument(s.source + ": /lights: the bilinear-only unit has no shading stage");
  for (const auto& [name, m] : s.materials)
    if (m.specular && m.specular->model != "auto" && shading::model_of(m.specular->model) != o.shade_model)
      throw std::invalid_argument(s.source + ": /materials/" + name + "/specular/model: " + m.specular->model +
                                  ", but the unit's shading stage is " + brdf::name(o.shade_model));
  // EWA border weights: the full unit's walk has them with one clip volume (o.clip_variant).
  auto clip_on = [&](const scene::Material& m) { return !m.clip.empty() && o.filter.value_or(m.filter) == scene::Filter::Ewa; };
  for (const auto& [name, m] : s.materials)
    if (clip_on(m) && (o.corridor_unit || m.clip != o.clip_variant))
      throw std::invalid_argument(s.source + ": /materials/" + name + "/clip: " + m.clip + ", but the " +
                                  (o.corridor_unit ? std::string("corridor unit has no EWA border weights")
                                                   : "unit's EWA walk has the clip volume " + o.clip_variant) +
                                  " (render with --clip off or --clip " + o.clip_variant + ")");
  if (o.ewa_lanes != 1 && (o.ewa_lanes != 4 || o.corridor_unit || !o.has_ewa || s.footprint == scene::Footprint::Recurrence ||
                           o.clip_variant != "mm_p1"))
    throw std::invalid_argument("render_rtl: ewa_lanes " + std::to_string(o.ewa_lanes) +
                                ": the K = 4 full unit only (analytic ellipse, clip mm_p1)");
  ewa::EngineParams ep = o.corridor_unit     ? corridor_ewa_params()
                         : o.ewa_lanes == 4  ? full_unit_k4_ewa_params()
                                             : ewa::EngineParams{};
  ep.clip_variant = ewa::rtl_clip_code(o.clip_variant);
  if (ep.clip_variant < 0) throw std::invalid_argument("render_rtl: clip variant " + o.clip_variant + " has no RTL");
  // B2 variant: the unit with EllRecurrence = 1 (full unit only).
  const bool rec = s.footprint == scene::Footprint::Recurrence;
  // The recurrence-ellipse model has the octave-serial noise unit (NoiseScheme = 1, the full
  // unit's NoiseCores = NoiseOctaves octaves per sum, one clock each).
  if (rec) ep.noise_slots = fmt::kNoiseOctaves;
  if (rec && !o.has_ewa)
    throw std::invalid_argument(s.source + ": /footprint: recurrence, but the bilinear-only unit has the analytic ellipse");
  render::CmodelOptions copt;
  copt.shade_model = o.shade_model;
  copt.weights = o.weights;
  copt.relief = o.relief;
  copt.threads = o.threads;
  const render::Frame expect = render::render_cmodel(s, o.filter, copt);

  // Textures in the RAM, per-triangle set-up.
  struct Obj {
    tex::Texture tex;
    uint64_t base;
    std::vector<Coefs> coefs;
    std::optional<relief::Maps> maps;  // with o.relief and a relief material
    uint64_t hbase = 0;                // its depth map in the depth RAM
    uint64_t dbase = 0;                // its distance map (after the depth map), if it has one
    std::optional<noise::ProcCodes> proc;  // a procedural material's constants
  };
  std::vector<Obj> objs;
  SyncReadRam64::Image ram;  // texel RAM words (64 bits with HasBc1; 32 otherwise: the low half)
  SyncReadRam::Image depth_ram;
  for (size_t oi = 0; oi < s.objects.size(); ++oi) {
    const auto& ob = s.objects[oi];
    Obj x{scene::build_texture(s, s.materials.at(ob.material).texture), ram.size() + 1, {}, std::nullopt, 0, 0, std::nullopt};  // after its border word
    if (s.materials.at(ob.material).procedural)
      x.proc = noise::quantise(render::procedural_params(s.materials.at(ob.material), x.tex.levels[0].width));
    if (o.relief && s.materials.at(ob.material).relief) {
      x.maps = relief::make_maps(s, ob.material);
      x.hbase = depth_ram.size();
      for (uint8_t d : x.maps->depth.px) depth_ram.push_back(d);
      x.dbase = depth_ram.size();
      if (x.maps->dist)
        for (uint8_t c : x.maps->dist->code) depth_ram.push_back(c);
    }
    const auto words = texture_words(x.tex);
    if (x.tex.format == static_cast<int>(tex::TexelFormat::Bc1)) {  // two words per block: one RAM word
      for (size_t j = 0; j + 1 < words.size(); j += 2) ram.push_back(uint64_t(words[j]) | uint64_t(words[j + 1]) << 32);
    } else {
      ram.insert(ram.end(), words.begin(), words.end());
    }
    if (ram.size() > kRamWords || depth_ram.size() > kDepthWords)
      throw std::runtime_error(s.source + ": textures need " + std::to_string(ram.size()) + " texel words and " +
                               std::to_string(depth_ram.size()) + " depth and distance-map words, the RTL RAM models hold " +
                               std::to_string(kRamWords) + " and " + std::to_string(kDepthWords));
    x.coefs = render::setup_fx(s, oi, x.tex.levels[0].width, x.tex.levels[0].height);
    objs.push_back(std::move(x));
  }

  // Spans, and the per-pixel cycle costs from the C model.
  const auto cov = render::visibility(s, o.threads);
  std::vector<Span> spans;
  std::vector<ewa::PixelCost> costs;
  std::vector<relief::StagePixel> relief_px;  // each pixel's relief step (the stage's cycle model)
  StreamSource<ViewWord>::Words views;     // the view port's words
  StreamSource<ShadeWord>::Words shades;   // the shade port's words
  const shading::Setup shade(s, o.shade_model);
  const persp::RayCaster rays(s.camera);
  auto lw_of = [](const Obj& ob) { return log2_size(ob.tex.levels[0].width); };
  auto lh_of = [](const Obj& ob) { return log2_size(ob.tex.levels[0].height); };
  size_t pix = 0;
  for (const render::CoverRun& run : render::cover_runs(cov, w)) {
    const int y = run.y, x = run.x0, x1 = run.x1;
    const render::Cover c = run.c;
    const Obj& ob = objs[static_cast<size_t>(c.object)];
    const auto& m = s.materials.at(s.objects[static_cast<size_t>(c.object)].material);
    const Coefs& k = ob.coefs[static_cast<size_t>(c.triangle)];
    const int top = ob.tex.num_levels() - 1;
    const i128 a = k.a.raw(), b = k.b.raw(), cc = k.c.raw(), d = k.d.raw(), e = k.e.raw(),
               f = k.f.raw(), g = k.g.raw(), hh = k.h.raw(), i = k.i.raw();
    const i128 kk[6] = {a * i - cc * g, d * i - f * g, b * i - cc * hh, e * i - f * hh,
                        a * hh - b * g, d * hh - e * g};
    int64_t dm;
    int32_t dexp;
    ellipse::fx::det3(k, &dm, &dexp);
    Span r;
    r.a = code(a, fmt::kPerspPW), r.b = code(b, fmt::kPerspPW), r.c = code(cc, fmt::kPerspPW);
    r.d = code(d, fmt::kPerspPW), r.e = code(e, fmt::kPerspPW), r.f = code(f, fmt::kPerspPW);
    r.g = code(g, fmt::kPerspQW), r.h = code(hh, fmt::kPerspQW), r.i = code(i, fmt::kPerspQW);
    r.x0 = static_cast<uint64_t>(x);
    r.x1 = static_cast<uint64_t>(x1);
    r.y = static_cast<uint64_t>(y);
    r.kux = kk[0], r.kvx = kk[1], r.kuy = kk[2], r.kvy = kk[3], r.m = kk[4], r.nn = kk[5];
    r.dm = code(dm, fmt::kEllDetW);
    r.dexp = code(dexp, fmt::kEllDetExpW);
    r.laniso = render::laniso_code(m.max_aniso);
    r.maxlod = static_cast<uint64_t>(top);
    const tex::LodParams lp = render::lod_params(m);
    r.lbias = code(lp.bias, fmt::kTexLodBiasW);
    r.lminlod = lp.min_lod;
    r.lmaxlod = lp.max_lod;
    const tex::LevelRange lv = tex::level_range(lp, top);
    r.lbase = static_cast<uint64_t>(lv.base);
    r.ltop = static_cast<uint64_t>(lv.top);
    r.tbase = ob.base;
    r.tlw = static_cast<uint64_t>(log2_size(ob.tex.levels[0].width));
    r.tlh = static_cast<uint64_t>(log2_size(ob.tex.levels[0].height));
    r.twrap = wrap_code(ob.tex.addressing);
    r.tfmt = static_cast<uint64_t>(ob.tex.format);
    r.tsrgb = ob.tex.srgb;
    r.wsrc = static_cast<uint64_t>(o.weights.value_or(m.weights));
    r.cap = ewa::kDefaultMaxTexels;
    const ewa::Engine eng = engine_of.at(s.objects[static_cast<size_t>(c.object)].material);
    r.filt = static_cast<uint64_t>(eng);
    r.fnmax = static_cast<uint64_t>(m.feline_max_probes);
    r.clip = clip_on(m);
    if (ob.proc) {
      r.proc = pack_proc(*ob.proc);
    }
    if (ob.maps) {
      const auto& rel = *m.relief;
      const pom::View q = relief::quantise({}, rel.scale);
      r.rel = 1;
      r.radapt = rel.method == scene::ReliefMethod::PomAdaptive;
      r.riter = rel.method == scene::ReliefMethod::Iterative;
      r.rdm = ob.maps->dist != nullptr;
      r.rlayers = r.rdm ? relief::dm_cap(rel.layers) : static_cast<uint64_t>(std::clamp(rel.layers, 1, 63));
      r.dlayers = r.rdm ? static_cast<uint64_t>(ob.maps->dist->layers) : 0;
      r.dbase = ob.dbase;
      r.rscale = q.scale;
      r.hbase = ob.hbase;
      r.hlw = static_cast<uint64_t>(log2_size(ob.maps->depth.width));
      r.hlh = static_cast<uint64_t>(log2_size(ob.maps->depth.height));
      r.afv = afv_on(m);
      r.admin = afvis::min_depth(ob.maps->depth);
      r.abias = afvis::kDefaultBias;
      r.arule = static_cast<uint64_t>(afvis::Rule::Row);
      // One view word per pixel: {ok, vx, vy, vz, complexity at the unshifted uv}.
      for (int px = x; px <= x1; ++px) {
        relief::TangentView tv;
        const bool ok = relief::pixel_view(s, c.object, c.triangle, px, y, &tv);
        const pom::View v = relief::quantise(ok ? tv : relief::TangentView{}, rel.scale);
        const persp::Pixel p = persp::Unit::pixel(persp::Unit::direct(k, px, y));
        const int du = fmt::kPomUvF - fmt::kTexUvF;
        const uint64_t cplx = pom::tex_nearest(ob.maps->complexity, relief::shift_code(p.u, du - lw_of(ob)),
                                               relief::shift_code(p.v, du - lh_of(ob)));
        views.push_back({.ok = ok, .vx = code(v.vx, fmt::kPomVzW), .vy = code(v.vy, fmt::kPomVzW),
                         .vz = code(v.vz, fmt::kPomVzW), .c = cplx});
      }
    }
    spans.push_back(r);
    for (int px = x; px <= x1; ++px, ++pix) {
      ewa::fx::In in;
      in.b2 = ellipse::fx::pixel(k, px, y, static_cast<uint32_t>(r.laniso), static_cast<uint32_t>(top), rec);
      in.b2.lod = tex::trilinear_lod(in.b2.lmin, lp, top).lod;  // the EWA's level (render_cmodel)
      const bool guard = persp::Unit::pixel(persp::Unit::direct(k, px, y)).flag;
      ewa::PixelCost pc;
      if (eng == ewa::Engine::Ewa && pix < expect.pixels.size()) {
        const auto& rec = expect.pixels[pix];
        pc = ewa::pixel_cost(in, static_cast<int>(rec.lod), rec.ewa_flags, static_cast<uint64_t>(rec.texels), top);
        pc.afv_walk = rec.afv_clocks;  // tu_afvis (0: tu_ewa)
        pc.blocks = static_cast<uint64_t>(rec.ewa_blocks);
      }
      pc.engine = eng;
      pc.guard = guard;
      pc.clip = r.clip != 0;
      pc.noise = ob.proc.has_value();
      // A format change drains (fk_q), and so does another BC1 texture (btex_q: its base, one per object).
      pc.texfmt = ob.tex.format * 2 + (ob.tex.srgb ? 1 : 0) +
                  (ob.tex.format == static_cast<int>(tex::TexelFormat::Bc1) ? static_cast<int>(c.object + 1) << 4 : 0);
      pc.water = ob.proc && ob.proc->water;
      // Trilinear: one bilinear pass for a guard pixel or a lod (GL rule) at the top level.
      const uint32_t tlod = tex::trilinear_lod(in.b2.lrho, lp, top).lod;
      pc.one_level = ewa::trilinear_one_level(guard, static_cast<int>(tlod >> fmt::kTexLodF), top);
      if (eng == ewa::Engine::Feline && pix < expect.pixels.size()) {  // its probes at their lod
        const auto& rec = expect.pixels[pix];
        pc.probes = guard ? 1 : rec.probes;
        pc.one_level = ewa::trilinear_one_level(guard, static_cast<int>(std::floor(rec.lod)), top);
      }
      costs.push_back(pc);
      if (shade_unit) shades.push_back(brdf::shade::pack(shade.fx_in(rays, c.object, c.triangle, px, y)));
      relief::StagePixel rp;
      if (ob.maps && pix < expect.pixels.size() && expect.pixels[pix].relief_n > 0)
        rp = relief::stage_pixel(true, static_cast<uint32_t>(expect.pixels[pix].relief_steps), m.relief->method);
      relief_px.push_back(rp);
    }
  }

  RunOptions ro;
  ro.stall_prob = o.stall_prob;
  ro.seed = o.seed;
  ro.skip_fall_eval = true;  // no negedge clk_i in the unit (harness.hpp)
  // The scoreboard expects one output per covered pixel of each span.
  std::vector<uint64_t> fanout;
  for (const Span& r : spans) fanout.push_back(r.x1 - r.x0 + 1);
  const auto t0 = std::chrono::steady_clock::now();
  BasicRunResult<UnitPixel> rr;
  UnitImages images;
  images.texels = std::make_shared<const SyncReadRam64::Image>(std::move(ram));
  images.depth = std::make_shared<const SyncReadRam::Image>(std::move(depth_ram));
  images.views = std::make_shared<const StreamSource<ViewWord>::Words>(std::move(views));
  images.shades = std::make_shared<const StreamSource<ShadeWord>::Words>(std::move(shades));
  images.ewa_lanes = o.corridor_unit || o.ewa_lanes == 4 ? 4 : 1;  // testbench/cosim/CMakeLists.txt -GEwaLanes
  // Every Verilated variant of the unit (parameters differ, ports equal) runs through one harness.
  auto run_unit = [&](auto model) {
    using V = typename decltype(model)::type;
    Harness<V, Span, UnitPixel> hs(drive<V>, sample<V>, [&images]() { return unit_env<V>(images); });
    rr = hs.run(spans, ro, fanout);
  };
  if (o.corridor_unit) {
    if (!o.has_ewa) throw std::invalid_argument("render_rtl: the corridor unit has EWA (has_ewa must be set)");
    run_unit(std::type_identity<Vtu_texture_unit_corridor>{});
  } else if (rec) {
    run_unit(std::type_identity<Vtu_texture_unit_rec>{});
  } else if (o.ewa_lanes == 4) {
#if TU_COSIM_K4_UNIT
    run_unit(std::type_identity<Vtu_texture_unit_k4>{});
#else
    throw std::invalid_argument("render_rtl: the full unit with the K = 4 EWA engine is verilated only with "
                                "-DTU_COSIM_K4_UNIT=ON");
#endif
  } else if (o.has_ewa && ep.clip_variant != 0) {
#if TU_COSIM_CLIP_VARIANTS
    if (ep.clip_variant == 1) {
      run_unit(std::type_identity<Vtu_texture_unit_clip1>{});
    } else {
      run_unit(std::type_identity<Vtu_texture_unit_clip2>{});
    }
#else
    throw std::invalid_argument("render_rtl: the unit with clip volume " + o.clip_variant +
                                " (EwaClipVariant " + std::to_string(ep.clip_variant) +
                                ") is verilated only with -DTU_COSIM_CLIP_VARIANTS=ON (scripts/cosim_clip_variants.sh)");
#endif
  } else if (o.has_ewa) {
    run_unit(std::type_identity<Vtu_texture_unit>{});
  } else {
    run_unit(std::type_identity<Vtu_texture_unit_bil>{});
  }
  RtlRender out;
  out.sim_wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  out.spans = spans.size();
  out.cycles = rr.sim_cycles;
  out.hung = rr.hung;
  out.extra_outputs = rr.extra_outputs;
  // The full unit has the relief stage: its marches and iterations interleave with the filter's
  // work (ewa::texture_unit_cycles); the bilinear-only unit streams its pixels (stream_cycles).
  // The recurrence ellipse's longer front (B1 waits in a FIFO) is modelled for scenes without
  // relief pixels only (stream_cycles from its front latency); with relief pixels: not predicted.
  // The shading stage (II = 1, its words preloaded) adds its pipeline's latency once, at the end.
  const uint64_t shade_lat = shade_unit ? static_cast<uint64_t>(brdf::shade::latency(o.shade_model)) : 0;
  if (rec)
    out.predicted_cycles = images.views->empty() ? ewa::stream_cycles(costs, static_cast<uint64_t>(ewa::texture_unit_front_latency(true, true)), ep) + shade_lat : 0;
  else
    out.predicted_cycles = (o.has_ewa ? ewa::texture_unit_cycles(costs, relief_px, ep)
                                      : ewa::stream_cycles(costs, static_cast<uint64_t>(ewa::texture_unit_front_latency(false)))) +
                           shade_lat;
  out.frame.image = expect.image;
  for (size_t i = 0; i < rr.outputs.size(); ++i) {
    const UnitPixel& q = rr.outputs[i];
    render::PixelRecord rec;
    rec.x = static_cast<int>(q.x);
    rec.y = static_cast<int>(q.y);
    rec.color = unpack_rgba(static_cast<uint32_t>(q.rgba));
    rec.lod = static_cast<double>(q.level);
    rec.texels = static_cast<int>(q.visited);
    rec.texels_inside = static_cast<int>(q.inside);
    rec.ewa_flags = static_cast<uint32_t>(q.flags);
    rec.b2_flags = static_cast<uint32_t>(q.eflags);
    rec.relief_n = static_cast<int>(q.rn);
    rec.relief_steps = static_cast<int>(q.rsteps);
    rec.relief_flags = static_cast<uint32_t>(q.rflags);
    if (i < expect.pixels.size()) {
      const auto& e = expect.pixels[i];
      rec.object = e.object, rec.u = e.u, rec.v = e.v;
      // Bilinear / trilinear / nearest pixels: the unit reports 4 / 8 / 1 texels, no EWA flags (the C
      // model's level and texel records of those are its own bookkeeping: compared is the engine
      // that filtered, and the colour).
      // Procedural pixels (the noise unit): no texels, no filter flags. Feline pixels: floor(lod),
      // their texels, and their probes in the inside count (0 for a guard pixel: no filter).
      const ewa::Engine eng = engine_of.at(s.objects[static_cast<size_t>(e.object)].material);
      const bool noise = objs[static_cast<size_t>(e.object)].proc.has_value();
      const bool same = rec.x == e.x && rec.y == e.y && rec.color == e.color && rec.b2_flags == e.b2_flags &&
                        rec.relief_n == e.relief_n && rec.relief_steps == e.relief_steps &&
                        rec.relief_flags == e.relief_flags &&
                        (noise ? rec.lod == 0 && rec.texels == 0 && rec.texels_inside == 0 && rec.ewa_flags == 0
                         : eng == ewa::Engine::Ewa
                             ? rec.lod == e.lod && rec.texels == e.texels && rec.texels_inside == e.texels_inside &&
                                   rec.ewa_flags == e.ewa_flags
                         : eng == ewa::Engine::Feline
                             ? rec.lod == std::floor(e.lod) && rec.texels == e.texels &&
                                   rec.texels_inside == e.probes && rec.ewa_flags == 0
                             : rec.texels == (eng == ewa::Engine::Trilinear ? 8 : eng == ewa::Engine::Nearest ? 1 : 4) &&
                                   rec.texels_inside == 0 &&
                                   rec.ewa_flags == 0);
      if (eng == ewa::Engine::Feline) rec.probes = rec.texels_inside, rec.texels_inside = 0;
      if (!same) {
        if (out.mismatches == 0) {
          char buf[256];
          std::snprintf(buf, sizeof buf,
                        "pixel %zu (%d,%d): RTL (%d,%d) rgba %d %d %d %d level %g texels %d/%d flags %u/%u; "
                        "C model rgba %d %d %d %d level %g texels %d/%d flags %u/%u",
                        i, e.x, e.y, rec.x, rec.y, rec.color.r, rec.color.g, rec.color.b, rec.color.a,
                        rec.lod, rec.texels, rec.texels_inside, rec.b2_flags, rec.ewa_flags, e.color.r,
                        e.color.g, e.color.b, e.color.a, e.lod, e.texels, e.texels_inside, e.b2_flags,
                        e.ewa_flags);
          out.first_mismatch = buf;
        }
        ++out.mismatches;
      }
      out.frame.image.at(rec.x, rec.y) = rec.color;
    }
    out.frame.pixels.push_back(rec);
  }
  out.mismatches += expect.pixels.size() > rr.outputs.size() ? expect.pixels.size() - rr.outputs.size() : 0;
  return out;
}

}  // namespace tu::cosim
