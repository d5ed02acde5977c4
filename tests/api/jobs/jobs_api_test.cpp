// Tests of /v1/jobs without a socket (api/jobs/jobs_api.h): create with its checks and the
// next run from now, list, pause, resume (next run from the resume time), delete.
#include "api/jobs/jobs_api.h"

#include <gtest/gtest.h>

#include "api/error/api_error.h"
#include "api/evaluation/evaluations_api.h"
#include "storage/repositories/capture_repository.h"
#include "storage/repositories/dataset_repository.h"
#include "storage/schema/migrations.h"
#include "tests/models/evaluation/function_model.h"

namespace clearsky::api {
namespace {

// The test model, taking the atmosphere's turbidity.
const ModelDescriptor& turbid_descriptor() {
  static const ModelDescriptor d = [] {
    ModelDescriptor m = testing::test_descriptor();
    m.parameters.push_back(
        ParameterSpec{"turbidity", "", "turbidity", 2.53, 1.0, 10.0, false, true});
    return m;
  }();
  return d;
}

const std::vector<ModelFactory>& factories() {
  static const std::vector<ModelFactory> f = {
      {&turbid_descriptor(),
       [](const ModelConfig& c, const PrecomputeContext&) -> std::shared_ptr<const SkyModel> {
         return std::make_shared<testing::FunctionModel>(
             [](const ViewDirection&, double) { return 0.0; }, c);
       }},
  };
  return f;
}

int status_of(const std::function<void()>& call) {
  try {
    call();
  } catch (const ApiError& e) {
    return e.status();
  }
  return 0;
}

constexpr double kNow = 1795258800;  // 2026-11-21T11:00:00Z, a Saturday

struct Fixture {
  storage::Database db = storage::Database::open(":memory:");
  Fixture() {
    storage::migrate(db);
    storage::DatasetRepository(db).find_or_create("synthetic", "kider2014");
  }
};

TEST(JobsApi, CreateComputesTheNextRunAndListShowsIt) {
  Fixture f;
  const CreatedResource created =
      create_job(f.db,
                 R"({"name": "nightly", "schedule": "30 2 * * *", "dataset": "synthetic",
                                  "models": ["test-model"], "parameters": {"turbidity": 3}})",
                 factories(), kNow);
  const auto& job = created.body;
  EXPECT_EQ(created.location, "/v1/jobs/" + std::to_string(job["id"].get<std::int64_t>()));
  EXPECT_EQ(job["name"], "nightly");
  EXPECT_EQ(job["dataset"], "synthetic");
  EXPECT_EQ(job["models"], nlohmann::ordered_json::array({"test-model"}));
  EXPECT_EQ(job["parameters"]["turbidity"], 3);
  EXPECT_EQ(job["paused"], false);
  EXPECT_EQ(job["next_run"], "2026-11-22T02:30:00Z");
  EXPECT_TRUE(job["last_run"].is_null());
  EXPECT_TRUE(job["last_result"].empty());
  const auto all =
      create_job(f.db, R"({"name": "hourly", "schedule": "0 * * * *", "dataset": "synthetic"})",
                 factories(), kNow)
          .body;
  EXPECT_EQ(all["models"], "all");
  EXPECT_EQ(all["next_run"], "2026-11-21T12:00:00Z");
  const auto list = list_jobs(f.db).items;
  ASSERT_EQ(list.size(), 2u);
  EXPECT_EQ(list[0]["name"], "hourly");  // by name

  // The evaluation a job runs.
  const auto record = storage::JobRepository(f.db).get(job["id"].get<std::int64_t>());
  const EvaluationRequest request = job_evaluation_request(f.db, *record, "v");
  EXPECT_EQ(request.dataset, "synthetic");
  EXPECT_EQ(request.models, std::vector<std::string>{"test-model"});
  EXPECT_EQ(request.parameters, nlohmann::json({{"turbidity", 3}}));
  EXPECT_EQ(request.job_id, record->id);
}

TEST(JobsApi, BadJobsAreRefused) {
  Fixture f;
  const auto create = [&](const std::string& body) { create_job(f.db, body, factories(), kNow); };
  EXPECT_EQ(status_of([&] { create(R"({"schedule": "* * * * *", "dataset": "synthetic"})"); }),
            400);
  EXPECT_EQ(status_of([&] { create(R"({"name": "a", "dataset": "synthetic"})"); }), 400);
  EXPECT_EQ(status_of([&] {
              create(R"({"name": "a", "schedule": "61 * * * *", "dataset": "synthetic"})");
            }),
            400);
  EXPECT_EQ(status_of([&] {
              create(R"({"name": "a", "schedule": "0 0 31 4 *", "dataset": "synthetic"})");
            }),
            400);
  EXPECT_EQ(
      status_of([&] { create(R"({"name": "a", "schedule": "* * * * *", "dataset": "none"})"); }),
      404);
  EXPECT_EQ(
      status_of([&] {
        create(
            R"({"name": "a", "schedule": "* * * * *", "dataset": "synthetic", "models": ["x"]})");
      }),
      404);
  EXPECT_EQ(
      status_of([&] {
        create(R"({"name": "a", "schedule": "* * * * *", "dataset": "synthetic", "when": 1})");
      }),
      400);
  create(R"({"name": "a", "schedule": "* * * * *", "dataset": "synthetic"})");
  EXPECT_EQ(status_of([&] {
              create(R"({"name": "a", "schedule": "* * * * *", "dataset": "synthetic"})");
            }),
            409);
  try {
    create(R"({"name": "b", "schedule": "* 25 * * *", "dataset": "synthetic"})");
    FAIL();
  } catch (const ApiError& e) {
    EXPECT_EQ(e.parameter(), "schedule");
    EXPECT_NE(std::string(e.what()).find("hour"), std::string::npos) << e.what();
  }
}

TEST(JobsApi, PauseResumeDelete) {
  Fixture f;
  const auto job =
      create_job(f.db, R"({"name": "j", "schedule": "0 6 * * mon", "dataset": "synthetic"})",
                 factories(), kNow)
          .body;
  const std::int64_t id = job["id"];
  EXPECT_EQ(job["next_run"], "2026-11-23T06:00:00Z");
  EXPECT_EQ(pause_job(f.db, id)["paused"], true);
  // Resumed a week later: the next run is after the resume, not the missed one.
  const auto resumed = resume_job(f.db, id, kNow + 7 * 86400);
  EXPECT_EQ(resumed["paused"], false);
  EXPECT_EQ(resumed["next_run"], "2026-11-30T06:00:00Z");
  EXPECT_EQ(delete_job(f.db, id)["deleted"], id);
  EXPECT_EQ(status_of([&] { show_job(f.db, id); }), 404);
  EXPECT_EQ(status_of([&] { pause_job(f.db, id); }), 404);
  EXPECT_EQ(status_of([&] { delete_job(f.db, id); }), 404);
}

// A job's parameters follow the rule of POST /v1/evaluations: the test model takes
// turbidity, not alpha.
TEST(JobsApi, AParameterNoModelTakesIsRefused) {
  Fixture f;
  try {
    create_job(f.db, R"({"name": "a", "schedule": "* * * * *", "dataset": "synthetic",
                         "models": ["test-model"], "parameters": {"alpha": 1}})",
               factories(), kNow);
    ADD_FAILURE() << "alpha accepted";
  } catch (const ApiError& e) {
    EXPECT_EQ(e.status(), 400);
    EXPECT_EQ(e.parameter(), "alpha");
  }
}

// Deleting a job keeps its runs, found by the job's id, which no later job gets.
TEST(JobsApi, ADeletedJobsRunsKeepItsId) {
  Fixture f;
  const auto dataset = storage::DatasetRepository(f.db).find("synthetic")->id;
  storage::CaptureRepository(f.db).insert(
      dataset, testing::synthetic_capture([](const ViewDirection&, double) { return 0.0; }), "hash",
      "test");
  const std::int64_t id =
      create_job(f.db, R"({"name": "n", "schedule": "0 3 * * *", "dataset": "synthetic",
                           "models": ["test-model"], "parameters": {"turbidity": 3}})",
                 factories(), kNow)
          .body["id"];
  const EvaluationRequest request =
      job_evaluation_request(f.db, *storage::JobRepository(f.db).get(id), "v");
  const std::int64_t run = run_evaluation(f.db, request, factories()).models.at(0).run_id;
  delete_job(f.db, id);
  for (const char* name : {"job", "job_id"}) {
    Parameters query("GET /v1/evaluations");
    query.add(name, std::to_string(id));
    const ListPage runs = list_evaluations(f.db, parse_evaluation_filter(std::move(query)));
    ASSERT_EQ(runs.items.size(), 1u) << name;
    EXPECT_EQ(runs.items[0]["id"], run);
    EXPECT_EQ(runs.items[0]["job"], id);
  }
  EXPECT_EQ(show_evaluation(f.db, run)["parameters"], nlohmann::ordered_json({{"turbidity", 3}}));
  const std::int64_t next =
      create_job(f.db, R"({"name": "n", "schedule": "0 3 * * *", "dataset": "synthetic"})",
                 factories(), kNow)
          .body["id"];
  EXPECT_GT(next, id);
}

}  // namespace
}  // namespace clearsky::api
