#include "noise/noise_core.hpp"

#include "noise/noise_fade.hpp"
#include "noise/noise_grad.hpp"
#include "noise/noise_hash.hpp"
#include "noise/noise_lerp.hpp"

namespace tu::noise {

static_assert(fmt::kNoiseTF == 16 && fmt::kNoiseLatW == 8, "split() slices a 24-bit lattice+fraction field");

Axis split(int64_t code, int octave) {
  const uint64_t shifted = static_cast<uint64_t>(code) << octave;  // 2^i x, low bits exact
  Axis a;
  a.cell = static_cast<uint32_t>((shifted >> fmt::kNoiseTF) & ((1u << fmt::kNoiseLatW) - 1));
  a.t = T::from_bits(shifted);
  return a;
}

Val noise_fx(int dims, const Axis a[3]) {
  const int corners = 1 << dims;
  S s[3];
  D d[3][2];  // offset of the point from the low (0) and high (1) corner on each axis
  for (int k = 0; k < 3; ++k) {
    const bool used = k < dims;
    const T t = used ? a[k].t : T();
    s[k] = fade(t);
    d[k][0] = t.as<D>();
    d[k][1] = (t - UFixed<1, 0>::from_raw(1)).as<D>();
  }
  const uint32_t Z = dims == 3 ? a[2].cell : 0;
  Val v[8];
  for (int c = 0; c < corners; ++c) {
    const uint32_t cx = c & 1, cy = (c >> 1) & 1, cz = (c >> 2) & 1;
    const uint32_t h = corner_hash(a[0].cell, a[1].cell, Z, cx, cy, cz);
    v[c] = grad(h, d[0][cx], d[1][cy], d[2][cz]).as<Val>();
  }
  // Lerp tree: x pairs (c, c+1), then y, then z; n halves each level.
  for (int k = 0, n = corners; k < dims; ++k, n /= 2)
    for (int c = 0; c < n / 2; ++c) v[c] = lerp(s[k], v[2 * c], v[2 * c + 1]);
  return v[0];
}

}  // namespace tu::noise
