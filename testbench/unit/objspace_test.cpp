// Object-space pipeline (docs/blocks/objspace.md): the seed's rotation with the [FIX], the
// per-sample datapath's error against the float reference (1M random + stiff samples), the
// renders' holes / overlaps, and the sample cap.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include <glm/glm.hpp>

#include "objspace/objspace.hpp"

namespace {
using namespace tu;

using objspace::quad_scene;
// Fills the view at distance 2 (fronto-parallel) and a floor receding at a grazing angle.
const char* kFront = "[[-2, -1.5, -2], [2, -1.5, -2], [2, 1.5, -2], [-2, 1.5, -2]]";
const std::string kFloor = objspace::stiff_quad_vertices()[0];

// The sanitizer build (Debug, ASan + UBSan) checks the same code paths on 1/16 of the samples.
#if defined(__SANITIZE_ADDRESS__)
constexpr uint64_t kThin = 16;
#else
constexpr uint64_t kThin = 1;
#endif

glm::dvec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  glm::dvec3 n{g(rng), g(rng), g(rng)};
  return n / glm::length(n);
}

TEST(ObjSpace, RotationTakesTheNormalToZAndMatchesTheSeedsPrintedFormulas) {
  std::mt19937_64 rng(19);
  double max_err = 0, max_seed = 0, max_orth = 0;
  for (int k = 0; k < 100000; ++k) {
    glm::dvec3 n = random_unit(rng);
    if (k == 0) n = {1, 0, 0};  // d = 0: the normal along x
    if (k == 1) n = {0, 0, -1};
    const double nn[3] = {n.x, n.y, n.z};
    const auto r = objspace::rotation(nn);
    double out[3], seed[3], back[3];
    objspace::rotate(r, nn, out);
    max_err = std::max({max_err, std::fabs(out[0]), std::fabs(out[1]), std::fabs(out[2] - 1)});
    const double p[3] = {std::sin(k * 0.1), std::cos(k * 0.37), 3.0 - k % 7};
    objspace::rotate(r, p, out);
    objspace::rotate_seed(r, n.z, p, seed);
    objspace::rotate_back(r, out, back);
    for (int c = 0; c < 3; ++c)
      max_seed = std::max(max_seed, std::fabs(out[c] - seed[c])), max_orth = std::max(max_orth, std::fabs(back[c] - p[c]));
  }
  EXPECT_LT(max_err, 1e-12);
  EXPECT_LT(max_seed, 1e-12);  // the thesis' x', y', z' are the rows of Ry(b) Rx(a)
  EXPECT_LT(max_orth, 1e-12);  // R^T undoes R
  // The printed d = sqrt(Ny^2 - Nz^2) is not the projection's length: NaN when |Nz| > |Ny|, and
  // cos^2 a + sin^2 a != 1 otherwise.
  const double ny = 0.6, nz = 0.3;
  const double d_printed = std::sqrt(ny * ny - nz * nz);
  EXPECT_GT(std::fabs((nz / d_printed) * (nz / d_printed) + (ny / d_printed) * (ny / d_printed) - 1), 0.5);
  EXPECT_TRUE(std::isnan(std::sqrt(nz * nz - ny * ny)));
}

// The per-sample datapath (rotate back -> project -> splat weights) of the C model against the
// float reference on the same set-up: pixel position and weight error.
struct SplatErr {
  double pos = 0, weight = 0, sum_sq = 0;
  uint64_t n = 0, guarded = 0;
};
void measure(const scene::Scene& s, uint64_t draws, SplatErr* e) {
  // Grazing planes close to the eye have grids far beyond a render's cap: set-up only (tiles).
  const auto tris = objspace::setup(s, {1, uint64_t(1) << 44});
  std::vector<std::pair<const objspace::Tile*, persp::Unit::Coefs>> tiles;
  for (const auto& t : tris)
    for (const auto& tile : t.tiles) tiles.emplace_back(&tile, persp::Unit::quantise(tile.screen, "t"));
  ASSERT_FALSE(tiles.empty());
  std::mt19937_64 rng(e->n + 1);
  for (uint64_t m = 0; m < draws; ++m) {
    const auto& [tile, k] = tiles[rng() % tiles.size()];
    const int i = static_cast<int>(rng() % static_cast<uint64_t>(tile->ni));
    const int j = static_cast<int>(rng() % static_cast<uint64_t>(tile->nj));
    if (!tile->inside(i, j)) continue;
    const auto f = objspace::splat_fx(k, i, j);
    const auto r = objspace::splat_ref(tile->screen, i, j);
    ++e->n;
    if (f.guard) {
      ++e->guarded;
      continue;
    }
    // The C model's position is floor + fraction = x + (w10 + w11); weights compared pixel by
    // pixel with the float splat's bilinear tent (a floor crossing moves weight to a neighbour).
    const double fx = static_cast<double>(f.x), fy = static_cast<double>(f.y);
    const double ex = std::fabs(fx + (f.w[1] + f.w[3]) * 0x1p-16 - r.px);
    const double ey = std::fabs(fy + (f.w[2] + f.w[3]) * 0x1p-16 - r.py);
    e->pos = std::max({e->pos, ex, ey});
    e->sum_sq += ex * ex + ey * ey;
    for (int q = 0; q < 4; ++q) {
      const double X = fx + (q & 1), Y = fy + (q >> 1);
      const double wr = std::max(0.0, 1 - std::fabs(r.px - X)) * std::max(0.0, 1 - std::fabs(r.py - Y));
      e->weight = std::max(e->weight, std::fabs(f.w[q] * 0x1p-16 - wr));
    }
  }
}

TEST(ObjSpace, PerSampleDatapathErrorBound) {
  // Random planes (orientation, distance) seen by the 256 x 192 default camera, plus the stiff
  // cases: grazing (89.9 degrees), magnification (the near plane), a far plane.
  std::mt19937_64 rng(7);
  SplatErr e;
  for (int k = 0; k < 60; ++k) measure(quad_scene(objspace::random_quad_vertices(rng), 256, 192), 20000 / kThin, &e);
  const uint64_t random_n = e.n;
  for (const auto& v : objspace::stiff_quad_vertices())
    measure(quad_scene(v, 256, 192), 200000 / kThin, &e);
  std::printf("per-sample datapath vs float: %llu samples (%llu random), max |dp| %.6f px, RMS %.6f px, "
              "max |dw| %.6f, guarded %llu\n",
              (unsigned long long)e.n, (unsigned long long)random_n, e.pos, std::sqrt(e.sum_sq / (2.0 * double(e.n))),
              e.weight, (unsigned long long)e.guarded);
  EXPECT_GE(e.n, 1000000u / kThin);
  EXPECT_EQ(e.guarded, 0u);
  EXPECT_LT(e.pos, 1.0 / 256);    // B1's round half up (2^-9) + reciprocal and quantisation
  EXPECT_LT(e.weight, 1.0 / 128); // two fractions each within the position bound
}

TEST(ObjSpace, FrontoParallelQuadHasOneSamplePerPixelAndNoHoles) {
  const auto s = quad_scene(kFront);
  for (const auto& r : {objspace::render_ref(s), objspace::render_cmodel(s)}) {
    EXPECT_EQ(r.stats.covered, 64u * 48u);
    EXPECT_EQ(r.stats.holes, 0u);
    EXPECT_EQ(r.stats.overlaps, 0u);
    // One sample per pixel over the frustum's 2-pixel margin: (64 + 4) (48 + 4) / (64 x 48).
    EXPECT_NEAR(r.stats.samples_per_pixel(), 68.0 * 52.0 / (64.0 * 48.0), 0.01);
  }
  const auto a = objspace::render_ref(s), b = objspace::render_cmodel(s);
  EXPECT_GT(render::psnr_covered(b.frame, a.frame), 40);
}

TEST(ObjSpace, GrazingFloorOverlapsAndWideSpacingLeavesCountedHoles) {
  const auto s = quad_scene(kFloor);
  const auto dense = objspace::render_cmodel(s);
  EXPECT_EQ(dense.stats.holes, 0u);
  EXPECT_GT(dense.stats.overlaps, 0u);  // far rows: many samples per pixel
  EXPECT_GT(dense.stats.samples_per_pixel(), 2);
  // Splatting to four pixels leaves no hole while samples land < 2 pixels apart; 2.5 does not.
  objspace::Options wide;
  wide.spacing = 2.5;
  const auto sparse = objspace::render_cmodel(quad_scene(kFront), wide);
  EXPECT_GT(sparse.stats.holes, 0u);
  size_t painted = 0;
  for (const auto& p : sparse.frame.pixels)
    painted += p.texels == 0 && p.color.r == 0 && p.color.g == 0 && p.color.b == 80;
  EXPECT_EQ(painted, sparse.stats.holes);  // holes shown, not filled
}

// The datapath hook is the one the render uses (texunit render --engine rtl passes the RTL there):
// the C model through it gives the same frame, a datapath one pixel off does not.
TEST(ObjSpace, RenderUsesTheDatapathItIsGiven) {
  const auto s = quad_scene(kFront);
  const auto base = objspace::render_cmodel(s);
  auto cmodel = [](const std::vector<objspace::SampleIn>& in, std::vector<objspace::Splat>& out) {
    for (size_t k = 0; k < in.size(); ++k) out[k] = objspace::splat_fx(*in[k].k, in[k].i, in[k].j);
  };
  auto shifted = [&](const std::vector<objspace::SampleIn>& in, std::vector<objspace::Splat>& out) {
    cmodel(in, out);
    for (auto& sp : out) ++sp.x;
  };
  const auto same = objspace::render_cmodel(s, {}, cmodel), off = objspace::render_cmodel(s, {}, shifted);
  EXPECT_TRUE(same.frame.image.px == base.frame.image.px);
  EXPECT_EQ(same.stats.splats, base.stats.splats);
  EXPECT_FALSE(off.frame.image.px == base.frame.image.px);
}

TEST(ObjSpace, SampleCapNamesTheObject) {
  objspace::Options o;
  o.max_samples = 1000;
  try {
    objspace::render_ref(quad_scene(kFront), o);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("object 'q'"), std::string::npos) << e.what();
  }
  o.spacing = 0;
  EXPECT_THROW(objspace::setup(quad_scene(kFront), o), std::invalid_argument);
}

}  // namespace

namespace {
// A 2 x 2 quad centred at (0, 0, -3) turned by `deg` about y (0: facing the camera; 90: its plane
// contains the eye).
std::string turned_quad(double deg) {
  const double a = deg * M_PI / 180, cx = std::cos(a), sz = -std::sin(a);
  char v[256];
  std::snprintf(v, sizeof v, "[[%.17g, -1, %.17g], [%.17g, -1, %.17g], [%.17g, 1, %.17g], [%.17g, 1, %.17g]]", -cx, -3 - sz, cx,
                -3 + sz, cx, -3 + sz, -cx, -3 - sz);
  return v;
}
}  // namespace

// Edge-on: the plane through the eye is the screen-space set-up's error in every object-space
// engine (it rendered 0 pixels with exit 0, and the RTL engine failed on its cycle count).
TEST(ObjSpace, PlaneThroughTheEyeIsTheScreenSpaceSetupError) {
  const auto s = quad_scene(turned_quad(90));
  std::string screen;
  try {
    (void)render::render_ref(s);
  } catch (const persp::SetupError& e) {
    screen = e.what();
  }
  ASSERT_NE(screen.find("its plane contains the eye"), std::string::npos) << screen;
  for (int engine = 0; engine < 2; ++engine) {
    try {
      engine ? (void)objspace::render_cmodel(s) : (void)objspace::render_ref(s);
      ADD_FAILURE() << "engine " << engine << " rendered a plane through the eye";
    } catch (const persp::SetupError& e) {
      EXPECT_EQ(e.what(), screen);
    }
  }
}

// Grazing (89.9 degrees, the plane 0.005 from the eye: ~10^8 samples for a few pixels): with a cap
// below the clipped polygons' lattice area the set-up fails before the walk (it walked up to the
// cap first), in both engines.
TEST(ObjSpace, GrazingPlaneFailsTheSampleCapBeforeSampling) {
  const auto s = quad_scene(turned_quad(89.9));
  objspace::Options o;
  o.max_samples = uint64_t(1) << 26;  // above a quarter of the grid (252 M points): the walk would run
  for (int engine = 0; engine < 2; ++engine) {
    try {
      engine ? (void)objspace::render_cmodel(s, o) : (void)objspace::render_ref(s, o);
      ADD_FAILURE() << "engine " << engine << " accepted the grazing quad";
    } catch (const std::runtime_error& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find("object 'q' (/objects/0): object-space samples exceed --max-samples 67108864"), std::string::npos) << m;
      EXPECT_NE(m.find("before sampling"), std::string::npos) << m;
    }
  }
  // The bound never refuses what the walk accepts: at 60 degrees the render completes.
  EXPECT_GT(objspace::render_cmodel(quad_scene(turned_quad(60))).stats.covered, 0u);
}
