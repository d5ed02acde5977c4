// Tests of stored evaluation runs and their JSON (api/evaluation/evaluation_runner.h,
// api/encode/evaluation_json.h), with test-only models: on synthetic captures whose errors are
// known by hand, and end to end on a real imported capture against a black sky.
#include "api/evaluation/evaluation_runner.h"

#include <gtest/gtest.h>

#include <cmath>

#include "api/encode/evaluation_json.h"
#include "models/evaluation/sample_repair.h"
#include "storage/importers/kider_importer.h"
#include "storage/importers/kider_reader.h"
#include "storage/repositories/capture_repository.h"
#include "storage/repositories/dataset_repository.h"
#include "storage/repositories/evaluation_run_repository.h"
#include "storage/schema/migrations.h"
#include "tests/models/evaluation/function_model.h"
#include "tests/support/shared_data.h"

namespace clearsky::api {
namespace {

// A sky symmetric about azimuth 120 degrees (so the estimate finds 120), W/(m2.sr.nm).
double sky(const ViewDirection& v, double nm) {
  return 0.05 + 0.02 * std::sin(v.zenith_rad) * std::cos(v.azimuth_rad - 120.0 * kDegree) +
         1e-5 * (nm - 500);
}

ModelDescriptor descriptor_with_id(const std::string& id) {
  ModelDescriptor d = testing::test_descriptor();
  d.id = id;
  return d;
}
const ModelDescriptor& exact_descriptor() {
  static const ModelDescriptor d = descriptor_with_id("exact");
  return d;
}
const ModelDescriptor& offset_descriptor() {
  static const ModelDescriptor d = descriptor_with_id("offset");
  return d;
}
const ModelDescriptor& black_descriptor() {
  static const ModelDescriptor d = descriptor_with_id("black");
  return d;
}
const ModelDescriptor& broken_descriptor() {
  static const ModelDescriptor d = descriptor_with_id("broken");
  return d;
}

const std::vector<ModelFactory>& test_factories() {
  static const std::vector<ModelFactory> factories = {
      {&exact_descriptor(),
       [](const ModelConfig& c, const PrecomputeContext&) -> std::shared_ptr<const SkyModel> {
         return std::make_shared<testing::FunctionModel>(sky, c, exact_descriptor());
       }},
      {&offset_descriptor(),
       [](const ModelConfig& c, const PrecomputeContext&) -> std::shared_ptr<const SkyModel> {
         return std::make_shared<testing::FunctionModel>(
             [](const ViewDirection& v, double nm) { return sky(v, nm) + 0.003; }, c,
             offset_descriptor());
       }},
      {&black_descriptor(),
       [](const ModelConfig& c, const PrecomputeContext&) -> std::shared_ptr<const SkyModel> {
         return std::make_shared<testing::FunctionModel>(
             [](const ViewDirection&, double) { return 0.0; }, c, black_descriptor());
       }},
      {&broken_descriptor(),
       [](const ModelConfig&, const PrecomputeContext&) -> std::shared_ptr<const SkyModel> {
         throw std::runtime_error("tables could not be built");
       }},
  };
  return factories;
}

struct Fixture {
  storage::Database db = storage::Database::open(":memory:");
  Fixture() {
    storage::migrate(db);
    const auto dataset = storage::DatasetRepository(db).find_or_create("synthetic", "kider2014");
    storage::CaptureRepository captures(db);
    for (int i = 0; i < 2; ++i) {
      MeasuredCapture c = testing::synthetic_capture(sky, 40.0 + i, 125.0);
      c.label = "capture " + std::to_string(i);
      c.unix_time_utc_s += 900.0 * i;
      c.sun_azimuth_estimated_deg = kNotComputed;
      captures.insert(dataset, c, "hash" + std::to_string(i), "test");
    }
  }
};

EvaluationRequest request(std::vector<std::string> models,
                          const std::string& dataset = "synthetic") {
  EvaluationRequest r;
  r.dataset = dataset;
  r.models = std::move(models);
  r.software_version = "test";
  return r;
}

TEST(EvaluationRunner, StoresEveryRunWithItsCaptureResults) {
  Fixture f;
  const EvaluationReport report =
      run_evaluation(f.db, request({"exact", "offset"}), test_factories());
  ASSERT_EQ(report.models.size(), 2u);
  EXPECT_NEAR(report.models[0].result.rmse, 0.0, 1e-9);
  EXPECT_NEAR(report.models[1].result.rmse, 3.0, 1e-9);
  storage::EvaluationRunRepository runs(f.db);
  const auto stored = runs.get(report.models[1].run_id);
  ASSERT_TRUE(stored);
  EXPECT_EQ(stored->status, "succeeded");
  EXPECT_EQ(stored->model_id, "offset");
  EXPECT_EQ(stored->software_version, "test");
  EXPECT_EQ(stored->parameters, "{}");
  EXPECT_EQ(stored->configuration, ModelConfig{}.canonical_string());
  EXPECT_NEAR(*stored->rmse, 3.0, 1e-9);
  ASSERT_EQ(stored->captures.size(), 2u);
  EXPECT_EQ(stored->captures[1].capture_label, "capture 1");
  EXPECT_DOUBLE_EQ(stored->captures[1].sun_zenith_deg, 41.0);
  // The symmetry axis of the synthetic sky, found from the computed 125 degrees.
  EXPECT_NEAR(stored->captures[1].sun_azimuth_deg, 120.0, 0.2 + 1e-9);
  EXPECT_NE(stored->processing_steps.find("sun azimuth estimated"), std::string::npos);
  // The estimate is also kept with the capture.
  const auto dataset = storage::DatasetRepository(f.db).find("synthetic");
  EXPECT_NEAR(
      storage::CaptureRepository(f.db).load(dataset->id)[0].capture.sun_azimuth_estimated_deg,
      120.0, 0.2 + 1e-9);
}

TEST(EvaluationRunner, JsonFollowsTheCliContract) {
  Fixture f;
  const nlohmann::ordered_json j =
      evaluation_to_json(run_evaluation(f.db, request({"offset"}), test_factories()));
  EXPECT_EQ(j.at("dataset"), "synthetic");
  EXPECT_EQ(j.at("wavelength_range_nm").dump(), "[360,720]");
  ASSERT_EQ(j.at("models").size(), 1u);
  const auto& m = j.at("models")[0];
  EXPECT_EQ(m.size(), 10u);
  EXPECT_EQ(m.at("model"), "offset");
  // What the RMSE covers: every sample of both captures, none left out.
  EXPECT_EQ(m.at("out_of_domain"), "exclude");
  EXPECT_EQ(m.at("samples_compared"), 162);
  EXPECT_EQ(m.at("samples_excluded"), 0);
  EXPECT_EQ(m.at("samples_clamped"), 0);
  EXPECT_EQ(m.at("captures_unanswered"), 0);
  EXPECT_NEAR(m.at("rmse").get<double>(), 3.0, 1e-9);
  EXPECT_TRUE(m.at("precompute_seconds").is_number());
  EXPECT_TRUE(m.at("evaluate_seconds").is_number());
  ASSERT_EQ(m.at("captures").size(), 2u);
  const auto& c = m.at("captures")[0];
  EXPECT_EQ(c.size(), 7u);
  EXPECT_EQ(c.at("samples_compared"), 81);
  EXPECT_EQ(c.at("excluded").dump(), "[]");
  EXPECT_EQ(c.at("clamped").dump(), "[]");
  EXPECT_EQ(c.at("time"), "2013-05-27T09:30:00-04:00");
  EXPECT_DOUBLE_EQ(c.at("sun_zenith").get<double>(), 40.0);
  EXPECT_TRUE(c.at("sun_azimuth").is_number());
  EXPECT_NEAR(c.at("rmse").get<double>(), 3.0, 1e-9);
  // Keys in the contract's order.
  const std::string text = j.dump();
  EXPECT_EQ(
      text.rfind(
          R"({"dataset":"synthetic","wavelength_range_nm":[360,720],"models":[{"model":"offset","rmse":)",
          0),
      0u)
      << text;
  EXPECT_NE(
      text.find(
          R"("captures":[{"time":"2013-05-27T09:30:00-04:00","sun_zenith":40.0,"sun_azimuth":)"),
      std::string::npos)
      << text;
  EXPECT_NE(text.find(R"(],"precompute_seconds":)"), std::string::npos) << text;
  EXPECT_LT(text.find("precompute_seconds"), text.find("evaluate_seconds"));
}

TEST(EvaluationRunner, AllMeansEveryAvailableModel) {
  Fixture f;
  auto factories = test_factories();
  factories.pop_back();  // without the broken one
  EXPECT_EQ(run_evaluation(f.db, request({"all"}), factories).models.size(), 3u);
}

TEST(EvaluationRunner, UnknownModelOrDatasetIsRefusedBeforeAnyRun) {
  Fixture f;
  try {
    run_evaluation(f.db, request({"exact", "nishita2042"}), test_factories());
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("nishita2042"), std::string::npos) << e.what();
  }
  EXPECT_THROW(run_evaluation(f.db, request({"exact"}, "missing"), test_factories()),
               std::invalid_argument);
  const auto dataset = storage::DatasetRepository(f.db).find("synthetic");
  EXPECT_TRUE(storage::EvaluationRunRepository(f.db).list(dataset->id).empty());
}

TEST(EvaluationRunner, AFailingModelIsRecordedAsAFailedRun) {
  Fixture f;
  EXPECT_THROW(run_evaluation(f.db, request({"broken"}), test_factories()), std::runtime_error);
  const auto dataset = storage::DatasetRepository(f.db).find("synthetic");
  const auto runs = storage::EvaluationRunRepository(f.db).list(dataset->id);
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_EQ(runs[0].status, "failed");
  EXPECT_EQ(*runs[0].error, "tables could not be built");
}

TEST(EvaluationRunner, BlackSkyAgainstARealCaptureGivesTheMeasuredRms) {
  const std::string archive = "kider2014/2013-05-27/RADIANCE/2013-05-27___11.45.00.7z";
  CLEARSKY_REQUIRE_SHARED_DATA(archive);
  storage::Database db = storage::Database::open(":memory:");
  storage::migrate(db);
  storage::KiderImportRequest import;
  import.dataset_name = "real";
  import.paths = {clearsky::testing::shared_data_dir() / archive};
  storage::import_kider(db, import);
  const EvaluationReport report = run_evaluation(db, request({"black"}, "real"), test_factories());

  // By hand: the RMS of the repaired measurements at 360 + 11.75 i nm, i = 0..30.
  MeasuredCapture capture =
      storage::read_kider_archive(clearsky::testing::shared_data_dir() / archive).at(0);
  repair_defective_samples(capture);
  double sum = 0;
  for (const MeasuredSample& s : capture.samples)
    for (int i = 0; i <= 30; ++i)
      sum += std::pow(s.radiance.at(360 + 11.75 * i, OutOfRange::error), 2);
  const double expected = 1000.0 * std::sqrt(sum / (81 * 31));
  ASSERT_EQ(report.models.size(), 1u);
  EXPECT_NEAR(report.models[0].result.rmse, expected, 1e-9 * expected);
  const CaptureEvaluation& c = report.models[0].result.captures.at(0);
  EXPECT_EQ(c.time_iso, "2013-05-27T11:45:00-04:00");
  EXPECT_NEAR(c.sun_zenith_deg, 26.654, 0.005);
  EXPECT_NEAR(c.sun_azimuth_deg, 122.265, 0.2);
}

}  // namespace
}  // namespace clearsky::api
