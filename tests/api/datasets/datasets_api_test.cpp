// Tests of /v1/datasets without a socket (api/datasets/datasets_api.h, upload_spool.h): list,
// show (captures with time, place, sun angles; samples and spectra on request), delete, and
// import of an uploaded real Kider archive spooled to disk, with its failures (size limit,
// not an archive, conflicts) leaving nothing behind.
#include "api/datasets/datasets_api.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "api/datasets/upload_spool.h"
#include "api/error/api_error.h"
#include "storage/repositories/capture_repository.h"
#include "storage/repositories/dataset_repository.h"
#include "storage/schema/migrations.h"
#include "tests/models/evaluation/synthetic_sky.h"
#include "tests/support/shared_data.h"
#include "tests/support/temp_dir.h"

namespace clearsky::api {
namespace {

double flat_sky(const ViewDirection&, double) { return 0.05; }

storage::Database database_with_synthetic_dataset() {
  storage::Database db = storage::Database::open(":memory:");
  storage::migrate(db);
  const auto dataset = storage::DatasetRepository(db).find_or_create("synthetic", "kider2014");
  MeasuredCapture c = testing::synthetic_capture(flat_sky, 40.0, 125.0);
  c.label = "capture 0";
  storage::CaptureRepository(db).insert(dataset, c, "hash0", "test");
  return db;
}

int status_of(const std::function<void()>& call) {
  try {
    call();
  } catch (const ApiError& e) {
    return e.status();
  }
  return 0;
}

const char* kArchive = "kider2014/2013-05-27/RADIANCE/2013-05-27___11.45.00.7z";

std::string file_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

// The upload path of the HTTP layer: the body arrives in chunks, spooled under a limit.
nlohmann::ordered_json upload(storage::Database& db, const std::filesystem::path& folder,
                              const std::string& bytes, std::size_t limit,
                              const std::string& name = "uploaded") {
  UploadSpool spool(folder, limit, ".7z");
  for (std::size_t i = 0; i < bytes.size(); i += 65536)
    spool.append(std::string_view(bytes).substr(i, 65536));
  return import_dataset(db, name, "kider", {spool.finish(), {}, {}, {}});
}

TEST(DatasetsApi, ListAndShowSyntheticCapture) {
  storage::Database db = database_with_synthetic_dataset();
  const auto list = list_datasets(db).items;
  ASSERT_EQ(list.size(), 1u);
  EXPECT_EQ(list[0]["name"], "synthetic");
  EXPECT_EQ(list[0]["format"], "kider2014");
  EXPECT_EQ(list[0]["captures"], 1);
  EXPECT_EQ(list[0]["samples"], 81);

  const auto shown = show_dataset(db, "synthetic");
  ASSERT_EQ(shown["captures"].size(), 1u);
  const auto& c = shown["captures"][0];
  EXPECT_EQ(c["label"], "capture 0");
  EXPECT_EQ(c["time"], "2013-05-27T09:30:00-04:00");
  EXPECT_EQ(c["time_utc"], "2013-05-27T13:30:00Z");
  EXPECT_DOUBLE_EQ(c["place"]["latitude"].get<double>(), kider_cornell_site().latitude_deg);
  EXPECT_DOUBLE_EQ(c["sun_zenith"].get<double>(), 40.0);
  EXPECT_DOUBLE_EQ(c["sun_azimuth"].get<double>(), 125.0);
  EXPECT_EQ(c["samples"], 81);  // a count unless samples are asked for

  const auto with_samples = show_dataset(db, "synthetic", {true, std::nullopt});
  const auto& samples = with_samples["captures"][0]["samples"];
  ASSERT_EQ(samples.size(), 81u);
  EXPECT_FALSE(samples[0].contains("radiance"));
  // Directions in degrees: zenith within the upper hemisphere.
  for (const auto& s : samples) {
    EXPECT_GE(s["view_zenith"].get<double>(), 0.0);
    EXPECT_LE(s["view_zenith"].get<double>(), 90.0);
  }

  const auto one = show_dataset(db, "synthetic", {false, std::string("capture 0")});
  const auto& spectrum = one["captures"][0]["samples"][5];
  ASSERT_EQ(spectrum["radiance"].size(), spectrum["wavelengths_nm"].size());
  EXPECT_DOUBLE_EQ(spectrum["radiance"][0].get<double>(), 0.05);
}

TEST(DatasetsApi, UnknownDatasetOrCaptureIs404AndDeleteRemoves) {
  storage::Database db = database_with_synthetic_dataset();
  EXPECT_EQ(status_of([&] { show_dataset(db, "missing"); }), 404);
  EXPECT_EQ(status_of([&] { show_dataset(db, "synthetic", {false, std::string("nope")}); }), 404);
  EXPECT_EQ(delete_dataset(db, "synthetic")["deleted"], "synthetic");
  EXPECT_TRUE(list_datasets(db).items.empty());
  EXPECT_EQ(status_of([&] { delete_dataset(db, "synthetic"); }), 404);
}

TEST(DatasetsApi, UploadedArchiveImportsOnceAndReimportIsUnchanged) {
  CLEARSKY_REQUIRE_SHARED_DATA(kArchive);
  clearsky::testing::TempDir dir;
  storage::Database db = storage::open_database(dir.path / "db.sqlite");
  const std::string bytes = file_bytes(clearsky::testing::shared_data_dir() / kArchive);
  const auto report = upload(db, dir.path / "uploads", bytes, 8u << 20);
  // Its kind tells it from the report of a broadband irradiance import (OpenAPI ImportReport).
  EXPECT_EQ(report["kind"], "sky_radiance");
  ASSERT_EQ(report["added"].size(), 1u);
  EXPECT_EQ(report["added"][0], "2013-05-27___11.45.00");
  EXPECT_EQ(report["samples_added"], 81);
  const auto again = upload(db, dir.path / "uploads", bytes, 8u << 20);
  EXPECT_TRUE(again["added"].empty());
  EXPECT_EQ(again["unchanged"].size(), 1u);
  // The spool files are gone.
  EXPECT_TRUE(std::filesystem::is_empty(dir.path / "uploads"));
  // Sun angles computed at import (SPA), shown with the capture: late morning in May at
  // Ithaca, sun about 25 degrees from the zenith, in the south-east.
  const auto shown = show_dataset(db, "uploaded");
  const auto& c = shown["captures"][0];
  EXPECT_EQ(c["time"], "2013-05-27T11:45:00-04:00");
  EXPECT_NEAR(c["sun_zenith"].get<double>(), 25.0, 5.0);
  EXPECT_GT(c["sun_azimuth"].get<double>(), 100.0);
  EXPECT_LT(c["sun_azimuth"].get<double>(), 180.0);
}

TEST(DatasetsApi, OversizedUploadIs413AndLeavesNothing) {
  CLEARSKY_REQUIRE_SHARED_DATA(kArchive);
  clearsky::testing::TempDir dir;
  storage::Database db = storage::open_database(dir.path / "db.sqlite");
  const std::string bytes = file_bytes(clearsky::testing::shared_data_dir() / kArchive);
  EXPECT_EQ(status_of([&] { upload(db, dir.path / "uploads", bytes, bytes.size() - 1); }), 413);
  EXPECT_TRUE(list_datasets(db).items.empty());
  EXPECT_TRUE(std::filesystem::is_empty(dir.path / "uploads"));
}

TEST(DatasetsApi, TruncatedOrForeignUploadIs400AndLeavesNothing) {
  CLEARSKY_REQUIRE_SHARED_DATA(kArchive);
  clearsky::testing::TempDir dir;
  storage::Database db = storage::open_database(dir.path / "db.sqlite");
  const std::string bytes = file_bytes(clearsky::testing::shared_data_dir() / kArchive);
  EXPECT_EQ(
      status_of([&] { upload(db, dir.path / "u", bytes.substr(0, bytes.size() / 2), 8u << 20); }),
      400);
  EXPECT_EQ(status_of([&] { upload(db, dir.path / "u", "this is not an archive", 8u << 20); }),
            400);
  EXPECT_TRUE(list_datasets(db).items.empty());
  EXPECT_EQ(status_of([&] { import_dataset(db, "x", "csv", {dir.path, {}, {}, {}}); }), 400);
}

TEST(DatasetsApi, SameLabelWithOtherContentIs409) {
  CLEARSKY_REQUIRE_SHARED_DATA(kArchive);
  clearsky::testing::TempDir dir;
  storage::Database db = storage::open_database(dir.path / "db.sqlite");
  // A capture with the archive's label but other content, already stored.
  const auto dataset = storage::DatasetRepository(db).find_or_create("uploaded", "kider2014");
  MeasuredCapture c = testing::synthetic_capture(flat_sky);
  c.label = "2013-05-27___11.45.00";
  storage::CaptureRepository(db).insert(dataset, c, "other", "test");
  const std::string bytes = file_bytes(clearsky::testing::shared_data_dir() / kArchive);
  EXPECT_EQ(status_of([&] { upload(db, dir.path / "u", bytes, 8u << 20); }), 409);
  EXPECT_EQ(list_datasets(db).items[0]["captures"], 1);
}

// The importer's conflicts are typed (storage::ImportConflict): a dataset name that another
// format already uses is 409 as well, and its captures are untouched.
TEST(DatasetsApi, DatasetOfAnotherFormatIs409) {
  CLEARSKY_REQUIRE_SHARED_DATA(kArchive);
  clearsky::testing::TempDir dir;
  storage::Database db = storage::open_database(dir.path / "db.sqlite");
  storage::DatasetRepository(db).find_or_create("uploaded", "another-format");
  const std::string bytes = file_bytes(clearsky::testing::shared_data_dir() / kArchive);
  EXPECT_EQ(status_of([&] { upload(db, dir.path / "u", bytes, 8u << 20); }), 409);
  EXPECT_EQ(list_datasets(db).items[0]["captures"], 0);
}

TEST(UploadSpool, StaleFilesOfAKilledProcessAreRemovedAtStartUp) {
  clearsky::testing::TempDir dir;
  const auto folder = dir.path / "uploads";
  {
    UploadSpool kept(folder, 100);
    kept.append("abc");
    // A killed process never runs the destructor: copy the file aside as it would remain.
    std::filesystem::copy_file(kept.finish(), folder / "upload-left.7z");
  }
  std::ofstream(folder / "other.txt") << "not an upload";
  EXPECT_EQ(remove_stale_uploads(folder), 1);
  EXPECT_TRUE(std::filesystem::exists(folder / "other.txt"));
  EXPECT_EQ(remove_stale_uploads(dir.path / "absent"), 0);
}

}  // namespace
}  // namespace clearsky::api
