// Shared helpers of the Bruneton/Elek tests: small configurations (so that each test
// precomputes in well under a second) and an in-memory TableCache.
#pragma once

#include <map>
#include <mutex>
#include <optional>
#include <string>

#include "models/bruneton/bruneton.h"

namespace clearsky::testing {

// A reduced 4D resolution and 3 wavelengths: fast, same code paths.
inline ModelConfig small_bruneton_config(int orders = 4) {
  ModelConfig c;
  c.wavelengths = WavelengthGrid::points({440.0, 550.0, 680.0});
  c.options["scattering_orders"] = orders;
  c.options["table_r_size"] = 8;
  c.options["table_mu_size"] = 32;
  c.options["table_mu_s_size"] = 8;
  c.options["table_nu_size"] = 4;
  return c;
}

// A TableCache in memory, counting its traffic; blobs can be tampered with.
class MemoryTableCache : public TableCache {
 public:
  std::optional<std::string> load(const std::string& key) const override {
    std::lock_guard lock(mutex_);
    ++loads;
    auto it = blobs.find(key);
    if (it == blobs.end()) return std::nullopt;
    return it->second;
  }
  void store(const std::string& key, std::string_view bytes) const override {
    std::lock_guard lock(mutex_);
    ++stores;
    blobs[key] = std::string(bytes);
  }
  mutable std::map<std::string, std::string> blobs;
  mutable int loads = 0;
  mutable int stores = 0;

 private:
  mutable std::mutex mutex_;
};

}  // namespace clearsky::testing
