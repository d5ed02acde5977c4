// The day's per-sun states, built in the background after start (docs/tables-and-memory.md
// "The day's per-sun states"): for each configuration the server builds at start (start_builds.h:
// every draft, then every default, or exactly `serve --prebuild`) of a model with per-sun
// precomputation and sun buckets (the option sun_zenith_bucket_deg > 0: Haber's draft and
// standard, Nishita96's draft), every bucket from zenith 0 to the model's dark threshold
// (ModelCapabilities::dark_beyond_sun_zenith_deg), lowest bucket first, is prepared once through
// the model, which loads it from the disk table cache or computes and stores it there. A sun of
// any time of day, anywhere, then falls in a bucket already in the cache: the server has no
// configured place, so it cannot order the buckets by a day's clock, and from the zenith down
// every request's bucket is reached at the latest after the whole pass.
//
// The pass runs on one thread at the lowest scheduling priority (SCHED_IDLE:
// background_priority.h) and computes with one worker (PrecomputeContext::threads = 1), so that
// HTTP answers never wait for its CPU. It leaves the states in the disk cache only
// (PrecomputeContext::keep_sun_state = false): the models' memory caches keep those requests
// use, and a request's bucket the pass built is loaded from disk in milliseconds. It waits
// for each configuration's tables (it never starts a table build of its own) and stops, cancelling
// the state under way, when the object is destroyed. A request for a bucket the pass is building
// waits on that build (the models' per-sun caches are single flight). An exact-sun configuration
// (bucket width 0) has no buckets and no pass.
// Thread-safety: progress() may be called from any thread; the destructor stops and joins.
#pragma once

#include <atomic>
#include <cstddef>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "server/tables/table_store.h"

namespace clearsky::server {

class DaySunStates {
 public:
  struct Progress {
    std::size_t built = 0;  // buckets ready in the disk cache (computed or found there)
    std::size_t total = 0;  // buckets of the configurations the pass covers
  };

  // Starts the pass over `configurations` (the start builds, in their order); the store and the
  // cache must outlive this object.
  DaySunStates(const TableStore& tables,
               std::vector<std::pair<const ModelFactory*, ModelConfig>> configurations,
               const TableCache* cache);
  ~DaySunStates();
  DaySunStates(const DaySunStates&) = delete;
  DaySunStates& operator=(const DaySunStates&) = delete;

  // Per model id, summed over its configurations; only the models the pass covers.
  std::map<std::string, Progress> progress() const;

  // The bucket count of a configuration: 0 without per-sun precomputation or with exact suns,
  // else the buckets whose centres lie from zenith 0 to the dark threshold's bucket, both ends
  // included. std::invalid_argument for a configuration that does not validate.
  static std::size_t bucket_count(const ModelFactory& factory, const ModelConfig& config);

 private:
  struct Pass {
    const ModelFactory* factory;
    ModelConfig config;
    std::size_t buckets;
  };
  void run();
  void run_pass(const Pass& pass);

  const TableStore& tables_;
  const TableCache* cache_;
  std::vector<Pass> passes_;
  std::atomic<bool> stop_{false};
  mutable std::mutex mutex_;
  std::map<std::string, Progress> progress_;
  std::thread thread_;
};

}  // namespace clearsky::server
