// Single-flight builds of model tables, with LRU eviction of non-default configurations.
#include "server/tables/table_store.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "api/error/api_error.h"
#include "models/core/canonical_config.h"
#include "models/core/invalid_input.h"
#include "models/core/numeric.h"
#include "server/memory/heap_bounds.h"
#include "server/tables/background_priority.h"
#include "server/tables/recent_sun_states.h"

namespace clearsky::server {

struct TableStore::Entry {
  const ModelFactory* factory = nullptr;
  ModelConfig config;
  std::string key;
  bool pinned = false;
  api::ModelState::Status status = api::ModelState::Status::queued;
  std::atomic<double> progress{0.0};
  std::string stage;  // guarded by the store's mutex
  std::string error;
  std::shared_ptr<const SkyModel> model;
  double seconds = 0;
  bool from_cache = false;
  std::uint64_t last_used = 0;
  std::size_t estimated_bytes = 0;  // counted while the build is pending
  // Queued by prebuild(): built by the builders at the lowest priority (background_priority.h).
  bool background = false;
};

struct TableStore::SunPreparation {
  bool done = false;  // guarded by the store's mutex
  std::shared_ptr<const SunState> state;
  std::exception_ptr error;
};

namespace {

// Counts the cache traffic of one build, to tell a cache load from a build.
class ObservedCache final : public TableCache {
 public:
  explicit ObservedCache(const TableCache* inner) : inner_(inner) {}
  std::optional<std::string> load(const std::string& key) const override {
    auto value = inner_->load(key);
    (value ? hits : misses)++;
    return value;
  }
  void store(const std::string& key, std::string_view bytes) const override {
    ++stores;
    inner_->store(key, bytes);
  }
  mutable std::atomic<int> hits{0}, misses{0}, stores{0};

 private:
  const TableCache* inner_;
};

const std::string& default_canonical_string() {
  static const std::string canonical = ModelConfig{}.canonical_string();
  return canonical;
}

std::string entry_key(const ModelFactory& factory, const std::string& canonical) {
  return factory.descriptor->id + "|" + factory.descriptor->version + "|" + canonical;
}

// A configuration whose options at their default were dropped (canonical_config.h) that is the
// default one (most requests): its canonical text is known without writing it again.
bool is_default_config(const ModelConfig& canonical) {
  static const AtmosphereParameters default_atmosphere;
  static const WavelengthGrid default_grid = ModelConfig{}.wavelengths;
  return canonical.options.empty() && canonical.atmosphere == default_atmosphere &&
         canonical.wavelengths == default_grid;
}

std::string canonical_text(const ModelConfig& canonical) {
  return is_default_config(canonical) ? default_canonical_string() : canonical.canonical_string();
}

// Writing a configuration's text through its ostringstreams was a sixth of a radiance request's
// instructions (callgrind of a server under wrk: model_or_fallback looks its configuration up on
// every standard request), and the default configuration's text never changes.
std::string entry_key(const ModelFactory& factory, const ModelConfig& config) {
  return entry_key(factory, canonical_text(canonical_config(*factory.descriptor, config)));
}

bool pending(api::ModelState::Status status) {
  return status == api::ModelState::Status::queued ||
         status == api::ModelState::Status::precomputing;
}

}  // namespace

TableStore::TableStore(std::vector<ModelFactory> factories, Options options)
    : factories_(std::move(factories)),
      options_(options),
      build_rate_(options.build_rate, options.build_rate_window) {
  for (unsigned i = 0; i < std::max(1u, options_.builder_threads); ++i)
    builders_.emplace_back([this] { builder_loop(); });
}

TableStore::~TableStore() {
  std::vector<OnDemandBuild> on_demand;
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
    on_demand.swap(on_demand_);
  }
  changed_.notify_all();
  for (auto& t : builders_) t.join();
  for (auto& b : on_demand) b.thread.join();
}

void TableStore::launch_locked(const std::shared_ptr<Entry>& entry) const {
  // Join the builds that have finished, so that threads do not accumulate.
  std::erase_if(on_demand_, [](OnDemandBuild& b) {
    if (!b.done->load()) return false;
    b.thread.join();
    return true;
  });
  entry->status = api::ModelState::Status::precomputing;
  auto done = std::make_shared<std::atomic<bool>>(false);
  on_demand_.push_back({std::thread([this, entry, done] {
                          build(*entry);
                          changed_.notify_all();
                          *done = true;
                        }),
                        done});
}

std::shared_ptr<TableStore::Entry> TableStore::find_or_queue(
    const ModelFactory& factory, const ModelConfig& config, const std::string& key, bool pinned,
    const api::ModelRequester& requester) const {
  // Caller holds mutex_.
  auto it = entries_.find(key);
  if (it != entries_.end()) {
    if (pinned) it->second->pinned = true;
    it->second->last_used = ++clock_;
    return it->second;
  }
  if (!pinned) {
    std::size_t pending = 0;
    for (const auto& [k, e] : entries_) {
      pending += !e->pinned && e->status != api::ModelState::Status::ready &&
                 e->status != api::ModelState::Status::failed;
    }
    if (pending >= options_.capacity) {
      throw api::not_ready(factory.descriptor->id,
                           "too many table builds are pending; try again later",
                           options_.retry_after_s);
    }
  }
  const auto now = BuildRateLimiter::Clock::now();
  if (!pinned) {
    if (const int wait_s = build_rate_.seconds_until_allowed(requester.client_address, now)) {
      throw api::ApiError(
          429, "too_many_builds", "build_rate",
          "build_rate: " + requester.client_address + " started " +
              std::to_string(build_rate_.builds_per_window()) + " table builds within " +
              std::to_string(build_rate_.window().count()) +
              " s, the most one client may; ask for a configuration already built (the "
              "defaults) or try again later",
          wait_s);
    }
  }
  const std::size_t estimate = estimate_bytes_locked(factory, config);
  // A build that would not fit even with every evictable table gone can never be served: a 413
  // that says so, not a 503 asking the client to retry what will never succeed.
  if (!pinned && pinned_bytes_locked() + estimate > options_.memory_budget_bytes) {
    throw api::too_large(
        "table_memory",
        "the tables of model " + factory.descriptor->id + " (about " + std::to_string(estimate) +
            " bytes) never fit in the table memory budget of " +
            std::to_string(options_.memory_budget_bytes) + " bytes beside the " +
            std::to_string(pinned_bytes_locked()) +
            " bytes of the tables kept for good (the defaults and what was built at start); ask "
            "for fewer wavelengths or a coarser setting, or start the server with a larger "
            "--table-memory");
  }
  if (!pinned && !make_room_locked(estimate, nullptr)) {
    throw api::ApiError(503, "busy", "table_memory",
                        "table_memory: the tables of model " + factory.descriptor->id + " (about " +
                            std::to_string(estimate) +
                            " bytes) do not fit in the table memory "
                            "budget of " +
                            std::to_string(options_.memory_budget_bytes) + " bytes (" +
                            std::to_string(accounted_bytes_locked()) +
                            " in use by tables being kept or built); try again later",
                        options_.retry_after_s);
  }
  auto entry = std::make_shared<Entry>();
  entry->estimated_bytes = estimate;
  entry->factory = &factory;
  entry->config = config;
  entry->key = key;
  entry->pinned = pinned;
  entry->last_used = ++clock_;
  entries_.emplace(key, entry);
  if (!pinned) build_rate_.record(requester.client_address, now);
  if (pinned) {
    queue_.push_back(entry);
    changed_.notify_all();
  } else {
    launch_locked(entry);
  }
  return entry;
}

std::shared_ptr<const SkyModel> TableStore::model(const ModelFactory& factory,
                                                  const ModelConfig& requested,
                                                  const api::ModelRequester& requester) const {
  // One entry for the options given at their default and those left out (canonical_config.h);
  // a configuration without options (most requests) is not copied.
  std::optional<ModelConfig> without_defaults;
  if (!requested.options.empty())
    without_defaults = canonical_config(*factory.descriptor, requested);
  const ModelConfig& config = without_defaults ? *without_defaults : requested;
  // The default configuration (most requests) skips building its canonical text.
  const bool plain = is_default_config(config);
  // Any other configuration is checked against the descriptor before it is queued, so that a
  // caller that did not parse it from a request (evaluations, jobs, tests) gets a 400 naming the
  // parameter at once instead of a failed build (the build checks it again, once per build:
  // models/core/model_factory.h).
  if (!plain) {
    try {
      validate_config(*factory.descriptor, config);
    } catch (const InvalidInput& e) {
      throw api::invalid_parameter(e.field(), e.reason());
    }
  }
  const std::string canonical = plain ? default_canonical_string() : config.canonical_string();
  const bool is_default = canonical == default_canonical_string();
  const std::string key = entry_key(factory, canonical);
  std::unique_lock lock(mutex_);
  std::shared_ptr<Entry> entry = find_or_queue(factory, config, key, is_default, requester);
  bool launched_now = false;
  if (entry->status == api::ModelState::Status::queued) {
    // A request needs a queued default: build it now rather than after the queue.
    std::erase(queue_, entry);
    launch_locked(entry);
    launched_now = true;
  }
  const auto settled = [&] {
    return entry->status == api::ModelState::Status::ready ||
           entry->status == api::ModelState::Status::failed;
  };
  // Wait for a build that may be short (a non-default one, or one started by this request); a
  // default build already under way since start is long: answer 503 at once.
  if (!settled() && (launched_now || !is_default))
    changed_.wait_for(lock, options_.build_wait, settled);
  if (entry->status == api::ModelState::Status::ready) return entry->model;
  if (entry->status == api::ModelState::Status::failed) {
    const std::string error = entry->error;
    if (!entry->pinned) entries_.erase(entry->key);  // a later request tries again
    throw api::ApiError(500, "precomputation_failed", "model",
                        "model " + factory.descriptor->id + ": precomputation failed: " + error);
  }
  std::ostringstream message;
  message << "its tables for this configuration are being built ("
          << (entry->status == api::ModelState::Status::queued ? "queued" : "in progress") << ", "
          << std::lround(100.0 * entry->progress.load()) << "% done)";
  throw api::not_ready(factory.descriptor->id, message.str(), options_.retry_after_s);
}

std::shared_ptr<const SunState> TableStore::sun_state(const std::shared_ptr<const SkyModel>& model,
                                                      const SunPosition& sun) const {
  // The models whose per-sun preparation is costly (Haber, Nishita96) keep their own bounded,
  // single-flight cache of per-sun states (models/core/sun_state_cache.h); for the others a
  // SunState is just the sun. A second cache here would only defeat the models' memory bound.
  // A dark sun (ModelCapabilities::dark_beyond_sun_zenith_deg) builds nothing: its state is
  // made at once.
  if (model->sun_is_dark(sun)) return model->prepare_sun(sun);
  if (!model->descriptor().capabilities.per_sun_precomputation) {
    // A state made for each request: the thread's last few are kept (recent_sun_states.h).
    RecentSunStates& recent = RecentSunStates::of_this_thread();
    if (auto kept = recent.find(model, sun)) return kept;
    auto state = model->prepare_sun(sun);
    recent.keep(model, sun, state);
    return state;
  }
  // A costly preparation runs on its own thread so that the request waits at most build_wait,
  // like a table build; the thread keeps the model alive and fills the model's cache, where a
  // later request finds the state.
  std::ostringstream key_text;
  key_text.precision(17);
  key_text << static_cast<const void*>(model.get()) << '|' << sun.zenith_rad << '|'
           << sun.azimuth_rad;
  const std::string key = key_text.str();
  std::unique_lock lock(mutex_);
  std::shared_ptr<SunPreparation> preparation;
  if (const auto it = sun_preparations_.find(key); it != sun_preparations_.end()) {
    preparation = it->second;
  } else {
    if (sun_preparations_.size() >= options_.capacity) {
      throw api::not_ready(model->descriptor().id,
                           "too many per-sun preparations are pending; try again later",
                           options_.retry_after_s);
    }
    preparation = std::make_shared<SunPreparation>();
    sun_preparations_.emplace(key, preparation);
    std::erase_if(on_demand_, [](OnDemandBuild& b) {
      if (!b.done->load()) return false;
      b.thread.join();
      return true;
    });
    auto done = std::make_shared<std::atomic<bool>>(false);
    on_demand_.push_back(
        {std::thread([this, model, sun, key, preparation, done] {
           std::shared_ptr<const SunState> state;
           std::exception_ptr error;
           PrecomputeContext context;
           context.cancel = &stopping_;
           // Haber's domes persist in the disk table cache.
           context.cache = options_.cache;
           const std::size_t computed_before = model->sun_states_built();
           const auto start = std::chrono::steady_clock::now();
           try {
             state = model->prepare_sun(sun, context);
             spdlog::info(
                 "sun state: {} sun zenith {:.4f} deg {} in {:.3f} s", model->descriptor().id,
                 radians_to_degrees(sun.zenith_rad),
                 model->sun_states_built() > computed_before ? "computed"
                                                             : "ready (memory or disk cache)",
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
           } catch (...) {
             error = std::current_exception();
           }
           {
             std::lock_guard done_lock(mutex_);
             preparation->state = std::move(state);
             preparation->error = error;
             preparation->done = true;
             sun_preparations_.erase(key);
           }
           changed_.notify_all();
           *done = true;
         }),
         done});
  }
  changed_.wait_for(lock, options_.build_wait, [&] { return preparation->done; });
  if (!preparation->done) {
    throw api::not_ready(model->descriptor().id, "its per-sun state for this sun is being prepared",
                         options_.retry_after_s);
  }
  if (preparation->error) std::rethrow_exception(preparation->error);
  return preparation->state;
}

api::ModelState TableStore::default_state(const ModelFactory& factory) const {
  return config_state(factory, ModelConfig{}).value_or(api::ModelState{});
}

std::optional<api::ModelState> TableStore::config_state(const ModelFactory& factory,
                                                        const ModelConfig& config) const {
  std::lock_guard lock(mutex_);
  api::ModelState state;
  const auto it = entries_.find(entry_key(factory, config));
  if (it == entries_.end()) return std::nullopt;
  const Entry& e = *it->second;
  state.status = e.status;
  state.progress =
      e.status == api::ModelState::Status::ready ? 1.0 : std::clamp(e.progress.load(), 0.0, 1.0);
  state.stage = e.stage;
  state.error = e.error;
  state.precompute_seconds = e.seconds;
  state.table_bytes = e.model ? e.model->table_bytes() : 0;
  state.loaded_from_cache = e.from_cache;
  return state;
}

void TableStore::start_default_builds() {
  std::lock_guard lock(mutex_);
  for (const ModelFactory& f : factories_)
    find_or_queue(f, ModelConfig{}, entry_key(f, default_canonical_string()), true);
}

void TableStore::start_builds(
    const std::vector<std::pair<const ModelFactory*, ModelConfig>>& builds) {
  for (const auto& [factory, config] : builds) validate_config(*factory->descriptor, config);
  std::lock_guard lock(mutex_);
  for (const auto& [factory, config] : builds) {
    const std::string key = entry_key(*factory, config);
    find_or_queue(*factory, canonical_config(*factory->descriptor, config), key, true);
    if (std::find(start_keys_.begin(), start_keys_.end(), key) == start_keys_.end())
      start_keys_.push_back(key);
  }
}

TableStore::ServedModel TableStore::model_or_fallback(const ModelFactory& factory,
                                                      const ModelConfig& config,
                                                      const FallbackConfig& fallback,
                                                      const api::ModelRequester& requester) const {
  if (fallback) {
    // The configuration's text (the default's is kept: canonical_text) is written outside the
    // lock; the draft's configuration is made only while the wanted tables are not ready.
    // Writing both texts on every standard request, under the lock, was over a third of a
    // radiance request's instructions (docs/performance.md "A radiance request through the
    // server").
    const ModelConfig wanted_config = canonical_config(*factory.descriptor, config);
    const std::string canonical = canonical_text(wanted_config);
    const bool is_default = canonical == default_canonical_string();
    const std::string key = entry_key(factory, canonical);
    std::unique_lock lock(mutex_);
    auto wanted = entries_.find(key);
    if (wanted != entries_.end() && wanted->second->status == api::ModelState::Status::ready) {
      // What model() does with a ready entry (find_or_queue): a default is pinned, and the
      // entry is marked used; without looking the configuration up a second time.
      if (is_default) wanted->second->pinned = true;
      wanted->second->last_used = ++clock_;
      return {wanted->second->model, false};
    }
    const std::optional<ModelConfig> fallback_config = fallback();
    if (fallback_config) {
      const auto draft = entries_.find(entry_key(factory, *fallback_config));
      const bool draft_ready =
          draft != entries_.end() && draft->second->status == api::ModelState::Status::ready;
      // A default not built at start (standard on first use, or left out of --prebuild) with
      // its draft ready: its build starts now, pinned like every default, on its own thread at
      // the requests' priority, and this request is answered from the draft at once rather
      // than after build_wait and a 503 (docs/quality-levels.md "Serving at once").
      if (wanted == entries_.end() && draft_ready && is_default) {
        const std::shared_ptr<Entry> entry =
            find_or_queue(factory, wanted_config, key, true, requester);
        if (entry->status == api::ModelState::Status::queued) {
          std::erase(queue_, entry);
          launch_locked(entry);
        }
        wanted = entries_.find(key);
      }
      // Only while config's own build is under way (queued at start or started by a request):
      // an unknown configuration is asked for as usual, so that its build starts.
      if (wanted != entries_.end() && wanted->second->status != api::ModelState::Status::ready &&
          wanted->second->status != api::ModelState::Status::failed && draft_ready) {
        draft->second->last_used = ++clock_;
        return {draft->second->model, true};
      }
    }
  }
  return {model(factory, config, requester), false};
}

void TableStore::prebuild(const ModelFactory& factory, const ModelConfig& config) {
  validate_config(*factory.descriptor, config);
  std::lock_guard lock(mutex_);
  const std::string key = entry_key(factory, config);
  const bool known = entries_.contains(key);
  const std::shared_ptr<Entry> entry =
      find_or_queue(factory, canonical_config(*factory.descriptor, config), key, true);
  if (!known) entry->background = true;
}

bool TableStore::ready() const {
  std::lock_guard lock(mutex_);
  if (!start_keys_.empty()) {
    for (const std::string& key : start_keys_) {
      const auto it = entries_.find(key);
      if (it == entries_.end() || it->second->status != api::ModelState::Status::ready)
        return false;
    }
    return true;
  }
  for (const ModelFactory& f : factories_) {
    const auto it = entries_.find(entry_key(f, default_canonical_string()));
    if (it == entries_.end() || it->second->status != api::ModelState::Status::ready) return false;
  }
  return true;
}

std::size_t TableStore::accounted_bytes() const {
  std::lock_guard lock(mutex_);
  return accounted_bytes_locked();
}

std::size_t TableStore::accounted_bytes_locked() const {
  std::size_t bytes = 0;
  for (const auto& [key, e] : entries_) {
    if (e->model)
      bytes += e->model->table_bytes();
    else if (pending(e->status))
      bytes += e->estimated_bytes;
  }
  return bytes;
}

std::size_t TableStore::pinned_bytes_locked() const {
  std::size_t bytes = 0;
  for (const auto& [key, e] : entries_) {
    if (!e->pinned) continue;
    if (e->model)
      bytes += e->model->table_bytes();
    else if (pending(e->status))
      bytes += e->estimated_bytes;
  }
  return bytes;
}

std::size_t TableStore::estimate_bytes_locked(const ModelFactory& factory,
                                              const ModelConfig& config) const {
  // The model's own estimate from the configuration (cheap: arithmetic on the resolution and
  // the wavelength count; the configuration was validated by model()).
  if (factory.estimate_table_bytes != nullptr) {
    try {
      return factory.estimate_table_bytes(config);
    } catch (const std::invalid_argument& e) {
      // The build will refuse the configuration the same way; count what was seen so far.
      spdlog::warn("tables: no estimate for {}: {}", factory.descriptor->id, e.what());
    }
  }
  // Without one, the largest tables of this model built so far (its default, pinned and built
  // at start, at the least) stand in.
  std::size_t bytes = 0;
  for (const auto& [key, e] : entries_) {
    if (e->factory == &factory)
      bytes = std::max(bytes, e->model ? e->model->table_bytes() : e->estimated_bytes);
  }
  return bytes;
}

bool TableStore::make_room_locked(std::size_t extra, const Entry* keep) const {
  while (accounted_bytes_locked() + extra > options_.memory_budget_bytes) {
    std::shared_ptr<Entry> oldest;
    for (const auto& [key, e] : entries_) {
      if (e->pinned || e->status != api::ModelState::Status::ready || e.get() == keep) continue;
      if (!oldest || e->last_used < oldest->last_used) oldest = e;
    }
    if (!oldest) return false;
    spdlog::info("tables: evicting {} ({} bytes) to stay within the table memory budget",
                 oldest->key, oldest->model->table_bytes());
    entries_.erase(oldest->key);
  }
  return true;
}

std::map<std::string, std::size_t> TableStore::table_bytes() const {
  std::lock_guard lock(mutex_);
  std::map<std::string, std::size_t> bytes;
  for (const ModelFactory& f : factories_) bytes[f.descriptor->id] = 0;
  for (const auto& [key, e] : entries_) {
    if (e->model) bytes[e->factory->descriptor->id] += e->model->table_bytes();
  }
  return bytes;
}

void TableStore::builder_loop() {
  while (true) {
    std::shared_ptr<Entry> entry;
    {
      std::unique_lock lock(mutex_);
      changed_.wait(lock, [&] { return stopping_ || !queue_.empty(); });
      if (stopping_) return;
      entry = queue_.front();
      queue_.pop_front();
      entry->status = api::ModelState::Status::precomputing;
    }
    // A background build yields the cores to requests; a start build keeps the normal
    // priority (readiness waits for it), as does a build a request starts (launch_locked).
    if (entry->background)
      run_at_idle_priority([&] { build(*entry); });
    else
      build(*entry);
    changed_.notify_all();
  }
}

void TableStore::build(Entry& entry) const {
  const std::string& id = entry.factory->descriptor->id;
  ObservedCache cache(options_.cache);
  PrecomputeContext context;
  context.progress = [this, &entry](double fraction, std::string_view stage) {
    entry.progress = fraction;
    std::lock_guard lock(mutex_);
    entry.stage = std::string(stage);
  };
  context.cancel = &stopping_;
  context.cache = options_.cache ? &cache : nullptr;
  context.threads = options_.threads_per_build;
  context.sun_state_memory_bytes = options_.sun_state_memory_bytes;
  spdlog::info("tables: building {} ({})", id, entry.key);
  const auto start = std::chrono::steady_clock::now();
  std::shared_ptr<const SkyModel> model;
  std::string error;
  try {
    model = entry.factory->create(entry.config, context);
    if (!model) error = "the factory returned no model";
  } catch (const PrecomputeCancelled&) {
    error = "cancelled";
  } catch (const std::exception& e) {
    error = e.what();
  } catch (...) {
    error = "unknown error";
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const bool from_cache = cache.hits > 0 && cache.misses == 0 && cache.stores == 0;
  {
    std::lock_guard lock(mutex_);
    entry.seconds = seconds;
    entry.from_cache = from_cache;
    if (model) {
      entry.model = std::move(model);
      entry.status = api::ModelState::Status::ready;
      entry.progress = 1.0;
    } else {
      entry.error = error;
      entry.status = api::ModelState::Status::failed;
    }
    evict_locked();
  }
  // The build's intermediates (and the tables an eviction dropped) were freed in the arenas of
  // its threads: give that memory back rather than keep it for allocations that may not come.
  release_free_heap_memory_now();
  if (error.empty()) {
    const std::size_t bytes = entry.model->table_bytes();
    spdlog::info("tables: {} ready in {:.3f} s ({}, {} bytes)", id, seconds,
                 from_cache ? "from cache" : "built", bytes);
    // The budget admitted the build on its estimate and counts the real bytes from now on; an
    // estimate well below them is a model bug worth seeing.
    if (static_cast<double>(bytes) > 1.1 * static_cast<double>(entry.estimated_bytes)) {
      spdlog::warn("tables: {} holds {} bytes, above its estimate of {} bytes", entry.key, bytes,
                   entry.estimated_bytes);
    }
    if (observer_) observer_(id, seconds, from_cache);
  } else {
    spdlog::error("tables: {} failed after {:.3f} s: {}", id, seconds, error);
  }
}

void TableStore::evict_locked() const {
  while (true) {
    std::size_t unpinned = 0;
    std::shared_ptr<Entry> oldest;
    for (const auto& [key, e] : entries_) {
      if (e->pinned || e->status != api::ModelState::Status::ready) continue;
      ++unpinned;
      if (!oldest || e->last_used < oldest->last_used) oldest = e;
    }
    if (unpinned <= options_.capacity || !oldest) break;
    entries_.erase(oldest->key);
  }
  // A build larger than its estimate: evict the least recently used until within the budget,
  // this entry last (its requests still hold its model).
  make_room_locked(0, nullptr);
}

}  // namespace clearsky::server
