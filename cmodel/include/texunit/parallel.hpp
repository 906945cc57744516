// Work split over threads with results independent of the thread count: every index runs once,
// writes only its own slot, and callers combine the slots in index order, so one thread and N
// threads produce the same bits (tests: RenderCmodel.ThreadsBitIdentical, Vectors.ThreadsBitIdentical).
#pragma once

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace tu::par {

// Every hardware thread (at least 1): the default of `--threads`.
inline int hardware_threads() {
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}
// n <= 0 means "every hardware thread".
inline int resolve_threads(int n) { return n > 0 ? n : hardware_threads(); }

// fn(i) for every i in [0, n) on up to `threads` threads (<= 0: all), indices handed out in
// increasing order from a shared counter (cheap dynamic balance for uneven rows). After an
// exception no new index starts; the one of the lowest index is rethrown once every thread has
// stopped: every lower index was already handed out, so it is the exception one thread throws.
template <class F>
void for_each_index(int n, int threads, F&& fn) {
  const int t = std::min(resolve_threads(threads), std::max(n, 1));
  if (t <= 1) {
    for (int i = 0; i < n; ++i) fn(i);
    return;
  }
  std::atomic<int> next{0};
  std::exception_ptr error;
  int error_index = n;
  std::mutex error_mutex;
  auto worker = [&] {
    for (int i; (i = next.fetch_add(1)) < n;) {
      try {
        fn(i);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(error_mutex);
        if (i < error_index) error = std::current_exception(), error_index = i;
        next.store(n);  // stop handing out work
      }
    }
  };
  std::vector<std::thread> pool;
  for (int k = 1; k < t; ++k) pool.emplace_back(worker);
  worker();
  for (auto& th : pool) th.join();
  if (error) std::rethrow_exception(error);
}

// Appends the per-index vectors in index order.
template <class T>
std::vector<T> concat(std::vector<std::vector<T>>&& parts) {
  size_t n = 0;
  for (const auto& p : parts) n += p.size();
  std::vector<T> out;
  out.reserve(n);
  for (auto& p : parts) out.insert(out.end(), std::make_move_iterator(p.begin()), std::make_move_iterator(p.end()));
  return out;
}

}  // namespace tu::par
