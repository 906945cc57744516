// Texel cache of the system model (docs/systemc.md "Texel cache"): a set-associative, LRU,
// read-only cache in front of the texel memory, fed with the C model's texel reads in stream order
// (render::CmodelOptions::trace_texels). What it assumes: one RGBA8 texel = 4 bytes at its word
// address of the RTL's texel RAM layout (tu_texel_addr: levels one after another, row-major; each
// texture in its own 2^32-word space), lines of `line_bytes` consecutive bytes (a run of texels of
// one row), allocate on every miss, no prefetch; a miss fills one whole line from memory and, in
// the timing, stalls the filter engine `miss_penalty` clocks (a blocking cache: no hit under miss).
// The RTL keeps its single-cycle texel RAM; this is the what-if for a real memory.
#pragma once

#include <cstdint>
#include <vector>

#include "texunit/render.hpp"

namespace tu::sysmodel {

struct CacheConfig {
  uint32_t size_bytes = 16 * 1024;
  uint32_t line_bytes = 64;
  uint32_t ways = 4;
  uint32_t miss_penalty = 0;  // clocks per miss added to the filter engine (0: the ideal RAM)
};

struct CacheStats {
  uint64_t reads = 0, hits = 0, misses = 0;
  uint64_t memory_bytes = 0;  // misses x line_bytes
  std::vector<uint32_t> misses_per_pixel;  // frame order
  double hit_rate() const { return reads ? double(hits) / double(reads) : 0; }
};

// Throws std::invalid_argument for a geometry that is not powers of two or has fewer than one set.
class TexelCache {
 public:
  explicit TexelCache(const CacheConfig& c);
  bool read(uint64_t texel_addr);  // true: hit

 private:
  uint32_t line_shift_, sets_, ways_;
  std::vector<uint64_t> tags_;  // sets x ways, most recently used first; ~0: empty
};

// Every covered pixel's texel reads (frame rendered with trace_texels) through one cache.
CacheStats run_cache(const render::Frame& f, const CacheConfig& c);

}  // namespace tu::sysmodel
