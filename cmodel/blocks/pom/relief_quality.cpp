#include "pom/relief_quality.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <sstream>

#include "complexity/complexity.hpp"
#include "pom/pom_layers.hpp"
#include "pom/pom_march.hpp"

namespace tu::pom {

namespace {
uint8_t code(double depth) {
  return static_cast<uint8_t>(std::lround(std::clamp(depth, 0.0, 1.0) * 255.0));
}

// Deterministic hash noise in [0,1).
double hash01(uint32_t x, uint32_t y, uint32_t s) {
  uint32_t h = x * 374761393u + y * 668265263u + s * 2246822519u;
  h = (h ^ (h >> 13)) * 1274126177u;
  h ^= h >> 16;
  return static_cast<double>(h & 0xffffff) / 16777216.0;
}

double value_noise(double x, double y, int period, uint32_t s) {
  const double fx = std::floor(x), fy = std::floor(y);
  const double tx = x - fx, ty = y - fy;
  auto g = [&](int i, int j) {
    return hash01(static_cast<uint32_t>(((int(fx) + i) % period + period) % period),
                  static_cast<uint32_t>(((int(fy) + j) % period + period) % period), s);
  };
  auto sm = [](double t) { return t * t * (3 - 2 * t); };
  const double a = g(0, 0) + (g(1, 0) - g(0, 0)) * sm(tx);
  const double b = g(0, 1) + (g(1, 1) - g(0, 1)) * sm(tx);
  return a + (b - a) * sm(ty);
}

double psnr(double mse) {
  return mse == 0 ? std::numeric_limits<double>::infinity() : 10 * std::log10(255.0 * 255.0 / mse);
}
}  // namespace

img::Gray8 map_smooth(int side) {
  img::Gray8 m(side, side);
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x) {
      const double s = std::sin(2 * M_PI * 2 * (x + 0.5) / side) * std::sin(2 * M_PI * 2 * (y + 0.5) / side);
      m.at(x, y) = code(0.5 - 0.45 * s);
    }
  return m;
}

img::Gray8 map_bricks(int side) {
  img::Gray8 m(side, side);
  const int bh = side / 4, bw = side / 2, mortar = std::max(2, side / 32), bevel = std::max(2, side / 32);
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x) {
      const int row = y / bh;
      const int xs = (x + (row % 2) * bw / 2) % side;
      const int dx = std::min(xs % bw, bw - 1 - xs % bw), dy = std::min(y % bh, bh - 1 - y % bh);
      const int e = std::min(dx, dy) - mortar / 2;  // distance inside the brick
      double d;
      if (e < 0) d = 1.0;                             // mortar
      else if (e < bevel) d = 0.1 + 0.5 * (bevel - e) / bevel;  // bevel
      else d = 0.1;                                   // brick face
      m.at(x, y) = code(d);
    }
  return m;
}

img::Gray8 map_noisy(int side) {
  img::Gray8 m(side, side);
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x) {
      double v = 0, amp = 0.5;
      for (int o = 0, per = 4; o < 3; ++o, per *= 2, amp *= 0.5)
        v += amp * value_noise((x + 0.5) * per / side, (y + 0.5) * per / side, per, 17u + o);
      v = v / 0.875 * 0.85 + 0.15 * hash01(static_cast<uint32_t>(x), static_cast<uint32_t>(y), 99u);
      m.at(x, y) = code(v);
    }
  return m;
}

double albedo(double u, double v) {
  return std::round(127.5 + 127.0 * std::sin(2 * M_PI * 8 * u) * std::cos(2 * M_PI * 8 * v));
}

img::Gray8 depth_from_height(const std::string& path) {
  img::Gray8 h = img::read_png_channel0(path);
  if (h.width != h.height || h.width < 16 || h.width > kMaxHeightSide || (h.width & (h.width - 1)))
    throw std::invalid_argument(path + ": a height map for relief-quality is square, a power of two from 16 to " +
                                std::to_string(kMaxHeightSide) + " texels per side (this one is " +
                                std::to_string(h.width) + "x" + std::to_string(h.height) + ")");
  for (auto& x : h.px) x = static_cast<uint8_t>(255 - x);  // height 255 = top -> depth 0
  return h;
}

std::vector<QualityRow> quality(const QualityParams& p) {
  std::vector<QualityRow> rows;
  const double uvs = std::ldexp(1.0, -fmt::kPomUvF);
  struct M { std::string name; img::Gray8 d; };
  std::vector<M> maps;
  if (!p.height_png.empty()) {
    maps.push_back({std::filesystem::path(p.height_png).stem().string(), depth_from_height(p.height_png)});
  } else {
    maps = {{"smooth", map_smooth(p.side)}, {"bricks", map_bricks(p.side)}, {"noisy", map_noisy(p.side)}};
  }
  const int G = maps[0].d.width;
  for (const auto& mp : maps) {
    const img::Gray8 cmap = complexity::complexity_map(mp.d);
    for (double ang : p.angles) {
      const double th = ang * M_PI / 180, ph = p.azimuth * M_PI / 180;
      View vw;
      vw.vx = static_cast<int32_t>(std::lround(std::sin(th) * std::cos(ph) * (1 << fmt::kPomVzF)));
      vw.vy = static_cast<int32_t>(std::lround(std::sin(th) * std::sin(ph) * (1 << fmt::kPomVzF)));
      vw.vz = static_cast<int32_t>(std::lround(std::cos(th) * (1 << fmt::kPomVzF)));
      vw.scale = static_cast<uint32_t>(std::lround(p.scale * (1 << fmt::kPomSF)));
      const double vx = std::ldexp(vw.vx, -fmt::kPomVzF), vy = std::ldexp(vw.vy, -fmt::kPomVzF),
                   vz = std::ldexp(vw.vz, -fmt::kPomVzF), S = std::ldexp(vw.scale, -fmt::kPomSF);
      // reference image
      std::vector<double> ref(static_cast<size_t>(G) * G);
      double ref_steps = 0;
      for (int y = 0; y < G; ++y)
        for (int x = 0; x < G; ++x) {
          const double u = (x + 0.5) / G, v = (y + 0.5) / G;
          const auto r = march_ref(mp.d, u, v, vx, vy, vz, S, 256);
          ref[static_cast<size_t>(y) * G + x] = albedo(r.u, r.v);
          ref_steps += r.steps;
        }
      ref_steps /= double(G) * G;
      const std::vector<std::string> methods = {"N=4", "N=8", "N=16", "N=24", "N=32", "adaptive",
                                                "iter-seed", "iter-norm"};
      img::Gray8 dbg(G, G);
      for (const auto& meth : methods) {
        double se = 0, steps = 0, nc = 0;
        const IpxDir dseed = ipx_dir_seed(vw), dnorm = ipx_dir_normalised(vw);
        for (int y = 0; y < G; ++y)
          for (int x = 0; x < G; ++x) {
            const int64_t u = (int64_t(2 * x + 1) << fmt::kPomUvF) / (2 * G);
            const int64_t v = (int64_t(2 * y + 1) << fmt::kPomUvF) / (2 * G);
            int64_t ou, ov;
            if (meth.rfind("iter", 0) == 0) {
              const auto r = iter_parallax(mp.d, u, v, meth == "iter-seed" ? dseed : dnorm);
              ou = r.u; ov = r.v; steps += r.iters; nc += r.nonconv;
            } else {
              uint32_t n;
              if (meth == "adaptive") {
                n = layers(vw.vz, tex_nearest(cmap, u, v)).n;
                dbg.at(x, y) = static_cast<uint8_t>((n - kDefaultNmin) * 255 / (kDefaultNmax - kDefaultNmin));
              } else {
                n = static_cast<uint32_t>(std::stoi(meth.substr(2)));
              }
              const auto r = march(mp.d, u, v, vw, n, true);
              ou = r.u; ov = r.v; steps += r.steps;
            }
            const double e = albedo(ou * uvs, ov * uvs) - ref[static_cast<size_t>(y) * G + x];
            se += e * e;
          }
        const double np = double(G) * G;
        QualityRow row;
        row.map = mp.name; row.method = meth; row.angle = ang;
        row.psnr = psnr(se / np);
        row.steps = steps / np;
        row.fetches = row.steps + 1;
        row.nonconv = nc / np;
        row.ref_steps = ref_steps;
        rows.push_back(row);
      }
      if (!p.debug_dir.empty()) {
        char name[256];
        std::snprintf(name, sizeof name, "%s/layers_%s_%02d.png", p.debug_dir.c_str(), mp.name.c_str(), int(ang));
        img::write_png_gray(name, dbg);
      }
    }
  }
  return rows;
}

std::string quality_markdown(const std::vector<QualityRow>& rows) {
  auto f1 = [](double x) {
    if (std::isinf(x)) return std::string("inf");
    char b[32];
    std::snprintf(b, sizeof b, "%.1f", x);
    return std::string(b);
  };
  std::ostringstream o;
  o << "| map | angle | method | steps/px | fetches/px | PSNR dB | non-conv % | ref steps/px |\n"
       "|---|---|---|---|---|---|---|---|\n";
  char buf[256];
  for (const auto& r : rows) {
    const std::string ps = f1(r.psnr);
    const std::string nc = r.method.rfind("iter", 0) == 0 ? f1(100 * r.nonconv) : "-";
    std::snprintf(buf, sizeof buf, "| %s | %g | %s | %.2f | %.2f | %s | %s | %.1f |\n", r.map.c_str(),
                  r.angle, r.method.c_str(), r.steps, r.fetches, ps.c_str(), nc.c_str(), r.ref_steps);
    o << buf;
  }
  return o.str();
}

}  // namespace tu::pom
