// Tests of the stored per-sample errors of evaluation runs (storage/repositories/
// sample_errors_blob.h, evaluation_run_repository.h, schema version 2): the blob round trip and
// its size, identical blobs stored once and removed with their last reference, runs stored
// before version 2 read back without samples.
#include <gtest/gtest.h>

#include "storage/repositories/capture_repository.h"
#include "storage/repositories/dataset_repository.h"
#include "storage/repositories/evaluation_run_repository.h"
#include "storage/repositories/sample_errors_blob.h"
#include "storage/schema/migrations.h"
#include "tests/models/evaluation/synthetic_sky.h"

namespace clearsky::storage {
namespace {

SampleErrorTable table(std::size_t samples, std::uint32_t wavelengths, float offset) {
  SampleErrorTable t;
  t.wavelength_count = wavelengths;
  for (std::size_t s = 0; s < samples; ++s) {
    const float x = static_cast<float>(s);
    t.samples.push_back({static_cast<std::int32_t>(s), 77.88f - 0.5f * x, 11.25f * x,
                         10.0 + 0.123456789012345 * static_cast<double>(s),
                         -3.0 - 1e-13 * static_cast<double>(s)});
    for (std::uint32_t w = 0; w < wavelengths; ++w)
      t.errors.push_back(offset + 0.1f * x - 0.01f * static_cast<float>(w));
  }
  return t;
}

TEST(SampleErrorsBlob, RoundTripsExactlyAndHasTheDocumentedSize) {
  const SampleErrorTable original = table(81, 31, 1.5f);
  const std::vector<std::byte> bytes = encode_sample_errors(original);
  EXPECT_EQ(bytes.size(), 12320u);  // 8 + 81 x (28 + 4 x 31)
  const SampleErrorTable back = decode_sample_errors(bytes);
  EXPECT_EQ(back, original);  // float64 RMSE and bias to the bit
  EXPECT_EQ(back.errors_of(80)[30], original.errors[80 * 31 + 30]);
  // Little-endian header: 81 samples, 31 wavelengths; then sample 0's index.
  EXPECT_EQ(static_cast<int>(bytes[0]), 81);
  EXPECT_EQ(static_cast<int>(bytes[4]), 31);
  EXPECT_EQ(static_cast<int>(bytes[8]), 0);
  EXPECT_EQ(static_cast<int>(bytes[8 + 152]), 1);  // record 1 starts 28 + 4 x 31 later

  EXPECT_EQ(decode_sample_errors(encode_sample_errors(SampleErrorTable{})), SampleErrorTable{});
  EXPECT_EQ(decode_sample_errors(encode_sample_errors(table(0, 31, 0))).wavelength_count, 31u);
}

TEST(SampleErrorsBlob, RefusesInconsistentTablesAndBlobs) {
  SampleErrorTable bad = table(3, 4, 0);
  bad.errors.pop_back();
  EXPECT_THROW(encode_sample_errors(bad), std::invalid_argument);
  std::vector<std::byte> bytes = encode_sample_errors(table(3, 4, 0));
  bytes.pop_back();
  EXPECT_THROW(decode_sample_errors(bytes), std::runtime_error);
  EXPECT_THROW(decode_sample_errors(std::vector<std::byte>(5)), std::runtime_error);
  // A header announcing huge counts is refused, not allocated.
  std::vector<std::byte> huge(8, std::byte{0xff});
  EXPECT_THROW(decode_sample_errors(huge), std::runtime_error);
}

struct Fixture {
  Database db = Database::open(":memory:");
  std::int64_t dataset = 0;
  std::int64_t capture = 0;
  explicit Fixture(int schema_version = latest_schema_version()) {
    const auto& all = schema_migrations();
    migrate(db, std::vector<std::string_view>(all.begin(), all.begin() + schema_version));
    dataset = DatasetRepository(db).find_or_create("set", "kider2014");
    MeasuredCapture c =
        clearsky::testing::synthetic_capture([](const ViewDirection&, double) { return 0.1; });
    c.label = "2013-05-27___09.30.00";
    capture = CaptureRepository(db).insert(dataset, c, "0123456789abcdef", "test");
  }
  std::int64_t count(const std::string& table_name) {
    auto q = db.prepare("SELECT count(*) FROM " + table_name);
    q.step();
    return q.column_int64(0);
  }
};

NewRun new_run(std::int64_t dataset) {
  NewRun run;
  run.dataset_id = dataset;
  run.model_id = "preetham";
  run.model_version = std::string("1");
  run.parameters = R"({"alpha":0.8})";
  run.software_version = "0.1.0";
  return run;
}

RunCaptureResult result(std::int64_t capture, std::optional<SampleErrorTable> samples) {
  RunCaptureResult r;
  r.capture_id = capture;
  r.sun_zenith_deg = 48.9;
  r.sun_azimuth_deg = 91.1;
  r.rmse = 12.0;
  r.values_compared = 81 * 31;
  r.samples = std::move(samples);
  return r;
}

const std::vector<double> kWavelengths = [] {
  std::vector<double> nm;
  for (int i = 0; i < 31; ++i) nm.push_back(360.0 + 11.75 * i);
  return nm;
}();

TEST(EvaluationRunSamples, StoredWithTheRunAndReadOnRequest) {
  Fixture f;
  EvaluationRunRepository runs(f.db);
  const std::int64_t id = runs.start(new_run(f.dataset));
  runs.finish(id, 12, 0, 0, "", {result(f.capture, table(81, 31, 2.0f))}, kWavelengths);
  const auto plain = runs.get(id);
  ASSERT_EQ(plain->captures.size(), 1u);
  EXPECT_FALSE(plain->captures[0].samples.has_value());  // not read unless asked
  EXPECT_EQ(*plain->wavelengths_nm, kWavelengths);
  const auto detailed = runs.get(id, true);
  ASSERT_TRUE(detailed->captures[0].samples.has_value());
  EXPECT_EQ(*detailed->captures[0].samples, table(81, 31, 2.0f));
  // Errors must have one column per listed wavelength.
  const std::int64_t other = runs.start(new_run(f.dataset));
  EXPECT_THROW(runs.finish(other, 1, 0, 0, "", {result(f.capture, table(81, 30, 0))}, kWavelengths),
               std::invalid_argument);
  EXPECT_EQ(runs.get(other)->status, "running");
}

TEST(EvaluationRunSamples, RepeatedIdenticalRunsShareOneBlob) {
  Fixture f;
  EvaluationRunRepository runs(f.db);
  std::vector<std::int64_t> ids;
  for (int i = 0; i < 5; ++i) {
    ids.push_back(runs.start(new_run(f.dataset)));
    runs.finish(ids.back(), 12, 0, 0, "", {result(f.capture, table(81, 31, 2.0f))}, kWavelengths);
  }
  EXPECT_EQ(f.count("evaluation_sample_errors"), 1);
  // Other errors: a second blob.
  const std::int64_t changed = runs.start(new_run(f.dataset));
  runs.finish(changed, 13, 0, 0, "", {result(f.capture, table(81, 31, 2.5f))}, kWavelengths);
  EXPECT_EQ(f.count("evaluation_sample_errors"), 2);
  EXPECT_EQ(*runs.get(ids[3], true)->captures[0].samples, table(81, 31, 2.0f));
  EXPECT_EQ(*runs.get(changed, true)->captures[0].samples, table(81, 31, 2.5f));

  // A blob stays while one run refers to it and goes with the last one.
  f.db.execute("DELETE FROM evaluation_runs WHERE id IN (" + std::to_string(ids[0]) + ", " +
               std::to_string(ids[1]) + ")");
  EXPECT_EQ(f.count("evaluation_sample_errors"), 2);
  f.db.execute("DELETE FROM evaluation_runs WHERE id = " + std::to_string(changed));
  EXPECT_EQ(f.count("evaluation_sample_errors"), 1);
  EXPECT_EQ(*runs.get(ids[4], true)->captures[0].samples, table(81, 31, 2.0f));
  // Deleting the dataset (runs and results by cascade) leaves no blob behind.
  EXPECT_TRUE(DatasetRepository(f.db).remove("set"));
  EXPECT_EQ(f.count("evaluation_sample_errors"), 0);
}

TEST(EvaluationRunSamples, RunsStoredBeforeSchemaVersion2HaveNoSamples) {
  Fixture f(1);
  ASSERT_EQ(f.db.user_version(), 1);
  // A version-1 run, written with version 1's columns.
  f.db.execute(
      "INSERT INTO evaluation_runs (id, dataset_id, model_id, model_version, parameters,"
      " software_version, min_wavelength_nm, max_wavelength_nm, started_utc, finished_utc,"
      " status, rmse) VALUES (7, " +
      std::to_string(f.dataset) +
      ", 'preetham', '1', '', 'old', 360, 720, '2026-01-01T00:00:00.000Z',"
      " '2026-01-01T00:00:01.000Z', 'succeeded', 88.7);"
      "INSERT INTO evaluation_capture_results (run_id, capture_id, sun_zenith_deg,"
      " sun_azimuth_deg, rmse, values_compared) VALUES (7, " +
      std::to_string(f.capture) + ", 48.9, 91.1, 88.7, 2511)");
  EXPECT_EQ(migrate(f.db), latest_schema_version() - 1);
  const auto old = EvaluationRunRepository(f.db).get(7, true);
  ASSERT_TRUE(old);
  EXPECT_DOUBLE_EQ(*old->rmse, 88.7);
  EXPECT_FALSE(old->wavelengths_nm.has_value());
  ASSERT_EQ(old->captures.size(), 1u);
  EXPECT_FALSE(old->captures[0].samples.has_value());
  EXPECT_DOUBLE_EQ(old->captures[0].rmse, 88.7);
}

}  // namespace
}  // namespace clearsky::storage
