// The bounded worker pool that runs evaluations in the background (POST /v1/evaluations and
// scheduled jobs), separate from the HTTP query threads so that evaluations never starve
// queries: a fixed number of worker threads, a bounded queue (a full queue refuses with 503),
// each worker with its own database connection (storage/sqlite/database.h: one connection
// per thread). Each submission gets a ticket whose state (queued, running, succeeded, failed)
// and run ids are kept in memory; the runs themselves are in the database.
// Thread-safety: every member may be called from any thread.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include "api/evaluation/evaluation_runner.h"
#include "storage/sqlite/database.h"

namespace clearsky::api {

struct EvaluationPoolOptions {
  unsigned workers = 1;
  std::size_t max_queued = 16;
  // Threads each evaluation uses for its captures (EvaluationOptions::capture_threads).
  unsigned capture_threads = 1;
};

struct TicketState {
  std::int64_t id = 0;
  std::string status;  // queued, running, succeeded, failed
  std::vector<std::int64_t> run_ids;
  std::string error;
};

class EvaluationPool {
 public:
  using OpenDatabase = std::function<storage::Database()>;
  // Called on the worker thread when a submission ends (succeeded or not).
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
  struct Task {
    std::int64_t ticket = 0;
    EvaluationRequest request;
    Finished on_finished;
  };
  void work();

  OpenDatabase open_database_;
  std::span<const ModelFactory> models_;
  EvaluationPoolOptions options_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::condition_variable idle_;
  std::deque<Task> queue_;
  std::map<std::int64_t, TicketState> tickets_;
  std::int64_t next_ticket_ = 1;
  unsigned running_ = 0;
  bool stopping_ = false;
  std::vector<std::thread> threads_;
};

nlohmann::ordered_json ticket_to_json(const TicketState& ticket);

}  // namespace clearsky::api
