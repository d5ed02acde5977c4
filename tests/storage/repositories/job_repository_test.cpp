// Tests of the scheduler's writes to the jobs table (storage/repositories/job_repository.h):
// the next run set alone, and the compare-and-set claim of a due run.
#include "storage/repositories/job_repository.h"

#include <gtest/gtest.h>

#include "storage/repositories/dataset_repository.h"
#include "storage/schema/migrations.h"

namespace clearsky::storage {
namespace {

TEST(JobRepository, ClaimingADueRunSucceedsOnce) {
  Database db = Database::open(":memory:");
  migrate(db);
  JobRecord job;
  job.name = "j";
  job.schedule = "0 * * * *";
  job.dataset_id = DatasetRepository(db).find_or_create("d", "kider2014");
  job.models = "all";
  const std::int64_t id = JobRepository(db).create(job);
  JobRepository jobs(db);
  EXPECT_FALSE(jobs.get(id)->next_run_utc.has_value());
  EXPECT_TRUE(jobs.set_next_run(id, std::string("2026-11-21T11:00:00Z")));
  EXPECT_TRUE(jobs.claim_run(id, "2026-11-21T11:00:00Z", "2026-11-21T11:00:05Z",
                             std::string("2026-11-21T12:00:00Z")));
  // A second scheduler that read the same due time claims nothing.
  EXPECT_FALSE(jobs.claim_run(id, "2026-11-21T11:00:00Z", "2026-11-21T11:00:06Z",
                              std::string("2026-11-21T12:00:00Z")));
  const JobRecord stored = *jobs.get(id);
  EXPECT_EQ(*stored.last_run_utc, "2026-11-21T11:00:05Z");
  EXPECT_EQ(*stored.next_run_utc, "2026-11-21T12:00:00Z");
  EXPECT_TRUE(jobs.set_next_run(id, std::nullopt));
  EXPECT_FALSE(jobs.get(id)->next_run_utc.has_value());
  EXPECT_FALSE(jobs.set_next_run(id + 1, std::nullopt));
}

}  // namespace
}  // namespace clearsky::storage
