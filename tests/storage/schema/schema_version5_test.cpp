// Tests of schema version 5 (storage/schema/migrations.cpp): unanswered captures without RMSE,
// per-capture excluded and clamped samples, the run's sample counts and the key of its compared
// samples, which the history matches; runs stored before are converted with all their samples
// compared.
#include <gtest/gtest.h>

#include <cmath>

#include "models/core/sky_model.h"
#include "storage/repositories/capture_repository.h"
#include "storage/repositories/compared_samples.h"
#include "storage/repositories/dataset_repository.h"
#include "storage/repositories/evaluation_run_repository.h"
#include "storage/schema/migrations.h"
#include "storage/sqlite/blob.h"
#include "tests/models/evaluation/function_model.h"
#include "tests/support/database_at_schema_version.h"

namespace clearsky::storage {
namespace {

using clearsky::testing::database_at_schema_version;

NewRun new_run(std::int64_t dataset, const std::string& out_of_domain = "exclude") {
  NewRun run;
  run.dataset_id = dataset;
  run.model_id = "preetham";
  run.model_version = "1";
  run.configuration = ModelConfig{}.canonical_string();
  run.software_version = "t";
  run.out_of_domain = out_of_domain;
  return run;
}

std::int64_t add_capture(Database& db, std::int64_t dataset, const std::string& label) {
  MeasuredCapture c =
      clearsky::testing::synthetic_capture([](const ViewDirection&, double) { return 0.1; });
  c.label = label;
  return CaptureRepository(db).insert(dataset, c, "hash " + label, "test");
}

RunCaptureResult result(std::int64_t capture, double rmse, std::int64_t compared,
                        std::vector<SampleHandling> handling = {}) {
  RunCaptureResult r;
  r.capture_id = capture;
  r.rmse = rmse;
  r.samples_compared = compared;
  r.values_compared = compared * 31;
  r.out_of_domain = std::move(handling);
  return r;
}

TEST(SampleHandlingText, RoundTripsAndRefusesOtherText) {
  const std::vector<SampleHandling> entries = {{"excluded", "outside_fit_domain", {22, 23}},
                                               {"clamped", "sun_below_horizon_unsupported", {0}}};
  const std::string text = encode_sample_handling(entries);
  EXPECT_EQ(text, "excluded outside_fit_domain 22,23;clamped sun_below_horizon_unsupported 0");
  EXPECT_EQ(decode_sample_handling(text), entries);
  EXPECT_TRUE(decode_sample_handling("").empty());
  EXPECT_THROW(decode_sample_handling("excluded x"), std::runtime_error);
  EXPECT_THROW(decode_sample_handling("other x 1"), std::runtime_error);
  EXPECT_THROW(decode_sample_handling("excluded x 1,a"), std::runtime_error);
}

TEST(SchemaVersion5, ConvertsRunsWithEverySampleCompared) {
  Database db = database_at_schema_version(4);
  const std::int64_t dataset = DatasetRepository(db).find_or_create("set", "kider2014");
  const std::int64_t a = add_capture(db, dataset, "a");
  const std::int64_t b = add_capture(db, dataset, "b");
  const std::vector<double> wavelengths(31, 500.0);
  auto insert = db.prepare(
      "INSERT INTO evaluation_runs (id, dataset_id, model_id, model_version, parameters,"
      " configuration, software_version, min_wavelength_nm, max_wavelength_nm, started_utc,"
      " status, rmse, wavelengths_nm) VALUES (3, ?, 'preetham', '1', '{}', ?, 'old', 360, 720,"
      " '2026-01-01T00:00:00.000Z', 'succeeded', 88.7, ?)");
  insert.bind(1, dataset).bind(2, ModelConfig{}.canonical_string());
  insert.bind_blob(3, encode_doubles(wavelengths));
  insert.run();
  db.execute(
      "INSERT INTO evaluation_capture_results (run_id, capture_id, sun_zenith_deg,"
      " sun_azimuth_deg, rmse, values_compared) VALUES (3, " +
      std::to_string(a) + ", 48.9, 91.1, 88.7, 2511), (3, " + std::to_string(b) +
      ", 40.0, 100.0, 80.0, 2511)");
  const auto& all = schema_migrations();
  EXPECT_EQ(migrate(db, std::vector<std::string_view>(all.begin(), all.begin() + 5)), 1);
  EXPECT_EQ(db.user_version(), 5);
  migrate(db);  // the repository reads the latest schema
  EvaluationRunRepository runs(db);
  const auto old = runs.get(3);
  ASSERT_TRUE(old);
  EXPECT_EQ(old->out_of_domain, "exclude");
  EXPECT_EQ(old->samples_compared, 162);
  EXPECT_EQ(old->samples_excluded, 0);
  EXPECT_EQ(old->captures_unanswered, 0);
  ASSERT_EQ(old->captures.size(), 2u);
  EXPECT_EQ(old->captures[0].samples_compared, 81);
  EXPECT_TRUE(old->captures[0].answered);
  EXPECT_DOUBLE_EQ(old->captures[0].rmse, 88.7);
  // The key is the one a new run over all the samples of the same captures gets.
  EXPECT_EQ(old->compared_samples, compared_samples_key({{"b", ""}, {"a", ""}}));
  const std::int64_t id = runs.start(new_run(dataset));
  runs.finish(id, 84.4, 0, 0, "", {result(a, 88.7, 81), result(b, 80.0, 81)});
  EXPECT_EQ(runs.previous_like(*runs.get(id))->id, 3);
  // Deleting a capture still cascades to its results (the rebuilt table keeps its keys), and the
  // sample-error blobs still follow their last reference.
  db.execute("DELETE FROM captures WHERE id = " + std::to_string(b));
  EXPECT_EQ(runs.get(3)->captures.size(), 1u);
}

TEST(SchemaVersion5, UnansweredCapturesAndExcludedSamplesAreStoredAndCounted) {
  Database db = open_database(":memory:");
  const std::int64_t dataset = DatasetRepository(db).find_or_create("set", "kider2014");
  const std::int64_t a = add_capture(db, dataset, "a");
  const std::int64_t b = add_capture(db, dataset, "b");
  EvaluationRunRepository runs(db);
  const std::vector<int> all_samples = [] {
    std::vector<int> v;
    for (int i = 0; i < 81; ++i) v.push_back(i);
    return v;
  }();
  RunCaptureResult unanswered =
      result(b, 0.0, 0,
             {{"excluded", "sun_below_horizon_unsupported",
               std::vector<std::int32_t>(all_samples.begin(), all_samples.end())}});
  unanswered.answered = false;
  const std::int64_t id = runs.start(new_run(dataset));
  runs.finish(id, 12.5, 0, 0, "",
              {result(a, 12.5, 79, {{"excluded", "outside_fit_domain", {22, 23}}}), unanswered});
  const auto run = runs.get(id);
  EXPECT_EQ(run->samples_compared, 79);
  EXPECT_EQ(run->samples_excluded, 83);
  EXPECT_EQ(run->samples_clamped, 0);
  EXPECT_EQ(run->captures_unanswered, 1);
  ASSERT_EQ(run->captures.size(), 2u);
  EXPECT_EQ(run->captures[0].out_of_domain,
            (std::vector<SampleHandling>{{"excluded", "outside_fit_domain", {22, 23}}}));
  EXPECT_FALSE(run->captures[1].answered);
  EXPECT_TRUE(std::isnan(run->captures[1].rmse));

  // The history: a run over other samples (none excluded) or with clamping is not like it; one
  // over the same samples is.
  const std::int64_t all = runs.start(new_run(dataset));
  runs.finish(all, 20.0, 0, 0, "", {result(a, 20.0, 81), result(b, 20.0, 81)});
  EXPECT_FALSE(runs.previous_like(*runs.get(all)));
  const std::int64_t clamped = runs.start(new_run(dataset, "clamp"));
  runs.finish(clamped, 12.5, 0, 0, "",
              {result(a, 12.5, 79, {{"excluded", "outside_fit_domain", {22, 23}}}), unanswered});
  EXPECT_FALSE(runs.previous_like(*runs.get(clamped)));
  const std::int64_t again = runs.start(new_run(dataset));
  runs.finish(again, 12.5, 0, 0, "",
              {result(a, 12.5, 79, {{"excluded", "outside_fit_domain", {22, 23}}}), unanswered});
  EXPECT_EQ(runs.previous_like(*runs.get(again))->id, id);

  // No capture answered: the run succeeds without an RMSE (and is nobody's history).
  const std::int64_t none = runs.start(new_run(dataset));
  runs.finish(none, std::nan(""), 0, 0, "", {unanswered});
  EXPECT_EQ(runs.get(none)->status, "succeeded");
  EXPECT_FALSE(runs.get(none)->rmse);
}

}  // namespace
}  // namespace clearsky::storage
