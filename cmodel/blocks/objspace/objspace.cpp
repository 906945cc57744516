#include "objspace/objspace.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include <glm/glm.hpp>

#include "texunit/convert.hpp"

namespace tu::objspace {

namespace {
constexpr img::Rgba8 kBackground{0, 0, 80, 255};  // as render_ref
constexpr int kTileLog2 = fmt::kPerspXyW;          // grid indices fit B1's unsigned x, y

glm::dvec3 v3(const double p[3]) { return {p[0], p[1], p[2]}; }

// The camera's view frame (as persp's basis: fwd, right = fwd x up, up' = right x fwd) and its
// pixel-centre projection (the inverse of RayCaster's ray: px = (X / (Z th aspect) + 1) W / 2 - 0.5).
struct ViewFrame {
  glm::dvec3 pos, fwd, right, up;
  double th, aspect;
  int w, h;
  explicit ViewFrame(const persp::Camera& c) : w(c.width), h(c.height) {
    pos = v3(c.pos);
    fwd = glm::normalize(v3(c.look_at) - pos);
    right = glm::normalize(glm::cross(fwd, v3(c.up)));
    up = glm::cross(right, fwd);
    th = std::tan(c.fovy_deg * M_PI / 360.0);
    aspect = static_cast<double>(c.width) / c.height;
  }
  glm::dvec3 view(const double p[3]) const {
    const glm::dvec3 r = v3(p) - pos;
    return {glm::dot(r, right), glm::dot(r, up), glm::dot(r, fwd)};
  }
  // Homogeneous screen numerators of a view-space point (linear in the point): px = sx / Z.
  double sx(const glm::dvec3& p) const { return p.x * w / (2 * th * aspect) + p.z * (w / 2.0 - 0.5); }
  double sy(const glm::dvec3& p) const { return -p.y * h / (2 * th) + p.z * (h / 2.0 - 0.5); }
};

// Sutherland-Hodgman clip of a convex polygon against n . p + c >= 0.
std::vector<glm::dvec3> clip(const std::vector<glm::dvec3>& in, const glm::dvec3& n, double c) {
  std::vector<glm::dvec3> out;
  for (size_t k = 0; k < in.size(); ++k) {
    const glm::dvec3 &a = in[k], &b = in[(k + 1) % in.size()];
    const double da = glm::dot(n, a) + c, db = glm::dot(n, b) + c;
    if (da >= 0) out.push_back(a);
    if ((da >= 0) != (db >= 0)) out.push_back(a + (b - a) * (da / (da - db)));
  }
  return out;
}

glm::dvec3 mul(const double m[3][3], const glm::dvec3& p) {
  return {m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z, m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z,
          m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z};
}
glm::dvec3 mul_t(const double m[3][3], const glm::dvec3& p) {
  return {m[0][0] * p.x + m[1][0] * p.y + m[2][0] * p.z, m[0][1] * p.x + m[1][1] * p.y + m[2][1] * p.z,
          m[0][2] * p.x + m[1][2] * p.y + m[2][2] * p.z};
}

uint8_t to8(double x) { return static_cast<uint8_t>(std::clamp<int64_t>(round_i64(x), 0, 255)); }

int64_t quantise_coef(double x) { return round_i64(std::ldexp(x, fmt::kObjUvCoefF)); }

// u = u0 + ui i + uj j in ObjUvCoefF fraction bits, rounded half up to TexUvF bits (exact sums).
int64_t uv_fx(int64_t c0, int64_t ci, int64_t cj, int i, int j) {
  const i128 acc = static_cast<i128>(c0) + static_cast<i128>(ci) * i + static_cast<i128>(cj) * j;
  constexpr int sh = fmt::kObjUvCoefF - fmt::kTexUvF;
  return static_cast<int64_t>((acc + (i128(1) << (sh - 1))) >> sh);
}

// Per-pixel accumulation buffer of one engine (double or the fixed-point codes).
template <typename T>
struct Accum {
  std::vector<T> w, c[4];
  std::vector<uint8_t> sat;
  explicit Accum(size_t n) : w(n, 0), sat(n, 0) {
    for (auto& x : c) x.assign(n, 0);
  }
};

// The shared sample walk of both engines: every visible sample of every tile, in order, with the
// running sample count checked against the cap. `f(tri, tile, i, j)`.
template <typename F>
void for_each_sample(const scene::Scene& s, const std::vector<TriangleSetup>& tris, const Options& opt,
                     Stats* st, F&& f) {
  for (const auto& t : tris) {
    ++st->triangles;
    st->tiles += t.tiles.size();
    for (const auto& tile : t.tiles)
      for (int j = 0; j < tile.nj; ++j)
        for (int i = 0; i < tile.ni; ++i) {
          if (!tile.inside(i, j)) continue;
          if (++st->samples > opt.max_samples)
            throw std::runtime_error(scene::object_where(s, static_cast<size_t>(t.object)) +
                                     ": object-space samples exceed --max-samples " +
                                     std::to_string(opt.max_samples) + " (grid spacing " +
                                     std::to_string(opt.spacing) + " px)");
          f(t, tile, i, j);
        }
  }
}

// Splat one sample's four weights into the pixels that see its object; counts the rest.
template <typename T, typename Add>
void splat_into(const std::vector<render::Cover>& cov, int w, int h, int object, int64_t x0, int64_t y0,
                const T (&wt)[4], Stats* st, Add&& add) {
  bool on_screen = false;
  for (int k = 0; k < 4; ++k) {
    const int64_t x = x0 + (k & 1), y = y0 + (k >> 1);
    if (x < 0 || y < 0 || x >= w || y >= h) continue;
    on_screen = true;
    if (wt[k] == 0) continue;
    const size_t p = static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x);
    if (cov[p].object != object) {
      ++st->foreign;
      continue;
    }
    ++st->splats;
    add(p, wt[k]);
  }
  if (!on_screen) ++st->off_screen;
}

// The frame from the accumulators: I = sum w c / sum w per covered pixel; holes painted the
// background colour and counted. `colour(p)` gives the pixel's colour when sum w > 0; `weight(p)`
// its sum in samples' worth.
template <typename C, typename W>
render::Frame resolve(const std::vector<render::Cover>& cov, int w, int h, Stats* st, C&& colour, W&& weight) {
  render::Frame f;
  f.image = img::Rgba8Image(w, h, kBackground);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t p = static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x);
      if (cov[p].object < 0) continue;
      ++st->covered;
      render::PixelRecord rec;
      rec.x = x, rec.y = y, rec.object = cov[p].object;
      const double ws = weight(p);
      st->max_weight = std::max(st->max_weight, ws);
      if (ws > 4) ++st->overlaps;
      rec.texels = static_cast<int>(std::lround(8 * ws));  // trilinear: 8 texels per sample
      if (ws > 0) {
        rec.color = colour(p);
      } else {
        ++st->holes;
        rec.color = kBackground;
      }
      f.image.at(x, y) = rec.color;
      f.pixels.push_back(rec);
    }
  return f;
}
// What both engines share: the set-up, the visibility and the objects' textures.
struct Prepared {
  std::vector<TriangleSetup> tris;
  std::vector<render::Cover> cov;
  std::vector<tex::Texture> texs;
  Prepared(const scene::Scene& s, const Options& opt) : tris(setup(s, opt)), cov(render::visibility(s)) {
    for (const auto& o : s.objects) texs.push_back(scene::build_texture(s, s.materials.at(o.material).texture));
  }
};
}  // namespace

Rotation rotation(const double n[3]) {
  Rotation r;
  const double d = std::sqrt(n[1] * n[1] + n[2] * n[2]);  // [FIX] the seed prints Ny^2 - Nz^2
  if (d > 1e-12) {
    r.cos_a = n[2] / d, r.sin_a = n[1] / d;
  } else {
    r.x_normal = true;  // normal along x: any alpha; 0 keeps R = Ry(b)
  }
  r.cos_b = d, r.sin_b = n[0];
  // Rx(a): y' = y cos a - z sin a, z' = y sin a + z cos a (takes n to (nx, 0, d));
  // Ry(b): x'' = x cos b - z sin b, z'' = x sin b + z cos b (takes (nx, 0, d) to (0, 0, 1)).
  const double ca = r.cos_a, sa = r.sin_a, cb = r.cos_b, sb = r.sin_b;
  const double m[3][3] = {{cb, -sa * sb, -ca * sb}, {0, ca, -sa}, {sb, sa * cb, ca * cb}};
  std::copy(&m[0][0], &m[0][0] + 9, &r.m[0][0]);
  return r;
}

void rotate(const Rotation& r, const double p[3], double out[3]) {
  const auto q = mul(r.m, v3(p));
  out[0] = q.x, out[1] = q.y, out[2] = q.z;
}
void rotate_back(const Rotation& r, const double p[3], double out[3]) {
  const auto q = mul_t(r.m, v3(p));
  out[0] = q.x, out[1] = q.y, out[2] = q.z;
}
void rotate_seed(const Rotation& r, const double nz, const double p[3], double out[3]) {
  const double x = p[0], y = p[1], z = p[2];
  out[0] = x * r.cos_b - z * r.cos_a * r.sin_b - y * r.sin_a * r.sin_b;
  out[1] = y * r.cos_a - z * r.sin_a;
  out[2] = x * r.sin_b + y * r.cos_b * r.sin_a + z * nz;
}

bool Tile::inside(int i, int j) const {
  for (size_t k = 0; k < ea.size(); ++k) {
    const double e = ea[k] * i + eb[k] * j + ec[k];
    // Half-open edges (top-left rule): a sample on an edge shared by two triangles counts once.
    if (e < 0 || (e == 0 && !(ea[k] > 0 || (ea[k] == 0 && eb[k] > 0)))) return false;
  }
  return true;
}

std::vector<TriangleSetup> setup(const scene::Scene& s, const Options& opt) {
  if (!(opt.spacing > 0) || !std::isfinite(opt.spacing))
    throw std::invalid_argument("object-space: grid spacing must be > 0");
  const ViewFrame vf(s.camera);
  std::vector<TriangleSetup> out;
  double at_least = 0;  // samples the walk will take at least (the clipped polygons' lattice areas)
  for (size_t o = 0; o < s.objects.size(); ++o) {
    if (s.materials.at(s.objects[o].material).procedural)
      throw std::invalid_argument(scene::object_where(s, o) + ": the object-space pipeline textures from texels; "
                                  "procedural materials are not supported");
    const auto tex = scene::build_texture(s, s.materials.at(s.objects[o].material).texture);
    const int top = tex.num_levels() - 1;
    const auto tris = scene::in_texels(s.objects[o], tex.levels[0].width, tex.levels[0].height);
    for (size_t t = 0; t < tris.size(); ++t) {
      // A plane through the eye is refused as the screen-space set-up refuses it (same test, same
      // message), instead of rendering nothing.
      try {
        (void)persp::coefficients(s.camera, tris[t]);
      } catch (const persp::SetupError& e) {
        throw persp::SetupError(scene::object_where(s, o) + ": " + e.what());
      }
      TriangleSetup ts;
      ts.object = static_cast<int>(o), ts.triangle = static_cast<int>(t);
      glm::dvec3 p[3];
      for (int k = 0; k < 3; ++k) p[k] = vf.view(tris[t].v[k].p);
      glm::dvec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
      const double len = glm::length(n);
      if (!(len > 0)) continue;  // zero area (the scene loader drops these)
      n /= len;
      ts.dist = glm::dot(n, p[0]);
      if (ts.dist < 0) n = -n, ts.dist = -ts.dist;  // normal away from the eye: the plane at z'' = D > 0
      if (!(ts.dist > 1e-12)) {
        out.push_back(ts);  // the plane contains the eye: seen edge-on, nothing to sample
        continue;
      }
      const double nn[3] = {n.x, n.y, n.z};
      ts.rot = rotation(nn);
      // The visible part: near plane, the four sides 2 pixels out.
      const double tx = vf.th * vf.aspect * (1 + 4.0 / vf.w), ty = vf.th * (1 + 4.0 / vf.h);
      std::vector<glm::dvec3> poly = {p[0], p[1], p[2]};
      poly = clip(poly, {0, 0, 1}, -s.camera.z_near);
      poly = clip(poly, {-1, 0, tx}, 0);
      poly = clip(poly, {1, 0, tx}, 0);
      poly = clip(poly, {0, -1, ty}, 0);
      poly = clip(poly, {0, 1, ty}, 0);
      if (poly.size() < 3) {
        out.push_back(ts);
        continue;
      }
      ts.h = ts.dist * opt.spacing * 2 * vf.th / vf.h;
      // Lattice coordinates L = x'' / h - 1/2 (samples at integer L), and their bounding box.
      auto lattice = [&](const glm::dvec3& q) {
        const glm::dvec3 r = mul(ts.rot.m, q);
        return glm::dvec2(r.x / ts.h - 0.5, r.y / ts.h - 0.5);
      };
      std::vector<glm::dvec2> lp;
      double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY}, zmax = 0;
      for (const auto& q : poly) {
        lp.push_back(lattice(q));
        for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], lp.back()[k]), hi[k] = std::max(hi[k], lp.back()[k]);
        zmax = std::max(zmax, q.z);
      }
      const double g0[2] = {std::ceil(lo[0]), std::ceil(lo[1])};
      const double cnt[2] = {std::floor(hi[0]) - g0[0] + 1, std::floor(hi[1]) - g0[1] + 1};
      if (cnt[0] < 1 || cnt[1] < 1) {
        out.push_back(ts);
        continue;
      }
      if (cnt[0] * cnt[1] > 4.0 * static_cast<double>(opt.max_samples))
        throw std::runtime_error(scene::object_where(s, o) + ": triangle " + std::to_string(t) +
                                 ": object-space grid of " + std::to_string(cnt[0] * cnt[1]) +
                                 " points exceeds 4 x --max-samples");
      // uv affine in the lattice coordinates (from the triangle's own vertices).
      glm::dvec2 lv[3];
      for (int k = 0; k < 3; ++k) lv[k] = lattice(p[k]);
      const glm::dvec2 e1 = lv[1] - lv[0], e2 = lv[2] - lv[0];
      const double det = e1.x * e2.y - e1.y * e2.x;
      double grad[2][2], base[2];  // uv = base + grad . (L - lv0)
      for (int c = 0; c < 2; ++c) {
        const double d1 = tris[t].v[1].uv[c] - tris[t].v[0].uv[c], d2 = tris[t].v[2].uv[c] - tris[t].v[0].uv[c];
        grad[c][0] = (d1 * e2.y - d2 * e1.y) / det;
        grad[c][1] = (d2 * e1.x - d1 * e2.x) / det;
        base[c] = tris[t].v[0].uv[c];
      }
      const double rho = std::max(std::hypot(grad[0][0], grad[1][0]), std::hypot(grad[0][1], grad[1][1]));
      ts.lambda = std::clamp(std::log2(std::max(rho, 1e-300)), 0.0, static_cast<double>(top));
      // Clipped polygon's orientation in the lattice plane (edges kept inside-positive).
      double area = 0;
      for (size_t k = 0; k < lp.size(); ++k) {
        const auto &a = lp[k], &b = lp[(k + 1) % lp.size()];
        area += a.x * b.y - a.y * b.x;
      }
      const double sgn = area >= 0 ? 1 : -1;
      // Before sampling: a convex polygon of area A and perimeter P holds more than A - P/2 lattice
      // points (Nosarzewska); the half-open edges drop at most P + 1 + its vertex count more. Past
      // the cap the walk would only fail later (a grazing plane: minutes), so it fails now.
      double perim = 0;
      for (size_t k = 0; k < lp.size(); ++k) perim += glm::length(lp[(k + 1) % lp.size()] - lp[k]);
      at_least += std::max(0.0, std::fabs(area) / 2 - 1.5 * perim - 1 - static_cast<double>(lp.size()));
      if (at_least > static_cast<double>(opt.max_samples))
        throw std::runtime_error(scene::object_where(s, o) + ": object-space samples exceed --max-samples " +
                                 std::to_string(opt.max_samples) + " (grid spacing " + std::to_string(opt.spacing) +
                                 " px; at least " + std::to_string(static_cast<uint64_t>(at_least)) +
                                 " from the clipped polygons' areas, before sampling)");
      const int64_t n_i = static_cast<int64_t>(cnt[0]), n_j = static_cast<int64_t>(cnt[1]);
      const int64_t tile = int64_t(1) << kTileLog2;
      for (int64_t tj = 0; tj < n_j; tj += tile)
        for (int64_t ti = 0; ti < n_i; ti += tile) {
          Tile tl;
          tl.ni = static_cast<int>(std::min(tile, n_i - ti)), tl.nj = static_cast<int>(std::min(tile, n_j - tj));
          const double ox = g0[0] + static_cast<double>(ti), oy = g0[1] + static_cast<double>(tj);
          for (size_t k = 0; k < lp.size(); ++k) {
            const auto &a = lp[k], &b = lp[(k + 1) % lp.size()];
            // e(L) = sgn * cross(b - a, L - a), L = (ox + i, oy + j)
            const double ea = -sgn * (b.y - a.y), eb = sgn * (b.x - a.x);
            tl.ea.push_back(ea), tl.eb.push_back(eb);
            tl.ec.push_back(ea * (ox - a.x) + eb * (oy - a.y));
          }
          // Back-rotation of the lattice point (ox + i, oy + j) and its projection.
          auto point = [&](double lx, double ly) { return mul_t(ts.rot.m, {(lx + 0.5) * ts.h, (ly + 0.5) * ts.h, ts.dist}); };
          const glm::dvec3 P0 = point(ox, oy), Ei = point(ox + 1, oy) - P0, Ej = point(ox, oy + 1) - P0;
          tl.screen = {vf.sx(Ei) / zmax, vf.sx(Ej) / zmax, vf.sx(P0) / zmax, vf.sy(Ei) / zmax, vf.sy(Ej) / zmax,
                       vf.sy(P0) / zmax, Ei.z / zmax, Ej.z / zmax, P0.z / zmax};
          tl.u0 = base[0] + grad[0][0] * (ox - lv[0].x) + grad[0][1] * (oy - lv[0].y);
          tl.v0 = base[1] + grad[1][0] * (ox - lv[0].x) + grad[1][1] * (oy - lv[0].y);
          tl.ui = grad[0][0], tl.uj = grad[0][1], tl.vi = grad[1][0], tl.vj = grad[1][1];
          ts.tiles.push_back(std::move(tl));
        }
      ts.grid = static_cast<uint64_t>(n_i) * static_cast<uint64_t>(n_j);
      out.push_back(std::move(ts));
    }
  }
  return out;
}

SplatRef splat_ref(const persp::Coef9& k, int i, int j) {
  const double q = k.g * i + k.h * j + k.i;
  SplatRef r;
  r.px = (k.a * i + k.b * j + k.c) / q;
  r.py = (k.d * i + k.e * j + k.f) / q;
  const double fx = r.px - std::floor(r.px), fy = r.py - std::floor(r.py);
  r.w[0] = (1 - fx) * (1 - fy), r.w[1] = fx * (1 - fy), r.w[2] = (1 - fx) * fy, r.w[3] = fx * fy;
  return r;
}

Splat splat_fx(const persp::Unit::Coefs& k, int i, int j) {
  const persp::Pixel px = persp::Unit::pixel(persp::Unit::direct(k, i, j));
  Splat s;
  if (px.flag) {
    s.guard = true;
    return s;
  }
  constexpr int F = fmt::kPerspUvF;
  constexpr uint32_t one = 1u << F;
  s.x = px.u >> F, s.y = px.v >> F;  // floor (arithmetic shift)
  const uint32_t fx = static_cast<uint32_t>(px.u & (one - 1)), fy = static_cast<uint32_t>(px.v & (one - 1));
  static_assert(fmt::kObjSplatWF == 2 * F, "weights are exact products of two fractions");
  s.w[0] = (one - fx) * (one - fy), s.w[1] = fx * (one - fy), s.w[2] = (one - fx) * fy, s.w[3] = fx * fy;
  return s;
}

Result render_ref(const scene::Scene& s, const Options& opt) {
  const Prepared pr(s, opt);
  const auto& tris = pr.tris;  // not a structured binding: clang 14 (the fuzz build) cannot capture one
  const auto& cov = pr.cov;
  const auto& texs = pr.texs;
  const int w = s.camera.width, h = s.camera.height;
  Accum<double> acc(cov.size());
  Result r;
  for_each_sample(s, tris, opt, &r.stats, [&](const TriangleSetup& t, const Tile& tl, int i, int j) {
    const auto c = tex::trilinear_ref(texs[static_cast<size_t>(t.object)], t.lambda, tl.u0 + tl.ui * i + tl.uj * j,
                                      tl.v0 + tl.vi * i + tl.vj * j);
    const SplatRef sp = splat_ref(tl.screen, i, j);
    splat_into(cov, w, h, t.object, floor_i64(sp.px), floor_i64(sp.py), sp.w, &r.stats, [&](size_t p, double wt) {
      acc.w[p] += wt;
      acc.c[0][p] += wt * c.r, acc.c[1][p] += wt * c.g, acc.c[2][p] += wt * c.b, acc.c[3][p] += wt * c.a;
    });
  });
  r.frame = resolve(
      cov, w, h, &r.stats,
      [&](size_t p) {
        return img::Rgba8{to8(acc.c[0][p] / acc.w[p]), to8(acc.c[1][p] / acc.w[p]), to8(acc.c[2][p] / acc.w[p]),
                          to8(acc.c[3][p] / acc.w[p])};
      },
      [&](size_t p) { return acc.w[p]; });
  return r;
}

Result render_cmodel(const scene::Scene& s, const Options& opt, const Datapath& datapath) {
  const Prepared pr(s, opt);
  const auto& tris = pr.tris;  // not a structured binding: clang 14 (the fuzz build) cannot capture one
  const auto& cov = pr.cov;
  const auto& texs = pr.texs;
  const int w = s.camera.width, h = s.camera.height;
  // Per tile: the projective map in B1's formats and the uv plane in ObjUvCoefF bits.
  struct TileFx {
    persp::Unit::Coefs k;
    int64_t u[3], v[3];
  };
  std::vector<std::vector<TileFx>> fx(tris.size());
  for (size_t t = 0; t < tris.size(); ++t)
    for (size_t k = 0; k < tris[t].tiles.size(); ++k) {
      const Tile& tl = tris[t].tiles[k];
      const std::string name = "object-space tile " + std::to_string(k) + " of triangle " + std::to_string(tris[t].triangle);
      try {
        fx[t].push_back({persp::Unit::quantise(tl.screen, name),
                         {quantise_coef(tl.u0), quantise_coef(tl.ui), quantise_coef(tl.uj)},
                         {quantise_coef(tl.v0), quantise_coef(tl.vi), quantise_coef(tl.vj)}});
      } catch (const persp::SetupError& e) {
        throw persp::SetupError(scene::object_where(s, static_cast<size_t>(tris[t].object)) + ": " + e.what());
      }
    }
  Accum<uint64_t> acc(cov.size());
  constexpr uint64_t kWMax = (uint64_t(1) << fmt::kObjAccWW) - 1, kCMax = (uint64_t(1) << fmt::kObjAccCW) - 1;
  auto sat_add = [&](uint64_t* a, uint64_t x, uint64_t mx, size_t p) {
    if (*a > mx - x) {
      *a = mx;
      acc.sat[p] = 1;
    } else {
      *a += x;
    }
  };
  Result r;
  // Samples go through the datapath in batches (the RTL engine simulates one batch per run); the
  // accumulation is order-independent (exact sums, saturation at the format's maximum).
  constexpr size_t kBatch = size_t(1) << 16;
  std::vector<SampleIn> batch;
  std::vector<img::Rgba8> colour;
  std::vector<int> object;
  std::vector<Splat> out;
  batch.reserve(kBatch);
  auto flush = [&] {
    out.assign(batch.size(), Splat{});
    if (datapath) {
      datapath(batch, out);
    } else {
      for (size_t q = 0; q < batch.size(); ++q) out[q] = splat_fx(*batch[q].k, batch[q].i, batch[q].j);
    }
    for (size_t q = 0; q < batch.size(); ++q) {
      const Splat& sp = out[q];
      if (sp.guard) {
        ++r.stats.guarded;
        continue;
      }
      const img::Rgba8 c = colour[q];
      splat_into(cov, w, h, object[q], sp.x, sp.y, sp.w, &r.stats, [&](size_t p, uint32_t wt) {
        sat_add(&acc.w[p], wt, kWMax, p);
        const uint8_t ch[4] = {c.r, c.g, c.b, c.a};
        for (int ci = 0; ci < 4; ++ci) sat_add(&acc.c[ci][p], uint64_t(wt) * ch[ci], kCMax, p);
      });
    }
    batch.clear(), colour.clear(), object.clear();
  };
  for_each_sample(s, tris, opt, &r.stats, [&](const TriangleSetup& t, const Tile& tl, int i, int j) {
    const size_t ti = static_cast<size_t>(t.object);
    const TileFx& k = fx[static_cast<size_t>(&t - tris.data())][static_cast<size_t>(&tl - t.tiles.data())];
    const uint32_t lod = static_cast<uint32_t>(round_i64(std::ldexp(t.lambda, fmt::kTexLodF)));
    batch.push_back({&k.k, i, j});
    colour.push_back(
        tex::trilinear(texs[ti], lod, uv_fx(k.u[0], k.u[1], k.u[2], i, j), uv_fx(k.v[0], k.v[1], k.v[2], i, j)));
    object.push_back(t.object);
    if (batch.size() == kBatch) flush();
  });
  flush();
  // I = round half up (sum w c / sum w): floor((2 sum w c + sum w) / (2 sum w)), exact.
  auto div = [](uint64_t num, uint64_t den) {
    return static_cast<uint8_t>(std::min<u128>(255, (2 * u128(num) + den) / (2 * u128(den))));
  };
  r.frame = resolve(
      cov, w, h, &r.stats,
      [&](size_t p) {
        return img::Rgba8{div(acc.c[0][p], acc.w[p]), div(acc.c[1][p], acc.w[p]), div(acc.c[2][p], acc.w[p]),
                          div(acc.c[3][p], acc.w[p])};
      },
      [&](size_t p) { return std::ldexp(static_cast<double>(acc.w[p]), -fmt::kObjSplatWF); });
  for (uint8_t v : acc.sat) r.stats.acc_saturated += v;
  return r;
}

scene::Scene quad_scene(const std::string& vertices, int w, int h) {
  const std::string json = R"({"texunit_scene": 1,
    "camera": {"position": [0, 0, 0], "look_at": [0, 0, -1], "up": [0, 1, 0], "fovy_deg": 60,
               "width": )" + std::to_string(w) + R"(, "height": )" + std::to_string(h) + R"(, "z_near": 0.1},
    "textures": {"t": {"builtin": "checkerboard", "size": 64, "cells": 4, "wrap": "repeat"}},
    "materials": {"m": {"texture": "t", "filter": "trilinear"}},
    "objects": [{"name": "q", "type": "quad", "material": "m", "vertices": )" + vertices + R"(,
                 "uv": [[0, 1], [1, 1], [1, 0], [0, 0]]}]})";
  return scene::parse(json, "<objspace quad>", ".");
}

std::string random_quad_vertices(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> U(-1, 1);
  const double z = -1 - 20 * (U(rng) + 1), s = 0.5 + std::fabs(z) * 0.6, tilt = 0.5 * U(rng) * std::fabs(z) / s;
  const double far = U(rng);
  char v[256];
  std::snprintf(v, sizeof v, "[[%f, %f, %f], [%f, %f, %f], [%f, %f, %f], [%f, %f, %f]]", -s, -s, z + tilt * s, s, -s,
                z + tilt * s, s, s, z - tilt * s * far, -s, s, z - tilt * s);
  return v;
}

const std::vector<std::string>& stiff_quad_vertices() {
  static const std::vector<std::string> v = {
      "[[-3, -0.3, -0.5], [3, -0.3, -0.5], [3, -0.3, -12], [-3, -0.3, -12]]",
      "[[-3, -0.002, -0.2], [3, -0.002, -0.2], [3, -0.0001, -150], [-3, -0.0001, -150]]",
      "[[-0.2, -0.2, -0.1001], [0.2, -0.2, -0.1001], [0.2, 0.2, -0.1001], [-0.2, 0.2, -0.1001]]",
      "[[-900, -700, -800], [900, -700, -800], [900, 700, -800], [-900, 700, -800]]"};
  return v;
}

}  // namespace tu::objspace
