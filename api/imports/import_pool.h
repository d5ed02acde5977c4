// The dataset imports (POST /v1/datasets) run in the background on a bounded WorkerPool
// (api/work/worker_pool.h: never the HTTP query threads, a full queue refuses with 503, each
// worker with its own database connection, reset after a failure). Each import is a row of
// the imports table (storage/repositories/import_repository.h) written before it is queued,
// so its state survives a restart; the live progress of running imports is kept here in
// memory (the import's transaction holds SQLite's write lock, so progress is not written
// while it runs) and merged into the stored row by imports_api.h.
// An uploaded archive's spool file belongs to its task and is removed when the import ends,
// whatever happened, before its final state is recorded.
// Thread-safety: every member may be called from any thread.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "api/datasets/upload_spool.h"
#include "api/work/worker_pool.h"
#include "storage/importers/import_byte_budget.h"
#include "storage/importers/kider_format.h"
#include "storage/repositories/import_repository.h"
#include "storage/sqlite/database.h"

namespace clearsky::api {

struct ImportPoolOptions {
  unsigned workers = 1;
  std::size_t max_queued = 8;
  // Told how each import ended (ok false: message is the error), on the worker thread; the
  // server logs it. Also told when an outcome cannot be recorded.
  std::function<void(std::int64_t id, bool ok, const std::string& message)> log;
  // The bytes each import may read (storage/importers/import_byte_budget.h).
  storage::ImportByteLimits limits;
};

class ImportPool {
 public:
  using OpenDatabase = WorkerPool::OpenDatabase;

  ImportPool(OpenDatabase open_database, const ImportPoolOptions& options = {});
  // Lets running imports end; queued ones are recorded as failed (cancelled) and their spool
  // files removed; then joins the workers.
  ~ImportPool();
  ImportPool(const ImportPool&) = delete;
  ImportPool& operator=(const ImportPool&) = delete;

  // Records the import (queued) through db, the caller's connection, and queues it; returns
  // its id. source is the archive or folder to read: the finished spool's file for an upload
  // (the pool then owns the spool) or a server-side path, canonical and read confined to
  // confine_to, the import root it resolved in (api/datasets/import_roots.h); site_clock the
  // site and clock of an archive's captures (api/datasets/import_site_clock.h). Throws ApiError
  // 503 (busy) when the queue is full, before anything is recorded.
  std::int64_t submit(storage::Database& db, const storage::NewImport& what,
                      const std::filesystem::path& source, std::unique_ptr<UploadSpool> spool = {},
                      const std::filesystem::path& confine_to = {},
                      const storage::KiderImportOptions& site_clock = {});
  // The progress of an import running in this pool; nullopt when it is not running here.
  std::optional<storage::ImportProgress> live_progress(std::int64_t id) const;
  // The bytes each import may read.
  const storage::ImportByteLimits& limits() const { return options_.limits; }
  // Blocks until nothing is queued or running.
  void wait_idle();

 private:
  struct Task {
    std::int64_t id = 0;
    storage::NewImport what;
    std::filesystem::path source;
    std::unique_ptr<UploadSpool> spool;
    std::filesystem::path confine_to;
    storage::KiderImportOptions site_clock;
  };
  void run(storage::Database& db, Task& task);
  // The task is over, recorded or not: its upload removed, its live progress dropped.
  void end(Task& task);

  OpenDatabase open_database_;
  ImportPoolOptions options_;
  mutable std::mutex mutex_;
  std::map<std::int64_t, storage::ImportProgress> running_;
  WorkerPool workers_;  // last: stopped and joined before the progress map goes
};

}  // namespace clearsky::api
