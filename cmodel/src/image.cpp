#include "texunit/image.hpp"

#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <system_error>

// Every format stb_image reads (PNG, JPEG, BMP, TGA, GIF first frame, PSD composite, HDR tone
// mapped to 8 bits, PIC, PNM); the size is checked from the header before decoding (kMaxSide).
#define STB_IMAGE_IMPLEMENTATION
#define STBI_FAILURE_USERMSG
#define STBI_MAX_DIMENSIONS 65536
#include <stb/stb_image.h>
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

namespace tu::img {

namespace {
using StbData = std::unique_ptr<stbi_uc, void (*)(void*)>;

// Loads an image with `want` channels (0: as stored); n receives the stored channel count.
StbData load(const std::string& path, int want, int& w, int& h, int& n) {
  if (!std::filesystem::is_regular_file(path))
    throw std::runtime_error(path + ": no such file");
  // The header first: a too large image is refused before its pixels are decoded.
  if (!stbi_info(path.c_str(), &w, &h, &n))
    throw std::runtime_error(path + ": cannot read the image (" + std::string(stbi_failure_reason()) + ")");
  if (w > kMaxSide || h > kMaxSide)
    throw std::runtime_error(path + ": the image is " + std::to_string(w) + "x" + std::to_string(h) +
                             " pixels; at most " + std::to_string(kMaxSide) + " per side are read");
  StbData data(stbi_load(path.c_str(), &w, &h, &n, want), stbi_image_free);
  if (!data)
    throw std::runtime_error(path + ": cannot read the image (" + std::string(stbi_failure_reason()) +
                             ")");
  if (w <= 0 || h <= 0 || n <= 0) throw std::runtime_error(path + ": empty image");
  return data;
}

void write_png(const std::string& path, int w, int h, int channels, const void* data,
               size_t size) {
  if (w <= 0 || h <= 0 || size != static_cast<size_t>(w) * static_cast<size_t>(h))
    throw std::runtime_error(path + ": refusing to write an empty or inconsistent image");
  const std::string tmp = path + ".tmp";
  if (!stbi_write_png(tmp.c_str(), w, h, channels, data, w * channels)) {
    std::remove(tmp.c_str());
    throw std::runtime_error(path + ": cannot write PNG");
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::remove(tmp.c_str());
    throw std::runtime_error(path + ": cannot write PNG (" + ec.message() + ")");
  }
}
}  // namespace

Gray8 read_png_channel0(const std::string& path) {
  int w = 0, h = 0, n = 0;
  const StbData data = load(path, 0, w, h, n);
  Gray8 im(w, h);
  for (size_t i = 0; i < im.px.size(); ++i) im.px[i] = data.get()[i * static_cast<size_t>(n)];
  return im;
}

void write_png_gray(const std::string& path, const Gray8& im) {
  write_png(path, im.width, im.height, 1, im.px.data(), im.px.size());
}

Rgba8Image read_png_rgba(const std::string& path) {
  int w = 0, h = 0, n = 0;
  const StbData data = load(path, 4, w, h, n);
  Rgba8Image im(w, h);
  for (size_t i = 0; i < im.px.size(); ++i) {
    const stbi_uc* p = data.get() + 4 * i;
    im.px[i] = {p[0], p[1], p[2], p[3]};
  }
  return im;
}

void write_png_rgba(const std::string& path, const Rgba8Image& im) {
  static_assert(sizeof(Rgba8) == 4, "Rgba8 must be packed RGBA");
  write_png(path, im.width, im.height, 4, im.px.data(), im.px.size());
}

}  // namespace tu::img
