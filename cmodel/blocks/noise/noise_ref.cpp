#include "noise/noise_ref.hpp"

#include <algorithm>
#include <cmath>

namespace tu::noise {

const std::array<uint8_t, 256>& permutation() {
  static const std::array<uint8_t, 256> p = {
      151, 160, 137, 91,  90,  15,  131, 13,  201, 95,  96,  53,  194, 233, 7,   225, 140, 36,
      103, 30,  69,  142, 8,   99,  37,  240, 21,  10,  23,  190, 6,   148, 247, 120, 234, 75,
      0,   26,  197, 62,  94,  252, 219, 203, 117, 35,  11,  32,  57,  177, 33,  88,  237, 149,
      56,  87,  174, 20,  125, 136, 171, 168, 68,  175, 74,  165, 71,  134, 139, 48,  27,  166,
      77,  146, 158, 231, 83,  111, 229, 122, 60,  211, 133, 230, 220, 105, 92,  41,  55,  46,
      245, 40,  244, 102, 143, 54,  65,  25,  63,  161, 1,   216, 80,  73,  209, 76,  132, 187,
      208, 89,  18,  169, 200, 196, 135, 130, 116, 188, 159, 86,  164, 100, 109, 198, 173, 186,
      3,   64,  52,  217, 226, 250, 124, 123, 5,   202, 38,  147, 118, 126, 255, 82,  85,  212,
      207, 206, 59,  227, 47,  16,  58,  17,  182, 189, 28,  42,  223, 183, 170, 213, 119, 248,
      152, 2,   44,  154, 163, 70,  221, 153, 101, 155, 167, 43,  172, 9,   129, 22,  39,  253,
      19,  98,  108, 110, 79,  113, 224, 232, 178, 185, 112, 104, 218, 246, 97,  228, 251, 34,
      242, 193, 238, 210, 144, 12,  191, 179, 162, 241, 81,  51,  145, 235, 249, 14,  239, 107,
      49,  192, 214, 31,  181, 199, 106, 157, 184, 84,  204, 176, 115, 121, 50,  45,  127, 4,
      150, 254, 138, 236, 205, 93,  222, 114, 67,  29,  24,  72,  243, 141, 128, 195, 78,  66,
      215, 61,  156, 180};
  return p;
}

double fade_ref(double t) { return t * t * t * (t * (t * 6 - 15) + 10); }

double grad_ref(int hash, double x, double y, double z) {
  const int h = hash & 15;
  const double u = h < 8 ? x : y;
  const double v = h < 4 ? y : (h == 12 || h == 14) ? x : z;
  return ((h & 1) == 0 ? u : -u) + ((h & 2) == 0 ? v : -v);
}

namespace {
double lerp(double t, double a, double b) { return a + t * (b - a); }
}  // namespace

double noise3_ref(double x, double y, double z) {
  const auto& perm = permutation();
  auto p = [&](int i) { return static_cast<int>(perm[static_cast<size_t>(i & 255)]); };  // doubled table
  const double fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
  // floor(x) & 255 on the exact integer (two's complement: also right for negative cells).
  const int X = static_cast<int>(static_cast<int64_t>(fx) & 255);
  const int Y = static_cast<int>(static_cast<int64_t>(fy) & 255);
  const int Z = static_cast<int>(static_cast<int64_t>(fz) & 255);
  x -= fx;
  y -= fy;
  z -= fz;
  const double u = fade_ref(x), v = fade_ref(y), w = fade_ref(z);
  const int A = p(X) + Y, AA = p(A) + Z, AB = p(A + 1) + Z;
  const int B = p(X + 1) + Y, BA = p(B) + Z, BB = p(B + 1) + Z;
  return lerp(w,
              lerp(v, lerp(u, grad_ref(p(AA), x, y, z), grad_ref(p(BA), x - 1, y, z)),
                   lerp(u, grad_ref(p(AB), x, y - 1, z), grad_ref(p(BB), x - 1, y - 1, z))),
              lerp(v, lerp(u, grad_ref(p(AA + 1), x, y, z - 1), grad_ref(p(BA + 1), x - 1, y, z - 1)),
                   lerp(u, grad_ref(p(AB + 1), x, y - 1, z - 1), grad_ref(p(BB + 1), x - 1, y - 1, z - 1))));
}

double noise2_ref(double x, double y) { return noise3_ref(x, y, 0.0); }

double octave_amplitude_sum(int octaves) { return 2.0 - std::ldexp(1.0, 1 - octaves); }

double fbm_ref(int dims, int octaves, double x, double y, double z) {
  double p = 0;
  for (int i = 0; i < octaves; ++i) {
    const double s = std::ldexp(1.0, i);
    p += (dims == 2 ? noise2_ref(s * x, s * y) : noise3_ref(s * x, s * y, s * z)) * std::ldexp(1.0, -i);
  }
  const double bound = (dims == 2 ? kBound2 : kBound3) * octave_amplitude_sum(octaves);
  return (p / bound + 1.0) / 2.0;
}

double worst_case_ref(int dims, double tx, double ty, double tz) {
  const double t[3] = {tx, ty, dims == 2 ? 0.0 : tz};
  double b = 0;
  for (int c = 0; c < (1 << dims); ++c) {
    double w = 1, sum = 0, mn = 2;
    for (int i = 0; i < dims; ++i) {
      const int ci = (c >> i) & 1;
      const double s = fade_ref(t[i]);
      w *= ci ? s : 1 - s;
      const double a = std::fabs(t[i] - ci);
      sum += a;
      mn = std::min(mn, a);
    }
    // Gradients have two non-zero components of magnitude 1: the worst is the two largest |d_i|.
    b += w * (dims == 2 ? sum : sum - mn);
  }
  return b;
}

}  // namespace tu::noise
