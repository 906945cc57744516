// `--shard K/N` (vectors, cosim, report): a deterministic split of one run into N parts that an
// external scheduler (GNU parallel, a Slurm array job) runs anywhere; `texunit merge` combines the
// parts' JSON. Shard K (0 <= K < N) of T items is the contiguous range [floor(K*T/N),
// floor((K+1)*T/N)): the N ranges tile [0, T) in order, so concatenating the shards' items in K
// order gives the unsharded run's items (test: tools/texunit/shard_test.sh).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>

namespace tu {

struct Shard {
  uint64_t k = 0, n = 1;  // the whole run by default
  bool whole() const { return n == 1; }
  // [first, last) of T items; 128-bit product: K*T overflows 64 bits for T near 2^64.
  std::pair<uint64_t, uint64_t> range(uint64_t total) const {
    const auto at = [&](uint64_t i) {
      return static_cast<uint64_t>(static_cast<unsigned __int128>(i) * total / n);
    };
    return {at(k), at(k + 1)};
  }
  // Item i of T: is it in this shard? (round-robin over groups uses `i % n == k` instead)
  bool owns_round_robin(uint64_t i) const { return i % n == k; }
  std::string str() const { return std::to_string(k) + "/" + std::to_string(n); }

  // "K/N" with decimal digits only, 0 <= K < N <= 2^20; throws std::invalid_argument naming the text.
  static Shard parse(const std::string& s) {
    const auto slash = s.find('/');
    const auto digits = [](const std::string& t) {
      return !t.empty() && t.size() <= 7 && t.find_first_not_of("0123456789") == std::string::npos;
    };
    if (slash == std::string::npos || !digits(s.substr(0, slash)) || !digits(s.substr(slash + 1)))
      throw std::invalid_argument("shard '" + s + "' is not K/N (two decimal integers, 0 <= K < N)");
    Shard r;
    r.k = std::stoull(s.substr(0, slash));
    r.n = std::stoull(s.substr(slash + 1));
    if (r.n < 1 || r.n > (1u << 20) || r.k >= r.n)
      throw std::invalid_argument("shard '" + s + "': need 0 <= K < N <= 1048576");
    return r;
  }
};

}  // namespace tu
