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

namespace clearsky::server {

class TableStore final : public api::ModelProvider {
 public:
  struct Options {
    std::size_t capacity = 16;  // non-default configurations kept and pending
    std::chrono::milliseconds build_wait{2000};
    int retry_after_s = 5;
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
  std::shared_ptr<const SkyModel> model(const ModelFactory& factory,
                                        const ModelConfig& config) const override;
  api::ModelState default_state(const ModelFactory& factory) const override;
  // Per-sun states are kept (up to kSunStates, then the cache starts over), keyed by model and
  // exact sun angles; a model that has died is never matched (weak reference).
  std::shared_ptr<const SunState> sun_state(const std::shared_ptr<const SkyModel>& model,
                                            const SunPosition& sun) const override;
  static constexpr std::size_t kSunStates = 4096;

  // Queues the default configuration of every model (the server does this at start).
  void start_default_builds();
  // Queues another configuration to build in the background and keep (after the defaults;
  // readiness does not wait for it). std::invalid_argument for an invalid configuration.
  void prebuild(const ModelFactory& factory, const ModelConfig& config);
  // Whether the default tables of every model are ready.
  bool ready() const;
  // Bytes held by the tables of the ready entries, per model id.
  std::map<std::string, std::size_t> table_bytes() const;
  void set_build_observer(BuildObserver observer) { observer_ = std::move(observer); }

 private:
  struct Entry;
  std::shared_ptr<Entry> find_or_queue(const ModelFactory& factory, const ModelConfig& config,
                                       const std::string& key, bool pinned) const;
  void builder_loop();
  // Starts entry's build on its own thread (caller holds mutex_).
  void launch_locked(const std::shared_ptr<Entry>& entry) const;
  void build(Entry& entry) const;
  void evict_locked() const;

  std::vector<ModelFactory> factories_;
  Options options_;
  BuildObserver observer_;
  mutable std::mutex mutex_;
  mutable std::condition_variable changed_;
  mutable std::map<std::string, std::shared_ptr<Entry>> entries_;
  mutable std::deque<std::shared_ptr<Entry>> queue_;
  mutable std::uint64_t clock_ = 0;
  std::atomic<bool> stopping_{false};
  std::vector<std::thread> builders_;
  struct OnDemandBuild {
    std::thread thread;
    std::shared_ptr<std::atomic<bool>> done;
  };
  mutable std::vector<OnDemandBuild> on_demand_;
  struct SunKey {
    const SkyModel* model;
    double zenith_rad, azimuth_rad;
    bool operator<(const SunKey& o) const {
      return std::tie(model, zenith_rad, azimuth_rad) <
             std::tie(o.model, o.zenith_rad, o.azimuth_rad);
    }
  };
  struct SunValue {
    std::weak_ptr<const SkyModel> model;
    std::shared_ptr<const SunState> state;
  };
  mutable std::mutex sun_mutex_;
  mutable std::map<SunKey, SunValue> sun_states_;
};

}  // namespace clearsky::server
