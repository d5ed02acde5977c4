// How busy the HTTP workers are, shared by the worker pool (which updates it) and the
// connections (which read it): workers are scarce when connections wait for one (queued and no
// idle worker to take them), or when
// fewer than `reserve` workers are left below the cap. While they are scarce, connections
// that hold a worker without a request in progress let it go (docs/deployment.md "Limits in
// the server"): idle keep-alive connections close, answers carry `Connection: close`, and a
// request head still incomplete after a short grace is cut. Thread-safe (atomics only).
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>

namespace clearsky::server {

class WorkerLoad {
 public:
  explicit WorkerLoad(unsigned max_workers)
      : max_workers_(std::max(1u, max_workers)), reserve_(std::max(2u, max_workers_ / 16)) {}

  unsigned max_workers() const { return max_workers_; }
  unsigned reserve() const { return reserve_; }
  unsigned busy() const { return busy_.load(std::memory_order_relaxed); }
  std::size_t queued() const { return queued_.load(std::memory_order_relaxed); }

  bool scarce() const { return queued() > 0 || busy() + reserve_ >= max_workers_; }

  // Updated by the pool.
  void set(unsigned busy, std::size_t queued) {
    busy_.store(busy, std::memory_order_relaxed);
    queued_.store(queued, std::memory_order_relaxed);
  }

 private:
  unsigned max_workers_;
  unsigned reserve_;
  std::atomic<unsigned> busy_{0};
  std::atomic<std::size_t> queued_{0};
};

}  // namespace clearsky::server
