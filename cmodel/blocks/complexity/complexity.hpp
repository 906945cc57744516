// Complexity map (seed-000 note §1.2): an offline/host preprocessing step, not an RTL block.
//
//   G  = Sobel 3x3 magnitude of the 8-bit height codes (correlation with S_x, S_y; border
//        reflect-101, as cv2.Sobel), computed exactly in integers: Gx, Gy in [-1020, 1020],
//        G^2 = Gx^2 + Gy^2 < 2^21;
//   C  = G / max(G) over the whole image; a flat map (max = 0) gives C = 0 everywhere (no NaN);
//   C' = max filter of C over a dilate x dilate square (default 11 = cv2.dilate 3x3, 5 iterations);
//        pixels outside the image are ignored. Done on the integer G^2 (the max filter commutes
//        with the monotonic map G^2 -> C), so it is exact;
//   k  = round_half_even((levels-1) * C'^gamma)   (double; C' = sqrt(G'^2 / max^2));
//   code = floor(255 * k / (levels-1))           (exact integer; = the note's float32 truncation
//        for 24 levels: 0, 11, 22, ..., 121, 133, ..., 243, 255).
#pragma once

#include <cstdint>
#include <vector>

#include "texunit/image.hpp"

namespace tu::complexity {

struct Params {
  int levels = 24;      // quantisation levels, 2..256
  double gamma = 0.8;   // exponent, > 0
  int dilate = 11;      // odd square max-filter size, 1 = none
};

// Throws std::invalid_argument naming the field when a parameter is out of range.
void validate(const Params& p);

// Sobel squared magnitude Gx^2 + Gy^2 per pixel (integer, height codes in 0..255).
std::vector<int32_t> sobel_sq(const img::Gray8& h);
// Signed Sobel components at (x, y) (reflect-101 border), exposed for tests.
void sobel_at(const img::Gray8& h, int x, int y, int& gx, int& gy);

// Square max filter of odd size k over a w x h integer map (outside pixels ignored).
std::vector<int32_t> max_filter(const std::vector<int32_t>& v, int w, int h, int k);

// Output code of quantisation level k (0..levels-1).
uint8_t level_code(int k, int levels);

// Level (0..levels-1) per pixel, and the 8-bit complexity map.
std::vector<int> levels(const img::Gray8& height, const Params& p);
img::Gray8 complexity_map(const img::Gray8& height, const Params& p = {});

}  // namespace tu::complexity
