// Vector sets for the POM set-up, refinement and the full per-pixel unit (rtl/pom/tu_pom_setup.sv,
// tu_pom_refine.sv, tu_pom_unit.sv; docs/blocks/relief-appendix.md §8). Models: pom::setup, pom::refine,
// pom::march (depth: the engines' bricks ROM). References (double): dT = Vxy/a*S/N; the exact
// weight a/den; pom::march_ref at the same N. Errors in uv LSB (2^-16).
#include <random>

#include "complexity/complexity.hpp"
#include "pom/pom_layers.hpp"

#include "block.hpp"
#include "pom_vec_common.hpp"

namespace tu::blocks {

namespace {
using namespace pomvec;

vec::Field F(const char* n, vec::Role r, const char* f) { return vec::Field{n, r, vec::FieldFormat::parse(f)}; }
const vec::Role In = vec::Role::In, Out = vec::Role::Out, Ref = vec::Role::Ref;

pom::View view_of(const Row& in, size_t i) {  // vx, vy, vz, s at in[i..i+3]
  pom::View v;
  v.vx = static_cast<int32_t>(s16(in[i]));
  v.vy = static_cast<int32_t>(s16(in[i + 1]));
  v.vz = static_cast<int32_t>(s16(in[i + 2]));
  v.scale = static_cast<uint32_t>(in[i + 3]);
  return v;
}
Row view_row(const pom::View& v) { return {c16(v.vx), c16(v.vy), c16(v.vz), v.scale}; }

// View edge cases: Vz -> 0, Vz = 0, Vz < 0 (incl. -2^15), |V| > 1, V = 0, S = 0 and S max.
std::vector<pom::View> stiff_views() {
  std::vector<pom::View> vs;
  for (int32_t vz : {-32768, -16384, -513, -1, 0, 1, 511, 512, 513, 16384, 32767})
    for (int32_t vx : {-32768, -1, 0, 9000, 32767})
      for (uint32_t s : {0u, 3277u, 65535u}) {
        pom::View v;
        v.vx = vx;
        v.vy = vx == 0 ? 0 : -vx / 3 - 1;
        v.vz = vz;
        v.scale = s;
        vs.push_back(v);
      }
  return vs;
}

std::vector<pom::View> golden_views() {
  std::vector<pom::View> vs;
  for (double ang : {0.0, 30.0, 45.0, 60.0, 80.0, 85.0, 88.0, 89.0, 90.0})
    vs.push_back(view(ang, 30, 0.05));
  auto back = view(60, 30, 0.05);
  back.vz = -back.vz;
  vs.push_back(back);
  vs.push_back(pom::View{0, 0, 0, 3277});  // degenerate V = 0
  return vs;
}

pom::View random_view(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> ang(0, 89.5), az(0, 360), sc(0.0, 0.12);
  auto v = view(ang(rng), az(rng), sc(rng));
  if (rng() % 10 == 0) v.vz = -v.vz;  // back-facing
  return v;
}

const uint64_t kGoldenN[] = {1, 4, 8, 16, 24, 32, 63};

// Golden pixels of the refinement and the unit: views x N x 3 uv (one without wrap: discard).
template <class MakeRow>
std::vector<Row> golden_pixels(MakeRow make_row) {
  std::vector<Row> rows;
  for (const auto& v : golden_views())
    for (uint64_t n : kGoldenN)
      for (int64_t u : {int64_t(512), int64_t(20992), int64_t(65000)})
        rows.push_back(make_row(u, u / 3 + 777, v, n, u != 512));
  return rows;
}

// uv error in LSB, modulo 1 (wrapped outputs and the fract-wrapped march_ref).
ErrPoint uv_error(const Row&, const Row& out, const Row& ref) {
  ErrPoint e;
  e.abs = std::max(wrapped_lsb(s32(out[0]) / 65536.0, vec::bits_f64(ref[0])),
                   wrapped_lsb(s32(out[1]) / 65536.0, vec::bits_f64(ref[1])));
  e.ulp = e.abs;
  return e;
}

// ---- pom_setup ---------------------------------------------------------------------------------
Row setup_row(const pom::View& v, uint64_t n) {
  Row r = view_row(v);
  r.push_back(n);
  return r;
}

Block make_setup() {
  Block b;
  b.name = "pom_setup";
  b.description = "POM set-up: a = max(|Vz|, VzMin), P = Vxy*S/a, dT = P/N (two reciprocal cores)";
  b.fields = {F("vx", In, "s16.14"),     F("vy", In, "s16.14"),      F("vz", In, "s16.14"),
              F("s", In, "u16.16"),      F("n", In, "u6.0"),         F("du", Out, "s32.16"),
              F("dv", Out, "s32.16"),    F("n_out", Out, "u6.0"),    F("back", Out, "u1.0"),
              F("clamped", Out, "u1.0"), F("ref_du", Ref, "f64"),    F("ref_dv", Ref, "f64")};
  b.ports = {{"n_out", "n"}};  // tu_pom_setup's n_o (n_i is the requested count)
  b.sets = {"golden", "stiff", "random"};
  b.inputs = standard_sets(
      [] {
        std::vector<Row> rows;
        for (const auto& v : golden_views())
          for (uint64_t n : kGoldenN) rows.push_back(setup_row(v, n));
        return rows;
      },
      [] {
        std::vector<Row> rows;
        for (const auto& v : stiff_views())
          for (uint64_t n : {1u, 2u, 3u, 63u}) rows.push_back(setup_row(v, n));
        return rows;
      },
      [](uint64_t count, uint64_t seed) {
        std::mt19937_64 rng(seed);
        std::vector<Row> rows;
        for (uint64_t i = 0; i < count; ++i) {
          const uint64_t r = rng();
          // 1 in 4: raw 16-bit codes (any |V|, any S); else a unit view vector
          const pom::View v = (r & 3) == 0 ? pom::View{static_cast<int32_t>(s16(r >> 8)),
                                                       static_cast<int32_t>(s16(r >> 24)),
                                                       static_cast<int32_t>(s16(r >> 40)),
                                                       static_cast<uint32_t>(rng() & 0xffff)}
                                           : random_view(rng);
          rows.push_back(setup_row(v, 1 + (r >> 56) % 63));
        }
        return rows;
      });
  b.model = [](const Row& in) {
    const auto s = pom::setup(view_of(in, 0), static_cast<uint32_t>(in[4]));
    return Row{c32(s.du), c32(s.dv), in[4], s.back ? 1u : 0u, s.clamped ? 1u : 0u};
  };
  b.ref = [](const Row& in) {
    const auto v = view_of(in, 0);
    const double a = std::max(std::fabs(v.vz / 16384.0), fmt::kPomVzMin / 16384.0);
    const double k = v.scale / 65536.0 / a / static_cast<double>(in[4]);
    return Row{vec::f64_bits(v.vx / 16384.0 * k), vec::f64_bits(v.vy / 16384.0 * k)};
  };
  b.error = [](const Row&, const Row& out, const Row& ref) {
    ErrPoint e;
    e.abs = std::max(std::fabs(s32(out[0]) / 65536.0 - vec::bits_f64(ref[0])),
                     std::fabs(s32(out[1]) / 65536.0 - vec::bits_f64(ref[1]))) * 65536.0;
    e.ulp = e.abs;  // uv LSB
    return e;
  };
  b.latency_cycles = fmt::kPomSetupLatency;
  b.ii_cycles = 1;
  return b;
}

// ---- pom_refine --------------------------------------------------------------------------------
// Inputs are march results: T_k, dT, k, a, den from pom::march_core on the bricks map.
Row refine_row(int64_t u, int64_t v, const pom::View& vw, uint32_t n, bool wrap) {
  const auto s = pom::setup(vw, n);
  const auto c = pom::march_core(depth(), u, v, s.du, s.dv, n);
  return {c32(c.u), c32(c.v), c32(s.du), c32(s.dv), c.steps, c.a, c.den, wrap ? 1u : 0u};
}

Block make_refine() {
  Block b;
  b.name = "pom_refine";
  b.description = "POM refinement: w = a*recip(den), T'' = T_k + w*dT, wrap or discard";
  b.fields = {F("tu", In, "s32.16"),      F("tv", In, "s32.16"),     F("du", In, "s32.16"),
              F("dv", In, "s32.16"),      F("steps", In, "u6.0"),    F("a", In, "u16.0"),
              F("den", In, "u16.0"),      F("wrap", In, "u1.0"),     F("u", Out, "s32.16"),
              F("v", Out, "s32.16"),      F("steps_out", Out, "u6.0"), F("w", Out, "u17.16"),
              F("discard", Out, "u1.0"),  F("ref_u", Ref, "f64"),    F("ref_v", Ref, "f64")};
  b.ports = {{"tu", "u"}, {"tv", "v"}, {"steps_out", "steps"}};  // tu_pom_refine's u_i / u_o, ...
  b.sets = {"golden", "stiff", "random"};
  b.inputs = standard_sets(
      [] {
        return golden_pixels([](int64_t u, int64_t v, const pom::View& vw, uint64_t n, bool wrap) {
          return refine_row(u, v, vw, static_cast<uint32_t>(n), wrap);
        });
      },
      [] {
        std::vector<Row> rows;
        // w at its ends (a = 0, a = den), den = 1 and the largest den, k = 63, T at the [0,1] edges
        for (uint64_t den : {1u, 2u, 255u, 16065u, 32767u})
          for (uint64_t a : {uint64_t(0), den / 2, den})
            for (int64_t t : {int64_t(-1), int64_t(0), int64_t(65536), int64_t(65537), int64_t(1) << 22})
              for (int64_t d : {-(int64_t(1) << 22) + 1, int64_t(-1), int64_t(0), int64_t(1) << 21})
                rows.push_back({c32(t), c32(65536 - t), c32(d), c32(-d), 63, a, den, uint64_t(t & 1)});
        for (int64_t t : {int64_t(0), int64_t(65536), int64_t(-5)})
          rows.push_back({c32(t), c32(t), 100, 100, 0, 0, 0, 0});  // k = 0: T'' = T
        return rows;
      },
      [](uint64_t count, uint64_t seed) {
        std::mt19937_64 rng(seed);
        std::vector<Row> rows;
        for (uint64_t i = 0; i < count; ++i) {
          const uint64_t r = rng();
          const auto v = random_view(rng);
          rows.push_back(refine_row(r & 0xffff, (r >> 16) & 0xffff, v,
                                    static_cast<uint32_t>(1 + (r >> 32) % 63), (r >> 40) & 1));
        }
        return rows;
      });
  b.model = [](const Row& in) {
    pom::MarchCore c;
    c.u = s32(in[0]);
    c.v = s32(in[1]);
    c.steps = static_cast<uint32_t>(in[4]);
    c.a = static_cast<uint32_t>(in[5]);
    c.den = static_cast<uint32_t>(in[6]);
    const auto o = pom::refine(c, s32(in[2]), s32(in[3]), in[7] != 0);
    return Row{c32(o.u), c32(o.v), o.steps, o.w, o.discard ? 1u : 0u};
  };
  b.ref = [](const Row& in) {
    const double w = in[4] == 0 ? 0.0 : double(in[5]) / double(in[6]);
    double u = (s32(in[0]) + w * s32(in[2])) / 65536.0, v = (s32(in[1]) + w * s32(in[3])) / 65536.0;
    if (in[7]) {
      u -= std::floor(u);
      v -= std::floor(v);
    }
    return Row{vec::f64_bits(u), vec::f64_bits(v)};
  };
  b.error = uv_error;
  b.latency_cycles = fmt::kPomRefineLatency;
  b.ii_cycles = 1;
  return b;
}

// ---- pom_unit ----------------------------------------------------------------------------------
Row unit_row(int64_t u, int64_t v, const pom::View& vw, uint64_t n, bool wrap) {
  Row r{c32(u), c32(v)};
  for (uint64_t x : view_row(vw)) r.push_back(x);
  r.push_back(n);
  r.push_back(wrap ? 1u : 0u);
  return r;
}

Block make_unit() {
  Block b;
  b.name = "pom_unit";
  b.description = "per-pixel POM: set-up -> march (1 layer/clock) -> refinement, bricks ROM";
  b.fields = {F("u", In, "s32.16"),       F("v", In, "s32.16"),     F("vx", In, "s16.14"),
              F("vy", In, "s16.14"),      F("vz", In, "s16.14"),    F("s", In, "u16.16"),
              F("n", In, "u6.0"),         F("wrap", In, "u1.0"),    F("tu", Out, "s32.16"),
              F("tv", Out, "s32.16"),     F("steps", Out, "u6.0"),  F("w", Out, "u17.16"),
              F("discard", Out, "u1.0"),  F("back", Out, "u1.0"),   F("clamped", Out, "u1.0"),
              F("ref_u", Ref, "f64"),     F("ref_v", Ref, "f64")};
  b.ports = {{"tu", "u"}, {"tv", "v"}};  // tu_pom_unit's u_o / v_o
  b.sets = {"golden", "stiff", "random"};
  b.inputs = standard_sets(
      [] { return golden_pixels(unit_row); },
      [] {
        std::vector<Row> rows;
        for (const auto& v : stiff_views())
          for (uint64_t n : {1u, 63u})
            for (int64_t u : {int64_t(0), int64_t(65536), int64_t(-70000), int64_t(1) << 21})
              rows.push_back(unit_row(u, 65536 - u, v, n, (u & 1) == 0 && n == 1));
        return rows;
      },
      [](uint64_t count, uint64_t seed) {
        std::mt19937_64 rng(seed);
        std::vector<Row> rows;
        for (uint64_t i = 0; i < count; ++i) {
          const uint64_t r = rng();
          rows.push_back(unit_row(r & 0xffff, (r >> 16) & 0xffff, random_view(rng),
                                  1 + (r >> 32) % 63, (r >> 40) & 1));
        }
        return rows;
      });
  b.model = [](const Row& in) {
    const auto o = pom::march(depth(), s32(in[0]), s32(in[1]), view_of(in, 2),
                              static_cast<uint32_t>(in[6]), in[7] != 0);
    return Row{c32(o.u), c32(o.v), o.steps, o.w, o.discard ? 1u : 0u, o.back ? 1u : 0u,
               o.clamped ? 1u : 0u};
  };
  b.ref = [](const Row& in) {
    const auto v = view_of(in, 2);
    const auto r = pom::march_ref(depth(), s32(in[0]) / 65536.0, s32(in[1]) / 65536.0,
                                  v.vx / 16384.0, v.vy / 16384.0, v.vz / 16384.0,
                                  v.scale / 65536.0, static_cast<uint32_t>(in[6]));
    return Row{vec::f64_bits(r.u), vec::f64_bits(r.v)};
  };
  b.error = uv_error;
  // k = 0 pixel alone: set-up, engine (accept, compare, output register), refinement; a stream
  // takes k + 1 cycles per pixel (pom::unit_cycles)
  b.latency_cycles = fmt::kPomSetupLatency + 2 + fmt::kPomRefineLatency;
  b.ii_cycles = 1;
  return b;
}
}  // namespace

vec::VectorFile pomvec::scene_vectors(const std::string& block, double deg, int n) {
  const Block& b = find(block);
  static const img::Gray8 cmap = complexity::complexity_map(pom::map_bricks(64));
  const pom::View vw = view(deg, 30, 0.05);
  vec::VectorFile vf;
  vf.block = b.name;
  vf.set = "scene";
  vf.fields = b.fields;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const int64_t u = (2 * x + 1) << 9, v = (2 * y + 1) << 9;
      const uint32_t nn = n > 0 ? uint32_t(n) : pom::layers(vw.vz, pom::tex_nearest(cmap, u, v)).n;
      Row row;
      if (block == "iter_parallax") {
        const auto d = n ? pom::ipx_dir_normalised(vw) : pom::ipx_dir_seed(vw);
        row = {uint64_t(u), uint64_t(v), c32(d.su), c32(d.sv), c32(d.sh)};
      } else if (block == "pom_march") {
        const auto s = pom::setup(vw, nn);
        row = {uint64_t(u), uint64_t(v), c32(s.du), c32(s.dv), nn};
      } else {
        row = unit_row(u, v, vw, nn, true);
      }
      const Row out = b.model(row), ref = b.ref(row);
      row.insert(row.end(), out.begin(), out.end());
      row.insert(row.end(), ref.begin(), ref.end());
      vf.rows.push_back(std::move(row));
    }
  return vf;
}

std::vector<Block> make_pom_unit_blocks() { return {make_setup(), make_refine(), make_unit()}; }

}  // namespace tu::blocks
