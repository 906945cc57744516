// The synchronous-read RAM of the co-simulation (the texel and depth RAMs a block reads through
// its texel or depth port; in silicon a texture cache), modelled in C++ and attached by the
// harness to a block's read ports, so that the block itself is the Verilator top (no simulation
// wrapper repeating its port list):
//   SyncReadRam    the memory (a preloaded image, shared by every run) and one read register per
//                  port: on each rising clock edge a port whose enable is high latches the word at
//                  its address (0 at or above `words`, and above the image), and the block sees that
//                  word from the edge on (1-cycle latency); the register holds when not enabled.
//                  SyncReadRam64: the same with 64-bit words (the BC1 texel RAM: a block a word).
//   attach_ram()   puts one RAM on a Verilated block's req / addr / data ports (Env hooks of the
//                  Harness: sample before the edge, drive after it).
// The harness preloads the image directly: no RAM write port passes through the RTL and no clock
// is spent loading.
#pragma once

#include <verilated.h>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

#include "harness.hpp"
#include "texunit/formats.hpp"

namespace tu::cosim {

// Word: the stored word (uint32_t, or uint64_t for the BC1 texel RAM's 64-bit blocks); 32-bit
// users keep 32-bit words (BasicSyncReadRam<uint32_t> is SyncReadRam, as fast as before).
template <class Word>
class BasicSyncReadRam {
  static_assert(std::is_same_v<Word, uint32_t> || std::is_same_v<Word, uint64_t>, "32- or 64-bit words");
  static constexpr int kWordBits = 8 * static_cast<int>(sizeof(Word));

 public:
  using Image = std::vector<Word>;  // word i at address i (from address 0)

  // words (the RAM's size), ports (read ports), addr_w and data_w (a port's address and data
  // width: a data port narrower than the word gets a word's low bits).
  BasicSyncReadRam(std::shared_ptr<const Image> image, uint64_t words, int ports = 1, int addr_w = fmt::kTexAddrW,
                   int data_w = kWordBits)
      : image_(std::move(image)),
        size_(std::min<uint64_t>(words, image_->size())),
        addr_w_(addr_w),
        data_w_(data_w),
        q_(static_cast<size_t>(ports), 0) {}

  int ports() const { return static_cast<int>(q_.size()); }
  int addr_w() const { return addr_w_; }
  int data_w() const { return data_w_; }
  // Rising clock edge at port p: its enable and address as the block drives them before the edge.
  void clock(int p, bool en, uint64_t addr) {
    if (en) q_[static_cast<size_t>(p)] = addr < size_ ? (*image_)[addr] : 0;  // unloaded words are 0
  }
  // Port p's read register (the data the block sees after the edge).
  Word q(int p) const {
    const Word w = q_[static_cast<size_t>(p)];
    return data_w_ >= kWordBits ? w : w & ((Word(1) << data_w_) - 1);
  }

 private:
  std::shared_ptr<const Image> image_;
  uint64_t size_;  // words readable (the rest read 0)
  int addr_w_, data_w_;
  std::vector<Word> q_;
};
using SyncReadRam = BasicSyncReadRam<uint32_t>;
using SyncReadRam64 = BasicSyncReadRam<uint64_t>;

// Bits [lo, lo + w) of a Verilated port (w <= 32, or w = 64 at a multiple of 32), whatever its C++
// type (CData .. QData, or VlWide<N> above 64 bits).
template <class T>
uint64_t port_bits(const T& s, unsigned lo, unsigned w) {
  const uint64_t mask = w >= 64 ? ~uint64_t(0) : (uint64_t(1) << w) - 1;
  if constexpr (std::is_integral_v<T>) {
    return (static_cast<uint64_t>(s) >> lo) & mask;
  } else {
    const unsigned i = lo / 32, sh = lo % 32;
    uint64_t v = s[i] >> sh;
    if (sh + w > 32) v |= static_cast<uint64_t>(s[i + 1]) << (32 - sh);
    return v & mask;
  }
}
template <class T>
void set_port_bits(T& s, unsigned lo, unsigned w, uint64_t v) {
  const uint64_t mask = w >= 64 ? ~uint64_t(0) : (uint64_t(1) << w) - 1;
  if constexpr (std::is_integral_v<T>) {
    s = static_cast<T>((static_cast<uint64_t>(s) & ~(mask << lo)) | ((v & mask) << lo));
  } else {
    for (unsigned b = 0; b < w;) {  // word by word
      const unsigned k = lo + b, i = k / 32, sh = k % 32, n = std::min(w - b, 32 - sh);
      const uint32_t m = (n == 32 ? ~uint32_t(0) : ((uint32_t(1) << n) - 1)) << sh;
      s[i] = (s[i] & ~m) | (static_cast<uint32_t>((v >> b) << sh) & m);
      b += n;
    }
  }
}

// Attaches `ram` to the block's read ports: req(d) (one enable bit per port), addr(d) (port p at
// bits [p * AddrW, +AddrW)), data(d) (port p at [p * DataW, +DataW)); each accessor returns the
// Verilated port, e.g. [](V& d) -> auto& { return d.tex_addr_o; }. A fresh RAM state per run:
// call inside the harness's Env factory.
template <class V, class Word, class Req, class Addr, class Data>
void attach_ram(Env<V>& env, std::shared_ptr<BasicSyncReadRam<Word>> ram, Req req, Addr addr, Data data) {
  env.edge.push_back([=](V& d) {
    for (int p = 0; p < ram->ports(); ++p)
      ram->clock(p, port_bits(req(d), unsigned(p), 1) != 0,
                 port_bits(addr(d), unsigned(p * ram->addr_w()), unsigned(ram->addr_w())));
  });
  env.update.push_back([=](V& d) {
    for (int p = 0; p < ram->ports(); ++p)
      set_port_bits(data(d), unsigned(p * ram->data_w()), unsigned(ram->data_w()), ram->q(p));
  });
}

}  // namespace tu::cosim
