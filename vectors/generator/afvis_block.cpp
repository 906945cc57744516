// Vector sets for AF with parallax visibility (cmodel/blocks/afvis, docs/blocks/afvis.md): the EWA
// walk over the footprint texels the eye sees over the relief (afvis::filter).
//   in : the EWA block's pixel (u, v, B2's ae, ce, be, lmaj, lmin, lod, flags, weight source, cap;
//        no border weights), the quantised tangent-space view vx, vy, vz (s16.14) and height scale
//        S (u16.16), the trace map's smallest code dmin, the bias (depth codes) and the rule
//        (0 every texel, 1 the seed's row rule)
//   out: r, g, b, a, level, texels visited (box) and inside (w > 0), flags, texels kept (visible),
//        traced, depth reads (steps)
//   ref: the float EWA with the float visibility mask (afvis::with_visibility, trace_ref on the
//        double P of the float view), RGBA f64.
// Maps (fixed, not in the file): the built-in bricks colour texture 256 x 256, repeat (the ewa
// block's), and the bricks depth map pom::map_bricks(64) (64 x 64, trace cells = depth texels).
// Error unit: 8-bit colour levels, max over RGBA of |c - c_ref|.
#include <cmath>
#include <random>
#include <stdexcept>

#include "afvis/afvis.hpp"
#include "afvis/afvis_ref.hpp"
#include "afvis_block.hpp"
#include "block.hpp"
#include "ewa_pixel_fields.hpp"
#include "ewa/ewa_fx.hpp"
#include "pom/relief_quality.hpp"

namespace tu::blocks {

const tex::Texture& afvis_texture() {
  static const tex::Texture t = tex::Texture::build("bricks", tex::bricks(256).color, tex::Wrap::Repeat);
  return t;
}
const img::Gray8& afvis_depth() {
  static const img::Gray8 d = pom::map_bricks(64);
  return d;
}

namespace {
namespace efx = ellipse::fx;

struct Pixel {
  ewa::fx::In in;
  ewa::fx::Config cfg;
  pom::View view;
  int dmin = 0, bias = afvis::kDefaultBias;
  afvis::Rule rule = afvis::Rule::Row;
};

Row row_of(const Pixel& p) {
  Row r = ewa_pixel_row(p.in, p.cfg);
  r.insert(r.end(), {field_bits(p.view.vx, fmt::kPomVzW), field_bits(p.view.vy, fmt::kPomVzW), field_bits(p.view.vz, fmt::kPomVzW),
          p.view.scale, static_cast<uint64_t>(p.dmin), static_cast<uint64_t>(p.bias), static_cast<uint64_t>(p.rule)});
  return r;
}
Pixel pixel_of(const Row& r) {
  Pixel p;
  ewa_pixel_of(r, "afvis", p.in, p.cfg);
  p.view.vx = static_cast<int32_t>(vec::sext(r[11], fmt::kPomVzW));
  p.view.vy = static_cast<int32_t>(vec::sext(r[12], fmt::kPomVzW));
  p.view.vz = static_cast<int32_t>(vec::sext(r[13], fmt::kPomVzW));
  p.view.scale = static_cast<uint32_t>(r[14]);
  p.dmin = static_cast<int>(r[15]);
  p.bias = static_cast<int>(r[16]);
  if (r[17] > 1) throw std::invalid_argument("afvis: field rule = " + std::to_string(r[17]) + " (0, 1)");
  p.rule = static_cast<afvis::Rule>(r[17]);
  return p;
}

afvis::Relief relief_of(const Pixel& p) {
  const pom::Parallax pp = pom::parallax(p.view);
  afvis::Relief r;
  r.depth = &afvis_depth();
  r.dmin = static_cast<uint8_t>(p.dmin);
  r.pu = pp.pu, r.pv = pp.pv;
  r.lw = 8, r.lh = 8;
  r.bias = p.bias;
  return r;
}

// The unit's view (s16.14, S u0.16) at `angle` degrees from the normal, azimuth `az` degrees.
pom::View view_at(double angle, double az, double scale) {
  const double th = angle * M_PI / 180, ph = az * M_PI / 180;
  pom::View v;
  v.vx = static_cast<int32_t>(std::lround(std::sin(th) * std::cos(ph) * (1 << fmt::kPomVzF)));
  v.vy = static_cast<int32_t>(std::lround(std::sin(th) * std::sin(ph) * (1 << fmt::kPomVzF)));
  v.vz = static_cast<int32_t>(std::lround(std::cos(th) * (1 << fmt::kPomVzF)));
  v.scale = static_cast<uint32_t>(std::min(65535.0, std::round(scale * (1 << fmt::kPomSF))));
  return v;
}

constexpr auto local = ewa::fx::footprint_local;
Pixel px(const efx::Local& l, int w, const pom::View& v, afvis::Rule rule = afvis::Rule::Row,
         int bias = afvis::kDefaultBias, uint32_t cap = 1024, uint32_t max_lod = 8,
         uint32_t laniso = 4 << fmt::kEllLogF) {
  Pixel p;
  p.in = ewa::fx::in_from_local(l, laniso, max_lod);
  p.cfg = {static_cast<ewa::fx::Weights>(w), cap, nullptr};
  p.view = v;
  p.dmin = afvis::min_depth(afvis_depth());
  p.bias = bias;
  p.rule = rule;
  return p;
}

// Curated: magnified to minified footprints at 45 .. 88 degrees, both rules, each weight source.
std::vector<Row> golden_inputs() {
  std::vector<Row> rows;
  for (int w = 0; w < 3; ++w)
    for (auto rule : {afvis::Rule::Every, afvis::Rule::Row}) {
      rows.push_back(row_of(px(local(0.3, 1.2, 0.4, 10.25, 20.75), w, view_at(60, 10, 0.08), rule)));
      rows.push_back(row_of(px(local(1.0, 1.0, 0.0, 100.5, 100.5), w, view_at(70, 90, 0.08), rule)));
      rows.push_back(row_of(px(local(6.0, 1.5, 1.0, -33.1, 57.9), w, view_at(75, 200, 0.1), rule)));
      rows.push_back(row_of(px(local(24.0, 8, 2.2, 77.7, 66.6), w, view_at(80, 33, 0.08), rule)));
      rows.push_back(row_of(px(local(12.0, 4, -0.9, 5.5, 250.5), w, view_at(85, 300, 0.05), rule)));
      rows.push_back(row_of(px(local(60.0, 16, 0.8, 128.0, 128.0), w, view_at(45, 120, 0.2), rule, 16, 40)));
      rows.push_back(row_of(px(local(3.0, 2, 0.3, 40.0, 90.0), w, view_at(88, 0, 0.3), rule, 0)));
    }
  return rows;
}

std::vector<Row> stiff_inputs() {
  std::vector<Row> rows;
  // Grazing views (to the 88.2 deg guard and beyond: vz 0, vz < 0 mirrored), the largest S:
  // traces reach the AfvStepMax cap.
  for (double a : {86.0, 88.0, 89.5, 90.0})
    for (double s : {0.5, 65535.0 / 65536})
      rows.push_back(row_of(px(local(4, 8, 0.7, 13.7, 7.3), static_cast<int>(a) % 3, view_at(a, 45 * a, s))));
  {
    pom::View v = view_at(70, 30, 0.1);
    v.vz = -v.vz;  // the back face: |Vz| as the relief step
    rows.push_back(row_of(px(local(8, 2, 0.2, 50.0, 60.0), 0, v)));
  }
  // P = 0 (normal view, or S = 0): every trace ends at its first read; the plain walk's colour.
  rows.push_back(row_of(px(local(8, 2, 0.2, 50.0, 60.0), 1, view_at(0, 0, 0.1))));
  rows.push_back(row_of(px(local(8, 2, 0.2, 50.0, 60.0), 2, view_at(70, 0, 0))));
  // Bias 0 and 255, dmin 255 (no texel below the top: nothing traced beyond d0), dmin 0.
  for (int bias : {0, 255}) rows.push_back(row_of(px(local(10, 4, 1.1, 70.0, 20.0), 0, view_at(80, 100, 0.1), afvis::Rule::Every, bias)));
  for (int d : {255, 0}) {
    Pixel p = px(local(10, 4, 1.1, 70.0, 20.0), 1, view_at(80, 100, 0.1));
    p.dmin = d;
    rows.push_back(row_of(p));
  }
  // The widest rows (the row buffer): the anisotropy limit 1024:1 clamps the major axis to
  // 2^EwaAxisMaxLog2 texels, along a row (0) and at 0.7 rad; 1:1000 before the clamp at 4 angles,
  // horizon, point and line footprints.
  for (double t : {0.0, 0.7})
    rows.push_back(row_of(px(local(2000, 1000, t, 9.0, 9.0), 0, view_at(50, 10, 0.05), afvis::Rule::Row, 16, 1u << 16, 8,
                             10 << fmt::kEllLogF)));
  for (int t = 0; t < 4; ++t) rows.push_back(row_of(px(local(64, 1000, t * M_PI / 4, 50.5 + t, 20.25), t % 3, view_at(75, 90 * t, 0.08))));
  {
    Pixel p = px(local(64, 4, 0.3, 3.5, 4.5), 0, view_at(70, 0, 0.1));
    p.in.b2 = efx::Out{};
    p.in.b2.flags = efx::kHorizon;
    rows.push_back(row_of(p));
    efx::Local pt = local(1, 1, 0, 7.0, 8.0);
    pt.ux = pt.vx = pt.uy = pt.vy = 0;
    rows.push_back(row_of(px(pt, 0, view_at(70, 0, 0.1))));
    rows.push_back(row_of(px(local(32, 0, 0.7, 11.0, 12.0), 1, view_at(70, 45, 0.1))));
  }
  // Caps 1 and the largest, lod saturation, far coordinates (repeat), texture edges.
  for (uint32_t cap : {1u, (1u << fmt::kEwaCountW) - 1})
    rows.push_back(row_of(px(local(90, 16, 0.5, 60.0, 70.0), 0, view_at(80, 10, 0.1), afvis::Rule::Row, 16, cap)));
  rows.push_back(row_of(px(local(3000, 1.5, 0.2, 1.0, 2.0), 0, view_at(80, 10, 0.1), afvis::Rule::Row, 16, 1024, 12)));
  for (double u : {0.0, 255.99, -0.5, 1e6, -8e6})
    rows.push_back(row_of(px(local(5, 2, 0.1, u, 255.9), 2, view_at(82, 190, 0.1))));
  return rows;
}

std::vector<Row> random_inputs(uint64_t count, uint64_t seed) {
  return random_rows(count, seed, [](std::mt19937_64& rng) {
    Pixel p;
    p.in = ewa::fx::random_in(rng);
    p.cfg.weights = static_cast<ewa::fx::Weights>(rng() % 3);
    p.cfg.max_texels = rng() % 8 == 0 ? static_cast<uint32_t>(1 + rng() % 2048) : 1024;
    std::uniform_real_distribution<double> ang(0, 90), az(0, 360), sc(0, 0.3);
    p.view = view_at(ang(rng), az(rng), sc(rng));
    p.dmin = rng() % 8 == 0 ? static_cast<int>(rng() % 256) : afvis::min_depth(afvis_depth());
    p.bias = rng() % 4 == 0 ? static_cast<int>(rng() % 256) : afvis::kDefaultBias;
    p.rule = static_cast<afvis::Rule>(rng() % 2);
    return row_of(p);
  });
}

Row ref_of(const Row& r) {
  const Pixel p = pixel_of(r);
  const afvis::ParallaxRef pr = afvis::parallax_ref(std::ldexp(double(p.view.vx), -fmt::kPomVzF),
                                                    std::ldexp(double(p.view.vy), -fmt::kPomVzF),
                                                    std::ldexp(double(p.view.vz), -fmt::kPomVzF),
                                                    std::ldexp(double(p.view.scale), -fmt::kPomSF));
  afvis::RefRelief rr{&afvis_depth(), nullptr, static_cast<uint8_t>(p.dmin), pr.pu, pr.pv, 8, 8, p.rule,
                      nullptr, nullptr, p.bias};
  ewa::Params ep;
  ep.max_texels = static_cast<int>(p.cfg.max_texels);
  const auto res = ewa::fx::filter_ref_b2(p.in, afvis_texture(), afvis::with_visibility(ep, rr));
  return {vec::f64_bits(res.color.r), vec::f64_bits(res.color.g), vec::f64_bits(res.color.b),
          vec::f64_bits(res.color.a)};
}
}  // namespace

afvis::Out afvis_block_model(const Row& in) {
  const Pixel p = pixel_of(in);
  return afvis::filter(p.in, afvis_texture(), {p.cfg, p.rule}, relief_of(p));
}

Block make_afvis() {
  Block b;
  b.name = "afvis";
  b.description =
      "AF with parallax visibility (seed 003 §6): the EWA walk keeping the footprint texels whose "
      "ray towards the eye clears the relief (integer box-field DDA per texel, row rule, weights "
      "renormalised, nearest-texel fallback); maps fixed: bricks colour 256x256 repeat, bricks "
      "depth 64x64; variable latency";
  using vec::Role;
  auto sf = [](int w, int f) { return "s" + std::to_string(w) + "." + std::to_string(f); };
  auto uf = [](int w, int f) { return "u" + std::to_string(w) + "." + std::to_string(f); };
  const std::string uv = sf(fmt::kPerspUvW, fmt::kTexUvF), lg = sf(fmt::kEllLogW, fmt::kEllLogF);
  const std::string cnt = uf(fmt::kEwaCountW, 0), vz = sf(fmt::kPomVzW, fmt::kPomVzF);
  b.fields = {field("u", Role::In, uv),
              field("v", Role::In, uv),
              field("ae", Role::In, uf(fmt::kEllCoefW - 2, 0)),
              field("ce", Role::In, uf(fmt::kEllCoefW - 2, 0)),
              field("be", Role::In, sf(fmt::kEllCoefW, 0)),
              field("lmaj", Role::In, lg),
              field("lmin", Role::In, lg),
              field("lod", Role::In, uf(fmt::kEllLodW, fmt::kEllLodF)),
              field("b2flags", Role::In, uf(5, 0)),
              field("wsrc", Role::In, uf(2, 0)),
              field("cap", Role::In, cnt),
              field("vx", Role::In, vz),
              field("vy", Role::In, vz),
              field("vz", Role::In, vz),
              field("scale", Role::In, uf(fmt::kPomSW, fmt::kPomSF)),
              field("dmin", Role::In, uf(8, 0)),
              field("bias", Role::In, uf(8, 0)),
              field("rule", Role::In, uf(1, 0)),
              field("r", Role::Out, uf(8, 0)),
              field("g", Role::Out, uf(8, 0)),
              field("b", Role::Out, uf(8, 0)),
              field("a", Role::Out, uf(8, 0)),
              field("level", Role::Out, uf(4, 0)),
              field("visited", Role::Out, cnt),
              field("inside", Role::Out, cnt),
              field("flags", Role::Out, uf(ewa::fx::kFlagW, 0)),
              field("kept", Role::Out, cnt),
              field("traced", Role::Out, cnt),
              field("steps", Role::Out, uf(24, 0)),
              field("r_ref", Role::Ref, "f64"),
              field("g_ref", Role::Ref, "f64"),
              field("b_ref", Role::Ref, "f64"),
              field("a_ref", Role::Ref, "f64")};
  b.ports = {{"b2flags", "eflags"}};  // tu_afvis's eflags_i (B2's footprint flags)
  b.sets = {"golden", "stiff", "random"};
  b.inputs = standard_sets(golden_inputs, stiff_inputs, random_inputs);
  b.model = [](const Row& r) {
    const afvis::Out o = afvis_block_model(r);
    return Row{o.ewa.color.r, o.ewa.color.g, o.ewa.color.b, o.ewa.color.a, static_cast<uint64_t>(o.ewa.level),
               o.ewa.texels_visited, o.ewa.texels_inside, o.ewa.flags, o.visible, o.traced, o.steps};
  };
  b.ref = ref_of;
  b.error = [](const Row&, const Row& out, const Row& ref) {
    ErrPoint e;
    for (int c = 0; c < 4; ++c)
      e.abs = std::max(e.abs, std::fabs(double(out[static_cast<size_t>(c)]) - vec::bits_f64(ref[static_cast<size_t>(c)])));
    e.ulp = e.abs;
    return e;
  };
  b.latency_cycles = 0;  // data-dependent (box, traces): afvis::Out::clocks, the cycle model
  b.ii_cycles = 0;
  b.err_metric = "max_color_err";
  return b;
}

}  // namespace tu::blocks
