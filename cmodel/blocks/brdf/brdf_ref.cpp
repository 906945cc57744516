#include "brdf_ref.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace tu::brdf::ref {

double blinn(double c, int n) { return std::pow(c, n); }
double schlick(double c, int n) { return c / (n - n * c + c); }
double msh(double c, int n) {
  const double d = n - n * c + 1.25 * c;
  return 2 * c / (1.25 * d * d);
}
namespace {
double dsh_g(double c, int n) {
  const double c8 = std::pow(c, 8);
  const double d = 1.25 * n - 1.25 * n * c + 1.25 * c8;
  return 2 * std::pow(c + 0.1, 8) / (1.25 * d * d + 1.5) - 0.25;
}
}  // namespace
double dsh(double c, int n) { return std::max(0.0, (schlick(c, n) + dsh_g(c, n)) / 2); }
double dsh_printed_sum(double c, int n) { return schlick(c, n) + dsh_g(c, n); }
double scos(double c, int n) {
  const double b = std::max(0.0, 1 - n * (1 - c) / 2);
  return b * b;
}
double scos2(double c, int n) {
  const double u = n * (1 - c);
  const double b = std::max(0.0, (2 * c - 0.1 * u) / (u + 2 * c));
  return b * b;
}
double st(double c, int n, int a) {
  return std::pow(std::max(0.0, 1 - static_cast<double>(n) / a * (1 - c)), a);
}
double qr(double c, int n) { return std::max(0.0, c * (1 - 0.786 * n * (1 - c))); }

double msh_template(const MshTemplate& t, double c, int n) {
  const double den = t.a3 * std::pow(n, t.b3) - t.a3 * std::pow(n * c, t.b3) +
                     t.a5 * std::pow(c, t.b5);
  return t.a1 * std::pow(c, t.b1) / (t.a2 * std::pow(den, t.b2));
}
double dsh_template(const DshTemplate& t, double c, int n) {
  const double den = t.a2 * std::pow(t.a3 * std::pow(n, t.b3) - t.a3 * std::pow(n * c, t.b3) +
                                         t.a5 * std::pow(c, t.b5),
                                     t.b2) +
                     t.c2;
  const double g = std::pow(t.a1 * std::pow(c + t.c1, t.b1) / den, t.b6) - t.c3;
  return std::max(0.0, (schlick(c, n) + g) / 2);
}

double mad_vs_blinn(const std::function<double(double, int)>& f, int deg_step, int n_step,
                    int n_max) {
  double sum = 0;
  long count = 0;
  for (int deg = 0; deg <= 90; deg += deg_step) {
    const double c = std::cos(deg * std::numbers::pi / 180);
    for (int n = 1; n <= n_max; n += n_step) {
      sum += std::fabs(blinn(c, n) - f(c, n));
      ++count;
    }
  }
  return sum / static_cast<double>(count);
}

double lobe_energy(const std::function<double(double)>& f, double x_max, int steps) {
  if (steps % 2) ++steps;
  const double h = x_max / steps;
  auto g = [&](double x) { return f(std::cos(x)) * std::cos(x) * std::sin(x); };
  double s = g(0) + g(x_max);
  for (int i = 1; i < steps; ++i) s += (i % 2 ? 4 : 2) * g(i * h);
  return 2 * std::numbers::pi * s * h / 3;
}

double msh_coef_exact(int n) {
  const double k = n - 1.25;
  const double integral = 1.6 * (0.8 * n * n - 1.25 - 2 * n * std::log(0.8 * n)) / (k * k * k);
  return 1 / (2 * std::numbers::pi * integral);
}
double msh_coef_fit(int n) { return 0.125 * n - 45.76 / (n + 46.578) + 1.317; }
double qr_coef_exact(int n) {
  const double a = 0.786 * n;
  if (a < 1)  // the zero lies below the horizon: integrate the whole hemisphere
    return 1 / (2 * std::numbers::pi * (a / 4 + (1 - a) / 3));
  return 6 * a * a * a / (std::numbers::pi * (6 * a * a - 4 * a + 1));
}
double qr_coef_thesis(int n) {
  const double arg = 2.545e-3 * (393.0 * n - 500) / n;
  const double x_max = arg < -1 ? std::numbers::pi : std::acos(std::min(1.0, arg));
  // The thesis integrates the unclamped quadratic up to its zero (n = 1: past the horizon).
  return 1 / lobe_energy([n](double c) { return 0.786 * n * c * c + (1 - 0.786 * n) * c; },
                         x_max);
}
double qr_coef_fit(int n) {
  if (n <= 20) return 0.212 * (1.175 * (n + (1.265 + (n * (-0.023 * std::tan(-0.0008 * n))))));
  return 0.255 * n;
}

std::vector<double> sphere_render(const std::function<double(double, int)>& spec, int n, int width,
                                  int height) {
  struct V3 {
    double x, y, z;
  };
  auto sub = [](V3 a, V3 b) { return V3{a.x - b.x, a.y - b.y, a.z - b.z}; };
  auto dot = [](V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; };
  auto nrm = [&](V3 a) {
    const double l = std::sqrt(dot(a, a));
    return V3{a.x / l, a.y / l, a.z / l};
  };
  auto kor = [](double d) { return static_cast<int>(std::min(255.0, std::max(0.0, d))); };
  const V3 centre{-1, 1, -6}, light{10, 0, 10}, eye{0, 0, 6};
  const double ka = 0.4, ks = 0.5, kd = 0.5;
  std::vector<double> img(static_cast<size_t>(width) * static_cast<size_t>(height), 0.0);
  for (int py = 0; py < height; ++py) {
    const double yn = py / (height / 2.0) - 1;
    for (int px = 0; px < width; ++px) {
      const double xn = px / (width / 2.0) - 1;
      const V3 d = nrm({xn / 2.41, yn / 2.51, -1});
      const V3 oc{-centre.x, -centre.y, -centre.z};
      const double b = dot(oc, d), cc = dot(oc, oc) - 1, disc = b * b - cc;
      if (disc < 0) continue;
      const double t = -b - std::sqrt(disc);
      const V3 pv{d.x * t, d.y * t, d.z * t};
      const V3 nn = sub(pv, centre);
      const V3 pw{pv.x, pv.y, pv.z + 6};
      const V3 v = nrm(sub(eye, pw)), l = nrm(sub(light, pw));
      const double diff = std::max(dot(nn, l), 0.0);
      const V3 r{2 * diff * nn.x - l.x, 2 * diff * nn.y - l.y, 2 * diff * nn.z - l.z};
      const double cosrv = dot(r, v) / std::sqrt(dot(r, r));
      const double sp = 255 * ks * spec(cosrv, n), dp = 255 * kd * diff;
      const double red = ka * 255 + dp + sp, green = dp + sp, blue = dp + sp;
      img[static_cast<size_t>(py) * static_cast<size_t>(width) + static_cast<size_t>(px)] =
          0.299 * kor(red) + 0.587 * kor(green) + 0.114 * kor(blue);
    }
  }
  return img;
}

double manhattan(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) throw std::invalid_argument("manhattan: image sizes differ");
  double s = 0;
  for (size_t i = 0; i < a.size(); ++i) s += std::fabs(a[i] - b[i]);
  return s / static_cast<double>(a.size());
}

}  // namespace tu::brdf::ref
