#include "persp.hpp"

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

namespace tu::persp {

namespace {
glm::dvec3 v3(const double* p) { return {p[0], p[1], p[2]}; }

struct Basis {
  glm::dvec3 pos, fwd, dx, dy, d0;  // ray direction d(x, y) = dx*x + dy*y + d0, d . fwd = 1
};

Basis basis(const Camera& cam) {
  Basis b;
  b.pos = v3(cam.pos);
  b.fwd = glm::normalize(v3(cam.look_at) - b.pos);
  const glm::dvec3 right = glm::normalize(glm::cross(b.fwd, v3(cam.up)));
  const glm::dvec3 up = glm::cross(right, b.fwd);
  const double th = std::tan(cam.fovy_deg * M_PI / 360.0);
  const double aspect = static_cast<double>(cam.width) / cam.height;
  // ndc_x = 2 (x + 0.5) / W - 1, ndc_y = 1 - 2 (y + 0.5) / H
  b.dx = right * (2.0 / cam.width * th * aspect);
  b.dy = up * (-2.0 / cam.height * th);
  b.d0 = b.fwd + right * ((1.0 / cam.width - 1.0) * th * aspect) + up * ((1.0 - 1.0 / cam.height) * th);
  return b;
}
}  // namespace

Coef9 coefficients(const Camera& cam, const Triangle& t) {
  const Basis b = basis(cam);
  const glm::dvec3 p0 = v3(t.v[0].p), e1 = v3(t.v[1].p) - p0, e2 = v3(t.v[2].p) - p0;
  const glm::dvec3 c = b.pos - p0;
  const glm::dvec3 n = glm::cross(e1, e2);
  const double cn = glm::dot(c, n);
  // Cramer on s*e1 + r*e2 - t*d = c: s = d.(c x e2) / d.n, r = d.(e1 x c) / d.n, d.n = -c.n / z.
  const glm::dvec3 sv = glm::cross(c, e2), rv = glm::cross(e1, c);
  double zmin = INFINITY;
  for (const auto& v : t.v) zmin = std::min(zmin, glm::dot(v3(v.p) - b.pos, b.fwd));
  const double scale_len = glm::length(e1) * glm::length(e2) * (glm::length(c) + 1.0);
  if (!(std::fabs(cn) > 1e-12 * scale_len))
    throw SetupError("persp set-up: triangle '" + t.name + "': its plane contains the eye");
  const double zn = std::max(zmin, cam.z_near);
  const double lambda = -zn / cn;  // q = d.n * lambda = zn / z
  auto row = [&](int k) {
    const double du1 = t.v[1].uv[k] - t.v[0].uv[k], du2 = t.v[2].uv[k] - t.v[0].uv[k];
    return (t.v[0].uv[k] * n + du1 * sv + du2 * rv) * lambda;
  };
  const glm::dvec3 nu = row(0), nv = row(1), nq = n * lambda;
  return {glm::dot(nu, b.dx), glm::dot(nu, b.dy), glm::dot(nu, b.d0),
          glm::dot(nv, b.dx), glm::dot(nv, b.dy), glm::dot(nv, b.d0),
          glm::dot(nq, b.dx), glm::dot(nq, b.dy), glm::dot(nq, b.d0)};
}

RayCaster::RayCaster(const Camera& cam) : width_(cam.width), height_(cam.height) {
  const Basis b = basis(cam);
  th_ = std::tan(cam.fovy_deg * M_PI / 360.0);
  aspect_ = static_cast<double>(cam.width) / cam.height;
  const glm::dvec3 right = glm::normalize(glm::cross(b.fwd, v3(cam.up)));
  const glm::dvec3 up = glm::cross(right, b.fwd);
  for (int k = 0; k < 3; ++k) {
    pos_[k] = b.pos[k];
    fwd_[k] = b.fwd[k];
    right_[k] = right[k];
    up_[k] = up[k];
  }
}

void RayCaster::dir(int x, int y, double* d) const {
  // Per-pixel ray, built from the pixel centre directly (not from the linear form above).
  const glm::dvec3 fwd = v3(fwd_), right = v3(right_), up = v3(up_);
  const double nx = 2.0 * (x + 0.5) / width_ - 1.0, ny = 1.0 - 2.0 * (y + 0.5) / height_;
  const glm::dvec3 r = glm::normalize(fwd + right * (nx * th_ * aspect_) + up * (ny * th_));
  d[0] = r.x, d[1] = r.y, d[2] = r.z;
}

bool RayCaster::hit_dir(const Triangle& t, const double* dp, Hit* h) const {
  const glm::dvec3 d = v3(dp);
  const glm::dvec3 p0 = v3(t.v[0].p), e1 = v3(t.v[1].p) - p0, e2 = v3(t.v[2].p) - p0;
  const glm::dmat3 m(e1, e2, -d);  // columns
  const double det = glm::determinant(m);
  if (std::fabs(det) < 1e-300) return false;
  const glm::dvec3 srt = glm::inverse(m) * (v3(pos_) - p0);
  if (srt.z <= 0) return false;
  *h = {srt.x, srt.y, srt.z};
  return true;
}

bool RayCaster::hit(const Triangle& t, int x, int y, Hit* h) const {
  double d[3];
  dir(x, y, d);
  return hit_dir(t, d, h);
}

bool RayCaster::bounds(const Triangle& t, int* x0, int* x1, int* y0, int* y1) const {
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (const auto& v : t.v) {
    const glm::dvec3 rel = v3(v.p) - v3(pos_);
    const double z = glm::dot(rel, v3(fwd_));
    if (!(z > 1e-9 * glm::length(rel))) return false;
    // Inverse of the ray's pixel-centre mapping: nx = 2 (x + 0.5) / W - 1, ny = 1 - 2 (y + 0.5) / H.
    const double nx = glm::dot(rel, v3(right_)) / (z * th_ * aspect_);
    const double ny = glm::dot(rel, v3(up_)) / (z * th_);
    const double p[2] = {(nx + 1) * width_ / 2 - 0.5, (1 - ny) * height_ / 2 - 0.5};
    for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  }
  // Clamped as doubles first: a far-off projection does not fit an int. x0 > x1: nothing.
  auto clip = [](double v, int n) { return static_cast<int>(std::clamp(v, -1.0, double(n))); };
  *x0 = clip(std::floor(lo[0]) - 2, width_), *x1 = clip(std::ceil(hi[0]) + 2, width_ - 1);
  *y0 = clip(std::floor(lo[1]) - 2, height_), *y1 = clip(std::ceil(hi[1]) + 2, height_ - 1);
  *x0 = std::max(*x0, 0), *y0 = std::max(*y0, 0);
  return true;
}

std::array<double, 2> rebase_offset(const Triangle& t, const std::array<double, 2>& period, bool force) {
  std::array<double, 2> off{0, 0};
  for (int k = 0; k < 2; ++k) {
    if (!(period[k] > 0)) continue;
    double lo = INFINITY, hi = -INFINITY, big = 0;
    for (const auto& v : t.v) lo = std::min(lo, v.uv[k]), hi = std::max(hi, v.uv[k]), big = std::max(big, std::fabs(v.uv[k]));
    if (big < kRebaseFrom && !force) continue;
    off[k] = period[k] * std::ceil((lo + hi) / (2 * period[k]) - 0.5);
  }
  return off;
}

Triangle rebased(const Triangle& t, const std::array<double, 2>& period, bool force) {
  const auto off = rebase_offset(t, period, force);
  Triangle r = t;
  for (auto& v : r.v) v.uv[0] -= off[0], v.uv[1] -= off[1];
  return r;
}

bool ray_hit(const Camera& cam, const Triangle& t, int x, int y, Hit* h) {
  return RayCaster(cam).hit(t, x, y, h);
}

bool ray_uv(const Camera& cam, const Triangle& t, int x, int y, double* u, double* v) {
  Hit h;
  if (!ray_hit(cam, t, x, y, &h)) return false;
  *u = t.v[0].uv[0] + h.s * (t.v[1].uv[0] - t.v[0].uv[0]) + h.r * (t.v[2].uv[0] - t.v[0].uv[0]);
  *v = t.v[0].uv[1] + h.s * (t.v[1].uv[1] - t.v[0].uv[1]) + h.r * (t.v[2].uv[1] - t.v[0].uv[1]);
  return true;
}

Coef9 span_map(int y, int x0, int x1, double q0, double q1, double u0, double u1, double v0,
               double v1, double bq, double bu, double bv) {
  const double w = x1 > x0 ? x1 - x0 : 1;
  Coef9 k{};
  k.g = (q1 - q0) / w;
  k.h = bq;
  k.i = q0 - k.g * x0 - bq * y;
  k.a = (u1 * q1 - u0 * q0) / w;
  k.b = bu;
  k.c = u0 * q0 - k.a * x0 - bu * y;
  k.d = (v1 * q1 - v0 * q0) / w;
  k.e = bv;
  k.f = v0 * q0 - k.d * x0 - bv * y;
  return k;
}

Coef9 random_span_map(std::mt19937_64& rng, int y, int x0, int x1, double q0, double q1) {
  std::uniform_real_distribution<double> U(0, 1);
  const double lim = 0.8 * std::max(1, x1 - x0);
  // |G| x1 <= 4: q extrapolated to x = 0 (the coefficient I) stays inside its format.
  const double dq = 4.0 * std::max(1, x1 - x0) / std::max(1, x1);
  q1 = std::clamp(q1, q0 - dq, q0 + dq);
  auto ends = [&](double* a0, double* a1) {
    // The far end (smaller |q|) first; the near end's p within lim of it and |u| <= 4096.
    const bool far0 = std::fabs(q0) < std::fabs(q1);
    const double qf = far0 ? q0 : q1, qn = far0 ? q1 : q0;
    const double uf = (U(rng) - 0.5) * 8192, pf = uf * qf;
    double pn = std::clamp((U(rng) - 0.5) * 8192 * qn, pf - lim, pf + lim);
    pn = std::clamp(pn, -4096 * std::fabs(qn), 4096 * std::fabs(qn));
    const double un = qn != 0 ? pn / qn : 0;
    *a0 = far0 ? uf : un;
    *a1 = far0 ? un : uf;
  };
  double u0, u1, v0, v1;
  ends(&u0, &u1);
  ends(&v0, &v1);
  return span_map(y, x0, x1, q0, q1, u0, u1, v0, v1, (U(rng) - 0.5) / 8192, (U(rng) - 0.5) / 2,
                  (U(rng) - 0.5) / 2);
}

}  // namespace tu::persp
