#include "pom/relief_quality.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <limits>
#include <memory>
#include <sstream>

#include "complexity/complexity.hpp"
#include "distmap/dm_trace.hpp"
#include "pom/relief_exact.hpp"
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

namespace {
double fbm01(double x, double y, int side, int octaves, int base, uint32_t seed) {
  double v = 0, amp = 0.5, norm = 0;
  for (int o = 0, per = base; o < octaves && per <= side; ++o, per *= 2, amp *= 0.5) {
    v += amp * value_noise(x * per / side, y * per / side, per, seed + static_cast<uint32_t>(o));
    norm += amp;
  }
  return v / norm;
}
img::Gray8 from_unit(int side, const std::function<double(double, double)>& f) {
  img::Gray8 m(side, side);
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x) m.at(x, y) = code(f(x + 0.5, y + 0.5));
  return m;
}
}  // namespace

img::Gray8 height_fbm(int side) {
  return from_unit(side, [&](double x, double y) { return fbm01(x, y, side, 6, 4, 31u); });
}

img::Gray8 height_gravel(int side) {
  const int cells = std::max(2, side / 8);  // pebbles about 8 texels across
  const double cs = double(side) / cells;
  return from_unit(side, [&](double x, double y) {
    const int cx = static_cast<int>(x / cs), cy = static_cast<int>(y / cs);
    double best = 1e9, top = 0;
    for (int j = -1; j <= 1; ++j)
      for (int i = -1; i <= 1; ++i) {
        const int gx = cx + i, gy = cy + j;
        const auto wx = static_cast<uint32_t>((gx % cells + cells) % cells), wy = static_cast<uint32_t>((gy % cells + cells) % cells);
        const double px = (gx + 0.15 + 0.7 * hash01(wx, wy, 5u)) * cs, py = (gy + 0.15 + 0.7 * hash01(wx, wy, 6u)) * cs;
        const double d = std::hypot(x - px, y - py) / (0.75 * cs);
        if (d < best) best = d, top = 0.55 + 0.45 * hash01(wx, wy, 7u);
      }
    const double dome = best < 1 ? top * std::sqrt(1 - best * best) : 0;
    return 0.9 * dome + 0.1 * hash01(static_cast<uint32_t>(x), static_cast<uint32_t>(y), 8u);
  });
}

img::Gray8 height_bark(int side) {
  return from_unit(side, [&](double x, double y) {
    const double warp = fbm01(x, y * 0.25, side, 4, 4, 41u);
    const double r = std::abs(std::sin(M_PI * (8.0 * x / side + 1.5 * warp)));  // 8 ridges across
    const double crack = r < 0.18 ? 0.0 : 1.0;
    return crack * (0.35 + 0.45 * std::sqrt(r) + 0.2 * fbm01(x, y, side, 5, 8, 43u));
  });
}

img::Gray8 height_stone(int side) {
  return from_unit(side, [&](double x, double y) {
    double v = 0, amp = 0.5, norm = 0;
    for (int o = 0, per = 4; o < 5 && per <= side; ++o, per *= 2, amp *= 0.5) {
      v += amp * (1 - std::abs(2 * value_noise(x * per / side, y * per / side, per, 51u + static_cast<uint32_t>(o)) - 1));
      norm += amp;
    }
    v /= norm;
    const double c = fbm01(x, y, side, 3, 4, 57u);
    return std::abs(c - 0.5) < 0.025 ? 0.05 : v;  // cracks along a noise contour
  });
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
    if (p.compare)
      for (auto& [name, h] : std::vector<std::pair<std::string, img::Gray8>>{
               {"fbm", height_fbm(p.side)}, {"gravel", height_gravel(p.side)}, {"bark", height_bark(p.side)},
               {"stone", height_stone(p.side)}}) {
        if (!p.debug_dir.empty()) img::write_png_gray(p.debug_dir + "/height_" + name + ".png", h);
        for (auto& x : h.px) x = static_cast<uint8_t>(255 - x);
        maps.push_back({name, h});
      }
  }
  const int G = maps[0].d.width;
  for (const auto& mp : maps) {
    const img::Gray8 cmap = complexity::complexity_map(mp.d);
    std::unique_ptr<dm::Map> dmc, dmr;
    if (p.compare) {
      dm::Params dp;
      dp.layers = p.dm_layers;
      dp.scale = p.scale;
      dp.direction_step_deg = p.dm_step_deg;
      dmc = std::make_unique<dm::Map>(dm::build(mp.d, dp));
      dp.refined = true;
      dmr = std::make_unique<dm::Map>(dm::build(mp.d, dp));
    }
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
      std::vector<double> ref(static_cast<size_t>(G) * G), exact(p.compare ? ref.size() : 0);
      double ref_steps = 0;
      for (int y = 0; y < G; ++y)
        for (int x = 0; x < G; ++x) {
          const double u = (x + 0.5) / G, v = (y + 0.5) / G;
          const auto r = march_ref(mp.d, u, v, vx, vy, vz, S, 256);
          ref[static_cast<size_t>(y) * G + x] = albedo(r.u, r.v);
          ref_steps += r.steps;
          if (p.compare) {
            const auto e = relief::exact_hit(mp.d, u, v, vx, vy, vz, S);
            exact[static_cast<size_t>(y) * G + x] = albedo(e.u, e.v);
          }
        }
      ref_steps /= double(G) * G;
      std::vector<std::string> methods = {"N=4", "N=8", "N=16", "N=24", "N=32", "adaptive",
                                          "iter-seed", "iter-norm"};
      if (p.compare)
        for (const char* m : {"linbin-8", "linbin-16", "linbin-32", "dm", "dm-refined", "dm+finish", "dm-refined+finish"})
          methods.push_back(m);
      img::Gray8 dbg(G, G);
      for (const auto& meth : methods) {
        double se = 0, se_exact = 0, steps = 0, nc = 0, cycles = 0;
        const IpxDir dseed = ipx_dir_seed(vw), dnorm = ipx_dir_normalised(vw);
        for (int y = 0; y < G; ++y)
          for (int x = 0; x < G; ++x) {
            const int64_t u = (int64_t(2 * x + 1) << fmt::kPomUvF) / (2 * G);
            const int64_t v = (int64_t(2 * y + 1) << fmt::kPomUvF) / (2 * G);
            int64_t ou, ov;
            if (meth.rfind("iter", 0) == 0) {
              const auto r = iter_parallax(mp.d, u, v, meth == "iter-seed" ? dseed : dnorm);
              ou = r.u; ov = r.v; steps += r.iters; nc += r.nonconv;
              cycles += r.iters + 3;
            } else if (meth.rfind("linbin-", 0) == 0) {
              const auto r = dm::linbin(mp.d, u, v, vw, static_cast<uint32_t>(std::stoi(meth.substr(7))));
              ou = r.u; ov = r.v; steps += r.steps;
              cycles += r.steps;  // one depth read per clock
            } else if (meth.rfind("dm", 0) == 0) {
              const bool fin = meth.find("+finish") != std::string::npos;
              const auto r = dm::trace(meth.rfind("dm-refined", 0) == 0 ? *dmr : *dmc, mp.d, u, v, vw, fmt::kDmCap,
                                       fin ? fmt::kDmFinish : 0);
              ou = r.u; ov = r.v; steps += r.steps + r.finish_steps; nc += r.capped;
              cycles += r.steps + 1 + r.finish_steps;  // map reads k + 1, then the finish's depth reads
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
              cycles += r.steps + 1;
            }
            const double a = albedo(ou * uvs, ov * uvs);
            const double e = a - ref[static_cast<size_t>(y) * G + x];
            se += e * e;
            if (p.compare) {
              const double ex = a - exact[static_cast<size_t>(y) * G + x];
              se_exact += ex * ex;
            }
          }
        const double np = double(G) * G;
        QualityRow row;
        row.map = mp.name; row.method = meth; row.angle = ang;
        row.psnr = psnr(se / np);
        row.steps = steps / np;
        row.fetches = row.steps + 1;
        row.nonconv = nc / np;
        row.psnr_exact = p.compare ? psnr(se_exact / np) : 0;
        row.cycles = cycles / np;
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
  o << "| map | angle | method | steps/px | fetches/px | cycles/px | PSNR dB | PSNR vs exact dB | non-conv % | ref steps/px |\n"
       "|---|---|---|---|---|---|---|---|---|---|\n";
  char buf[320];
  for (const auto& r : rows) {
    const std::string ps = f1(r.psnr);
    const bool flagged = r.method.rfind("iter", 0) == 0 || r.method.rfind("dm", 0) == 0;  // non-conv / capped
    const std::string nc = flagged ? f1(100 * r.nonconv) : "-";
    const std::string pe = r.psnr_exact == 0 ? "-" : f1(r.psnr_exact);
    std::snprintf(buf, sizeof buf, "| %s | %g | %s | %.2f | %.2f | %.2f | %s | %s | %s | %.1f |\n", r.map.c_str(),
                  r.angle, r.method.c_str(), r.steps, r.fetches, r.cycles, ps.c_str(), pe.c_str(), nc.c_str(),
                  r.ref_steps);
    o << buf;
  }
  return o.str();
}

}  // namespace tu::pom
