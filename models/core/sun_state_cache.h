// A bounded, shared cache of immutable per-sun states (docs/architecture.md "Precomputation and
// caches": per-sun preparation returns an immutable state; docs/conventions.md "Immutable shared
// state": never a mutable cache inside a const method without synchronisation). Models whose
// precomputation depends on the sun (Haber, Nishita96) key their states by (model configuration,
// sun zenith bucket) and ask this cache:
//  - single flight: concurrent requests for a key that is being built wait for that one build
//    instead of starting their own;
//  - bounded: at most `capacity` finished states are kept, the least recently used is dropped
//    first (holders of a dropped state keep it alive through their shared_ptr);
//  - a build that throws is not cached: its waiters receive the exception and the next
//    request builds again (a cancelled build thus reaches every request waiting on it).
// Thread-safety: every member function may be called concurrently.
#pragma once

#include <cmath>
#include <cstddef>
#include <functional>
#include <future>
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
};

template <class State>
class SunStateCache {
 public:
  using Pointer = std::shared_ptr<const State>;

  explicit SunStateCache(std::size_t capacity) : capacity_(capacity < 1 ? 1 : capacity) {}
  SunStateCache(const SunStateCache&) = delete;
  SunStateCache& operator=(const SunStateCache&) = delete;

  // The state of `key`, built by `build` (outside the lock) when no request has built or is
  // building it. Rethrows the build's exception.
  Pointer get_or_build(const std::string& key, const std::function<Pointer()>& build) {
    std::unique_lock lock(mutex_);
    if (auto it = entries_.find(key); it != entries_.end()) {
      ++stats_.hits;
      lru_.splice(lru_.begin(), lru_, it->second.position);
      std::shared_future<Pointer> future = it->second.future;
      lock.unlock();
      return future.get();
    }
    std::promise<Pointer> promise;
    lru_.push_front(key);
    entries_.emplace(key, Entry{promise.get_future().share(), lru_.begin(), false});
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
    lock.lock();
    if (auto it = entries_.find(key); it != entries_.end()) it->second.ready = true;
    evict_locked();
    return state;
  }

  std::size_t size() const {
    std::lock_guard lock(mutex_);
    return entries_.size();
  }
  std::size_t capacity() const { return capacity_; }
  SunStateCacheStats stats() const {
    std::lock_guard lock(mutex_);
    return stats_;
  }

 private:
  struct Entry {
    std::shared_future<Pointer> future;
    std::list<std::string>::iterator position;
    bool ready;
  };

  // Drops the least recently used finished entries beyond capacity; entries being built are
  // never dropped (their requesters are waiting on them).
  void evict_locked() {
    auto it = lru_.end();
    while (entries_.size() > capacity_ && it != lru_.begin()) {
      --it;
      auto entry = entries_.find(*it);
      if (entry != entries_.end() && entry->second.ready) {
        entries_.erase(entry);
        it = lru_.erase(it);
        ++stats_.evictions;
      }
    }
  }

  const std::size_t capacity_;
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
