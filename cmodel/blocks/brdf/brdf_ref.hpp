// Float references of the BRDF specular models of seed 004 (Zavalniuk, VNTU 2022; the note
// shared/spec/notes/seed-004-brdf.md) and the thesis's measures: c = cos x (N.H, or cos(R,V) in the
// thesis's tool), n the specular exponent. Every formula is the note's reconstruction; the tests in
// testbench/unit/brdf_ref_test.cpp reproduce the thesis's numbers with them.
#pragma once

#include <functional>
#include <vector>

namespace tu::brdf::ref {

double blinn(double c, int n);    // F_B = c^n (1.5), the reference every model is fitted to
double schlick(double c, int n);  // F_SH = c / (n - n c + c) (1.6)
double msh(double c, int n);      // F_MSH = 2c / (1.25 (n - n c + 1.25 c)^2) (2.3); F(1) = 1.024
// F_dsh = max(0, (F_SH + G) / 2), G = 2(c+0.1)^8 / (1.25 (1.25 n(1-c) + 1.25 c^8)^2 + 1.5) - 0.25:
// the clamped average (the note's §3.3; the printed plain sum (2.26) peaks at 1.99).
double dsh(double c, int n);
double dsh_printed_sum(double c, int n);  // (2.26) as printed, for the discrepancy test
double scos(double c, int n);   // F_SCOS = max(0, 1 - n(1-c)/2)^2 (3.1)
// F_SCOS2 = max(0, (2c - 0.1 n(1-c)) / (n(1-c) + 2c))^2 (3.10), base clamped before squaring.
double scos2(double c, int n);
double st(double c, int n, int a);  // F_ST = max(0, 1 - (n/a)(1-c))^a (3.15); a = 16 and 268
double qr(double c, int n);         // F_QR = max(0, c (1 - 0.786 n (1-c))) (3.18)

// Search templates: (2.2) with powers b1..b5 and coefficients a1..a5 (Table 2.1), and the
// two-generating-function template (2.25) averaged and clamped (Fig. 2.14).
struct MshTemplate {
  double b1, b2, b3, b5, a1, a2, a3, a5;
};
double msh_template(const MshTemplate& t, double c, int n);
struct DshTemplate {
  double b1, b2, b3, b5, b6, a1, a2, a3, a5, c1, c2, c3;
};
double dsh_template(const DshTemplate& t, double c, int n);

// MAD against Blinn on the thesis grid (Appendix B): deg = 0..90 x n = 1..n_max, mean |F_B - F|.
// `deg_step` / `n_step` > 1 give a coarser grid (CI); the thesis's is 1, 1 with n_max = 1000.
double mad_vs_blinn(const std::function<double(double, int)>& f, int deg_step = 1, int n_step = 1,
                    int n_max = 1000);

// Normalising coefficients (lobe convention of the note's A4: coef * 2 pi Int_0^pi/2 F cos sin = 1).
double msh_coef_exact(int n);  // closed form 1 / (2 pi 1.6 (0.8n^2 - 1.25 - 2n ln 0.8n) / (n-1.25)^3)
double msh_coef_fit(int n);    // (2.24): 0.125 n - 45.76 / (n + 46.578) + 1.317
double qr_coef_exact(int n);   // 6a^3 / (pi (6a^2 - 4a + 1)), a = 0.786 n (n >= 2); n = 1 below
double qr_coef_thesis(int n);  // the thesis's table: integral to acos(2.545e-3 (393n - 500)/n)
double qr_coef_fit(int n);     // (3.25) for n in [1, 20], 0.255 n (3.26) above
// Energy 2 pi Int_0^{x_max} F(cos x) cos x sin x dx by composite Simpson with `steps` panels.
double lobe_energy(const std::function<double(double)>& f, double x_max, int steps = 20000);

// The thesis tool's test scene (§6.1, note's render.py): a ray-cast unit sphere, 499 x 520, light
// (10,0,10), eye (0,0,6), ambient 0.4 red, kd = ks = 0.5, the specular term fed cos(R,V) unclamped;
// grey = 0.299 R + 0.587 G + 0.114 B of the truncated 0..255 channels. Returns one grey per pixel.
std::vector<double> sphere_render(const std::function<double(double, int)>& spec, int n,
                                  int width = 499, int height = 520);
// Mean Manhattan grey distance of two renders (the thesis's Table 4.2 metric).
double manhattan(const std::vector<double>& a, const std::vector<double>& b);

}  // namespace tu::brdf::ref
