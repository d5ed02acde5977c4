// Where handlers get built models from: the registered factories and, for a (model,
// configuration) pair, the immutable SkyModel with its tables. The server implements it with
// its table store (build on demand, single-flight, disk cache); tests may implement it with
// any factory list. Implementations must be thread-safe.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>

#include "models/core/sky_model.h"

namespace clearsky::api {

// The state of a model's default tables, as GET /v1/models reports it.
struct ModelState {
  enum class Status { queued, precomputing, ready, failed };
  Status status = Status::queued;
  double progress = 0;             // [0, 1]
  std::string stage;               // the precomputation's current stage
  std::string error;               // when failed
  double precompute_seconds = 0;   // measured build (or cache load) time, when ready
  std::size_t table_bytes = 0;     // SkyModel::table_bytes(), when ready
  bool loaded_from_cache = false;  // whether the disk cache supplied the tables
};

std::string_view to_string(ModelState::Status status);

// Who asks for a model: the network address of the HTTP client (the server limits the table
// builds each client may trigger), or empty for the server's own work (evaluations, jobs,
// prebuilt tables), which is not limited.
struct ModelRequester {
  std::string client_address;
};

class ModelProvider {
 public:
  virtual ~ModelProvider() = default;
  virtual std::span<const ModelFactory> factories() const = 0;
  // The model built with config. Throws ApiError: 400 for a configuration the descriptor
  // rejects, 503 (with Retry-After) while its tables are being built or when they do not fit
  // the server's table memory, 429 (with Retry-After) when the requester triggered too many
  // builds lately, 500 when the build failed.
  virtual std::shared_ptr<const SkyModel> model(const ModelFactory& factory,
                                                const ModelConfig& config,
                                                const ModelRequester& requester) const = 0;
  // The same for the server's own work (no requester). Implementations that override the
  // other overload bring this one into scope with `using api::ModelProvider::model;`.
  std::shared_ptr<const SkyModel> model(const ModelFactory& factory,
                                        const ModelConfig& config) const {
    return model(factory, config, ModelRequester{});
  }
  // A model and whether it is the fallback's.
  struct ServedModel {
    std::shared_ptr<const SkyModel> model;
    bool fallback = false;
  };
  // The fallback's configuration (a cheaper quality level of the same request:
  // docs/quality-levels.md "Serving at once"), made only when it is needed: nearly every
  // request finds its own tables ready, and making the draft's configuration on each was a
  // twentieth of a radiance request's instructions (docs/performance.md "A radiance request
  // through the server"). Empty: no fallback; nullopt: the fallback is config itself.
  using FallbackConfig = std::function<std::optional<ModelConfig>()>;
  // The model built with config or, while config's tables are still being built and the
  // fallback's are ready, the fallback's model. Without a fallback, or when neither is ready,
  // as model(). This default implementation never falls back.
  virtual ServedModel model_or_fallback(const ModelFactory& factory, const ModelConfig& config,
                                        const FallbackConfig& fallback,
                                        const ModelRequester& requester) const {
    (void)fallback;
    return {model(factory, config, requester), false};
  }
  virtual ModelState default_state(const ModelFactory& factory) const = 0;
  // The state of config's tables (a quality level's, for /readyz); nullopt when they were
  // neither built nor asked for. This default implementation knows only the defaults.
  virtual std::optional<ModelState> config_state(const ModelFactory& factory,
                                                 const ModelConfig& config) const {
    if (config.canonical_string() != ModelConfig{}.canonical_string()) return std::nullopt;
    return default_state(factory);
  }
  // Whether the tables the server builds at start are ready (/readyz answers 200). This default
  // implementation: every model's default tables.
  virtual bool start_builds_ready() const {
    for (const ModelFactory& f : factories()) {
      if (default_state(f).status != ModelState::Status::ready) return false;
    }
    return true;
  }
  // The model's per-sun state (SkyModel::prepare_sun; sun already checked). Providers may
  // share it between requests for the same model and sun: it is immutable.
  virtual std::shared_ptr<const SunState> sun_state(const std::shared_ptr<const SkyModel>& model,
                                                    const SunPosition& sun) const {
    return model->prepare_sun(sun);
  }
};

}  // namespace clearsky::api
