// What a precomputation receives besides its parameters: a progress sink, a cancellation
// flag, and an optional byte cache for its tables (the server backs it with versioned,
// checksummed files; models/ never opens files itself).
// Thread-safety: report() and cancelled() may be called from any worker thread.
#pragma once

#include <atomic>
#include <cstddef>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace clearsky {

class PrecomputeCancelled : public std::runtime_error {
 public:
  PrecomputeCancelled() : std::runtime_error("precomputation cancelled") {}
};

// A store of immutable blobs by key. load() returns nothing for a missing, stale or corrupt
// entry (the implementation verifies version and checksum); store() failures are not fatal.
class TableCache {
 public:
  virtual ~TableCache() = default;
  virtual std::optional<std::string> load(const std::string& key) const = 0;
  virtual void store(const std::string& key, std::string_view bytes) const = 0;
};

struct PrecomputeContext {
  // fraction in [0, 1], stage a short human-readable name ("transmittance", "order 3", ...).
  std::function<void(double fraction, std::string_view stage)> progress;
  const std::atomic<bool>* cancel = nullptr;
  const TableCache* cache = nullptr;
  unsigned threads = 0;  // 0: all cores
  // Models with per-sun states (Haber, Nishita96) keep at most this many bytes of them per
  // built configuration, least recently used dropped first (models/core/sun_state_cache.h);
  // the server sets it from `serve --sun-state-memory`.
  static constexpr std::size_t kDefaultSunStateMemoryBytes = std::size_t{256} << 20;
  std::size_t sun_state_memory_bytes = kDefaultSunStateMemoryBytes;
  // Models whose tables another live model already holds take those (Bruneton and Elek of one
  // configuration: one copy in memory); false builds or loads them anew (benchmarks of the
  // precomputation and of the cache, tests of the cache).
  bool reuse_live_tables = true;
  // A sun beyond the descriptor's dark_beyond_sun_zenith_deg gets a dark SunState at once
  // (SkyModel::prepare_sun); false prepares its state in full, so that its queries run the
  // whole computation (the contract test that checks the declared darkness against it).
  bool dark_sun_at_once = true;
  // false: a per-sun state prepared only to be stored in the disk cache (the server's background
  // pass over the day's states, docs/tables-and-memory.md) is not kept in the model's per-sun
  // memory cache once prepared (SunStateCache::get_or_build), so that the pass does not fill
  // that cache with states no request asked for.
  bool keep_sun_state = true;

  void report(double fraction, std::string_view stage) const {
    if (progress) progress(fraction, stage);
  }
  bool cancelled() const { return cancel != nullptr && cancel->load(std::memory_order_relaxed); }
  // Throws PrecomputeCancelled when cancellation was requested.
  void check_cancelled() const {
    if (cancelled()) throw PrecomputeCancelled();
  }
};

}  // namespace clearsky
