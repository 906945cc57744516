#include "texunit/shading.hpp"

#include <cmath>
#include <stdexcept>

namespace tu::shading {

namespace {
using V3 = std::array<double, 3>;
V3 normalized(const V3& a) {
  const double l = std::hypot(a[0], a[1], a[2]);
  return l > 0 ? V3{a[0] / l, a[1] / l, a[2] / l} : a;
}
double dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
}  // namespace

brdf::Model model_of(const std::string& name) {
  for (brdf::Model m : brdf::kModels)
    if (brdf::name(m) == name) return m;
  throw std::invalid_argument("unknown BRDF model '" + name + "'");
}

Setup::Setup(const scene::Scene& s, brdf::Model unit_model) : s_(s) {
  for (const auto& o : s.objects) {
    const auto& spec = s.materials.at(o.material).specular;
    Obj b;
    b.model = spec && spec->model != "auto" ? model_of(spec->model) : unit_model;
    if (spec && !s.lights.empty()) {
      b.n = spec->n;
      for (int k = 0; k < 3; ++k) b.ks[k] = spec->color[k] * s.lights[0].color[k];
    }
    b.ccut = brdf::cut_code(b.model, b.n);
    obj_.push_back(b);
  }
}

bool Setup::ref_in(const persp::RayCaster& rays, int object, int triangle, int x, int y, brdf::shade::RefIn* out) const {
  if (!active()) return false;
  const auto& ob = s_.objects[static_cast<size_t>(object)];
  const auto& t = ob.triangles[static_cast<size_t>(triangle)];
  persp::Hit h;
  if (!rays.hit(t, x, y, &h)) return false;
  V3 p, n;
  for (int k = 0; k < 3; ++k) p[k] = t.v[0].p[k] + h.s * (t.v[1].p[k] - t.v[0].p[k]) + h.r * (t.v[2].p[k] - t.v[0].p[k]);
  if (!ob.normals.empty()) {
    const auto& vn = ob.normals[static_cast<size_t>(triangle)];
    for (size_t k = 0; k < 3; ++k) n[k] = vn[0][k] + h.s * (vn[1][k] - vn[0][k]) + h.r * (vn[2][k] - vn[0][k]);
  } else {
    const V3 e1{t.v[1].p[0] - t.v[0].p[0], t.v[1].p[1] - t.v[0].p[1], t.v[1].p[2] - t.v[0].p[2]};
    const V3 e2{t.v[2].p[0] - t.v[0].p[0], t.v[2].p[1] - t.v[0].p[1], t.v[2].p[2] - t.v[0].p[2]};
    n = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
  }
  n = normalized(n);
  const V3 v = normalized({s_.camera.pos[0] - p[0], s_.camera.pos[1] - p[1], s_.camera.pos[2] - p[2]});
  if (dot(n, v) < 0) n = {-n[0], -n[1], -n[2]};  // two-sided: the side the eye sees
  const scene::Light& li = s_.lights[0];
  const V3 l = li.positional ? normalized({li.position[0] - p[0], li.position[1] - p[1], li.position[2] - p[2]})
                             : normalized({-li.direction[0], -li.direction[1], -li.direction[2]});
  const V3 lv{l[0] + v[0], l[1] + v[1], l[2] + v[2]};
  // L = -V (the light straight behind the surface point): no half vector; N.L < 0 there anyway.
  const V3 hv = std::hypot(lv[0], lv[1], lv[2]) > 1e-12 ? normalized(lv) : n;
  const Obj& b = obj_[static_cast<size_t>(object)];
  for (int k = 0; k < 3; ++k) {
    out->n[k] = n[static_cast<size_t>(k)], out->l[k] = l[static_cast<size_t>(k)], out->h[k] = hv[static_cast<size_t>(k)];
    out->ks[k] = b.ks[k], out->lc[k] = li.color[k];
  }
  out->nexp = b.n;
  out->amb = li.ambient;
  return true;
}

brdf::shade::In Setup::fx_in(const persp::RayCaster& rays, int object, int triangle, int x, int y) const {
  brdf::shade::RefIn r;
  if (!ref_in(rays, object, triangle, x, y, &r)) return {};
  return brdf::shade::quantise(r, obj_[static_cast<size_t>(object)].ccut);
}

}  // namespace tu::shading
