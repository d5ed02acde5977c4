// Background evaluations with their stored tickets (evaluation_pool.h).
#include "api/evaluation/evaluation_pool.h"

#include <stdexcept>

#include "api/evaluation/broadband_evaluation_runner.h"
#include "storage/repositories/evaluation_ticket_repository.h"

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

// The ids the ticket lists, in the order the run evaluates them ("all" on a broadband
// irradiance dataset: the models with a broadband answer); the request's own names when they do
// not resolve (the run then fails, and the ticket says so).
std::vector<std::string> ticket_model_ids(const std::vector<std::string>& requested,
                                          std::span<const ModelFactory> available, bool broadband) {
  try {
    std::vector<std::string> ids;
    for (const ModelFactory* factory :
         broadband ? broadband_models(requested, available) : resolve_models(requested, available))
      ids.push_back(factory->descriptor->id);
    return ids;
  } catch (const std::exception&) {
    return requested;
  }
}

TicketState to_state(const storage::TicketRecord& record) {
  TicketState state;
  state.id = record.id;
  state.dataset = record.dataset;
  state.status = record.status;
  state.error = record.error.value_or("");
  state.created_utc = record.created_utc;
  state.finished_utc = record.finished_utc;
  for (const storage::TicketModelRecord& m : record.models) {
    state.models.push_back({m.model_id, m.run_id, m.status, m.error.value_or("")});
    if (!m.run_id) continue;
    state.runs.push_back({*m.run_id, m.model_id, m.status});
    state.run_ids.push_back(*m.run_id);
  }
  return state;
}

constexpr const char* kNotRunAfterFailure = "not run: the ticket failed before this model ran";
constexpr const char* kStoppedBeforeRun = "interrupted: the server stopped before this model ran";
constexpr const char* kStoppedDuringRun = "interrupted: the server stopped during the run";

}  // namespace

EvaluationPool::EvaluationPool(OpenDatabase open_database, std::span<const ModelFactory> models,
                               const EvaluationPoolOptions& options)
    : open_database_(open_database),
      models_(models),
      options_(options),
      workers_(std::move(open_database), {options.workers, options.max_queued, "evaluations", 30}) {
}

EvaluationPool::~EvaluationPool() { workers_.stop(); }

std::int64_t EvaluationPool::submit(EvaluationRequest request, Finished on_finished) {
  WorkerPool::Reservation place = workers_.reserve();
  std::int64_t id = 0;
  {
    storage::Database db = open_database_();
    id = storage::EvaluationTicketRepository(db).create(
        request.dataset, request.job_id,
        ticket_model_ids(request.models, models_, is_broadband_dataset(db, request.dataset)));
  }
  request.options.capture_threads = options_.capture_threads;
  auto shared_request = std::make_shared<EvaluationRequest>(std::move(request));
  auto finished = std::make_shared<Finished>(std::move(on_finished));
  WorkerTask task;
  task.started = [this, id] {
    storage::Database db = open_database_();
    storage::EvaluationTicketRepository(db).start(id);
  };
  task.run = [this, id, shared_request, finished](storage::Database& db) {
    // Each model's run is written to the ticket on the worker's connection as it changes.
    EvaluationRequest recorded = *shared_request;
    if (recorded.provider == nullptr) recorded.provider = provider_.load();
    recorded.on_run_status = [&db, id](std::int64_t run_id, const std::string& model,
                                       const std::string& status) {
      storage::EvaluationTicketRepository(db).record_run(id, model, run_id, status);
    };
    // A broadband irradiance series is compared by its own runner (docs/data-api.md
    // "Evaluations of broadband irradiance"), captures by run_evaluation; the kind is read when
    // the ticket runs, as the dataset is.
    if (is_broadband_dataset(db, recorded.dataset))
      run_broadband_evaluation(db, recorded, models_);
    else
      run_evaluation(db, recorded, models_);
    tell(*finished, finish(id, "succeeded", ""));
  };
  task.failed = [this, id, finished](const std::string& error) {
    tell(*finished, finish(id, "failed", error));
  };
  task.dropped = [this, id] {
    // A clean stop before the ticket ran: recorded now rather than at the next start.
    storage::Database db = open_database_();
    storage::EvaluationTicketRepository(db).finish(id, "interrupted", kStoppedBeforeRun,
                                                   kStoppedBeforeRun);
  };
  workers_.submit(std::move(place), std::move(task));
  return id;
}

TicketState EvaluationPool::finish(std::int64_t ticket, const std::string& status,
                                   const std::string& error) {
  storage::Database db = open_database_();
  storage::EvaluationTicketRepository tickets(db);
  tickets.finish(ticket, status, error, kNotRunAfterFailure);
  const auto record = tickets.get(ticket);
  if (!record) throw std::runtime_error("ticket " + std::to_string(ticket) + " disappeared");
  return to_state(*record);
}

std::optional<TicketState> EvaluationPool::ticket(std::int64_t id) const {
  storage::Database db = open_database_();
  return load_ticket(db, id);
}

void EvaluationPool::wait_idle() { workers_.wait_idle(); }

std::optional<TicketState> load_ticket(storage::Database& db, std::int64_t id) {
  const auto record = storage::EvaluationTicketRepository(db).get(id);
  if (!record) return std::nullopt;
  return to_state(*record);
}

int interrupt_unfinished_tickets(storage::Database& db) {
  return storage::EvaluationTicketRepository(db).interrupt_unfinished(kStoppedBeforeRun,
                                                                      kStoppedDuringRun);
}

nlohmann::ordered_json ticket_to_json(const TicketState& ticket) {
  nlohmann::ordered_json ids = nlohmann::ordered_json::array();
  for (const TicketRun& run : ticket.runs) ids.push_back(run.id);
  nlohmann::ordered_json models = nlohmann::ordered_json::array();
  for (const TicketModel& model : ticket.models) {
    nlohmann::ordered_json entry{
        {"model", model.model},
        {"run", model.run ? nlohmann::ordered_json(*model.run) : nlohmann::ordered_json(nullptr)},
        {"status", model.status}};
    if (!model.error.empty()) entry["error"] = model.error;
    models.push_back(std::move(entry));
  }
  nlohmann::ordered_json j{
      {"ticket", ticket.id},
      {"dataset", ticket.dataset},
      {"status", ticket.status},
      {"created", ticket.created_utc},
      {"finished", ticket.finished_utc ? nlohmann::ordered_json(*ticket.finished_utc)
                                       : nlohmann::ordered_json(nullptr)},
      {"runs", ids},
      {"models", models}};
  if (!ticket.error.empty()) j["error"] = ticket.error;
  return j;
}

std::string ticket_location(std::int64_t id) {
  return "/v1/evaluations/tickets/" + std::to_string(id);
}

}  // namespace clearsky::api
