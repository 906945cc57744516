#include "texunit/image.hpp"

#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <system_error>

#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_FAILURE_USERMSG
#include <stb/stb_image.h>
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

namespace tu::img {

Gray8 read_png_channel0(const std::string& path) {
  if (!std::filesystem::is_regular_file(path))
    throw std::runtime_error(path + ": no such file");
  int w = 0, h = 0, n = 0;
  std::unique_ptr<stbi_uc, void (*)(void*)> data(stbi_load(path.c_str(), &w, &h, &n, 0),
                                                stbi_image_free);
  if (!data)
    throw std::runtime_error(path + ": cannot read PNG (" + std::string(stbi_failure_reason()) +
                             ")");
  if (w <= 0 || h <= 0 || n <= 0) throw std::runtime_error(path + ": empty image");
  Gray8 im(w, h);
  for (size_t i = 0; i < im.px.size(); ++i) im.px[i] = data.get()[i * static_cast<size_t>(n)];
  return im;
}

void write_png_gray(const std::string& path, const Gray8& im) {
  if (im.width <= 0 || im.height <= 0 ||
      im.px.size() != static_cast<size_t>(im.width) * static_cast<size_t>(im.height))
    throw std::runtime_error(path + ": refusing to write an empty or inconsistent image");
  const std::string tmp = path + ".tmp";
  if (!stbi_write_png(tmp.c_str(), im.width, im.height, 1, im.px.data(), im.width)) {
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

}  // namespace tu::img
