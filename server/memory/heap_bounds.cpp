// glibc malloc bounds and trimming (heap_bounds.h).
#include "server/memory/heap_bounds.h"

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <cstring>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace clearsky::server {
namespace {

// Whether the environment chooses this malloc setting itself: its own variable, or the glibc
// tunable of that name in GLIBC_TUNABLES ("glibc.malloc.arena_max=2:...").
bool set_by_environment(const char* variable, const char* tunable) {
  if (std::getenv(variable) != nullptr) return true;
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  return tunables != nullptr && std::strstr(tunables, tunable) != nullptr;
}

}  // namespace

std::string bound_heap_arenas() {
#if defined(__GLIBC__)
  std::string done;
  if (set_by_environment("MALLOC_ARENA_MAX", "glibc.malloc.arena_max"))
    done = "malloc arenas as the environment sets them";
  else if (mallopt(M_ARENA_MAX, kHeapArenaMax) == 1)
    done = "malloc arenas <= " + std::to_string(kHeapArenaMax);
  else
    done = "malloc arenas not bounded (mallopt refused)";
  if (set_by_environment("MALLOC_MMAP_THRESHOLD_", "glibc.malloc.mmap_threshold"))
    done += ", mmap threshold as the environment sets it";
  else if (mallopt(M_MMAP_THRESHOLD, static_cast<int>(kHeapMmapThresholdBytes)) == 1)
    done += ", blocks >= " + std::to_string(kHeapMmapThresholdBytes) + " bytes mapped";
  else
    done += ", mmap threshold not set (mallopt refused)";
  return done;
#else
  return "malloc not bounded (not glibc)";
#endif
}

bool release_free_heap_memory() {
#if defined(__GLIBC__)
  using Clock = std::chrono::steady_clock;
  static std::atomic<Clock::rep> last_trim{0};
  const Clock::rep now = Clock::now().time_since_epoch().count();
  Clock::rep last = last_trim.load();
  const Clock::rep second =
      std::chrono::duration_cast<Clock::duration>(std::chrono::seconds(1)).count();
  if (last != 0 && now - last < second) return false;
  if (!last_trim.compare_exchange_strong(last, now)) return false;  // another thread trims
  malloc_trim(0);
  return true;
#else
  return false;
#endif
}

void release_free_heap_memory_now() {
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

}  // namespace clearsky::server
