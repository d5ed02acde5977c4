// A bounded, shared cache of immutable per-sun states (docs/architecture.md "Precomputation and
// caches": per-sun preparation returns an immutable state; docs/conventions.md "Immutable shared
// state": never a mutable cache inside a const method without synchronisation). Models whose
// precomputation depends on the sun (Haber, Nishita96) key their states by (model configuration,
// sun zenith bucket) and ask this cache:
//  - single flight: concurrent requests for a key that is being built wait for that one build
//    instead of starting their own;
//  - bounded: at most `capacity` finished states, and at most `max_bytes` bytes of them (a
//    state's memory_bytes(), sizeof(State) for a type without one), are kept; the least
//    recently used is dropped first (holders of a dropped state keep it alive through their
//    shared_ptr). The state just built is kept even when it alone is above max_bytes: its
//    requester is using it, and dropping it would rebuild it on every request;
//  - a build that throws is not cached: its waiters receive the exception and the next
//    request builds again (a cancelled build thus reaches every request waiting on it).
// Thread-safety: every member function may be called concurrently.
#pragma once

#include <cmath>
#include <concepts>
#include <cstddef>
#include <functional>
#include <future>
#include <limits>
#include <list>
#include <memory>
#include <mutex>
#include <numbers>
#include <string>
#include <unordered_map>
#include <utility>

namespace clearsky {

struct SunStateCacheStats {
  std::size_t hits = 0;    // served from a finished or in-flight entry
  std::size_t builds = 0;  // builder calls
  std::size_t evictions = 0;
  std::size_t bytes = 0;  // of the finished states kept
};

template <class State>
class SunStateCache {
 public:
  using Pointer = std::shared_ptr<const State>;

  explicit SunStateCache(std::size_t capacity,
                         std::size_t max_bytes = std::numeric_limits<std::size_t>::max())
      : capacity_(capacity < 1 ? 1 : capacity), max_bytes_(max_bytes) {}
  SunStateCache(const SunStateCache&) = delete;
  SunStateCache& operator=(const SunStateCache&) = delete;

  // The state of `key`, built by `build` (outside the lock) when no request has built or is
  // building it. Rethrows the build's exception. keep = false (PrecomputeContext::keep_sun_state:
  // the server's background pass, which fills the disk cache) neither keeps a state it builds
  // once built (callers that joined the build meanwhile still receive it) nor makes a kept one
  // more recently used.
  Pointer get_or_build(const std::string& key, const std::function<Pointer()>& build,
                       bool keep = true) {
    std::unique_lock lock(mutex_);
    if (auto it = entries_.find(key); it != entries_.end()) {
      ++stats_.hits;
      if (keep) lru_.splice(lru_.begin(), lru_, it->second.position);
      std::shared_future<Pointer> future = it->second.future;
      lock.unlock();
      return future.get();
    }
    std::promise<Pointer> promise;
    lru_.push_front(key);
    entries_.emplace(key, Entry{promise.get_future().share(), lru_.begin(), false, 0});
    ++stats_.builds;
    lock.unlock();

    Pointer state;
    try {
      state = build();
    } catch (...) {
      promise.set_exception(std::current_exception());
      lock.lock();
      if (auto it = entries_.find(key); it != entries_.end()) {
        lru_.erase(it->second.position);
        entries_.erase(it);
      }
      throw;
    }
    promise.set_value(state);
    const std::size_t bytes = bytes_of(state);
    lock.lock();
    if (auto it = entries_.find(key); it != entries_.end() && !keep) {
      lru_.erase(it->second.position);
      entries_.erase(it);
      return state;
    }
    if (auto it = entries_.find(key); it != entries_.end()) {
      it->second.ready = true;
      it->second.bytes = bytes;
      stats_.bytes += bytes;
    }
    evict_locked(key);
    return state;
  }

  std::size_t size() const {
    std::lock_guard lock(mutex_);
    return entries_.size();
  }
  std::size_t capacity() const { return capacity_; }
  std::size_t max_bytes() const { return max_bytes_; }
  SunStateCacheStats stats() const {
    std::lock_guard lock(mutex_);
    return stats_;
  }

 private:
  struct Entry {
    std::shared_future<Pointer> future;
    std::list<std::string>::iterator position;
    bool ready;
    std::size_t bytes;  // counted in stats_.bytes once ready
  };

  static std::size_t bytes_of(const Pointer& state) {
    if (!state) return 0;
    if constexpr (requires(const State& s) {
                    { s.memory_bytes() } -> std::convertible_to<std::size_t>;
                  }) {
      return state->memory_bytes();
    } else {
      return sizeof(State);
    }
  }

  // Drops the least recently used finished entries beyond capacity or max_bytes; entries
  // being built are never dropped (their requesters are waiting on them), nor `keep` (the
  // state just built).
  void evict_locked(const std::string& keep) {
    auto it = lru_.end();
    while ((entries_.size() > capacity_ || stats_.bytes > max_bytes_) && it != lru_.begin()) {
      --it;
      auto entry = entries_.find(*it);
      if (entry != entries_.end() && entry->second.ready && entry->first != keep) {
        stats_.bytes -= entry->second.bytes;
        entries_.erase(entry);
        it = lru_.erase(it);
        ++stats_.evictions;
      }
    }
  }

  const std::size_t capacity_;
  const std::size_t max_bytes_;
  mutable std::mutex mutex_;
  std::list<std::string> lru_;  // most recently used first
  std::unordered_map<std::string, Entry> entries_;
  SunStateCacheStats stats_;
};

// The sun zenith a per-sun state is built for: the centre of its bucket of width
// `bucket_width_rad` (buckets centred on multiples of the width), or the zenith itself when
// the width is 0.
inline double sun_zenith_bucket_centre(double sun_zenith_rad, double bucket_width_rad) {
  if (!(bucket_width_rad > 0.0)) return sun_zenith_rad;
  const double centre = std::round(sun_zenith_rad / bucket_width_rad) * bucket_width_rad;
  return centre < 0.0 ? 0.0 : (centre > std::numbers::pi ? std::numbers::pi : centre);
}

}  // namespace clearsky
