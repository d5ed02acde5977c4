// Tests of a job's refit member at creation (api/jobs/job_refit.h, docs/data-api.md "Jobs"):
// stored and answered as given, and refused as POST /v1/fits refuses it, naming
// `refit.<member>`, as well as for what only a job can get wrong (its dataset given, a model the
// job does not evaluate, evaluation parameters the new fit sets).
#include "api/jobs/job_refit.h"

#include <gtest/gtest.h>

#include "api/jobs/jobs_api.h"
#include "models/registry.h"
#include "storage/repositories/dataset_repository.h"
#include "storage/schema/migrations.h"
#include "tests/support/api_refusal.h"

namespace clearsky::api {
namespace {

constexpr double kNow = 1795258800;  // 2026-11-21T11:00:00Z

struct Fixture {
  storage::Database db = storage::Database::open(":memory:");
  Fixture() {
    storage::migrate(db);
    storage::DatasetRepository(db).find_or_create("made", "kider2014");
  }
  // POST /v1/jobs with the given refit (and parameters).
  CreatedResource create(const std::string& refit, const std::string& parameters = "{}") {
    return create_job(db,
                      R"({"name": "refit", "schedule": "0 * * * *", "dataset": "made",
                          "models": ["preetham", "hosek"], "parameters": )" +
                          parameters + R"(, "refit": )" + refit + "}",
                      registered_models(), kNow);
  }
};

TEST(JobRefit, IsStoredAndAnsweredAsGivenWithNoFitBeforeTheFirstOccurrence) {
  Fixture f;
  const auto created = f.create(R"({"model": "preetham", "free": ["turbidity"],
                                    "bounds": {"turbidity": [2, 6]}, "max_evaluations": 40})");
  const auto& job = created.body;
  EXPECT_EQ(job["refit"]["model"], "preetham");
  EXPECT_EQ(job["refit"]["bounds"]["turbidity"][1], 6);
  EXPECT_EQ(job["refit"]["max_evaluations"], 40);
  EXPECT_TRUE(job["last_fit"].is_null());
  const auto shown = show_job(f.db, job["id"].get<std::int64_t>());
  EXPECT_EQ(shown["refit"], job["refit"]);
  // A job without refit answers null.
  const auto plain = create_job(f.db,
                                R"({"name": "plain", "schedule": "0 * * * *", "dataset": "made",
                                    "models": ["preetham"]})",
                                registered_models(), kNow);
  EXPECT_TRUE(plain.body["refit"].is_null());
  EXPECT_TRUE(plain.body["last_fit"].is_null());
}

TEST(JobRefit, RefusalsOfPostFitsNameTheRefitMember) {
  Fixture f;
  using clearsky::testing::refusal_of;
  const auto unknown_model = refusal_of([&] { f.create(R"({"model": "nonsense"})"); });
  EXPECT_EQ(unknown_model.status, 400);
  EXPECT_EQ(unknown_model.parameter, "refit.model");
  EXPECT_NE(unknown_model.message.find("refit.model: "), std::string::npos)
      << unknown_model.message;
  const auto bad_free =
      refusal_of([&] { f.create(R"({"model": "preetham", "free": ["nonsense"]})"); });
  EXPECT_EQ(bad_free.status, 400);
  EXPECT_EQ(bad_free.parameter, "refit.free") << bad_free.message;
  const auto bad_grid = refusal_of([&] { f.create(R"({"model": "preetham", "grid": [0]})"); });
  EXPECT_EQ(bad_grid.status, 400);
  EXPECT_EQ(bad_grid.parameter, "refit.grid");
  const auto unknown_member =
      refusal_of([&] { f.create(R"({"model": "preetham", "colour": "blue"})"); });
  EXPECT_EQ(unknown_member.status, 400);
  EXPECT_EQ(unknown_member.parameter, "refit.colour");
  const auto no_model = refusal_of([&] { f.create(R"({"free": ["turbidity"]})"); });
  EXPECT_EQ(no_model.status, 400);
  EXPECT_EQ(no_model.parameter, "refit.model");
  EXPECT_EQ(refusal_of([&] { f.create("[1]"); }).parameter, "refit");
  // Nothing was stored.
  EXPECT_TRUE(list_jobs(f.db).items.empty());
}

TEST(JobRefit, WhatOnlyAJobCanGetWrongIsRefused) {
  Fixture f;
  using clearsky::testing::refusal_of;
  const auto dataset = refusal_of([&] { f.create(R"({"model": "preetham", "dataset": "made"})"); });
  EXPECT_EQ(dataset.status, 400);
  EXPECT_EQ(dataset.parameter, "refit.dataset");
  const auto not_evaluated = refusal_of([&] { f.create(R"({"model": "nishita93"})"); });
  EXPECT_EQ(not_evaluated.status, 400);
  EXPECT_EQ(not_evaluated.parameter, "refit.model");
  // The new fit sets the turbidity and is the run's fit: neither may be given as well.
  const auto turbidity = refusal_of(
      [&] { f.create(R"({"model": "preetham", "free": ["turbidity"]})", R"({"turbidity": 3})"); });
  EXPECT_EQ(turbidity.status, 400);
  EXPECT_EQ(turbidity.parameter, "refit");
  const auto fit =
      refusal_of([&] { f.create(R"({"model": "preetham"})", R"({"fit": "latest"})"); });
  EXPECT_EQ(fit.status, 400);
  EXPECT_EQ(fit.parameter, "refit");
  EXPECT_TRUE(list_jobs(f.db).items.empty());
}

}  // namespace
}  // namespace clearsky::api
