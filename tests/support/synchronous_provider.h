// A ModelProvider for api/ unit tests: builds each configuration once, synchronously, on the
// calling thread (the server's TableStore does the same in the background). Thread-safe.
#pragma once

#include <map>
#include <mutex>

#include "api/error/api_error.h"
#include "api/service/model_provider.h"

namespace clearsky::testing {

class SynchronousProvider final : public api::ModelProvider {
 public:
  explicit SynchronousProvider(std::vector<ModelFactory> factories)
      : factories_(std::move(factories)) {}
  std::span<const ModelFactory> factories() const override { return factories_; }
  using api::ModelProvider::model;
  std::shared_ptr<const SkyModel> model(const ModelFactory& factory, const ModelConfig& config,
                                        const api::ModelRequester&) const override {
    const std::string key = factory.descriptor->id + "|" + config.canonical_string();
    std::lock_guard lock(mutex_);
    auto& slot = built_[key];
    if (!slot) {
      try {
        slot = factory.create(config, {});
      } catch (const std::invalid_argument& e) {
        built_.erase(key);
        throw api::from_invalid_argument(e);
      }
    }
    return slot;
  }
  api::ModelState default_state(const ModelFactory& factory) const override {
    api::ModelState s;
    std::lock_guard lock(mutex_);
    if (built_.contains(factory.descriptor->id + "|" + ModelConfig{}.canonical_string())) {
      s.status = api::ModelState::Status::ready;
      s.progress = 1.0;
    }
    return s;
  }

 private:
  std::vector<ModelFactory> factories_;
  mutable std::mutex mutex_;
  mutable std::map<std::string, std::shared_ptr<const SkyModel>> built_;
};

}  // namespace clearsky::testing
