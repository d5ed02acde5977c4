// Background evaluation workers (evaluation_pool.h).
#include "api/evaluation/evaluation_pool.h"

#include "api/error/api_error.h"

namespace clearsky::api {

EvaluationPool::EvaluationPool(OpenDatabase open_database, std::span<const ModelFactory> models,
                               const EvaluationPoolOptions& options)
    : open_database_(std::move(open_database)), models_(models), options_(options) {
  const unsigned workers = std::max(1u, options_.workers);
  for (unsigned i = 0; i < workers; ++i) threads_.emplace_back([this] { work(); });
}

EvaluationPool::~EvaluationPool() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
    queue_.clear();
  }
  wake_.notify_all();
  for (std::thread& t : threads_) t.join();
}

std::int64_t EvaluationPool::submit(EvaluationRequest request, Finished on_finished) {
  std::int64_t id = 0;
  {
    std::lock_guard lock(mutex_);
    if (queue_.size() >= options_.max_queued)
      throw ApiError(503, "busy", "",
                     std::to_string(queue_.size()) + " evaluations are queued; try again later",
                     30);
    id = next_ticket_++;
    tickets_[id] = TicketState{id, "queued", {}, {}};
    request.options.capture_threads = options_.capture_threads;
    queue_.push_back(Task{id, std::move(request), std::move(on_finished)});
  }
  wake_.notify_one();
  return id;
}

std::optional<TicketState> EvaluationPool::ticket(std::int64_t id) const {
  std::lock_guard lock(mutex_);
  const auto found = tickets_.find(id);
  if (found == tickets_.end()) return std::nullopt;
  return found->second;
}

void EvaluationPool::wait_idle() {
  std::unique_lock lock(mutex_);
  idle_.wait(lock, [this] { return queue_.empty() && running_ == 0; });
}

void EvaluationPool::work() {
  std::optional<storage::Database> db;
  for (;;) {
    Task task;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
      if (stopping_) return;
      task = std::move(queue_.front());
      queue_.pop_front();
      ++running_;
      tickets_[task.ticket].status = "running";
    }
    TicketState done{task.ticket, "succeeded", {}, {}};
    try {
      if (!db) db.emplace(open_database_());
      const EvaluationReport report = run_evaluation(*db, task.request, models_);
      for (const ModelRun& run : report.models) done.run_ids.push_back(run.run_id);
    } catch (const std::exception& e) {
      done.status = "failed";
      done.error = e.what();
    }
    if (task.on_finished) {
      try {
        task.on_finished(done);
      } catch (...) {
        // A callback's failure must not kill the worker; the ticket still records the run.
      }
    }
    {
      std::lock_guard lock(mutex_);
      tickets_[task.ticket] = done;
      --running_;
    }
    idle_.notify_all();
  }
}

nlohmann::ordered_json ticket_to_json(const TicketState& ticket) {
  nlohmann::ordered_json runs = nlohmann::ordered_json::array();
  for (std::int64_t id : ticket.run_ids) runs.push_back(id);
  nlohmann::ordered_json j{{"ticket", ticket.id}, {"status", ticket.status}, {"runs", runs}};
  if (!ticket.error.empty()) j["error"] = ticket.error;
  return j;
}

}  // namespace clearsky::api
