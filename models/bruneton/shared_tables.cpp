// One copy of equal Bruneton tables in memory (shared_tables.h).
#include "models/bruneton/shared_tables.h"

#include <chrono>
#include <condition_variable>
#include <map>
#include <mutex>
#include <set>

namespace clearsky::bruneton {

namespace {

struct Registry {
  std::mutex mutex;
  std::condition_variable changed;
  std::map<std::string, std::weak_ptr<const Tables>> live;
  std::set<std::string> building;
};

Registry& registry() {
  static Registry r;
  return r;
}

}  // namespace

SharedTablesResult shared_tables(const std::string& description,
                                 const std::function<Tables()>& make,
                                 const PrecomputeContext& context) {
  if (!context.reuse_live_tables) return {std::make_shared<const Tables>(make()), true};
  Registry& r = registry();
  std::unique_lock lock(r.mutex);
  while (true) {
    if (const auto it = r.live.find(description); it != r.live.end()) {
      if (std::shared_ptr<const Tables> tables = it->second.lock())
        return {std::move(tables), false};
      r.live.erase(it);
    }
    if (!r.building.contains(description)) break;
    // Another thread builds these tables: wait, in slices so that a cancellation is seen.
    r.changed.wait_for(lock, std::chrono::milliseconds(200));
    context.check_cancelled();
  }
  r.building.insert(description);
  lock.unlock();
  std::shared_ptr<const Tables> tables;
  try {
    tables = std::make_shared<const Tables>(make());
  } catch (...) {
    lock.lock();
    r.building.erase(description);
    r.changed.notify_all();
    throw;
  }
  lock.lock();
  r.building.erase(description);
  // Entries of tables no model holds any more go when another is added: the map stays as
  // small as the set of live configurations.
  std::erase_if(r.live, [](const auto& entry) { return entry.second.expired(); });
  r.live[description] = tables;
  r.changed.notify_all();
  return {std::move(tables), true};
}

}  // namespace clearsky::bruneton
