// The server's built models, keyed by (model id, ModelConfig::canonical_string()): each
// configuration is built once (single-flight: concurrent requests for it wait on the same
// build), in the background, with the disk TableCache passed to the model. The default
// configurations queued at start are built by `builder_threads` builders in registry order;
// a configuration a request asks for (or a queued default a request needs) is built at once on
// its own thread, so a cheap build never waits behind an expensive one.
// A request waits up to build_wait for a build; past that it gets a 503 with Retry-After while
// the build goes on. The default configuration of every model is pinned; other configurations
// are evicted least-recently-used beyond `capacity` ready entries, and at most `capacity`
// builds may be pending (503 beyond).
// Memory: the tables of every entry (ready: their table_bytes(); pending: the estimate its
// model's factory computes from the configuration, ModelFactory::estimate_table_bytes, or for
// a factory without one the largest tables of that model seen so far) count against
// `memory_budget_bytes`. Before a requested build starts, least-recently-used unpinned entries
// are evicted to make room for its estimate; if it still does not fit, the request gets 503
// (parameter "table_memory") and nothing is built. Pinned entries (the defaults) count but are
// never evicted. A finished build counts its real bytes; one larger than its estimate evicts
// further (and is logged). Per-sun states are bounded by the models' own caches, in bytes per
// configuration (`sun_state_memory_bytes`, passed to the builds).
// Rate: a requester (the HTTP client's address) may trigger at most `build_rate` builds per
// `build_rate_window` (server/tables/build_rate_limiter.h); beyond, 429 naming "build_rate".
// Per-sun states of models with per-sun precomputation are prepared on a helper thread: a
// request waits up to build_wait for it, then gets 503 while the preparation goes on (the
// model's own per-sun cache keeps the result for the next request); at most `capacity`
// preparations run at once (503 beyond).
// Thread-safety: all public functions may be called from any thread. The destructor cancels
// pending builds and joins the builder threads.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <thread>
#include <tuple>
#include <vector>

#include "api/service/model_provider.h"
#include "server/tables/build_rate_limiter.h"

namespace clearsky::server {

class TableStore final : public api::ModelProvider {
 public:
  struct Options {
    std::size_t capacity = 16;  // non-default configurations kept and pending
    std::size_t memory_budget_bytes = std::size_t{1} << 30;  // tables of all entries
    std::chrono::milliseconds build_wait{2000};
    int retry_after_s = 5;
    // Per built configuration of Haber and Nishita96 (PrecomputeContext).
    std::size_t sun_state_memory_bytes = PrecomputeContext::kDefaultSunStateMemoryBytes;
    std::size_t build_rate = 30;  // builds one requester may trigger per window; 0: no limit
    std::chrono::seconds build_rate_window{60};
    unsigned builder_threads = 1;       // concurrent builds
    unsigned threads_per_build = 0;     // 0: all cores
    const TableCache* cache = nullptr;  // may be null
  };
  // Observes finished builds (model id, seconds, whether the cache supplied the tables).
  using BuildObserver =
      std::function<void(const std::string& model_id, double seconds, bool from_cache)>;

  TableStore(std::vector<ModelFactory> factories, Options options);
  ~TableStore() override;
  TableStore(const TableStore&) = delete;
  TableStore& operator=(const TableStore&) = delete;

  std::span<const ModelFactory> factories() const override { return factories_; }
  using api::ModelProvider::model;
  std::shared_ptr<const SkyModel> model(const ModelFactory& factory, const ModelConfig& config,
                                        const api::ModelRequester& requester) const override;
  // config's model when ready; else, while config is being built (not started by this call),
  // the fallback's when ready; else model(config).
  ServedModel model_or_fallback(const ModelFactory& factory, const ModelConfig& config,
                                const FallbackConfig& fallback,
                                const api::ModelRequester& requester) const override;
  api::ModelState default_state(const ModelFactory& factory) const override;
  std::optional<api::ModelState> config_state(const ModelFactory& factory,
                                              const ModelConfig& config) const override;
  bool start_builds_ready() const override { return ready(); }
  // The model's per-sun state; per-sun models share and bound them in their own cache.
  std::shared_ptr<const SunState> sun_state(const std::shared_ptr<const SkyModel>& model,
                                            const SunPosition& sun) const override;

  // Queues the default configuration of every model (the server does this at start).
  void start_default_builds();
  // Queues these configurations, pinned, in this order (serve --prebuild and the quality levels'
  // start: docs/quality-levels.md); readiness then waits for them instead of the defaults.
  // std::invalid_argument for an invalid configuration.
  void start_builds(const std::vector<std::pair<const ModelFactory*, ModelConfig>>& builds);
  // Queues another configuration to build in the background and keep (after the defaults;
  // readiness does not wait for it), at the lowest CPU priority (background_priority.h) unless a
  // request needs it before a builder takes it (then on its own thread at the normal priority).
  // std::invalid_argument for an invalid configuration.
  void prebuild(const ModelFactory& factory, const ModelConfig& config);
  // Whether the tables queued at start are ready: those of start_builds, else every model's
  // default.
  bool ready() const;
  // Bytes held by the tables of the ready entries, per model id.
  std::map<std::string, std::size_t> table_bytes() const;
  // Bytes counted against memory_budget_bytes: ready tables plus the estimates of pending builds.
  std::size_t accounted_bytes() const;
  void set_build_observer(BuildObserver observer) { observer_ = std::move(observer); }

 private:
  struct Entry;
  // Caller holds mutex_. requester: who triggers a build of an unpinned entry (rate-limited).
  std::shared_ptr<Entry> find_or_queue(const ModelFactory& factory, const ModelConfig& config,
                                       const std::string& key, bool pinned,
                                       const api::ModelRequester& requester = {}) const;
  void builder_loop();
  // Starts entry's build on its own thread (caller holds mutex_).
  void launch_locked(const std::shared_ptr<Entry>& entry) const;
  void build(Entry& entry) const;
  void evict_locked() const;
  // Evicts least-recently-used unpinned ready entries (never `keep`) while the accounted bytes
  // plus `extra` exceed the budget; whether they now fit.
  bool make_room_locked(std::size_t extra, const Entry* keep) const;
  std::size_t accounted_bytes_locked() const;
  // The bytes of the pinned entries (the defaults and what was built at start), which are never
  // evicted: what a requested build can never be given.
  std::size_t pinned_bytes_locked() const;
  std::size_t estimate_bytes_locked(const ModelFactory& factory, const ModelConfig& config) const;
  struct SunPreparation;

  std::vector<ModelFactory> factories_;
  Options options_;
  BuildObserver observer_;
  mutable std::mutex mutex_;
  mutable std::condition_variable changed_;
  mutable std::map<std::string, std::shared_ptr<Entry>> entries_;
  mutable std::deque<std::shared_ptr<Entry>> queue_;
  mutable std::uint64_t clock_ = 0;
  mutable BuildRateLimiter build_rate_;
  std::atomic<bool> stopping_{false};
  std::vector<std::thread> builders_;
  struct OnDemandBuild {
    std::thread thread;
    std::shared_ptr<std::atomic<bool>> done;
  };
  mutable std::vector<OnDemandBuild> on_demand_;
  mutable std::map<std::string, std::shared_ptr<SunPreparation>> sun_preparations_;
  // The entries readiness waits for (start_builds); empty: every model's default.
  std::vector<std::string> start_keys_;
};

}  // namespace clearsky::server
