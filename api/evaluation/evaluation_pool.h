// The evaluations run in the background (POST /v1/evaluations and scheduled jobs) on a
// bounded WorkerPool (api/work/worker_pool.h: a full queue refuses with 503, each worker with
// its own database connection, reset after a failure). Each submission gets a ticket, stored in
// the database before it is queued (storage/repositories/evaluation_ticket_repository.h) with
// every requested model `queued`; each model's entry gets its run id and status (running,
// succeeded, failed) as soon as the run starts and as it ends, and models an earlier failure
// left unrun become `skipped`. Tickets outlive the process and their ids are never reused; what
// a crash left queued or running reads `interrupted` after the next start
// (interrupt_unfinished_tickets; docs/data-api.md "Evaluation tickets" and "Durability").
// A ticket on a broadband irradiance dataset runs run_broadband_evaluation
// (broadband_evaluation_runner.h), one on captures run_evaluation; both report each model's
// run to the ticket alike.
// Thread-safety: every member may be called from any thread.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
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
  std::string status;  // running, succeeded, failed, interrupted
};

// One requested model of a ticket, whether or not its run started.
struct TicketModel {
  std::string model;
  std::optional<std::int64_t> run;  // set when its run starts
  std::string status;               // queued, running, succeeded, failed, skipped, interrupted
  std::string error;                // why it was skipped or interrupted
};

struct TicketState {
  std::int64_t id = 0;
  std::string dataset;
  std::string status;  // queued, running, succeeded, failed, interrupted
  std::vector<std::int64_t> run_ids;
  std::string error;
  std::vector<TicketRun> runs;      // the runs started, in the order they started
  std::vector<TicketModel> models;  // every requested model, in the order they run
  std::string created_utc;
  std::optional<std::string> finished_utc;
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

  // Records the ticket and queues it; returns its id. Throws ApiError 503 (busy) when the queue
  // is full (nothing recorded), storage::SqliteError when the ticket cannot be written.
  std::int64_t submit(EvaluationRequest request, Finished on_finished = {});
  // The stored ticket (of this process or an earlier one).
  std::optional<TicketState> ticket(std::int64_t id) const;
  // Blocks until nothing is queued or running.
  void wait_idle();
  std::span<const ModelFactory> models() const { return models_; }
  // The provider every later run takes its models from (EvaluationRequest::provider): the
  // server's TableStore, set once it exists. The caller keeps it alive until the pool is gone.
  void set_provider(const ModelProvider* provider) { provider_ = provider; }

 private:
  // The ticket's final state, after recording how it ended on a connection of its own.
  TicketState finish(std::int64_t ticket, const std::string& status, const std::string& error);

  OpenDatabase open_database_;
  std::span<const ModelFactory> models_;
  EvaluationPoolOptions options_;
  std::atomic<const ModelProvider*> provider_{nullptr};
  WorkerPool workers_;  // last: stopped and joined before the rest goes
};

// The ticket as stored (std::nullopt when there is none).
std::optional<TicketState> load_ticket(storage::Database& db, std::int64_t id);
// At start-up, before the pool runs: tickets and ticket models a stopped process left queued or
// running become `interrupted` with the reason; returns the number of tickets.
int interrupt_unfinished_tickets(storage::Database& db);

// {"ticket", "dataset", "status", "created", "finished", "runs": [ids], "models": [{"model",
// "run", "status", "error" (when skipped or interrupted)}], "error" (when failed or
// interrupted)}; "models" lists every requested model from the start ("run" null until its run
// starts); "runs" grows as each model's run starts.
nlohmann::ordered_json ticket_to_json(const TicketState& ticket);
// The path of a ticket.
std::string ticket_location(std::int64_t id);

}  // namespace clearsky::api
