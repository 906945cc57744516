// Vector sets for the bit-accurate EWA filter (B5, cmodel/blocks/ewa/ewa_fx.hpp).
//   in : u, v (s32.8 level-0 texels), B2 outputs ae, ce (u64), be (s64), lmaj, lmin (s18.10),
//        lod (u12.8), b2flags (u5), weight source wsrc (0 formula, 1 table1d, 2 table2d), cap
//        (max_texels, u17), clip (1: sub-texel border weights with the block's clip volume mm_p1,
//        the co-simulated tu_ewa's ClipVariant 0)
//   out: r, g, b, a (u8), level (u4), texels visited (box) and inside (w > 0) (u17), flags (u5)
//   ref: float EWA (ewa_ref.hpp filter_axes) on the same B2 axes and conic direction (border
//        weights with the exact Phi when clip), RGBA f64.
// Texture (fixed, not in the file): the built-in bricks colour texture, 256 x 256, repeat
// (tex::bricks(256).color); the RTL testbench loads the same texture.
// Error unit: 8-bit colour levels, max over RGBA of |c - c_ref|.
#include <cmath>
#include <random>
#include <stdexcept>

#include "block.hpp"
#include "ewa_pixel_fields.hpp"
#include "ewa/ewa_cycles.hpp"
#include "ewa/ewa_fx.hpp"
#include "gauss/clip.hpp"

namespace tu::blocks {

namespace {
namespace efx = ellipse::fx;
using ewa::fx::In;

// The block's clip volume for clip = 1: the co-simulated tu_ewa's ClipVariant 0.
const clip::Variant& block_clip() { return clip::variant(ewa::kRtlClipVariants[0]); }

struct Pixel {
  In in;
  ewa::fx::Config cfg;
};

Row row_of(const Pixel& p) {
  Row r = ewa_pixel_row(p.in, p.cfg);
  r.push_back(p.cfg.clip != nullptr);
  return r;
}
Pixel pixel_of(const Row& r) {
  Pixel p;
  ewa_pixel_of(r, "ewa", p.in, p.cfg);
  if (r[11] > 1) throw std::invalid_argument("ewa: field clip = " + std::to_string(r[11]) + " (0, 1)");
  if (r[11]) p.cfg.clip = &block_clip();
  return p;
}

const tex::Texture& texture() {
  static const tex::Texture t = tex::Texture::build("bricks", tex::bricks(256).color, tex::Wrap::Repeat);
  return t;
}

using ewa::fx::footprint_local;
constexpr auto local = footprint_local;
Row row(const efx::Local& l, int w, uint32_t cap = 1024, uint32_t laniso = 4 << fmt::kEllLogF,
        uint32_t max_lod = 8, bool clip = false) {
  return row_of({ewa::fx::in_from_local(l, laniso, max_lod),
                 {static_cast<ewa::fx::Weights>(w), cap, clip ? &block_clip() : nullptr}});
}
Row clip_row(const efx::Local& l, int w, uint32_t cap = 1024) { return row(l, w, cap, 4 << fmt::kEllLogF, 8, true); }

// Curated: magnified, minified, 16:1 clamped, rotated, cap fallback, each weight source.
std::vector<Row> golden_inputs() {
  std::vector<Row> rows;
  for (int w = 0; w < 3; ++w) {
    rows.push_back(row(local(0.3, 1.2, 0.4, 10.25, 20.75), w));         // magnified
    rows.push_back(row(local(1.0, 1.0, 0.0, 100.5, 100.5), w));         // one texel per pixel
    rows.push_back(row(local(6.0, 1.5, 1.0, -33.1, 57.9), w));          // minified, level 2
    rows.push_back(row(local(40.0, 200, 0.3, 300.7, -12.2), w));        // 16:1 clamped
    rows.push_back(row(local(24.0, 8, 2.2, 77.7, 66.6), w));            // rotated, 8:1
    rows.push_back(row(local(12.0, 4, -0.9, 5.5, 250.5), w));           // rotated the other way
    rows.push_back(row(local(60.0, 16, 0.8, 128.0, 128.0), w, 40));     // cap fallback
    rows.push_back(row(local(3000.0, 1.5, 0.2, 1.0, 2.0), w, 1024, 4 << fmt::kEllLogF, 12));  // lod sat
    // border weights: magnified (the 2 x 2 box becomes 3 x 3), minified, rotated 8:1, cap fallback
    rows.push_back(clip_row(local(0.3, 1.2, 0.4, 10.25, 20.75), w));
    rows.push_back(clip_row(local(6.0, 1.5, 1.0, -33.1, 57.9), w));
    rows.push_back(clip_row(local(24.0, 8, 2.2, 77.7, 66.6), w));
    rows.push_back(clip_row(local(60.0, 16, 0.8, 128.0, 128.0), w, 40));
  }
  return rows;
}

std::vector<Row> stiff_inputs() {
  std::vector<Row> rows;
  // 1:1000 before the clamp, 16 orientations, each weight source.
  for (int t = 0; t < 16; ++t) rows.push_back(row(local(64, 1000, t * M_PI / 16, 50.5 + t, 20.25), t % 3));
  // Anisotropy limit 1024:1 (laniso 10): the major axis is clamped to 2^EwaAxisMaxLog2 texels.
  for (int t = 0; t < 4; ++t) rows.push_back(row(local(2000, 1000, t * 0.7, 9.0, 9.0), t % 3, 1u << 16, 10 << fmt::kEllLogF));
  // Horizon, point, line.
  {
    Pixel p{ewa::fx::in_from_local(local(64, 4, 0.3, 3.5, 4.5)), {}};
    p.in.b2 = efx::Out{};
    p.in.b2.flags = efx::kHorizon;
    rows.push_back(row_of(p));
    efx::Local pt = local(1, 1, 0, 7.0, 8.0);
    pt.ux = pt.vx = pt.uy = pt.vy = 0;
    rows.push_back(row(pt, 0));
    rows.push_back(row(local(32, 0, 0.7, 11.0, 12.0), 1));
  }
  // Caps: 1 (top level walked anyway), the largest, and a few in between.
  for (uint32_t cap : {1u, 2u, 9u, 100u, (1u << fmt::kEwaCountW) - 1})
    rows.push_back(row(local(90, 16, 0.5, 60.0, 70.0), 0, cap));
  // Texture edges and far coordinates (repeat), the largest u, v codes.
  for (double u : {0.0, 0.01, 255.99, 256.0, -0.5, 1e6, -8e6})
    rows.push_back(row(local(5, 2, 0.1, u, 255.9), 2));
  // Magnification extremes and exact circles.
  for (double m : {1.0 / 1024, 0.5, 0.999, 1.0, 1.001, 2.0})
    rows.push_back(row(local(m, 1.0, 0.0, 31.5, 31.5), 1));
  // Border weights: 1:1000 at 4 angles, the 1024:1 limit, line, caps 1 and the largest (the grown
  // box counts), magnification extremes, texture edges.
  for (int t = 0; t < 4; ++t) rows.push_back(clip_row(local(64, 1000, t * M_PI / 4, 50.5 + t, 20.25), t % 3));
  rows.push_back(row(local(2000, 1000, 0.7, 9.0, 9.0), 1, 1u << 16, 10 << fmt::kEllLogF, 8, true));
  rows.push_back(clip_row(local(32, 0, 0.7, 11.0, 12.0), 2));
  for (uint32_t cap : {1u, (1u << fmt::kEwaCountW) - 1}) rows.push_back(clip_row(local(90, 16, 0.5, 60.0, 70.0), 0, cap));
  for (double m : {1.0 / 1024, 1.0, 2.0}) rows.push_back(clip_row(local(m, 1.0, 0.0, 31.5, 31.5), 1));
  for (double u : {0.0, 255.99}) rows.push_back(clip_row(local(5, 2, 0.1, u, 255.9), 0));
  return rows;
}

std::vector<Row> random_inputs(uint64_t count, uint64_t seed) {
  return random_rows(count, seed, [](std::mt19937_64& rng) {
    Pixel p{ewa::fx::random_in(rng), {}};
    p.cfg.weights = static_cast<ewa::fx::Weights>(rng() % 3);
    p.cfg.max_texels = rng() % 8 == 0 ? static_cast<uint32_t>(1 + rng() % 2048) : 1024;
    if (rng() % 4 == 0) p.cfg.clip = &block_clip();  // one pixel in 4 with border weights
    return row_of(p);
  });
}

Row ref_of(const Row& r) {
  const Pixel p = pixel_of(r);
  const auto res = ewa::fx::filter_ref_b2(p.in, texture(), p.cfg.max_texels, p.cfg.clip != nullptr);
  return {vec::f64_bits(res.color.r), vec::f64_bits(res.color.g), vec::f64_bits(res.color.b),
          vec::f64_bits(res.color.a)};
}
}  // namespace

uint64_t ewa_lane_blocks(const Row& in) {
  const Pixel p = pixel_of(in);
  return ewa::fx::filter(p.in, texture(), p.cfg).lane_blocks;
}

Row ewa_model_with(const Row& in, const tex::Texture& t) {
  const Pixel p = pixel_of(in);
  const auto o = ewa::fx::filter(p.in, t, p.cfg);
  return Row{o.color.r, o.color.g, o.color.b, o.color.a, static_cast<uint64_t>(o.level), o.texels_visited,
             o.texels_inside, o.flags};
}

Block make_ewa() {
  Block b;
  b.name = "ewa";
  b.description =
      "EWA texture filter (B5, bit-accurate): ellipse rebuilt from B2's axes and conic direction "
      "(CORDIC), Heckbert walk, Gaussian weights (formula / 1-D / 2-D table), reciprocal "
      "normalisation, optional sub-texel border weights (clip volume mm_p1); texture fixed: built-in "
      "bricks colour 256x256, repeat; variable latency";
  using vec::Role;
  auto sf = [](int w, int f) { return "s" + std::to_string(w) + "." + std::to_string(f); };
  auto uf = [](int w, int f) { return "u" + std::to_string(w) + "." + std::to_string(f); };
  const std::string uv = sf(fmt::kPerspUvW, fmt::kTexUvF), lg = sf(fmt::kEllLogW, fmt::kEllLogF);
  const std::string cnt = uf(fmt::kEwaCountW, 0);
  b.fields = {field("u", Role::In, uv),
              field("v", Role::In, uv),
              // B2 block-normalises Ae', Ce' below 2^(EllCoefW-2) (ellipse_fx.cpp): the field
              // holds exactly that range, on which ewa::fx's Ae' - Ce' cannot overflow.
              field("ae", Role::In, uf(fmt::kEllCoefW - 2, 0)),
              field("ce", Role::In, uf(fmt::kEllCoefW - 2, 0)),
              field("be", Role::In, sf(fmt::kEllCoefW, 0)),
              field("lmaj", Role::In, lg),
              field("lmin", Role::In, lg),
              field("lod", Role::In, uf(fmt::kEllLodW, fmt::kEllLodF)),
              field("b2flags", Role::In, uf(5, 0)),
              field("wsrc", Role::In, uf(2, 0)),
              field("cap", Role::In, cnt),
              field("clip", Role::In, uf(1, 0)),
              field("r", Role::Out, uf(8, 0)),
              field("g", Role::Out, uf(8, 0)),
              field("b", Role::Out, uf(8, 0)),
              field("a", Role::Out, uf(8, 0)),
              field("level", Role::Out, uf(4, 0)),
              field("visited", Role::Out, cnt),
              field("inside", Role::Out, cnt),
              field("flags", Role::Out, uf(ewa::fx::kFlagW, 0)),
              field("r_ref", Role::Ref, "f64"),
              field("g_ref", Role::Ref, "f64"),
              field("b_ref", Role::Ref, "f64"),
              field("a_ref", Role::Ref, "f64")};
  b.ports = {{"b2flags", "eflags"}};  // tu_ewa's eflags_i (B2's footprint flags)
  b.sets = {"golden", "stiff", "random"};
  b.inputs = standard_sets(golden_inputs, stiff_inputs, random_inputs);
  b.model = [](const Row& r) { return ewa_model_with(r, texture()); };
  b.ref = ref_of;
  b.error = [](const Row&, const Row& out, const Row& ref) {
    ErrPoint e;
    for (int c = 0; c < 4; ++c)
      e.abs = std::max(e.abs, std::fabs(double(out[static_cast<size_t>(c)]) - vec::bits_f64(ref[static_cast<size_t>(c)])));
    e.ulp = e.abs;
    return e;
  };
  b.latency_cycles = 0;  // data-dependent (box size): measured by the RTL's cycle model
  b.ii_cycles = 0;
  b.err_metric = "max_color_err";
  return b;
}

}  // namespace tu::blocks
