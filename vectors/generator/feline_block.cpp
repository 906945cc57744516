// Vector sets for the bit-accurate Feline filter (docs/blocks/feline.md, feline/feline_fx.hpp).
//   in : u, v (s32.8 level-0 texels), B2 outputs ae, ce (u62), be (s64), lmaj, lmin, lrho
//        (s18.10), b2flags (u5), guard (B1 guard pixel: the texture's mean), nmax (probe cap,
//        1..FelNMax), the sampler's lod rule: bias (s14.8), min_lod, max_lod (u12.8), base_level,
//        max_level (levels, tex::level_range on the texture's pyramid)
//   out: r, g, b, a (u8), level (floor of the probe lod; guard: the top level), texels (8 per
//        probe, 4 with one level; guard 1), probes (N; guard 0), flags (feline::fx::Flag)
//   ref: float Feline (feline::fx::filter_ref_b2) on the same B2 axes and direction, RGBA f64
//        (guard: the top level's texel).
// Texture (fixed, not in the file): the built-in bricks colour texture, 256 x 256, repeat, as the
// ewa block's; the RTL testbench loads the same texture.
// Error unit: 8-bit colour levels, max over RGBA of |c - c_ref|.
#include <cmath>
#include <random>
#include <stdexcept>

#include "block.hpp"
#include "ewa/ewa_fx.hpp"
#include "feline/feline_fx.hpp"
#include "texture/trilinear_lod.hpp"

namespace tu::blocks {

namespace {
namespace efx = ellipse::fx;
using ewa::fx::In;

struct Pixel {
  In in;
  bool guard = false;
  feline::fx::Config cfg;
};

const tex::Texture& texture() {
  static const tex::Texture t = tex::Texture::build("bricks", tex::bricks(256).color, tex::Wrap::Repeat);
  return t;
}

Row row_of(const Pixel& p) {
  const auto& o = p.in.b2;
  const auto& l = p.cfg.lod;
  return {field_bits(p.in.u, fmt::kPerspUvW), field_bits(p.in.v, fmt::kPerspUvW), o.ae, o.ce, static_cast<uint64_t>(o.be),
          field_bits(o.lmaj, fmt::kEllLogW), field_bits(o.lmin, fmt::kEllLogW), field_bits(o.lrho, fmt::kEllLogW), o.flags,
          p.guard, static_cast<uint64_t>(p.cfg.max_probes), field_bits(l.bias, fmt::kTexLodBiasW), l.min_lod, l.max_lod,
          l.base_level, l.max_level};
}
Pixel pixel_of(const Row& r) {
  Pixel p;
  p.in.u = vec::sext(r[0], fmt::kPerspUvW);
  p.in.v = vec::sext(r[1], fmt::kPerspUvW);
  p.in.b2.ae = r[2];
  p.in.b2.ce = r[3];
  p.in.b2.be = static_cast<int64_t>(r[4]);
  p.in.b2.lmaj = static_cast<int32_t>(vec::sext(r[5], fmt::kEllLogW));
  p.in.b2.lmin = static_cast<int32_t>(vec::sext(r[6], fmt::kEllLogW));
  p.in.b2.lrho = static_cast<int32_t>(vec::sext(r[7], fmt::kEllLogW));
  p.in.b2.flags = static_cast<uint32_t>(r[8]);
  p.guard = r[9] != 0;
  if (r[10] < 1 || r[10] > static_cast<uint64_t>(fmt::kFelNMax))
    throw std::invalid_argument("feline: field nmax = " + std::to_string(r[10]) + " (1.." + std::to_string(fmt::kFelNMax) + ")");
  p.cfg.max_probes = static_cast<int>(r[10]);
  p.cfg.lod.bias = static_cast<int32_t>(vec::sext(r[11], fmt::kTexLodBiasW));
  p.cfg.lod.min_lod = static_cast<uint32_t>(r[12]);
  p.cfg.lod.max_lod = static_cast<uint32_t>(r[13]);
  p.cfg.lod.base_level = static_cast<uint32_t>(r[14]);
  p.cfg.lod.max_level = static_cast<uint32_t>(r[15]);
  return p;
}

// The engine's output for a pixel (the render's guard rule: the 1 x 1 top level's texel).
feline::fx::Out model_out(const Pixel& p) {
  if (p.guard) {
    feline::fx::Out o;
    o.color = texture().levels.back().at(0, 0);
    o.probes = 0;
    o.texels = 1;
    o.lod = static_cast<uint32_t>(texture().num_levels() - 1) << fmt::kTexLodF;
    return o;
  }
  return feline::fx::filter(p.in, texture(), p.cfg);
}

using ewa::fx::footprint_local;
constexpr auto local = footprint_local;
Row row(const efx::Local& l, int nmax, tex::LodParams lod = {}, uint32_t laniso = 4 << fmt::kEllLogF, uint32_t max_lod = 8) {
  Pixel p{ewa::fx::in_from_local(l, laniso, max_lod), false, {nmax, lod}};
  return row_of(p);
}

// Curated: magnified, isotropic, 2 : 1 .. 8 : 1 rotated, clamped caps, lod bias and clamps,
// the top level (one level per probe), a guard pixel.
std::vector<Row> golden_inputs() {
  std::vector<Row> rows;
  for (int nmax : {2, 8, 16}) {
    rows.push_back(row(local(0.3, 1.2, 0.4, 10.25, 20.75), nmax));   // magnified
    rows.push_back(row(local(1.0, 1.0, 0.0, 100.5, 100.5), nmax));   // one texel per pixel
    rows.push_back(row(local(6.0, 2.0, 1.0, -33.1, 57.9), nmax));    // 2 : 1
    rows.push_back(row(local(24.0, 8, 2.2, 77.7, 66.6), nmax));      // rotated, 8 : 1
    rows.push_back(row(local(12.0, 4, -0.9, 5.5, 250.5), nmax));     // rotated the other way
    rows.push_back(row(local(40.0, 200, 0.3, 300.7, -12.2), nmax));  // clamped (16 : 1 aniso)
    rows.push_back(row(local(3000.0, 3, 0.2, 1.0, 2.0), nmax, {}, 4 << fmt::kEllLogF, 12));  // top level
  }
  rows.push_back(row(local(24.0, 8, 0.7, 7.5, 9.5), 8, tex::lod_params(1.5, 0.0, 15.99)));   // bias
  rows.push_back(row(local(24.0, 8, 0.7, 7.5, 9.5), 8, tex::lod_params(0.0, 0.0, 1.0)));     // max lod
  rows.push_back(row(local(24.0, 8, 0.7, 7.5, 9.5), 8, tex::lod_params(0.0, 4.0, 15.99)));   // min lod
  rows.push_back(row(local(24.0, 8, 0.7, 7.5, 9.5), 8, tex::lod_params(0.0, 0.0, 15.99, 2, 5)));  // levels
  Pixel g{ewa::fx::in_from_local(local(4.0, 2, 0.3, 3.5, 4.5)), true, {8, {}}};
  rows.push_back(row_of(g));
  return rows;
}

std::vector<Row> stiff_inputs() {
  std::vector<Row> rows;
  // 1 : 1000 before the clamp, 16 orientations, every cap.
  for (int t = 0; t < 16; ++t) rows.push_back(row(local(64, 1000, t * M_PI / 16, 50.5 + t, 20.25), 1 + t));
  // Anisotropy limit 1024 : 1 and the s1 clamp (2^FelAxisMaxLog2 texels).
  for (int t = 0; t < 4; ++t)
    rows.push_back(row(local(t < 2 ? 2000 : 1e5, 1000, t * 0.7, 9.0, 9.0), 16, {}, 10 << fmt::kEllLogF, 12));
  // Horizon, point, line.
  {
    Pixel p{ewa::fx::in_from_local(local(64, 4, 0.3, 3.5, 4.5)), false, {8, {}}};
    p.in.b2 = efx::Out{};
    p.in.b2.flags = efx::kHorizon;
    rows.push_back(row_of(p));
    efx::Local pt = local(1, 1, 0, 7.0, 8.0);
    pt.ux = pt.vx = pt.uy = pt.vy = 0;
    rows.push_back(row(pt, 8));
    rows.push_back(row(local(32, 0, 0.7, 11.0, 12.0), 8));
  }
  // Ratios at the probe-count thresholds (n : 1 and just above), cap 16.
  for (double r : {1.0, 1.004, 1.01, 2.0, 2.02, 3.0, 3.03, 7.0, 7.1, 15.0, 15.2, 16.0, 17.0})
    rows.push_back(row(local(16.0 * r, r, 0.4, 40.5, 41.5), 16));
  // Texture edges and far coordinates (repeat), the largest u, v codes.
  for (double u : {0.0, 0.01, 255.99, 256.0, -0.5, 1e6, -8e6})
    rows.push_back(row(local(5, 2, 0.1, u, 255.9), 4));
  // Magnification extremes; the lod rule's extremes (bias +-16, min lod above max lod).
  for (double m : {1.0 / 1024, 0.5, 0.999, 1.001, 2.0}) rows.push_back(row(local(m, 2.0, 0.0, 31.5, 31.5), 8));
  rows.push_back(row(local(24.0, 8, 0.7, 7.5, 9.5), 8, tex::lod_params(16.0, 0.0, 15.99)));
  rows.push_back(row(local(24.0, 8, 0.7, 7.5, 9.5), 8, tex::lod_params(-16.0, 0.0, 15.99)));
  rows.push_back(row(local(24.0, 8, 0.7, 7.5, 9.5), 8, tex::lod_params(0.0, 6.0, 2.0)));
  return rows;
}

std::vector<Row> random_inputs(uint64_t count, uint64_t seed) {
  return random_rows(count, seed, [](std::mt19937_64& rng) {
    Pixel p{ewa::fx::random_in(rng), rng() % 64 == 0, {1 + static_cast<int>(rng() % fmt::kFelNMax), {}}};
    if (rng() % 4 == 0) {  // a bias, clamps or a level range one pixel in 4
      const double bias = static_cast<double>(static_cast<int>(rng() % 33) - 16) / 4;
      const double lo = static_cast<double>(rng() % 8) / 2, hi = lo + static_cast<double>(rng() % 24) / 2;
      p.cfg.lod = tex::lod_params(bias, lo, std::min(hi, 15.99), static_cast<int>(rng() % 4), static_cast<int>(4 + rng() % 8));
    }
    return row_of(p);
  });
}

Row ref_of(const Row& r) {
  const Pixel p = pixel_of(r);
  tex::RgbaF c;
  if (p.guard) {
    const auto px = texture().levels.back().at(0, 0);
    c = {double(px.r), double(px.g), double(px.b), double(px.a)};
  } else {
    const auto& l = p.cfg.lod;
    feline::Params fp;
    fp.max_probes = p.cfg.max_probes;
    fp.lod_bias = std::ldexp(double(l.bias), -fmt::kTexLodF);
    fp.min_lod = std::ldexp(double(l.min_lod), -fmt::kTexLodF);
    fp.max_lod = std::ldexp(double(l.max_lod), -fmt::kTexLodF);
    fp.base_level = static_cast<int>(l.base_level);
    fp.max_level = static_cast<int>(l.max_level);
    c = feline::fx::filter_ref_b2(p.in, texture(), fp).color;
  }
  return {vec::f64_bits(c.r), vec::f64_bits(c.g), vec::f64_bits(c.b), vec::f64_bits(c.a)};
}
}  // namespace

Block make_feline() {
  Block b;
  b.name = "feline";
  b.description =
      "Feline probe filter (bit-accurate, docs/blocks/feline.md): N = ceil(major / minor) trilinear "
      "probes (capped) along B2's major axis (the EWA's CORDIC), Gaussian weights, reciprocal "
      "normalisation; texture fixed: built-in bricks colour 256x256, repeat; variable latency";
  using vec::Role;
  auto sf = [](int w, int f) { return "s" + std::to_string(w) + "." + std::to_string(f); };
  auto uf = [](int w, int f) { return "u" + std::to_string(w) + "." + std::to_string(f); };
  const std::string uv = sf(fmt::kPerspUvW, fmt::kTexUvF), lg = sf(fmt::kEllLogW, fmt::kEllLogF);
  const std::string lod = uf(fmt::kEllLodW, fmt::kTexLodF);
  b.fields = {field("u", Role::In, uv),
              field("v", Role::In, uv),
              field("ae", Role::In, uf(fmt::kEllCoefW - 2, 0)),
              field("ce", Role::In, uf(fmt::kEllCoefW - 2, 0)),
              field("be", Role::In, sf(fmt::kEllCoefW, 0)),
              field("lmaj", Role::In, lg),
              field("lmin", Role::In, lg),
              field("lrho", Role::In, lg),
              field("b2flags", Role::In, uf(5, 0)),
              field("guard", Role::In, uf(1, 0)),
              field("nmax", Role::In, uf(fmt::kFelProbeW, 0)),
              field("bias", Role::In, sf(fmt::kTexLodBiasW, fmt::kTexLodF)),
              field("min_lod", Role::In, lod),
              field("max_lod", Role::In, lod),
              field("base_level", Role::In, uf(4, 0)),
              field("max_level", Role::In, uf(11, 0)),
              field("r", Role::Out, uf(8, 0)),
              field("g", Role::Out, uf(8, 0)),
              field("b", Role::Out, uf(8, 0)),
              field("a", Role::Out, uf(8, 0)),
              field("level", Role::Out, uf(4, 0)),
              field("texels", Role::Out, uf(fmt::kEwaCountW, 0)),
              field("probes", Role::Out, uf(fmt::kFelProbeW, 0)),
              field("flags", Role::Out, uf(3, 0)),
              field("r_ref", Role::Ref, "f64"),
              field("g_ref", Role::Ref, "f64"),
              field("b_ref", Role::Ref, "f64"),
              field("a_ref", Role::Ref, "f64")};
  b.sets = {"golden", "stiff", "random"};
  b.inputs = standard_sets(golden_inputs, stiff_inputs, random_inputs);
  b.model = [](const Row& r) {
    const auto o = model_out(pixel_of(r));
    return Row{o.color.r, o.color.g, o.color.b, o.color.a, o.lod >> fmt::kTexLodF, static_cast<uint64_t>(o.texels),
               static_cast<uint64_t>(o.probes), o.flags};
  };
  b.ref = ref_of;
  b.error = [](const Row&, const Row& out, const Row& ref) {
    ErrPoint e;
    for (int c = 0; c < 4; ++c)
      e.abs = std::max(e.abs, std::fabs(double(out[static_cast<size_t>(c)]) - vec::bits_f64(ref[static_cast<size_t>(c)])));
    e.ulp = e.abs;
    return e;
  };
  b.latency_cycles = 0;  // data-dependent (probes, levels): feline::EngineModel
  b.ii_cycles = 0;
  b.err_metric = "max_color_err";
  return b;
}

}  // namespace tu::blocks
