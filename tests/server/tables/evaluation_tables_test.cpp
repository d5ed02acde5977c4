// Evaluations and jobs take their models from the server's TableStore
// (api::EvaluationRequest::provider): the tables and per-sun states the sky endpoints use, so
// that a second pass over a dataset (a job's next run) precomputes nothing. Nishita96 on cheap
// tables, two synthetic captures at two suns (exact sun zeniths: two per-sun states).
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "api/evaluation/evaluation_runner.h"
#include "models/registry.h"
#include "server/tables/table_store.h"
#include "storage/repositories/capture_repository.h"
#include "storage/repositories/dataset_repository.h"
#include "storage/schema/migrations.h"
#include "tests/models/evaluation/synthetic_sky.h"

namespace clearsky::server {
namespace {

double faint_sky(const ViewDirection& v, double nm) {
  return 0.05 + 0.01 * std::cos(v.zenith_rad) + 1e-5 * (nm - 500);
}

struct Dataset {
  storage::Database db = storage::Database::open(":memory:");
  Dataset() {
    storage::migrate(db);
    const auto dataset = storage::DatasetRepository(db).find_or_create("synthetic", "kider2014");
    storage::CaptureRepository captures(db);
    for (int i = 0; i < 2; ++i) {
      MeasuredCapture c = testing::synthetic_capture(faint_sky, 40.0 + 10.0 * i, 120.0);
      c.label = "capture " + std::to_string(i);
      c.unix_time_utc_s += 900.0 * i;
      captures.insert(dataset, c, "hash" + std::to_string(i), "test");
    }
  }
};

api::EvaluationRequest nishita96_request() {
  api::EvaluationRequest r;
  r.dataset = "synthetic";
  r.models = {"nishita96"};
  r.software_version = "test";
  r.parameters = {{"table_nodes", 9}, {"spheres", 16}, {"cylinders", 16}, {"phase_theta_cells", 8}};
  return r;
}

TEST(EvaluationTables, ASecondPassUsesTheServersTablesAndSunStates) {
  Dataset data;
  const std::vector<ModelFactory> factories = {*find_model("nishita96")};
  TableStore::Options options;
  options.build_wait = std::chrono::milliseconds(60000);
  TableStore tables(factories, options);
  std::atomic<int> builds{0};
  tables.set_build_observer([&builds](const std::string&, double, bool) { ++builds; });

  api::EvaluationRequest request = nishita96_request();
  request.provider = &tables;
  const api::EvaluationReport first = api::run_evaluation(data.db, request, factories);
  ASSERT_EQ(first.models.size(), 1u);
  EXPECT_EQ(builds.load(), 1);
  // The very model the sky endpoints get for this configuration, with the run's sun states.
  const auto model = tables.model(
      factories[0], api::config_for_model(*factories[0].descriptor, request.parameters));
  EXPECT_EQ(model->sun_states_built(), 2u);

  const api::EvaluationReport second = api::run_evaluation(data.db, request, factories);
  EXPECT_EQ(builds.load(), 1);
  EXPECT_EQ(model->sun_states_built(), 2u);
  EXPECT_EQ(second.models[0].result.rmse, first.models[0].result.rmse);
  EXPECT_NE(second.models[0].run_id, first.models[0].run_id);

  // Without the provider a run builds a model of its own: the store's model prepares nothing.
  request.provider = nullptr;
  const api::EvaluationReport own = api::run_evaluation(data.db, request, factories);
  EXPECT_EQ(own.models[0].result.rmse, first.models[0].result.rmse);
  EXPECT_EQ(builds.load(), 1);
}

}  // namespace
}  // namespace clearsky::server
