// Tests of schema version 10 (storage/schema/migrations.cpp, docs/data-api.md "Dataset kinds"):
// a database of version 8 migrates with its datasets of kind sky_radiance, and broadband
// irradiance samples are stored and read back through
// storage/repositories/irradiance_sample_repository.h.
#include <gtest/gtest.h>

#include "storage/importers/import_conflict.h"
#include "storage/repositories/dataset_repository.h"
#include "storage/repositories/irradiance_sample_repository.h"
#include "storage/schema/migrations.h"
#include "tests/support/database_at_schema_version.h"
#include "tests/support/rhodes_irradiance_instants.h"

namespace clearsky::storage {
namespace {

using clearsky::testing::database_at_schema_version;
using clearsky::testing::rhodes_hall_sample;

TEST(SchemaVersion10, MigratesAVersion8DatabaseWithItsDatasetsOfKindSkyRadiance) {
  Database db = database_at_schema_version(8);
  db.execute(
      "INSERT INTO datasets (name, format, created_utc) VALUES ('rhodes', 'kider2014', 'x')");
  EXPECT_THROW(db.execute("SELECT 1 FROM irradiance_samples"), SqliteError);
  EXPECT_EQ(migrate(db), latest_schema_version() - 8);
  EXPECT_GE(latest_schema_version(), 10);
  const auto rhodes = DatasetRepository(db).find("rhodes");
  ASSERT_TRUE(rhodes);
  EXPECT_EQ(rhodes->kind, "sky_radiance");
  EXPECT_EQ(rhodes->irradiance_samples, 0);
  EXPECT_FALSE(db.prepare("PRAGMA foreign_key_check").step());
}

TEST(SchemaVersion10, StoresASeriesWithMissingComponentsInTimeOrder) {
  Database db = database_at_schema_version(10);
  DatasetRepository datasets(db);
  const std::int64_t id =
      datasets.find_or_create("roof", "irradiance-csv", kBroadbandIrradianceKind);
  IrradianceSample later = rhodes_hall_sample(1369661400 + 60);
  later.ghi_w_m2 = 700.5;
  later.averaging_s = 60;
  IrradianceSample first = rhodes_hall_sample(1369661400);
  first.dhi_w_m2 = 80;
  first.dni_w_m2 = 850;
  IrradianceSampleRepository(db).insert(id, {later, first});

  const auto stored = IrradianceSampleRepository(db).list(id);
  ASSERT_EQ(stored.size(), 2u);
  EXPECT_EQ(stored[0].time_utc_s, 1369661400);
  EXPECT_FALSE(stored[0].ghi_w_m2);
  EXPECT_EQ(stored[0].dhi_w_m2, 80);
  EXPECT_EQ(stored[0].dni_w_m2, 850);
  EXPECT_FALSE(stored[0].averaging_s);
  EXPECT_EQ(stored[1].ghi_w_m2, 700.5);
  EXPECT_EQ(stored[1].averaging_s, 60);
  EXPECT_EQ(stored[1].utc_offset_minutes, -240);
  EXPECT_EQ(stored[1].latitude_deg, 42.443449);

  const auto summary = datasets.find("roof");
  ASSERT_TRUE(summary);
  EXPECT_EQ(summary->kind, "broadband_irradiance");
  EXPECT_EQ(summary->irradiance_samples, 2);
  EXPECT_EQ(summary->captures, 0);
}

TEST(SchemaVersion10, RefusesASampleWithoutAnyComponentAndADatasetOfAnotherKind) {
  Database db = database_at_schema_version(10);
  DatasetRepository datasets(db);
  const std::int64_t id =
      datasets.find_or_create("roof", "irradiance-csv", kBroadbandIrradianceKind);
  EXPECT_THROW(IrradianceSampleRepository(db).insert(id, {rhodes_hall_sample(0)}), SqliteError);
  EXPECT_THROW(datasets.find_or_create("roof", "kider2014"), ImportConflict);
  datasets.find_or_create("sky", "kider2014");
  EXPECT_THROW(datasets.find_or_create("sky", "irradiance-csv", kBroadbandIrradianceKind),
               ImportConflict);
}

TEST(SchemaVersion10, SamplesGoWithTheirDataset) {
  Database db = database_at_schema_version(10);
  DatasetRepository datasets(db);
  const std::int64_t id =
      datasets.find_or_create("roof", "irradiance-csv", kBroadbandIrradianceKind);
  IrradianceSample sample = rhodes_hall_sample(1369661400);
  sample.ghi_w_m2 = 650;
  IrradianceSampleRepository(db).insert(id, {sample, sample});
  EXPECT_TRUE(datasets.remove("roof"));
  auto count = db.prepare("SELECT COUNT(*) FROM irradiance_samples");
  ASSERT_TRUE(count.step());
  EXPECT_EQ(count.column_int64(0), 0);
}

}  // namespace
}  // namespace clearsky::storage
