// Data-parallel loops for precomputations: the index range [0, count) split over worker
// threads (all cores by default), each index visited exactly once. Exceptions thrown by the
// body (including PrecomputeCancelled) stop the remaining work and are rethrown to the caller.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace clearsky {

inline unsigned worker_count(unsigned requested) {
  if (requested > 0) return requested;
  const unsigned hw = std::thread::hardware_concurrency();
  return hw == 0 ? 1u : hw;
}

// Calls body(i) for every i in [0, count), dynamically scheduled in chunks of `grain`.
inline void parallel_for(std::size_t count, const std::function<void(std::size_t)>& body,
                         unsigned threads = 0, std::size_t grain = 1) {
  const unsigned n_threads = static_cast<unsigned>(std::min<std::size_t>(
      worker_count(threads), (count + grain - 1) / std::max<std::size_t>(grain, 1)));
  if (n_threads <= 1) {
    for (std::size_t i = 0; i < count; ++i) body(i);
    return;
  }
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  std::mutex error_mutex;
  auto worker = [&] {
    try {
      while (!failed.load(std::memory_order_relaxed)) {
        const std::size_t begin = next.fetch_add(grain);
        if (begin >= count) break;
        const std::size_t end = std::min(count, begin + grain);
        for (std::size_t i = begin; i < end; ++i) body(i);
      }
    } catch (...) {
      std::lock_guard lock(error_mutex);
      if (!error) error = std::current_exception();
      failed = true;
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(n_threads - 1);
  for (unsigned t = 1; t < n_threads; ++t) pool.emplace_back(worker);
  worker();
  for (auto& thread : pool) thread.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace clearsky
