// Background evaluations with their tickets (evaluation_pool.h).
#include "api/evaluation/evaluation_pool.h"

namespace clearsky::api {
namespace {

void tell(const EvaluationPool::Finished& finished, const TicketState& done) {
  if (!finished) return;
  try {
    finished(done);
  } catch (...) {
    // A callback's failure must not turn the run into a failure; the ticket holds the outcome.
  }
}

}  // namespace

EvaluationPool::EvaluationPool(OpenDatabase open_database, std::span<const ModelFactory> models,
                               const EvaluationPoolOptions& options)
    : models_(models),
      options_(options),
      workers_(std::move(open_database), {options.workers, options.max_queued, "evaluations", 30}) {
}

EvaluationPool::~EvaluationPool() { workers_.stop(); }

std::int64_t EvaluationPool::submit(EvaluationRequest request, Finished on_finished) {
  WorkerPool::Reservation place = workers_.reserve();
  std::int64_t id = 0;
  {
    std::lock_guard lock(mutex_);
    id = next_ticket_++;
    tickets_[id] = TicketState{id, "queued", {}, {}, {}};
  }
  request.options.capture_threads = options_.capture_threads;
  request.on_run_status = [this, id](std::int64_t run_id, const std::string& model,
                                     const std::string& status) {
    record_run(id, run_id, model, status);
  };
  auto shared_request = std::make_shared<EvaluationRequest>(std::move(request));
  auto finished = std::make_shared<Finished>(std::move(on_finished));
  WorkerTask task;
  task.started = [this, id] {
    std::lock_guard lock(mutex_);
    tickets_[id].status = "running";
  };
  task.run = [this, id, shared_request, finished](storage::Database& db) {
    run_evaluation(db, *shared_request, models_);
    tell(*finished, finish(id, "succeeded", ""));
  };
  task.failed = [this, id, finished](const std::string& error) {
    tell(*finished, finish(id, "failed", error));
  };
  workers_.submit(std::move(place), std::move(task));
  return id;
}

void EvaluationPool::record_run(std::int64_t ticket, std::int64_t run_id, const std::string& model,
                                const std::string& status) {
  std::lock_guard lock(mutex_);
  TicketState& state = tickets_[ticket];
  for (TicketRun& run : state.runs) {
    if (run.id != run_id) continue;
    run.status = status;
    return;
  }
  state.runs.push_back({run_id, model, status});
  state.run_ids.push_back(run_id);
}

TicketState EvaluationPool::finish(std::int64_t ticket, const std::string& status,
                                   const std::string& error) {
  std::lock_guard lock(mutex_);
  TicketState& state = tickets_[ticket];
  state.status = status;
  state.error = error;
  return state;
}

std::optional<TicketState> EvaluationPool::ticket(std::int64_t id) const {
  std::lock_guard lock(mutex_);
  const auto found = tickets_.find(id);
  if (found == tickets_.end()) return std::nullopt;
  return found->second;
}

void EvaluationPool::wait_idle() { workers_.wait_idle(); }

nlohmann::ordered_json ticket_to_json(const TicketState& ticket) {
  nlohmann::ordered_json ids = nlohmann::ordered_json::array();
  nlohmann::ordered_json runs = nlohmann::ordered_json::array();
  for (const TicketRun& run : ticket.runs) {
    ids.push_back(run.id);
    runs.push_back({{"model", run.model}, {"run", run.id}, {"status", run.status}});
  }
  nlohmann::ordered_json j{
      {"ticket", ticket.id}, {"status", ticket.status}, {"runs", ids}, {"models", runs}};
  if (!ticket.error.empty()) j["error"] = ticket.error;
  return j;
}

std::string ticket_location(std::int64_t id) {
  return "/v1/evaluations/tickets/" + std::to_string(id);
}

}  // namespace clearsky::api
