#include "distmap/distance_map.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "texunit/formats.hpp"
#include "texunit/parallel.hpp"

namespace tu::dm {

static_assert(kQuantumBits == fmt::kDmQF, "distance-map quantum shared with formats.hpp");

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

// Felzenszwalb-Huttenlocher lower envelope: out[p] = min_q (ys[p] - xs[q])^2 + f[q], xs and ys
// increasing; samples with f = inf take no part (out = inf if every f is inf).
void envelope(const std::vector<double>& xs, const std::vector<double>& f, const std::vector<double>& ys,
              double* out, size_t out_stride, std::vector<int>& v, std::vector<double>& z) {
  const int n = static_cast<int>(xs.size());
  v.assign(static_cast<size_t>(n), 0);
  z.assign(static_cast<size_t>(n) + 1, 0);
  int k = -1;
  for (int q = 0; q < n; ++q) {
    if (std::isinf(f[static_cast<size_t>(q)])) continue;
    const double fq = f[static_cast<size_t>(q)] + xs[static_cast<size_t>(q)] * xs[static_cast<size_t>(q)];
    double s = -kInf;
    while (k >= 0) {
      const int r = v[static_cast<size_t>(k)];
      const double fr = f[static_cast<size_t>(r)] + xs[static_cast<size_t>(r)] * xs[static_cast<size_t>(r)];
      s = (fq - fr) / (2 * (xs[static_cast<size_t>(q)] - xs[static_cast<size_t>(r)]));
      if (s > z[static_cast<size_t>(k)]) break;
      --k;
    }
    ++k;
    v[static_cast<size_t>(k)] = q;
    z[static_cast<size_t>(k)] = k == 0 ? -kInf : s;
    z[static_cast<size_t>(k) + 1] = kInf;
  }
  int j = 0;
  for (size_t p = 0; p < ys.size(); ++p) {
    if (k < 0) {
      out[p * out_stride] = kInf;
      continue;
    }
    while (j < k && z[static_cast<size_t>(j) + 1] < ys[p]) ++j;  // ys increasing
    const double d = ys[p] - xs[static_cast<size_t>(v[static_cast<size_t>(j)])];
    out[p * out_stride] = d * d + f[static_cast<size_t>(v[static_cast<size_t>(j)])];
  }
}

// In-place 1-D transform of n samples spaced `spacing`, stride apart; periodic: the line is
// seen three times (the nearest image of any sample is within half a period of the middle copy).
void line(double* a, size_t stride, int n, double spacing, bool periodic, std::vector<double>& xs,
          std::vector<double>& f, std::vector<double>& ys, std::vector<int>& v, std::vector<double>& z) {
  const int copies = periodic ? 3 : 1, first = periodic ? -n : 0;
  xs.resize(static_cast<size_t>(n) * static_cast<size_t>(copies));
  f.resize(xs.size());
  for (int c = 0; c < copies; ++c)
    for (int i = 0; i < n; ++i) {
      const size_t at = static_cast<size_t>(c) * static_cast<size_t>(n) + static_cast<size_t>(i);
      xs[at] = (first + c * n + i + 0.5) * spacing;
      f[at] = a[static_cast<size_t>(i) * stride];
    }
  ys.resize(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) ys[static_cast<size_t>(i)] = (i + 0.5) * spacing;
  envelope(xs, f, ys, a, stride, v, z);
}

int wrap(int64_t i, int n) { return static_cast<int>(((i % n) + n) % n); }
}  // namespace

std::vector<double> edt3(const std::vector<uint8_t>& member, int w, int hgt, int le, double h) {
  std::vector<double> d(member.size());
  for (size_t i = 0; i < d.size(); ++i) d[i] = member[i] ? 0.0 : kInf;
  std::vector<double> xs, f, ys, z;
  std::vector<int> v;
  const size_t plane = static_cast<size_t>(w) * static_cast<size_t>(hgt);
  for (size_t c = 0; c < plane; ++c) line(&d[c], plane, le, h, false, xs, f, ys, v, z);  // depth
  for (int k = 0; k < le; ++k)
    for (int y = 0; y < hgt; ++y)
      line(&d[static_cast<size_t>(k) * plane + static_cast<size_t>(y) * static_cast<size_t>(w)], 1, w, 1.0, true,
           xs, f, ys, v, z);
  for (int k = 0; k < le; ++k)
    for (int x = 0; x < w; ++x)
      line(&d[static_cast<size_t>(k) * plane + static_cast<size_t>(x)], static_cast<size_t>(w), hgt, 1.0, true,
           xs, f, ys, v, z);
  return d;
}

std::vector<double> edt3_brute(const std::vector<uint8_t>& member, int w, int hgt, int /*le*/, double h) {
  auto pd = [](int a, int b, int n) {
    const int d = std::abs(a - b) % n;
    return std::min(d, n - d);
  };
  const size_t plane = static_cast<size_t>(w) * static_cast<size_t>(hgt);
  std::vector<double> d(member.size(), kInf);
  for (size_t i = 0; i < d.size(); ++i)
    for (size_t j = 0; j < d.size(); ++j) {
      if (!member[j]) continue;
      const int xi = static_cast<int>(i % static_cast<size_t>(w)), yi = static_cast<int>((i % plane) / static_cast<size_t>(w)),
                ki = static_cast<int>(i / plane);
      const int xj = static_cast<int>(j % static_cast<size_t>(w)), yj = static_cast<int>((j % plane) / static_cast<size_t>(w)),
                kj = static_cast<int>(j / plane);
      const double dx = pd(xi, xj, w), dy = pd(yi, yj, hgt), dz = (ki - kj) * h;
      d[i] = std::min(d[i], dx * dx + dy * dy + dz * dz);
    }
  return d;
}

namespace {
// The voxel of the extended grid holding p (x, y wrapped, layer clamped to -1..D) and |p - centre|.
struct Cell {
  size_t ext;
  double off;
};
Cell cell_of(const Map& m, double x, double y, double z) {
  const double fx = std::floor(x), fy = std::floor(y);
  const int k = static_cast<int>(std::clamp(std::floor(z / m.layer_texels), -1.0, double(m.layers)));
  const double dx = x - (fx + 0.5), dy = y - (fy + 0.5), dz = z - (k + 0.5) * m.layer_texels;
  return {m.index_ext(wrap(static_cast<int64_t>(fx), m.w), wrap(static_cast<int64_t>(fy), m.h), k),
          std::sqrt(dx * dx + dy * dy + dz * dz)};
}
}  // namespace

double Map::lower_dist(double x, double y, double z) const {
  const Cell c = cell_of(*this, x, y, z);
  return dt_in[c.ext] - c.off - delta;
}

double Map::lower_depth_inside(double x, double y, double z) const {
  const Cell c = cell_of(*this, x, y, z);
  return dt_out[c.ext] - c.off - delta;
}

std::vector<Dir> directions(double step_deg) {
  if (!(step_deg >= 1 && step_deg <= 45)) throw std::invalid_argument("distance map: direction step must be 1..45 degrees");
  std::vector<Dir> out;
  const double st = step_deg * M_PI / 180;
  const int rings = static_cast<int>(std::ceil(90.0 / step_deg - 1e-9));
  for (int r = 0; r <= rings; ++r) {
    const double th = std::min(r * st, M_PI / 2);
    const int n = r == 0 ? 1 : static_cast<int>(std::ceil(2 * M_PI * std::sin(th) / st - 1e-9));
    for (int j = 0; j < n; ++j) {
      const double ph = 2 * M_PI * j / n;
      out.push_back({std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)});
    }
  }
  return out;
}

namespace {
// Conservative free length along d from the voxel centre (x, y, z): B - mu - s eps stays >= 0,
// marched by its Lipschitz constant 1 + eps; stops at `limit`.
double free_length(const Map& m, double x, double y, double z, const Dir& d, double mu, double limit) {
  double s = 0;
  for (int it = 0; it < 256 && s < limit; ++it) {
    const double b = m.lower_dist(x + s * d.x, y + s * d.y, z + s * d.z) - mu - s * m.eps;
    if (b <= 1e-3) break;
    s += b / (1 + m.eps);
  }
  return std::min(s, limit);
}

// Some point behind (x, y, z) along -d is inside V by more than mu + s eps (see the header).
bool hidden(const Map& m, double x, double y, double z, const Dir& d, double mu) {
  const double step = std::min(0.5, m.layer_texels / 2), smax = 4.0 * m.w;
  for (double s = step; s < smax;) {
    const double px = x - s * d.x, py = y - s * d.y, pz = z - s * d.z;
    if (pz < 0) return false;
    if (m.lower_depth_inside(px, py, pz) >= mu + s * m.eps) return true;
    s += std::max(step, m.lower_dist(px, py, pz));  // skipping is safe: it can only miss exclusions
  }
  return false;
}
}  // namespace

Map build(const img::Gray8& depth, const Params& p) {
  const int w = depth.width;
  if (w != depth.height || w < 1 || w > kMaxSide || (w & (w - 1)))
    throw std::invalid_argument("distance map: the height map must be square, a power of two from 1 to " +
                                std::to_string(kMaxSide) + " texels per side (this one is " + std::to_string(w) +
                                "x" + std::to_string(depth.height) + ")");
  if (p.layers < 1 || p.layers > kMaxLayers)
    throw std::invalid_argument("distance map: --depth (layers) must be 1.." + std::to_string(kMaxLayers));
  if (!(p.scale > 0 && p.scale < 1) || std::ldexp(std::round(std::ldexp(p.scale, fmt::kPomSF)), -fmt::kPomSF) * w < 1)
    throw std::invalid_argument("distance map: scale must be in (0, 1) with scale * side >= 1 texel of relief depth");
  Map m;
  m.w = m.h = w;
  m.layers = p.layers;
  m.scale_code = static_cast<uint32_t>(std::lround(p.scale * (1 << fmt::kPomSF)));
  m.scale = std::ldexp(double(m.scale_code), -fmt::kPomSF);
  m.depth_texels = m.scale * w;
  m.layer_texels = m.depth_texels / p.layers;
  m.delta = 0.5 * std::sqrt(2 + m.layer_texels * m.layer_texels);
  m.eta = std::ldexp(1.0, -fmt::kDmEtaF);
  m.margin = 2 * m.delta + m.eta;
  m.refined = p.refined;
  const int le = p.layers + 2;
  const size_t plane = static_cast<size_t>(w) * static_cast<size_t>(w);
  m.inside.assign(plane * static_cast<size_t>(le), 0);
  std::vector<uint8_t> outside(m.inside.size(), 0);
  for (int k = -1; k <= p.layers; ++k)
    for (int y = 0; y < w; ++y)
      for (int x = 0; x < w; ++x) {
        const bool in = k == p.layers || (k >= 0 && 255 * (2 * k + 1) >= 2 * p.layers * depth.at(x, y));
        m.inside[m.index_ext(x, y, k)] = in;
        outside[m.index_ext(x, y, k)] = !in;
      }
  const auto din = edt3(m.inside, w, w, le, m.layer_texels), dout = edt3(outside, w, w, le, m.layer_texels);
  m.dt_in.resize(din.size());
  m.dt_out.resize(dout.size());
  for (size_t i = 0; i < din.size(); ++i) {
    m.dt_in[i] = static_cast<float>(std::sqrt(din[i]));
    m.dt_out[i] = static_cast<float>(std::sqrt(dout[i]));
  }
  m.code.assign(plane * static_cast<size_t>(p.layers), 0);
  m.safe.assign(m.code.size(), 0);
  std::vector<Dir> omega;
  if (p.refined) {
    omega = directions(p.direction_step_deg);
    m.direction_step_deg = p.direction_step_deg;
    m.eps = 2 * std::sin(p.direction_step_deg * M_PI / 360);
    m.directions = static_cast<int>(omega.size());
  }
  const double mu = m.delta + m.eta, cap = 256 * kQuantum;
  // One task per (layer, row); each writes only its own voxels.
  par::for_each_index(p.layers * w, p.threads, [&](int task) {
    const int k = task / w, y = task % w;
    std::vector<std::pair<double, size_t>> cand;
    for (int x = 0; x < w; ++x) {
      const size_t i = m.index(x, y, k);
      // dt_in as float may round up by 2^-24 relative: the margin's eta slack covers it.
      double safe = std::max(0.0, static_cast<double>(m.dt_in[m.index_ext(x, y, k)]) - m.margin);
      if (p.refined && m.dt_in[m.index_ext(x, y, k)] > 0) {
        const double cx = x + 0.5, cy = y + 0.5, cz = (k + 0.5) * m.layer_texels;
        const double lv = free_length(m, cx, cy, cz, omega[0], mu, cap);  // vertical: never hidden
        if (lv > safe) {
          cand.clear();
          for (size_t o = 1; o < omega.size(); ++o) {
            const double l = free_length(m, cx, cy, cz, omega[o], mu, lv);
            if (l < lv) cand.push_back({l, o});
          }
          std::sort(cand.begin(), cand.end());
          double best = lv;
          for (const auto& [l, o] : cand)
            if (!hidden(m, cx, cy, cz, omega[o], mu)) {
              best = l;
              break;
            }
          safe = std::max(safe, best);
        }
      }
      m.safe[i] = static_cast<float>(safe);
      m.code[i] = static_cast<uint8_t>(std::min(255.0, std::floor(safe / kQuantum)));
    }
  });
  return m;
}

namespace {
// Distance from t to [a, b] on a circle of length n (a, b within [0, n]).
double interval_dist(double t, double a, double b, double n) {
  double best = kInf;
  for (int im = -1; im <= 1; ++im) {
    const double aa = a + im * n, bb = b + im * n;
    best = std::min(best, t < aa ? aa - t : t > bb ? t - bb : 0.0);
  }
  return best;
}
template <class F>
void for_each_box(const Map& m, F&& fn) {  // fn(x0, y0, z0, z1) for every inside box of layers 0..D-1
  for (int k = 0; k < m.layers; ++k)
    for (int y = 0; y < m.h; ++y)
      for (int x = 0; x < m.w; ++x)
        if (m.inside[m.index_ext(x, y, k)]) fn(double(x), double(y), k * m.layer_texels, (k + 1) * m.layer_texels);
}
// Slab test of the ray p + t d, t in [0, max_t], against the box and its periodic images that
// the segment's bounding box touches. strict: the open box (positive-length overlap inside);
// returns the entry t or inf.
double ray_box(double px, double py, double pz, const Dir& d, double x0, double y0, double z0, double z1,
               double n, double max_t, bool strict) {
  const double ze = pz + max_t * d.z;
  if (std::max(pz, ze) < z0 || std::min(pz, ze) > z1) return kInf;
  const double xa = std::min(px, px + max_t * d.x), xb = std::max(px, px + max_t * d.x);
  const double ya = std::min(py, py + max_t * d.y), yb = std::max(py, py + max_t * d.y);
  double best = kInf;
  for (int iy = static_cast<int>(std::floor((ya - y0 - 1) / n)); iy <= static_cast<int>(std::ceil((yb - y0) / n)); ++iy)
    for (int ix = static_cast<int>(std::floor((xa - x0 - 1) / n)); ix <= static_cast<int>(std::ceil((xb - x0) / n)); ++ix) {
      const double lo[3] = {x0 + ix * n, y0 + iy * n, z0}, hi[3] = {x0 + ix * n + 1, y0 + iy * n + 1, z1};
      const double o[3] = {px, py, pz}, dv[3] = {d.x, d.y, d.z};
      double t0 = 0, t1 = max_t;
      bool miss = false;
      for (int a = 0; a < 3 && !miss; ++a) {
        if (std::abs(dv[a]) < 1e-15) {
          if (strict ? (o[a] <= lo[a] || o[a] >= hi[a]) : (o[a] < lo[a] || o[a] > hi[a])) miss = true;
          continue;
        }
        double ta = (lo[a] - o[a]) / dv[a], tb = (hi[a] - o[a]) / dv[a];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
      }
      if (!miss && (strict ? t0 < t1 : t0 <= t1)) best = std::min(best, t0);
    }
  return best;
}
}  // namespace

double exact_dist(const Map& m, double x, double y, double z) {
  if (z >= m.depth_texels) return 0;
  double best = m.depth_texels - z;
  const double xw = std::fmod(std::fmod(x, m.w) + m.w, m.w), yw = std::fmod(std::fmod(y, m.h) + m.h, m.h);
  for_each_box(m, [&](double x0, double y0, double z0, double z1) {
    const double dx = interval_dist(xw, x0, x0 + 1, m.w), dy = interval_dist(yw, y0, y0 + 1, m.h);
    const double dz = z < z0 ? z0 - z : z > z1 ? z - z1 : 0.0;
    best = std::min(best, std::sqrt(dx * dx + dy * dy + dz * dz));
  });
  return best;
}

double exact_free_length(const Map& m, double x, double y, double z, const Dir& d, double max_t) {
  double best = d.z > 0 ? std::max(0.0, (m.depth_texels - z) / d.z) : kInf;
  best = std::min(best, max_t);
  const double xw = std::fmod(std::fmod(x, m.w) + m.w, m.w), yw = std::fmod(std::fmod(y, m.h) + m.h, m.h);
  for_each_box(m, [&](double x0, double y0, double z0, double z1) {
    best = std::min(best, ray_box(xw, yw, z, d, x0, y0, z0, z1, m.w, best, false));
  });
  return best;
}

bool exact_reaches(const Map& m, double x, double y, double z, const Dir& d) {
  if (d.z < 1e-9) return false;  // a horizontal ray never comes from the top
  const double top = z / d.z;  // back along -d to z = 0
  const Dir b{-d.x, -d.y, -d.z};
  const double xw = std::fmod(std::fmod(x, m.w) + m.w, m.w), yw = std::fmod(std::fmod(y, m.h) + m.h, m.h);
  bool blocked = z > m.depth_texels;
  for_each_box(m, [&](double x0, double y0, double z0, double z1) {
    if (!blocked && ray_box(xw, yw, z, b, x0, y0, z0, z1, m.w, top, true) < top) blocked = true;
  });
  return !blocked;
}

std::string header_json(const Map& m, const std::string& raw_name) {
  nlohmann::ordered_json j;
  j["format"] = "texunit-distance-map";
  j["version"] = 1;
  j["raw"] = raw_name;
  j["order"] = "x fastest, then y, then layer (layer 0 = top); one unsigned byte per voxel";
  j["width"] = m.w;
  j["height"] = m.h;
  j["layers"] = m.layers;
  j["scale"] = m.scale;
  j["scale_code_u0_16"] = m.scale_code;
  j["depth_texels"] = m.depth_texels;
  j["layer_texels"] = m.layer_texels;
  j["quantum_texels"] = kQuantum;
  j["code_bits"] = 8;
  j["value"] = "safe step in texels = code * quantum_texels (rounded down, saturates at 255)";
  j["margin_texels"] = m.margin;
  j["refined"] = m.refined;
  if (m.refined) {
    j["direction_step_deg"] = m.direction_step_deg;
    j["directions"] = m.directions;
    j["direction_chord"] = m.eps;
  }
  j["bytes"] = m.bytes();
  return j.dump(2) + "\n";
}

img::Gray8 slice(const Map& m, int k) {
  img::Gray8 s(m.w, m.h);
  for (int y = 0; y < m.h; ++y)
    for (int x = 0; x < m.w; ++x) s.at(x, y) = m.at(x, y, k);
  return s;
}

}  // namespace tu::dm
