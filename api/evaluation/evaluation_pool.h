// The evaluations run in the background (POST /v1/evaluations and scheduled jobs) on a
// bounded WorkerPool (api/work/worker_pool.h: a full queue refuses with 503, each worker with
// its own database connection, reset after a failure). Each submission gets a ticket whose
// state (queued, running, succeeded, failed) is kept in memory, with each model's run listed
// as soon as the run starts (its id and status: running, succeeded, failed); the runs
// themselves are in the database. Tickets are not kept across a restart (docs/data-api.md
// "Durability"); their runs are.
// Thread-safety: every member may be called from any thread.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "api/evaluation/evaluation_runner.h"
#include "api/work/worker_pool.h"
#include "storage/sqlite/database.h"

namespace clearsky::api {

struct EvaluationPoolOptions {
  unsigned workers = 1;
  std::size_t max_queued = 16;
  // Threads each evaluation uses for its captures (EvaluationOptions::capture_threads).
  unsigned capture_threads = 1;
};

struct TicketRun {
  std::int64_t id = 0;
  std::string model;
  std::string status;  // running, succeeded, failed
};

struct TicketState {
  std::int64_t id = 0;
  std::string status;  // queued, running, succeeded, failed
  std::vector<std::int64_t> run_ids;
  std::string error;
  std::vector<TicketRun> runs;  // in the order they started
};

class EvaluationPool {
 public:
  using OpenDatabase = WorkerPool::OpenDatabase;
  // Called on the worker thread when a submission ends (succeeded or not), after its ticket
  // holds the outcome.
  using Finished = std::function<void(const TicketState&)>;

  EvaluationPool(OpenDatabase open_database, std::span<const ModelFactory> models,
                 const EvaluationPoolOptions& options = {});
  // Lets running evaluations end (queued ones are dropped), then joins the workers.
  ~EvaluationPool();
  EvaluationPool(const EvaluationPool&) = delete;
  EvaluationPool& operator=(const EvaluationPool&) = delete;

  // Queues a run; returns its ticket. Throws ApiError 503 (busy) when the queue is full.
  std::int64_t submit(EvaluationRequest request, Finished on_finished = {});
  std::optional<TicketState> ticket(std::int64_t id) const;
  // Blocks until nothing is queued or running.
  void wait_idle();
  std::span<const ModelFactory> models() const { return models_; }

 private:
  void record_run(std::int64_t ticket, std::int64_t run_id, const std::string& model,
                  const std::string& status);
  TicketState finish(std::int64_t ticket, const std::string& status, const std::string& error);

  std::span<const ModelFactory> models_;
  EvaluationPoolOptions options_;
  mutable std::mutex mutex_;
  std::map<std::int64_t, TicketState> tickets_;
  std::int64_t next_ticket_ = 1;
  WorkerPool workers_;  // last: stopped and joined before the tickets go
};

// {"ticket", "status", "runs": [ids], "models": [{"model", "run", "status"}], "error" (when
// failed)}; "runs" and "models" grow as each model's run starts.
nlohmann::ordered_json ticket_to_json(const TicketState& ticket);
// The path of a ticket.
std::string ticket_location(std::int64_t id);

}  // namespace clearsky::api
