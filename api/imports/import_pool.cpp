// Background import workers (import_pool.h).
#include "api/imports/import_pool.h"

#include "api/datasets/datasets_api.h"
#include "api/error/api_error.h"

namespace clearsky::api {

ImportPool::ImportPool(OpenDatabase open_database, const ImportPoolOptions& options)
    : open_database_(std::move(open_database)), options_(options) {
  const unsigned workers = std::max(1u, options_.workers);
  for (unsigned i = 0; i < workers; ++i) threads_.emplace_back([this] { work(); });
}

ImportPool::~ImportPool() {
  std::deque<Task> dropped;
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
    dropped.swap(queue_);
  }
  wake_.notify_all();
  for (std::thread& t : threads_) t.join();
  if (dropped.empty()) return;
  try {
    storage::Database db = open_database_();
    for (Task& task : dropped) {
      task.spool.reset();
      storage::ImportRepository(db).fail(task.id, {}, "cancelled",
                                         "cancelled: the server stopped before the import ran");
    }
  } catch (const std::exception& e) {
    // Start-up marks them failed all the same (fail_unfinished).
    if (options_.log)
      options_.log(0, false, std::string("cannot record cancelled imports: ") + e.what());
  }
}

std::int64_t ImportPool::submit(storage::Database& db, const storage::NewImport& what,
                                const std::filesystem::path& source,
                                std::unique_ptr<UploadSpool> spool) {
  {
    std::lock_guard lock(mutex_);
    if (queue_.size() + reserved_ >= options_.max_queued)
      throw ApiError(503, "busy", "",
                     std::to_string(queue_.size()) + " imports are queued; try again later", 30);
    ++reserved_;
  }
  // The row is written without the lock held: the database may wait for an import's commit.
  std::int64_t id = 0;
  try {
    id = storage::ImportRepository(db).create(what);
  } catch (...) {
    {
      std::lock_guard lock(mutex_);
      --reserved_;
    }
    idle_.notify_all();
    throw;
  }
  {
    std::lock_guard lock(mutex_);
    --reserved_;
    queue_.push_back(Task{id, what, source, std::move(spool)});
  }
  wake_.notify_one();
  return id;
}

std::optional<storage::ImportProgress> ImportPool::live_progress(std::int64_t id) const {
  std::lock_guard lock(mutex_);
  const auto found = running_.find(id);
  if (found == running_.end()) return std::nullopt;
  return found->second;
}

void ImportPool::wait_idle() {
  std::unique_lock lock(mutex_);
  idle_.wait(lock, [this] { return queue_.empty() && reserved_ == 0 && running_.empty(); });
}

void ImportPool::work() {
  std::optional<storage::Database> db;
  for (;;) {
    Task task;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
      if (stopping_) return;
      task = std::move(queue_.front());
      queue_.pop_front();
      running_[task.id] = storage::ImportProgress{};
    }
    try {
      if (!db) db.emplace(open_database_());
      run(*db, task);
    } catch (const std::exception& e) {
      // Recording the outcome failed (the database is unavailable): start-up marks the row
      // failed if it is left unfinished.
      if (options_.log)
        options_.log(task.id, false, std::string("cannot record the outcome: ") + e.what());
      db.reset();
    }
    task.spool.reset();
    {
      std::lock_guard lock(mutex_);
      running_.erase(task.id);
    }
    idle_.notify_all();
  }
}

void ImportPool::run(storage::Database& db, Task& task) {
  storage::ImportRepository imports(db);
  imports.start(task.id);
  const auto record = [this, id = task.id](const storage::ImportProgress& p) {
    std::lock_guard lock(mutex_);
    running_[id] = p;
  };
  const auto last = [this, id = task.id] {
    std::lock_guard lock(mutex_);
    return running_[id];
  };
  std::string error_code;
  std::string error;
  nlohmann::ordered_json report;
  try {
    report = import_dataset(db, task.what.dataset, task.what.format, task.source, record);
  } catch (const ApiError& e) {
    error_code = e.code();
    error = e.what();
  } catch (const std::exception& e) {
    error_code = "internal_error";
    error = e.what();
  }
  // The upload is no longer needed whatever happened; removed before the outcome is recorded.
  task.spool.reset();
  if (error_code.empty()) {
    imports.succeed(task.id, last(), report.dump());
    if (options_.log)
      options_.log(task.id, true,
                   "into '" + task.what.dataset + "': " + std::to_string(report["added"].size()) +
                       " captures added, " + std::to_string(report["unchanged"].size()) +
                       " unchanged");
  } else {
    imports.fail(task.id, last(), error_code, error);
    if (options_.log) options_.log(task.id, false, "into '" + task.what.dataset + "': " + error);
  }
}

}  // namespace clearsky::api
