// The background pass over the day's per-sun states (day_sun_states.h).
#include "server/tables/day_sun_states.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>

#include "models/core/model_factory.h"
#include "models/core/numeric.h"
#include "models/core/sun_state_cache.h"
#include "server/memory/heap_bounds.h"
#include "server/tables/background_priority.h"

namespace clearsky::server {

namespace {

// The bucket width of a configuration, rad (0: exact suns or no per-sun precomputation).
double bucket_width_rad(const ModelFactory& factory, const ModelConfig& config) {
  const ModelDescriptor& descriptor = *factory.descriptor;
  if (!descriptor.capabilities.per_sun_precomputation) return 0.0;
  const bool bucketed =
      std::any_of(descriptor.parameters.begin(), descriptor.parameters.end(),
                  [](const auto& p) { return p.name == "sun_zenith_bucket_deg"; });
  if (!bucketed) return 0.0;
  return degrees_to_radians(validated_config(descriptor, config).option("sun_zenith_bucket_deg"));
}

// The darkest sun zenith that still needs a state, rad: the dark threshold, else the largest
// zenith the model answers.
double last_zenith_rad(const ModelDescriptor& descriptor) {
  const auto& capabilities = descriptor.capabilities;
  return degrees_to_radians(
      capabilities.dark_beyond_sun_zenith_deg.value_or(capabilities.max_sun_zenith_deg));
}

}  // namespace

std::size_t DaySunStates::bucket_count(const ModelFactory& factory, const ModelConfig& config) {
  const double width = bucket_width_rad(factory, config);
  if (!(width > 0.0)) return 0;
  // The same rounding as the models' (sun_zenith_bucket_centre): the last bucket is the one the
  // dark threshold itself falls in.
  const double last = sun_zenith_bucket_centre(last_zenith_rad(*factory.descriptor), width);
  return static_cast<std::size_t>(std::lround(last / width)) + 1;
}

DaySunStates::DaySunStates(const TableStore& tables,
                           std::vector<std::pair<const ModelFactory*, ModelConfig>> configurations,
                           const TableCache* cache)
    : tables_(tables), cache_(cache) {
  for (auto& [factory, config] : configurations) {
    const std::size_t buckets = bucket_count(*factory, config);
    if (buckets == 0) continue;
    progress_[factory->descriptor->id].total += buckets;
    passes_.push_back({factory, std::move(config), buckets});
  }
  if (!passes_.empty()) thread_ = std::thread([this] { run(); });
}

DaySunStates::~DaySunStates() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
}

std::map<std::string, DaySunStates::Progress> DaySunStates::progress() const {
  std::lock_guard lock(mutex_);
  return progress_;
}

void DaySunStates::run() {
  // SCHED_IDLE for this thread only, so that the HTTP workers get the cores first
  // (background_priority.h); it logs when that is refused.
  lower_this_thread_to_idle_priority();
  for (const Pass& pass : passes_) {
    if (stop_) return;
    try {
      run_pass(pass);
    } catch (const PrecomputeCancelled&) {
      return;
    } catch (const std::exception& e) {
      spdlog::error("day sun states: {} stopped: {}", pass.factory->descriptor->id, e.what());
    }
  }
}

void DaySunStates::run_pass(const Pass& pass) {
  const std::string& id = pass.factory->descriptor->id;
  // Wait for the configuration's tables, built by the store's builders; never start a build.
  while (true) {
    if (stop_) return;
    const auto state = tables_.config_state(*pass.factory, pass.config);
    if (state && state->status == api::ModelState::Status::ready) break;
    if (state && state->status == api::ModelState::Status::failed) {
      spdlog::warn("day sun states: {} tables failed, no pass", id);
      return;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  const std::shared_ptr<const SkyModel> model = tables_.model(*pass.factory, pass.config);
  PrecomputeContext context;
  context.cancel = &stop_;
  context.cache = cache_;
  context.threads = 1;
  // Into the disk cache, not the model's memory (day_sun_states.h).
  context.keep_sun_state = false;
  const double width = bucket_width_rad(*pass.factory, pass.config);
  const double last = last_zenith_rad(*pass.factory->descriptor);
  const std::size_t computed_before = model->sun_states_built();
  const auto start = std::chrono::steady_clock::now();
  for (std::size_t b = 0; b < pass.buckets; ++b) {
    context.check_cancelled();
    // The bucket's centre, or for the last bucket the dark threshold itself (its centre may lie
    // beyond it, where the state would be dark and nothing built).
    const SunPosition sun{std::min(static_cast<double>(b) * width, last), 0.0};
    model->prepare_sun(sun, context);
    std::lock_guard lock(mutex_);
    ++progress_[id].built;
  }
  // The states it computed were freed in its thread's arena.
  release_free_heap_memory_now();
  spdlog::info(
      "day sun states: {} {} buckets ready in {:.1f} s ({} computed, the rest from the "
      "disk cache)",
      id, pass.buckets,
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
      model->sun_states_built() - computed_before);
}

}  // namespace clearsky::server
