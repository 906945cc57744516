#include "noise/noise_fbm.hpp"

#include <algorithm>

namespace tu::noise {

int64_t fbm_sum(int dims, int64_t x, int64_t y, int64_t z) {
  int64_t acc = 0;
  for (int i = 0; i < fmt::kNoiseOctaves; ++i) {
    const Axis a[3] = {split(x, i), split(y, i), split(z, i)};
    acc += static_cast<int64_t>(noise_fx(dims, a).raw()) * (int64_t(1) << (fmt::kNoiseOctaves - 1 - i));
  }
  return acc;
}

uint32_t normalise_code(int64_t acc, int64_t c) {
  constexpr int kProdF = kAccF + fmt::kNoiseNormF;
  constexpr int kDrop = kProdF - fmt::kNoiseTF;
  // + 1/2 (the [0,1] offset) + half an output ULP (round half up), then floor.
  const int64_t p = acc * c + (int64_t(1) << (kProdF - 1)) + (int64_t(1) << (kDrop - 1));
  const int64_t q = p >> kDrop;
  return static_cast<uint32_t>(std::clamp<int64_t>(q, 0, int64_t(1) << fmt::kNoiseTF));
}

uint32_t fbm_normalise(int dims, int64_t acc) {
  return normalise_code(acc, dims == 2 ? fmt::kNoiseNorm2 : fmt::kNoiseNorm3);
}

uint32_t fbm_fx(int dims, int64_t x, int64_t y, int64_t z) {
  return fbm_normalise(dims, fbm_sum(dims, x, y, dims == 2 ? 0 : z));
}

}  // namespace tu::noise
