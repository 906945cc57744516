// Stimulus of the texture-unit top (rtl/top/tu_texture_unit.sv) for the Icarus testbench
// testbench/icarus/tu_unit_tb.sv, without Verilator: a scene's spans (the port codes render_rtl in
// testbench/cosim/texture_unit_rtl.cpp drives: B1 coefficient codes, the per-triangle footprint
// constants, the texture and the filter of each span), the texel RAM image and the C-model pixels
// the unit must output, one per covered pixel in span order. The texture path only: no relief,
// no procedural material, no light (the unit of `texunit plan docs/scenes/ui_quad.json` has no
// relief, noise or shading stage), and the bilinear, trilinear or nearest engine on every
// material (--filter; the EWA engine's texel counts and flags are not written).
// Usage: tu_unit_stimulus SCENE.json OUTDIR [--filter bilinear|trilinear|nearest]
//                         [--window X0 Y0 X1 Y1]   (only the pixels of that rectangle, inclusive:
//                         each span clipped to it; a crop of the scene's pixel stream)
// Writes OUTDIR/spans.txt (one span a line, hex fields in tu_unit_tb.sv's order), OUTDIR/texels.hex
// ($readmemh: 64-bit texel RAM words from address 0) and OUTDIR/expect.txt (one pixel a line:
// x y rgba visited eflags, hex; eflags: B2's flags, compared as render_rtl compares them), and prints "spans N pixels N texel_words N".
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "../cosim/texel_ram.hpp"
#include "ellipse/ellipse_fx.hpp"
#include "texture/texel_format.hpp"
#include "texture/trilinear_lod.hpp"
#include "texunit/formats.hpp"
#include "texunit/render.hpp"
#include "texunit/scene.hpp"

using namespace tu;

namespace {

uint64_t code(i128 v, int w) { return static_cast<uint64_t>(v) & (w >= 64 ? ~0ull : (1ull << w) - 1); }

// A 112-bit numerator constant as hex (28 digits).
std::string hex112(i128 v) {
  const unsigned __int128 u = static_cast<unsigned __int128>(v) & ((static_cast<unsigned __int128>(1) << 112) - 1);
  char buf[40];
  std::snprintf(buf, sizeof buf, "%012llx%016llx", static_cast<unsigned long long>(u >> 64),
                static_cast<unsigned long long>(u));
  return buf;
}

int run(int argc, char** argv) {
  if (argc < 3) throw std::invalid_argument("usage: tu_unit_stimulus SCENE.json OUTDIR [--filter F] [--window X0 Y0 X1 Y1]");
  const std::string scene_path = argv[1], out = argv[2];
  scene::Filter filter = scene::Filter::Bilinear;
  int wx0 = 0, wy0 = 0, wx1 = 1 << 30, wy1 = 1 << 30;
  for (int k = 3; k < argc; ++k) {
    const std::string a = argv[k];
    if (a == "--filter" && k + 1 < argc) {
      const std::string f = argv[++k];
      filter = f == "bilinear"    ? scene::Filter::Bilinear
               : f == "trilinear" ? scene::Filter::Trilinear
               : f == "nearest"   ? scene::Filter::Nearest
                                  : throw std::invalid_argument("--filter: bilinear, trilinear or nearest, not " + f);
    } else if (a == "--window" && k + 4 < argc) {
      wx0 = std::atoi(argv[k + 1]), wy0 = std::atoi(argv[k + 2]), wx1 = std::atoi(argv[k + 3]), wy1 = std::atoi(argv[k + 4]);
      k += 4;
    } else {
      throw std::invalid_argument("unknown argument " + a);
    }
  }
  const scene::Scene s = scene::load(scene_path);
  if (!s.lights.empty()) throw std::invalid_argument(s.source + ": /lights: the texture path only (no shading stage)");
  for (const auto& [name, m] : s.materials)
    if (m.procedural) throw std::invalid_argument(s.source + ": /materials/" + name + ": procedural: the texture path only");
  if (s.footprint == scene::Footprint::Recurrence)
    throw std::invalid_argument(s.source + ": /footprint: recurrence: the analytic ellipse only");
  render::CmodelOptions copt;
  copt.relief = false;
  const render::Frame expect = render::render_cmodel(s, filter, copt);
  const ewa::Engine eng = render::engine_of(filter);
  const int visited = eng == ewa::Engine::Trilinear ? 8 : eng == ewa::Engine::Nearest ? 1 : 4;

  // Texel RAM: every object's texture after the previous one (as render_rtl loads it).
  std::vector<uint64_t> ram;
  std::vector<tex::Texture> texs;
  std::vector<uint64_t> bases;
  std::vector<std::vector<persp::Unit::Coefs>> coefs;
  for (size_t oi = 0; oi < s.objects.size(); ++oi) {
    const auto& ob = s.objects[oi];
    texs.push_back(scene::build_texture(s, s.materials.at(ob.material).texture));
    const tex::Texture& t = texs.back();
    bases.push_back(ram.size() + 1);  // after its border word
    const auto words = cosim::texture_words(t);
    if (t.format == static_cast<int>(tex::TexelFormat::Bc1)) {
      for (size_t j = 0; j + 1 < words.size(); j += 2) ram.push_back(uint64_t(words[j]) | uint64_t(words[j + 1]) << 32);
    } else {
      ram.insert(ram.end(), words.begin(), words.end());
    }
    if (ram.size() > (uint64_t(1) << fmt::kTexRamLog2Words))
      throw std::runtime_error(s.source + ": textures need " + std::to_string(ram.size()) + " texel words");
    coefs.push_back(render::setup_fx(s, oi, t.levels[0].width, t.levels[0].height));
  }

  std::filesystem::create_directories(out);
  std::ofstream fs(out + "/spans.txt"), fe(out + "/expect.txt"), ft(out + "/texels.hex");
  fs << "# tu_unit_stimulus " << scene_path << ": a b c d e f g h i x0 x1 y kux kvx kuy kvy m nn dm dexp laniso "
        "maxlod lbias lminlod lmaxlod lbase ltop tbase tlw tlh twrap tfmt tsrgb wsrc cap filt fnmax clip\n";
  for (uint64_t w : ram) {
    char buf[24];
    std::snprintf(buf, sizeof buf, "%016llx\n", static_cast<unsigned long long>(w));
    ft << buf;
  }
  const int w = s.camera.width;
  const auto cov = render::visibility(s);
  size_t pix = 0, nspans = 0, npix = 0;
  for (const render::CoverRun& run : render::cover_runs(cov, w)) {
    const int y = run.y, x = run.x0, x1 = run.x1;
    const render::Cover c = run.c;
    const size_t first_pix = pix;
    pix += static_cast<size_t>(x1 - x + 1);
    // The part of the span inside the window.
    const int cx0 = std::max(x, wx0), cx1 = std::min(x1, wx1);
    if (y < wy0 || y > wy1 || cx0 > cx1) {
      continue;
    }
    const auto oi = static_cast<size_t>(c.object);
    const tex::Texture& t = texs[oi];
    const auto& m = s.materials.at(s.objects[oi].material);
    const persp::Unit::Coefs& k = coefs[oi][static_cast<size_t>(c.triangle)];
    const int top = t.num_levels() - 1;
    const i128 a = k.a.raw(), b = k.b.raw(), cc = k.c.raw(), d = k.d.raw(), e = k.e.raw(), f = k.f.raw(),
               g = k.g.raw(), hh = k.h.raw(), i = k.i.raw();
    const i128 kk[6] = {a * i - cc * g, d * i - f * g, b * i - cc * hh, e * i - f * hh, a * hh - b * g, d * hh - e * g};
    int64_t dm;
    int32_t dexp;
    ellipse::fx::det3(k, &dm, &dexp);
    const tex::LodParams lp = render::lod_params(m);
    const tex::LevelRange lv = tex::level_range(lp, top);
    const uint64_t f1[] = {code(a, fmt::kPerspPW), code(b, fmt::kPerspPW), code(cc, fmt::kPerspPW),
                           code(d, fmt::kPerspPW), code(e, fmt::kPerspPW), code(f, fmt::kPerspPW),
                           code(g, fmt::kPerspQW), code(hh, fmt::kPerspQW), code(i, fmt::kPerspQW),
                           static_cast<uint64_t>(cx0), static_cast<uint64_t>(cx1), static_cast<uint64_t>(y)};
    for (uint64_t v : f1) fs << std::hex << v << ' ';
    for (i128 v : kk) fs << hex112(v) << ' ';
    const uint64_t f2[] = {code(dm, fmt::kEllDetW), code(dexp, fmt::kEllDetExpW), render::laniso_code(m.max_aniso),
                           static_cast<uint64_t>(top), code(lp.bias, fmt::kTexLodBiasW), static_cast<uint64_t>(lp.min_lod),
                           static_cast<uint64_t>(lp.max_lod), static_cast<uint64_t>(lv.base), static_cast<uint64_t>(lv.top),
                           bases[oi], static_cast<uint64_t>(cosim::log2_size(t.levels[0].width)),
                           static_cast<uint64_t>(cosim::log2_size(t.levels[0].height)), cosim::wrap_code(t.addressing),
                           static_cast<uint64_t>(t.format), static_cast<uint64_t>(t.srgb),
                           static_cast<uint64_t>(m.weights), static_cast<uint64_t>(ewa::kDefaultMaxTexels),
                           static_cast<uint64_t>(eng), static_cast<uint64_t>(m.feline_max_probes), 0};
    for (size_t j = 0; j < std::size(f2); ++j) fs << std::hex << f2[j] << (j + 1 < std::size(f2) ? ' ' : '\n');
    ++nspans;
    for (int px = cx0; px <= cx1; ++px) {
      const render::PixelRecord& r = expect.pixels.at(first_pix + static_cast<size_t>(px - x));
      if (r.x != px || r.y != y) throw std::logic_error("C-model pixel order differs from the spans");
      char buf[64];
      std::snprintf(buf, sizeof buf, "%x %x %08x %x %x\n", r.x, r.y, cosim::pack_rgba(r.color), visited, r.b2_flags);
      fe << buf;
      ++npix;
    }
  }
  std::printf("spans %zu pixels %zu texel_words %zu\n", nspans, npix, ram.size());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tu_unit_stimulus: %s\n", e.what());
    return 2;
  }
}
