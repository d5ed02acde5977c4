// SQL of the evaluation_tickets and evaluation_ticket_models tables
// (evaluation_ticket_repository.h).
#include "storage/repositories/evaluation_ticket_repository.h"

#include "storage/repositories/utc_clock.h"

namespace clearsky::storage {
namespace {

std::optional<std::string> optional_text(const Statement& row, int column) {
  if (row.is_null(column)) return std::nullopt;
  return row.column_text(column);
}

}  // namespace

std::int64_t EvaluationTicketRepository::create(const std::string& dataset,
                                                std::optional<std::int64_t> job_id,
                                                const std::vector<std::string>& model_ids) {
  Transaction transaction(db_);
  auto ticket = db_.prepare(
      "INSERT INTO evaluation_tickets (dataset, job_id, status, created_utc)"
      " VALUES (?, ?, 'queued', ?)");
  ticket.bind(1, dataset);
  if (job_id)
    ticket.bind(2, *job_id);
  else
    ticket.bind_null(2);
  ticket.bind(3, utc_now_iso8601());
  ticket.run();
  const std::int64_t id = db_.last_insert_rowid();
  auto model = db_.prepare(
      "INSERT INTO evaluation_ticket_models (ticket_id, position, model_id, status)"
      " VALUES (?, ?, ?, 'queued')");
  for (std::size_t i = 0; i < model_ids.size(); ++i) {
    model.reset();
    model.bind(1, id).bind(2, static_cast<std::int64_t>(i)).bind(3, model_ids[i]);
    model.run();
  }
  transaction.commit();
  return id;
}

void EvaluationTicketRepository::start(std::int64_t id) {
  auto statement = db_.prepare(
      "UPDATE evaluation_tickets SET status = 'running' WHERE id = ? AND status = 'queued'");
  statement.bind(1, id);
  statement.run();
}

void EvaluationTicketRepository::record_run(std::int64_t id, const std::string& model_id,
                                            std::int64_t run_id, const std::string& status) {
  auto update = db_.prepare(
      "UPDATE evaluation_ticket_models SET status = ? WHERE ticket_id = ? AND run_id = ?");
  update.bind(1, status).bind(2, id).bind(3, run_id);
  update.run();
  if (db_.changes() > 0) return;
  auto first_queued = db_.prepare(
      "UPDATE evaluation_ticket_models SET run_id = ?, status = ? WHERE ticket_id = ? AND"
      " position = (SELECT min(position) FROM evaluation_ticket_models"
      "             WHERE ticket_id = ? AND model_id = ? AND status = 'queued')");
  first_queued.bind(1, run_id).bind(2, status).bind(3, id).bind(4, id).bind(5, model_id);
  first_queued.run();
  if (db_.changes() > 0) return;
  // A model the ticket did not list (the request named it in another way, e.g. "all" of a
  // set that changed): it is recorded after the others rather than lost.
  auto append = db_.prepare(
      "INSERT INTO evaluation_ticket_models (ticket_id, position, model_id, run_id, status)"
      " VALUES (?, (SELECT coalesce(max(position) + 1, 0) FROM evaluation_ticket_models"
      "             WHERE ticket_id = ?), ?, ?, ?)");
  append.bind(1, id).bind(2, id).bind(3, model_id).bind(4, run_id).bind(5, status);
  append.run();
}

void EvaluationTicketRepository::finish(std::int64_t id, const std::string& status,
                                        const std::string& error, const std::string& model_error) {
  Transaction transaction(db_);
  auto ticket = db_.prepare(
      "UPDATE evaluation_tickets SET status = ?, finished_utc = ?, error = ? WHERE id = ?");
  ticket.bind(1, status).bind(2, utc_now_iso8601());
  if (error.empty())
    ticket.bind_null(3);
  else
    ticket.bind(3, error);
  ticket.bind(4, id);
  ticket.run();
  auto queued = db_.prepare(
      "UPDATE evaluation_ticket_models SET status = ?, error = ?"
      " WHERE ticket_id = ? AND status = 'queued'");
  queued.bind(1, status == "interrupted" ? "interrupted" : "skipped").bind(2, model_error);
  queued.bind(3, id);
  queued.run();
  auto running = db_.prepare(
      "UPDATE evaluation_ticket_models SET status = ?, error = ?"
      " WHERE ticket_id = ? AND status = 'running'");
  running.bind(1, status == "interrupted" ? "interrupted" : "failed");
  if (error.empty())
    running.bind_null(2);
  else
    running.bind(2, error);
  running.bind(3, id);
  running.run();
  transaction.commit();
}

int EvaluationTicketRepository::interrupt_unfinished(const std::string& queued_error,
                                                     const std::string& running_error) {
  Transaction transaction(db_);
  auto models = db_.prepare(
      "UPDATE evaluation_ticket_models SET status = 'interrupted',"
      " error = CASE status WHEN 'queued' THEN ? ELSE ? END"
      " WHERE status IN ('queued', 'running') AND ticket_id IN"
      " (SELECT id FROM evaluation_tickets WHERE status IN ('queued', 'running'))");
  models.bind(1, queued_error).bind(2, running_error);
  models.run();
  auto tickets = db_.prepare(
      "UPDATE evaluation_tickets SET status = 'interrupted', finished_utc = ?,"
      " error = CASE status WHEN 'queued' THEN ? ELSE ? END"
      " WHERE status IN ('queued', 'running')");
  tickets.bind(1, utc_now_iso8601()).bind(2, queued_error).bind(3, running_error);
  tickets.run();
  const int count = db_.changes();
  transaction.commit();
  return count;
}

std::optional<TicketRecord> EvaluationTicketRepository::get(std::int64_t id) {
  auto ticket = db_.prepare(
      "SELECT id, dataset, job_id, status, created_utc, finished_utc, error"
      " FROM evaluation_tickets WHERE id = ?");
  ticket.bind(1, id);
  if (!ticket.step()) return std::nullopt;
  TicketRecord record;
  record.id = ticket.column_int64(0);
  record.dataset = ticket.column_text(1);
  if (!ticket.is_null(2)) record.job_id = ticket.column_int64(2);
  record.status = ticket.column_text(3);
  record.created_utc = ticket.column_text(4);
  record.finished_utc = optional_text(ticket, 5);
  record.error = optional_text(ticket, 6);
  auto models = db_.prepare(
      "SELECT model_id, run_id, status, error FROM evaluation_ticket_models"
      " WHERE ticket_id = ? ORDER BY position");
  models.bind(1, id);
  while (models.step()) {
    TicketModelRecord model;
    model.model_id = models.column_text(0);
    if (!models.is_null(1)) model.run_id = models.column_int64(1);
    model.status = models.column_text(2);
    model.error = optional_text(models, 3);
    record.models.push_back(std::move(model));
  }
  return record;
}

}  // namespace clearsky::storage
