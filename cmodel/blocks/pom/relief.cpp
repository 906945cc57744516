#include "pom/relief.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "texunit/formats.hpp"

#include "complexity/complexity.hpp"
#include "distmap/dm_trace.hpp"
#include "pom/pom_layers.hpp"

namespace tu::relief {

namespace {
void sub(const double a[3], const double b[3], double o[3]) {
  for (int i = 0; i < 3; ++i) o[i] = a[i] - b[i];
}
void cross(const double a[3], const double b[3], double o[3]) {
  o[0] = a[1] * b[2] - a[2] * b[1];
  o[1] = a[2] * b[0] - a[0] * b[2];
  o[2] = a[0] * b[1] - a[1] * b[0];
}
double dot(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double det3(const double a[3], const double b[3], const double c[3]) {
  double x[3];
  cross(b, c, x);
  return dot(a, x);
}
}  // namespace

Maps make_maps(const img::Gray8& height) {
  auto pow2 = [](int n) { return n > 0 && (n & (n - 1)) == 0; };
  if (!pow2(height.width) || !pow2(height.height))
    throw std::invalid_argument("relief height map: sides must be powers of two (got " +
                                std::to_string(height.width) + "x" + std::to_string(height.height) + ")");
  Maps m;
  m.depth = height;
  for (auto& p : m.depth.px) p = static_cast<uint8_t>(255 - p);
  m.complexity = complexity::complexity_map(height);
  return m;
}

Maps make_maps(const scene::Scene& s, const std::string& material) {
  const auto& rel = s.materials.at(material).relief.value();
  const auto& spec = s.textures.at(rel.height_texture);
  const img::Gray8 height = spec.builtin == "bricks" ? tex::bricks(spec.size).height : [&] {
    const tex::Texture t = scene::build_texture(s, rel.height_texture);
    const auto& im = t.levels[0];
    img::Gray8 g(im.width, im.height);
    for (size_t i = 0; i < im.px.size(); ++i) g.px[i] = im.px[i].r;
    return g;
  }();
  Maps m;
  try {
    m = make_maps(height);
  } catch (const std::invalid_argument& e) {
    throw scene::SceneError(s.source + ": /materials/" + material + "/relief/height: " + e.what());
  }
  if (rel.method == Method::DistanceMap || rel.method == Method::DistanceMapRefined) {
    dm::Params p;
    p.layers = rel.map_layers;
    p.scale = rel.scale;
    p.refined = rel.method == Method::DistanceMapRefined;
    try {
      m.dist = std::make_shared<const dm::Map>(dm::build(m.depth, p));
    } catch (const std::invalid_argument& e) {
      throw scene::SceneError(s.source + ": /materials/" + material + "/relief: " + e.what());
    }
  }
  return m;
}

bool tangent_view(const persp::Triangle& t, const double eye[3], double s, double r,
                  TangentView* out) {
  double e1[3], e2[3], n[3], p[3], vv[3], tt[3], bb[3], hh[3];
  sub(t.v[1].p, t.v[0].p, e1);
  sub(t.v[2].p, t.v[0].p, e2);
  const double du1 = t.v[1].uv[0] - t.v[0].uv[0], dv1 = t.v[1].uv[1] - t.v[0].uv[1];
  const double du2 = t.v[2].uv[0] - t.v[0].uv[0], dv2 = t.v[2].uv[1] - t.v[0].uv[1];
  const double det = du1 * dv2 - du2 * dv1;
  if (std::fabs(det) < 1e-300) return false;
  for (int i = 0; i < 3; ++i) {
    tt[i] = (e1[i] * dv2 - e2[i] * dv1) / det;  // dP/du
    bb[i] = (e2[i] * du1 - e1[i] * du2) / det;  // dP/dv
    p[i] = t.v[0].p[i] + s * e1[i] + r * e2[i];
  }
  sub(eye, p, vv);
  cross(e1, e2, n);
  const double nl = std::sqrt(dot(n, n));
  double tb[3];
  cross(tt, bb, tb);
  const double ell = std::sqrt(std::sqrt(dot(tb, tb)));  // world length of one repeat
  if (nl == 0 || ell == 0) return false;
  const double side = dot(n, vv) < 0 ? -1.0 : 1.0;      // normal towards the eye
  for (int i = 0; i < 3; ++i) hh[i] = side * n[i] / nl * ell;
  // V = a T + b B + c H (Cramer)
  const double d = det3(tt, bb, hh);
  if (std::fabs(d) < 1e-300) return false;
  const double a = det3(vv, bb, hh) / d, b = det3(tt, vv, hh) / d, c = det3(tt, bb, vv) / d;
  const double len = std::sqrt(a * a + b * b + c * c);
  if (len == 0) return false;
  *out = {a / len, b / len, c / len};
  return true;
}

pom::View quantise(const TangentView& v, double scale) {
  const double one = std::ldexp(1.0, fmt::kPomVzF);
  pom::View q;
  q.vx = static_cast<int32_t>(std::lround(v.x * one));
  q.vy = static_cast<int32_t>(std::lround(v.y * one));
  q.vz = static_cast<int32_t>(std::lround(v.z * one));
  q.scale = static_cast<uint32_t>(
      std::clamp<long>(std::lround(scale * std::ldexp(1.0, fmt::kPomSF)), 0, (1L << fmt::kPomSF) - 1));
  return q;
}

RefShift shift_uv_ref(const Maps& m, double u, double v, const TangentView& view, double scale) {
  const auto r = pom::march_ref(m.depth, u, v, view.x, view.y, view.z, scale, 256);
  return {r.tu, r.tv, r.steps};
}

uint32_t layers_at(const Maps& m, int64_t u, int64_t v, const pom::View& view, Method method,
                   int layers) {
  const auto n = static_cast<uint32_t>(std::clamp(layers, 1, 63));
  if (method != Method::PomAdaptive) return n;
  return pom::layers(view.vz, pom::tex_nearest(m.complexity, u, v), pom::kDefaultNmin, n).n;
}

FxShift shift_uv_fx(const Maps& m, int64_t u, int64_t v, const pom::View& view, Method method,
                    int layers, bool wrap) {
  const auto n = static_cast<uint32_t>(std::clamp(layers, 1, 63));
  // The march works inside one texture repeat; the integer part is put back afterwards.
  const int64_t iu = u & ~(pom::kUvOne - 1), iv = v & ~(pom::kUvOne - 1);
  FxShift o;
  if (method == Method::DistanceMap || method == Method::DistanceMapRefined) {
    if (!m.dist) throw std::invalid_argument("relief::shift_uv_fx: a distance-map method without its map");
    o.n = dm_cap(layers);
    const auto r = dm::trace(*m.dist, m.depth, u - iu, v - iv, view, o.n, fmt::kDmFinish);
    o.steps = r.steps + r.finish_steps;
    o.vz_guard = r.clamped;
    o.back = r.back;
    if (wrap) {
      o.u = iu + (r.u & (pom::kUvOne - 1));
      o.v = iv + (r.v & (pom::kUvOne - 1));
    } else {
      o.u = iu + r.u;
      o.v = iv + r.v;
      o.discard = r.u < 0 || r.u > pom::kUvOne || r.v < 0 || r.v > pom::kUvOne;
    }
    return o;
  }
  if (method == Method::Iterative) {
    const auto r = pom::iter_parallax(m.depth, u - iu, v - iv, pom::ipx_dir_normalised(view), n);
    o.u = iu + r.u;
    o.v = iv + r.v;
    o.steps = r.iters;
    o.n = n;
    o.nonconv = r.nonconv;
    o.vz_guard = pom::parallax(view).clamped;
    return o;
  }
  o.n = layers_at(m, u, v, view, method, layers);
  const auto r = pom::march(m.depth, u - iu, v - iv, view, o.n, wrap);
  o.u = iu + r.u;
  o.v = iv + r.v;
  o.steps = r.steps;
  o.discard = r.discard;
  o.vz_guard = r.clamped;
  o.back = r.back;
  return o;
}

uint32_t dm_cap(int layers) { return static_cast<uint32_t>(std::clamp(layers, 1, fmt::kDmCapMax)); }

int64_t shift_code(int64_t c, int by) { return by >= 0 ? c * (int64_t(1) << by) : c >> -by; }

TexelShift shift_texel_uv_fx(const Maps& m, int64_t u, int64_t v, int lw, int lh,
                             const pom::View& view, Method method, int layers) {
  const int du = fmt::kPomUvF - fmt::kTexUvF;
  const auto r = shift_uv_fx(m, shift_code(u, du - lw), shift_code(v, du - lh), view, method, layers);
  const uint32_t flags = (r.vz_guard ? uint32_t{kReliefVzGuard} : 0u) | (r.nonconv ? uint32_t{kReliefNonConv} : 0u) |
                         (r.back ? uint32_t{kReliefBack} : 0u);
  return {shift_code(r.u, lw - du), shift_code(r.v, lh - du), r.n, r.steps, flags};
}

StageModel::StageModel(const std::vector<StagePixel>& px, int fifo_depth)
    : px_(px),
      fifo_depth_(fifo_depth),
      lay_(fmt::kPomLayersLatency, -1),
      set_(fmt::kPomSetupLatency, -1),
      ref_(fmt::kPomRefineLatency, -1) {}

StageModel::Comb StageModel::comb(bool out_ready) const {
  Comb c;
  // The unit's output is taken at the head of the sideband FIFO (order is kept), so the
  // refinement advances when its last stage is empty or holds the head and the output is taken.
  const bool head = fifo_head_ < fifo_.size();
  const bool h_shift = head && px_[static_cast<size_t>(fifo_[fifo_head_])].shift;
  c.out = head && out_ready && (!h_shift || ref_.back() >= 0);
  c.r_en = ref_.back() < 0 || (h_shift && out_ready);
  c.out_free = mout_ < 0 || c.r_en;
  c.go = run_ && i_ < px_[static_cast<size_t>(cur_)].steps;
  c.finish = run_ && !c.go;
  // The set-up hands its last pixel to an engine only when the other holds none (the march's
  // count: marching, output register; the iterative engine's Idle; both registered).
  const bool take_in = !run_ || (c.finish && c.out_free);
  const bool m_empty = !run_ && mout_ < 0, i_empty = ist_ == kIdle;
  const int sb = set_.back();
  const bool sb_iter = sb >= 0 && px_[static_cast<size_t>(sb)].iter;
  c.m_fire = sb >= 0 && !sb_iter && take_in && i_empty;
  c.i_fire = sb >= 0 && sb_iter && i_empty && m_empty;
  c.s_en = sb < 0 || c.m_fire || c.i_fire;
  c.l_en = lay_.back() < 0 || c.s_en;
  const bool f_room = fifo_.size() - fifo_head_ < static_cast<size_t>(fifo_depth_);
  c.in_ready = next_ < px_.size() && f_room && (!px_[next_].shift || c.l_en);
  return c;
}

StageModel::Fired StageModel::step(bool in_valid, bool out_ready) {
  auto advance = [](Pipe& p, int in) {
    for (size_t k = p.size() - 1; k > 0; --k) p[k] = p[k - 1];
    p[0] = in;
  };
  const Comb c = comb(out_ready);
  Fired f{in_valid && c.in_ready, c.out};
  // The refinement takes the march's output register or the iterative engine's Done (never both).
  const bool i_out = ist_ == kDone && c.r_en;
  if (c.r_en) advance(ref_, mout_ >= 0 ? mout_ : ist_ == kDone ? icur_ : -1);
  const int mout_d = c.finish && c.out_free ? cur_ : (c.r_en ? -1 : mout_);
  if (c.m_fire) {
    cur_ = set_.back();
    i_ = 0;
    run_ = true;
  } else if (c.go) {
    ++i_;
  } else if (c.finish && c.out_free) {
    run_ = false;
  }
  if (ist_ == kIdle && c.i_fire) {
    icur_ = set_.back();
    ii_ = 0;
    ist_ = kRun;
  } else if (ist_ == kRun) {
    if (ii_ < px_[static_cast<size_t>(icur_)].steps) ++ii_;
    else ist_ = kDone;
  } else if (i_out) {
    ist_ = kIdle;
  }
  mout_ = mout_d;
  if (c.s_en) advance(set_, lay_.back());
  if (c.l_en) advance(lay_, f.in && px_[next_].shift ? static_cast<int>(next_) : -1);
  if (f.out) ++fifo_head_;
  if (f.in) fifo_.push_back(static_cast<int>(next_++));
  return f;
}

StagePixel stage_pixel(bool shift, uint32_t steps, Method m) {
  if (!shift) return {};
  const bool dm = m == Method::DistanceMap || m == Method::DistanceMapRefined;
  return {true, dm ? static_cast<uint32_t>(fmt::kDmSetupCycles) + 1 + steps : steps, dm || m == Method::Iterative};
}

uint64_t stage_cycles(const std::vector<StagePixel>& px, int fifo_depth) {
  StageModel m(px, fifo_depth);
  uint64_t t = 0, last = 0;
  const auto idle_limit = 1000 + 160 * static_cast<uint64_t>(px.size());  // a distance-map pixel: <= 85 clocks
  while (m.outputs() < px.size()) {
    if (t > idle_limit) throw std::logic_error("relief::stage_cycles: no progress");
    if (m.step(true, true).out) last = t;
    ++t;
  }
  return px.empty() ? 0 : last + 1;
}

bool pixel_view(const persp::RayCaster& rays, const scene::Scene& s, int object, int triangle,
                int x, int y, TangentView* out) {
  const auto& tri = s.objects[static_cast<size_t>(object)].triangles[static_cast<size_t>(triangle)];
  persp::Hit hit;
  return rays.hit(tri, x, y, &hit) && tangent_view(tri, s.camera.pos, hit.s, hit.r, out);
}

bool pixel_view(const scene::Scene& s, int object, int triangle, int x, int y, TangentView* out) {
  return pixel_view(persp::RayCaster(s.camera), s, object, triangle, x, y, out);
}

}  // namespace tu::relief
