#include "afvis/afvis_quality.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>
#include <stdexcept>

#include "pom/relief.hpp"
#include "pom/relief_quality.hpp"
#include "texunit/image.hpp"
#include "texunit/output.hpp"
#include "texunit/render.hpp"

namespace tu::afvis {

namespace {
constexpr const char* kHeight = "afvis_height";  // the texture every relief material's height becomes

struct Variant {
  const char* name;
  render::AfvisMode mode;
  Rule rule;
  int pyramid;
};
constexpr Variant kVariants[] = {{"plain", render::AfvisMode::Off, Rule::Row, 0},
                                 {"every", render::AfvisMode::On, Rule::Every, 0},
                                 {"row", render::AfvisMode::On, Rule::Row, 0},
                                 {"pyramid2", render::AfvisMode::On, Rule::Every, 2},
                                 {"row+pyramid2", render::AfvisMode::On, Rule::Row, 2}};

img::Gray8 height_map(const std::string& name) {
  if (name == "fbm") return pom::height_fbm(256);
  if (name == "gravel") return pom::height_gravel(256);
  if (name == "bark") return pom::height_bark(256);
  if (name == "stone") return pom::height_stone(256);
  throw std::invalid_argument("afvis quality: unknown height map '" + name + "' (bricks, fbm, gravel, bark, stone)");
}

// Every relief material's height texture becomes `map`.
scene::Scene with_height(scene::Scene s, const std::string& map, const std::string& tmp_dir) {
  scene::TextureSpec t;
  t.name = kHeight;
  t.size = 256;
  if (map == "bricks") {
    t.builtin = "bricks";
  } else {
    if (tmp_dir.empty()) throw std::invalid_argument("afvis quality: height map '" + map + "' needs a tmp_dir");
    t.png = (std::filesystem::path(tmp_dir) / ("afvis_height_" + map + ".png")).string();
    img::write_png_gray(t.png, height_map(map));
  }
  s.textures[kHeight] = t;
  for (auto& [name, m] : s.materials)
    if (m.relief) m.relief->height_texture = kHeight;
  return s;
}

double luma(const img::Rgba8& c) { return 0.299 * c.r + 0.587 * c.g + 0.114 * c.b; }

// The relief pixels of a frame (1 per pixel) and the squared luma gradient (central differences).
std::vector<char> relief_mask(const render::Frame& f, const scene::Scene& s) {
  const auto keep = render::relief_pixels(s);
  std::vector<char> m(static_cast<size_t>(s.camera.width) * static_cast<size_t>(s.camera.height), 0);
  for (const auto& p : f.pixels)
    if (keep(p)) m[static_cast<size_t>(p.y) * static_cast<size_t>(s.camera.width) + static_cast<size_t>(p.x)] = 1;
  return m;
}
double grad2(const img::Rgba8Image& im, int x, int y) {
  const double gx = luma(im.at(x + 1, y)) - luma(im.at(x - 1, y)), gy = luma(im.at(x, y + 1)) - luma(im.at(x, y - 1));
  return gx * gx + gy * gy;
}
}  // namespace

std::vector<QualityRow> quality(const scene::Scene& base, const QualityParams& p) {
  std::vector<QualityRow> rows;
  for (const auto& map : p.maps) {
    const scene::Scene s0 = with_height(base, map, p.tmp_dir);
    for (const double hm : p.heights) {
      scene::Scene s = s0;
      s.camera.pos[1] *= hm;
      render::TruthOptions to;
      to.ss = p.ss;
      const render::Frame truth = render::render_truth(s, to);
      const auto keep = render::relief_pixels(s);
      // Mean view angle from the relief's normal over the relief pixels.
      const auto cov = render::visibility(s, p.threads);
      double angle = 0;
      size_t n_view = 0;
      for (const auto& px : truth.pixels) {
        if (!keep(px)) continue;
        const auto& c = cov[static_cast<size_t>(px.y) * static_cast<size_t>(s.camera.width) + static_cast<size_t>(px.x)];
        relief::TangentView tv;
        if (relief::pixel_view(s, c.object, c.triangle, px.x, px.y, &tv)) angle += std::acos(std::clamp(tv.z, -1.0, 1.0)), ++n_view;
      }
      // Edge pixels: relief pixels (with relief neighbours) whose truth gradient is in the top 10 %.
      const int w = s.camera.width, h = s.camera.height;
      const auto mask = relief_mask(truth, s);
      auto inner = [&](int x, int y) {
        auto m = [&](int i, int j) { return mask[static_cast<size_t>(j) * static_cast<size_t>(w) + static_cast<size_t>(i)] != 0; };
        return x > 0 && y > 0 && x + 1 < w && y + 1 < h && m(x, y) && m(x - 1, y) && m(x + 1, y) && m(x, y - 1) && m(x, y + 1);
      };
      std::vector<std::pair<double, size_t>> g;
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
          if (inner(x, y)) g.push_back({grad2(truth.image, x, y), static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x)});
      std::sort(g.begin(), g.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
      g.resize(g.size() / 10);
      double e_truth = 0;
      for (const auto& [e, i] : g) e_truth += e;
      for (const Variant& v : kVariants) {
        render::CmodelOptions o;
        o.threads = p.threads;
        o.afvis = v.mode;
        o.afvis_rule = v.rule;
        o.afvis_pyramid = v.pyramid;
        o.afvis_bias = p.bias;
        const render::Frame f = render::render_cmodel(s, {}, o);
        QualityRow r;
        r.map = map, r.height = hm, r.variant = v.name;
        r.view_deg = n_view ? angle / double(n_view) * 180 / M_PI : 0;
        r.psnr = render::psnr_covered(f, truth, keep);
        double e = 0;
        for (const auto& [et, i] : g) e += grad2(f.image, static_cast<int>(i % static_cast<size_t>(w)), static_cast<int>(i / static_cast<size_t>(w)));
        r.sharpness = e_truth > 0 ? e / e_truth : 0;
        for (const auto& px : f.pixels) {
          if (!keep(px)) continue;
          ++r.pixels;
          r.texels += px.texels, r.inside += px.texels_inside;
          r.visible += v.mode == render::AfvisMode::Off ? px.texels_inside : px.afv_visible;
          r.traced += px.afv_traced, r.steps += px.afv_steps;
          r.no_visible += (px.ewa_flags & ewa::fx::kNoWeight) ? 1 : 0;
        }
        const double n = std::max<double>(1, double(r.pixels));
        r.texels /= n, r.inside /= n, r.visible /= n, r.traced /= n, r.steps /= n, r.no_visible /= n;
        r.cost_pct = 100 * r.steps / (r.texels + 12);
        rows.push_back(r);
      }
    }
  }
  return rows;
}

std::string quality_markdown(const std::vector<QualityRow>& rows) {
  std::ostringstream o;
  o << "| map | camera | view (mean) | variant | relief px | PSNR vs truth | sharpness | texels walked | inside | kept | traced | vis. steps | no visible | + clocks |\n"
    << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  char b[512];
  for (const auto& r : rows) {
    std::snprintf(b, sizeof b, "| %s | ×%g | %.1f° | %s | %zu | %.2f dB | %.3f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f %% | %+.1f %% |\n",
                  r.map.c_str(), r.height, r.view_deg, r.variant.c_str(), r.pixels, r.psnr, r.sharpness, r.texels,
                  r.inside, r.visible, r.traced, r.steps, 100 * r.no_visible, r.cost_pct);
    o << b;
  }
  return o.str();
}

void write_quality_plot(const std::vector<QualityRow>& rows, const std::string& dir) {
  const std::string base = (std::filesystem::path(dir) / "afvis_gain_vs_clocks").string();
  std::map<std::pair<std::string, double>, double> plain;  // (map, camera) -> PSNR of plain EWA
  for (const auto& r : rows)
    if (r.variant == "plain") plain[{r.map, r.height}] = r.psnr;
  out::Outputs outs;
  {
    std::ostringstream d;
    d << "# one block per variant: added_clocks_pct psnr_gain_db map camera\n";
    for (const Variant& v : kVariants) {
      if (v.mode == render::AfvisMode::Off) continue;
      d << "# " << v.name << "\n";
      for (const auto& r : rows)
        if (r.variant == v.name && plain.count({r.map, r.height}))
          d << r.cost_pct << ' ' << r.psnr - plain[{r.map, r.height}] << " \"" << r.map << " x" << r.height << "\"\n";
      d << "\n\n";
    }
    outs.write(base + ".dat", d.str());
  }
  std::ostringstream g;
  g << "set terminal pngcairo size 900,600\nset output '" << base << ".png'\n"
    << "set title 'AF visibility: PSNR gain over plain EWA (relief pixels, vs truth) vs added clocks'\n"
    << "set xlabel 'added clocks per relief pixel (%, serial trace: one depth read per clock)'\n"
    << "set ylabel 'PSNR gain over POM + plain EWA (dB)'\nset grid\nset key outside right\nset xzeroaxis lw 2\nplot";
  int i = 0;
  for (const Variant& v : kVariants) {
    if (v.mode == render::AfvisMode::Off) continue;
    g << (i ? ", " : " ") << "'" << base << ".dat' index " << i << " using 1:2 with points pt " << 5 + 2 * i
      << " ps 1.5 title '" << v.name << "'";
    ++i;
  }
  g << ", '' index 0 using 1:2:3 with labels offset 0,1 font ',8' notitle\n";
  outs.write(base + ".gp", g.str());
  if (const std::string why = out::gnuplot(outs, base + ".gp", {base + ".png"}); !why.empty())
    throw std::runtime_error("afvis plot: " + why);
  outs.commit();
}

}  // namespace tu::afvis
