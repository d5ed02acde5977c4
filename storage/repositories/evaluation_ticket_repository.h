// Evaluation tickets (POST /v1/evaluations, scheduled jobs) as rows of the evaluation_tickets
// and evaluation_ticket_models tables (schema version 6, docs/data-api.md "Evaluation tickets"):
// a ticket and one entry per requested model are written in one transaction when the ticket is
// accepted, before it is queued, so that a crash leaves a record of every model it had still
// to run; start-up turns what a crash left queued or running into `interrupted`
// (interrupt_unfinished). Ids are never reused (AUTOINCREMENT). SQL on these tables lives only
// here.
//   ticket status: queued, running, succeeded, failed, interrupted
//   model status:  queued, running, succeeded, failed, skipped (an earlier model of the ticket
//                  failed), interrupted (the server stopped first)
// Thread-safety: as the Database it uses.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "storage/sqlite/database.h"

namespace clearsky::storage {

struct TicketModelRecord {
  std::string model_id;
  std::optional<std::int64_t> run_id;  // set when the model's run starts
  std::string status;
  std::optional<std::string> error;  // why a model was skipped or interrupted
};

struct TicketRecord {
  std::int64_t id = 0;
  std::string dataset;
  std::optional<std::int64_t> job_id;
  std::string status;
  std::string created_utc;
  std::optional<std::string> finished_utc;
  std::optional<std::string> error;
  std::vector<TicketModelRecord> models;  // in the order they run
};

class EvaluationTicketRepository {
 public:
  explicit EvaluationTicketRepository(Database& db) : db_(db) {}
  // A queued ticket with every model queued (one transaction); returns its id.
  std::int64_t create(const std::string& dataset, std::optional<std::int64_t> job_id,
                      const std::vector<std::string>& model_ids);
  // The ticket left the queue for a worker.
  void start(std::int64_t id);
  // The first queued entry of this model gets its run id and status (running when the run is
  // recorded); later calls with the same run id change the status (succeeded, failed).
  void record_run(std::int64_t id, const std::string& model_id, std::int64_t run_id,
                  const std::string& status);
  // Ends the ticket (succeeded, failed or interrupted, with the error when there is one); the
  // models still queued become `skipped` (failed) or `interrupted` with model_error, and
  // a running one (left by a failure before its run was told) `failed`. One transaction.
  void finish(std::int64_t id, const std::string& status, const std::string& error,
              const std::string& model_error);
  // Marks every ticket still queued or running, and its unfinished models, interrupted (at
  // start-up: a crash stopped them); a queued model gets queued_error, a running one
  // running_error. Returns the number of tickets.
  int interrupt_unfinished(const std::string& queued_error, const std::string& running_error);
  std::optional<TicketRecord> get(std::int64_t id);

 private:
  Database& db_;
};

}  // namespace clearsky::storage
