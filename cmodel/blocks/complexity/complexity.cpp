#include "complexity/complexity.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace tu::complexity {

void validate(const Params& p) {
  if (p.levels < 2 || p.levels > 256)
    throw std::invalid_argument("--levels must be in 2..256 (got " + std::to_string(p.levels) + ")");
  if (!(p.gamma > 0) || !std::isfinite(p.gamma) || p.gamma > 16)
    throw std::invalid_argument("--gamma must be in (0, 16] (got " + std::to_string(p.gamma) + ")");
  if (p.dilate < 1 || p.dilate > 255 || p.dilate % 2 == 0)
    throw std::invalid_argument("--dilate must be an odd size in 1..255 (got " +
                                std::to_string(p.dilate) + ")");
}

namespace {
int reflect101(int i, int n) {
  if (n == 1) return 0;
  while (i < 0 || i >= n) i = i < 0 ? -i : 2 * (n - 1) - i;
  return i;
}
}  // namespace

void sobel_at(const img::Gray8& h, int x, int y, int& gx, int& gy) {
  auto H = [&](int dx, int dy) {
    return static_cast<int>(h.at(reflect101(x + dx, h.width), reflect101(y + dy, h.height)));
  };
  gx = (H(1, -1) - H(-1, -1)) + 2 * (H(1, 0) - H(-1, 0)) + (H(1, 1) - H(-1, 1));
  gy = (H(-1, 1) - H(-1, -1)) + 2 * (H(0, 1) - H(0, -1)) + (H(1, 1) - H(1, -1));
}

std::vector<int32_t> sobel_sq(const img::Gray8& h) {
  std::vector<int32_t> g(h.px.size());
  for (int y = 0; y < h.height; ++y)
    for (int x = 0; x < h.width; ++x) {
      int gx = 0, gy = 0;
      sobel_at(h, x, y, gx, gy);
      g[static_cast<size_t>(y) * static_cast<size_t>(h.width) + static_cast<size_t>(x)] =
          gx * gx + gy * gy;
    }
  return g;
}

std::vector<int32_t> max_filter(const std::vector<int32_t>& v, int w, int h, int k) {
  const int r = k / 2;
  auto idx = [w](int x, int y) { return static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x); };
  std::vector<int32_t> rows(v.size()), out(v.size());
  for (int y = 0; y < h; ++y)  // separable: a square max = max over rows of max over columns
    for (int x = 0; x < w; ++x) {
      int32_t m = v[idx(x, y)];
      for (int i = std::max(0, x - r); i <= std::min(w - 1, x + r); ++i) m = std::max(m, v[idx(i, y)]);
      rows[idx(x, y)] = m;
    }
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      int32_t m = rows[idx(x, y)];
      for (int j = std::max(0, y - r); j <= std::min(h - 1, y + r); ++j) m = std::max(m, rows[idx(x, j)]);
      out[idx(x, y)] = m;
    }
  return out;
}

uint8_t level_code(int k, int levels) {
  return static_cast<uint8_t>((255 * k) / (levels - 1));
}

std::vector<int> levels(const img::Gray8& height, const Params& p) {
  validate(p);
  if (height.width <= 0 || height.height <= 0) throw std::invalid_argument("empty height map");
  const auto g2 = max_filter(sobel_sq(height), height.width, height.height, p.dilate);
  const int32_t mx = *std::max_element(g2.begin(), g2.end());  // max of the dilated = global max
  std::vector<int> lv(g2.size(), 0);
  if (mx == 0) return lv;  // flat map: C = 0 everywhere, never 0/0
  const double q = p.levels - 1;
  for (size_t i = 0; i < g2.size(); ++i) {
    const double c = std::sqrt(static_cast<double>(g2[i]) / static_cast<double>(mx));
    lv[i] = static_cast<int>(std::nearbyint(q * std::pow(c, p.gamma)));  // half-even (FE_TONEAREST)
  }
  return lv;
}

img::Gray8 complexity_map(const img::Gray8& height, const Params& p) {
  const auto lv = levels(height, p);
  img::Gray8 out(height.width, height.height);
  for (size_t i = 0; i < lv.size(); ++i) out.px[i] = level_code(lv[i], p.levels);
  return out;
}

}  // namespace tu::complexity
