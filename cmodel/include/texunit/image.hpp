// Small image module: 8-bit grey images and PNG I/O (stb_image / stb_image_write), shared by the
// complexity-map tool and, later, the texture unit's texture loader.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace tu::img {

// Row-major 8-bit single-channel image.
struct Gray8 {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> px;  // width * height
  Gray8() = default;
  Gray8(int w, int h, uint8_t fill = 0)
      : width(w), height(h), px(static_cast<size_t>(w) * static_cast<size_t>(h), fill) {}
  uint8_t& at(int x, int y) { return px[static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)]; }
  uint8_t at(int x, int y) const { return px[static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)]; }
};

// Row-major RGBA8 image (textures, rendered frames, error heat maps).
struct Rgba8 {
  uint8_t r = 0, g = 0, b = 0, a = 255;
  friend bool operator==(const Rgba8&, const Rgba8&) = default;
};
struct Rgba8Image {
  int width = 0;
  int height = 0;
  std::vector<Rgba8> px;  // width * height
  Rgba8Image() = default;
  Rgba8Image(int w, int h, Rgba8 fill = {})
      : width(w), height(h), px(static_cast<size_t>(w) * static_cast<size_t>(h), fill) {}
  Rgba8& at(int x, int y) { return px[static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)]; }
  const Rgba8& at(int x, int y) const { return px[static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)]; }
};

// Largest side read_png_* accept (checked from the file's header before decoding): the largest
// texture a scene can declare (builtin size 4096); an RGBA image of that size takes 64 MB.
inline constexpr int kMaxSide = 4096;

// The readers take every format stb_image reads (PNG, JPEG, BMP, TGA, GIF (first frame), PSD,
// HDR, PIC, PNM), despite their names.
// Reads any 8/16-bit PNG as RGBA8 (grey and grey+alpha are expanded, missing alpha is 255).
// Throws std::runtime_error naming the file on a missing or malformed file.
Rgba8Image read_png_rgba(const std::string& path);
// Writes an RGBA8 PNG all or none (texunit/output.hpp: temporary file, every write checked, rename).
// Throws naming the file.
void write_png_rgba(const std::string& path, const Rgba8Image& im);
// The PNG file's bytes, for a writer that writes them through its own tu::out::Outputs (`path`:
// the file named in a message).
std::string png_rgba(const Rgba8Image& im, const std::string& path);

// Reads a PNG and returns its first colour channel (R; grey for grey images) as 8 bits
// (16-bit PNGs are reduced to 8 bits by stb_image: code16 >> 8). Throws std::runtime_error naming
// the file on a missing or malformed file.
Gray8 read_png_channel0(const std::string& path);

// Writes an 8-bit grey PNG all or none (texunit/output.hpp), so a failure (a full disk included)
// leaves no partial output. Throws std::runtime_error naming the file.
void write_png_gray(const std::string& path, const Gray8& im);
std::string png_gray(const Gray8& im, const std::string& path);

}  // namespace tu::img
