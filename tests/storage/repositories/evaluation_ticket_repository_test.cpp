// Tests of the stored evaluation tickets (storage/repositories/evaluation_ticket_repository.h):
// every model is listed from the start, gets its run as it starts, models left unrun are
// skipped or interrupted with the reason, and start-up interrupts what a crash left.
#include "storage/repositories/evaluation_ticket_repository.h"

#include <gtest/gtest.h>

#include "storage/schema/migrations.h"
#include "tests/support/temp_dir.h"

namespace clearsky::storage {
namespace {

std::vector<std::string> statuses(const TicketRecord& ticket) {
  std::vector<std::string> out;
  for (const TicketModelRecord& m : ticket.models) out.push_back(m.status);
  return out;
}

TEST(EvaluationTicketRepository, ListsEveryModelQueuedThenEachRunAsItStartsAndEnds) {
  Database db = Database::open(":memory:");
  migrate(db);
  EvaluationTicketRepository tickets(db);
  const std::int64_t id = tickets.create("set", 4, {"preetham", "hosek", "preetham"});
  auto ticket = tickets.get(id);
  ASSERT_TRUE(ticket);
  EXPECT_EQ(ticket->status, "queued");
  EXPECT_EQ(ticket->dataset, "set");
  EXPECT_EQ(ticket->job_id, 4);
  EXPECT_FALSE(ticket->finished_utc);
  EXPECT_EQ(statuses(*ticket), (std::vector<std::string>{"queued", "queued", "queued"}));
  EXPECT_FALSE(ticket->models[0].run_id);

  tickets.start(id);
  tickets.record_run(id, "preetham", 11, "running");
  tickets.record_run(id, "preetham", 11, "succeeded");
  tickets.record_run(id, "hosek", 12, "running");
  ticket = tickets.get(id);
  EXPECT_EQ(ticket->status, "running");
  EXPECT_EQ(statuses(*ticket), (std::vector<std::string>{"succeeded", "running", "queued"}));
  EXPECT_EQ(ticket->models[0].run_id, 11);
  EXPECT_EQ(ticket->models[1].run_id, 12);
  EXPECT_FALSE(ticket->models[2].run_id);
  // The same model twice: the second entry gets the second run.
  tickets.record_run(id, "hosek", 12, "succeeded");
  tickets.record_run(id, "preetham", 13, "running");
  ticket = tickets.get(id);
  EXPECT_EQ(ticket->models[2].run_id, 13);
  tickets.record_run(id, "preetham", 13, "failed");
  tickets.finish(id, "failed", "boom", "not run");
  ticket = tickets.get(id);
  EXPECT_EQ(ticket->status, "failed");
  EXPECT_EQ(ticket->error, "boom");
  EXPECT_TRUE(ticket->finished_utc);
  EXPECT_EQ(statuses(*ticket), (std::vector<std::string>{"succeeded", "succeeded", "failed"}));
}

TEST(EvaluationTicketRepository, AFailureSkipsTheModelsStillQueued) {
  Database db = Database::open(":memory:");
  migrate(db);
  EvaluationTicketRepository tickets(db);
  const std::int64_t id = tickets.create("set", std::nullopt, {"a", "b", "c"});
  tickets.start(id);
  tickets.record_run(id, "a", 1, "running");
  tickets.record_run(id, "a", 1, "failed");
  tickets.finish(id, "failed", "a failed", "not run: the ticket failed first");
  const auto ticket = tickets.get(id);
  EXPECT_EQ(statuses(*ticket), (std::vector<std::string>{"failed", "skipped", "skipped"}));
  EXPECT_FALSE(ticket->models[0].error);
  EXPECT_EQ(ticket->models[1].error, "not run: the ticket failed first");
  EXPECT_FALSE(ticket->models[1].run_id);
}

TEST(EvaluationTicketRepository, StartUpInterruptsWhatAKilledProcessLeft) {
  clearsky::testing::TempDir dir;
  const auto path = dir.path / "db.sqlite";
  std::int64_t running = 0, queued = 0, done = 0;
  {
    Database db = open_database(path);
    EvaluationTicketRepository tickets(db);
    done = tickets.create("set", std::nullopt, {"a"});
    tickets.start(done);
    tickets.record_run(done, "a", 1, "running");
    tickets.record_run(done, "a", 1, "succeeded");
    tickets.finish(done, "succeeded", "", "");
    running = tickets.create("set", std::nullopt, {"a", "b"});
    tickets.start(running);
    tickets.record_run(running, "a", 2, "running");
    queued = tickets.create("set", std::nullopt, {"b"});
  }
  Database db = open_database(path);
  EvaluationTicketRepository tickets(db);
  EXPECT_EQ(tickets.interrupt_unfinished("before", "during"), 2);
  EXPECT_EQ(tickets.interrupt_unfinished("before", "during"), 0);
  const auto r = tickets.get(running);
  EXPECT_EQ(r->status, "interrupted");
  EXPECT_EQ(r->error, "during");
  EXPECT_TRUE(r->finished_utc);
  EXPECT_EQ(statuses(*r), (std::vector<std::string>{"interrupted", "interrupted"}));
  EXPECT_EQ(r->models[0].run_id, 2);
  EXPECT_EQ(r->models[0].error, "during");
  EXPECT_EQ(r->models[1].error, "before");
  const auto q = tickets.get(queued);
  EXPECT_EQ(q->status, "interrupted");
  EXPECT_EQ(q->error, "before");
  EXPECT_EQ(tickets.get(done)->status, "succeeded");
  EXPECT_EQ(statuses(*tickets.get(done)), std::vector<std::string>{"succeeded"});
  // Ids go on after the restart.
  EXPECT_EQ(tickets.create("set", std::nullopt, {"a"}), queued + 1);
}

}  // namespace
}  // namespace clearsky::storage
