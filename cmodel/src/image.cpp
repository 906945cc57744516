#include "texunit/image.hpp"

#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <system_error>

#include "texunit/output.hpp"

// Every format stb_image reads (PNG, JPEG, BMP, TGA, GIF first frame, PSD composite, HDR tone
// mapped to 8 bits, PIC, PNM); the size is checked from the header before decoding (kMaxSide).
#define STB_IMAGE_IMPLEMENTATION
#define STBI_FAILURE_USERMSG
#define STBI_MAX_DIMENSIONS 65536
#include <stb/stb_image.h>
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_WRITE_NO_STDIO  // files are written by texunit/output.hpp only (encode_png)
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

// The PNG bytes in memory (stbi_write_png's encoder, which also builds the whole file in memory
// before writing it): the file is then written by the checked output path, not by stb's fwrite,
// whose errors stb does not report.
std::string encode_png(const std::string& path, int w, int h, int channels, const void* data, size_t size) {
  if (w <= 0 || h <= 0 || size != static_cast<size_t>(w) * static_cast<size_t>(h))
    throw std::runtime_error(path + ": refusing to write an empty or inconsistent image");
  std::string bytes;
  const auto append = [](void* ctx, void* p, int n) { static_cast<std::string*>(ctx)->append(static_cast<const char*>(p), static_cast<size_t>(n)); };
  if (!stbi_write_png_to_func(append, &bytes, w, h, channels, data, w * channels))
    throw std::runtime_error(path + ": cannot encode the PNG");
  return bytes;
}
}  // namespace

Gray8 read_png_channel0(const std::string& path) {
  int w = 0, h = 0, n = 0;
  const StbData data = load(path, 0, w, h, n);
  Gray8 im(w, h);
  for (size_t i = 0; i < im.px.size(); ++i) im.px[i] = data.get()[i * static_cast<size_t>(n)];
  return im;
}

std::string png_gray(const Gray8& im, const std::string& path) {
  return encode_png(path, im.width, im.height, 1, im.px.data(), im.px.size());
}

void write_png_gray(const std::string& path, const Gray8& im) { out::write_atomic(path, png_gray(im, path)); }

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

std::string png_rgba(const Rgba8Image& im, const std::string& path) {
  static_assert(sizeof(Rgba8) == 4, "Rgba8 must be packed RGBA");
  return encode_png(path, im.width, im.height, 4, im.px.data(), im.px.size());
}

void write_png_rgba(const std::string& path, const Rgba8Image& im) { out::write_atomic(path, png_rgba(im, path)); }

}  // namespace tu::img
