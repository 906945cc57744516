#include "texunit/texel_cache.hpp"

#include <algorithm>
#include <bit>
#include <stdexcept>
#include <string>

namespace tu::sysmodel {

namespace {
constexpr uint64_t kEmpty = ~uint64_t(0);
constexpr uint32_t kTexelBytes = 4;  // RGBA8
}  // namespace

TexelCache::TexelCache(const CacheConfig& c) {
  if (!std::has_single_bit(c.size_bytes) || !std::has_single_bit(c.line_bytes) || !std::has_single_bit(c.ways) ||
      c.line_bytes < kTexelBytes || uint64_t(c.line_bytes) * c.ways > c.size_bytes)
    throw std::invalid_argument("texel cache: size " + std::to_string(c.size_bytes) + " B, line " +
                                std::to_string(c.line_bytes) + " B, " + std::to_string(c.ways) +
                                " ways: each must be a power of two, line >= 4 B and line x ways <= size");
  line_shift_ = static_cast<uint32_t>(std::countr_zero(c.line_bytes / kTexelBytes));
  ways_ = c.ways;
  sets_ = c.size_bytes / (c.line_bytes * c.ways);
  tags_.assign(size_t(sets_) * ways_, kEmpty);
}

bool TexelCache::read(uint64_t texel_addr) {
  const uint64_t line = texel_addr >> line_shift_;
  const auto set = tags_.begin() + static_cast<std::ptrdiff_t>((line & (sets_ - 1)) * ways_);
  const auto end = set + ways_;
  auto it = std::find(set, end, line);
  const bool hit = it != end;
  if (!hit) it = end - 1;  // the least recently used way (or an empty one) is replaced
  std::rotate(set, it, it + 1);  // to the front: most recently used
  *set = line;
  return hit;
}

CacheStats run_cache(const render::Frame& f, const CacheConfig& c) {
  TexelCache cache(c);
  CacheStats st;
  st.misses_per_pixel.reserve(f.pixels.size());
  for (const auto& p : f.pixels) {
    uint32_t miss = 0;
    for (const uint64_t a : p.texel_addrs) miss += cache.read(a) ? 0 : 1;
    st.reads += p.texel_addrs.size();
    st.misses += miss;
    st.misses_per_pixel.push_back(miss);
  }
  st.hits = st.reads - st.misses;
  st.memory_bytes = st.misses * c.line_bytes;
  return st;
}

}  // namespace tu::sysmodel
