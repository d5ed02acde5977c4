// The open broadband irradiance format (api/datasets/irradiance_csv.h, irradiance_json.h,
// irradiance_rows.h), its formats from format= and the media type (import_format.h), and the
// import into a dataset of kind broadband_irradiance (irradiance_import.h) shown by
// GET /v1/datasets/{name} (datasets_api.h), on a real database.
#include <gtest/gtest.h>

#include <string>

#include "api/datasets/datasets_api.h"
#include "api/datasets/import_format.h"
#include "api/datasets/irradiance_csv.h"
#include "api/datasets/irradiance_import.h"
#include "api/datasets/irradiance_json.h"
#include "api/error/api_error.h"
#include "api/parse/iso8601_time.h"
#include "storage/schema/migrations.h"
#include "tests/support/api_refusal.h"
#include "tests/support/temp_dir.h"

namespace clearsky::api {
namespace {

using Refusal = clearsky::testing::ApiRefusal;
using clearsky::testing::refusal_of;

const std::string kHeader = "time,latitude,longitude,elevation_m,ghi,dhi,dni\n";

TEST(IrradianceCsv, ReadsAnySubsetOfTheComponentsWithTheirClock) {
  const std::string csv =
      "dni,time,latitude,longitude,elevation_m,ghi,averaging_s\r\n"
      "850,2013-05-27T09:30:00-04:00,42.44,-76.48,250,654.8,60\r\n"
      ",2013-05-27T13:30:00Z,42.44,-76.48,250,700,\r\n";
  const auto samples = parse_irradiance_csv(csv);
  ASSERT_EQ(samples.size(), 2u);
  EXPECT_EQ(samples[0].time_utc_s, 1369661400);
  EXPECT_EQ(samples[0].utc_offset_minutes, -240);
  EXPECT_EQ(samples[0].ghi_w_m2, 654.8);
  EXPECT_EQ(samples[0].dni_w_m2, 850);
  EXPECT_FALSE(samples[0].dhi_w_m2);
  EXPECT_EQ(samples[0].averaging_s, 60);
  EXPECT_EQ(samples[1].time_utc_s, 1369661400);
  EXPECT_EQ(samples[1].utc_offset_minutes, 0);
  EXPECT_FALSE(samples[1].dni_w_m2);
  EXPECT_FALSE(samples[1].averaging_s);
}

TEST(IrradianceCsv, RefusalsNameTheColumnAndTheRow) {
  const std::string row = "2013-05-27T09:30:00-04:00,42.44,-76.48,250,650,80,850\n";
  Refusal r = refusal_of([&] {
    parse_irradiance_csv(kHeader + row + "2013-05-27T09:31:00-04:00,42.44,-76.48,250,650,x,850\n");
  });
  EXPECT_EQ(r.status, 400);
  EXPECT_EQ(r.parameter, "dhi");
  EXPECT_NE(r.message.find("row 2 (line 3)"), std::string::npos) << r.message;
  r = refusal_of(
      [&] { parse_irradiance_csv(kHeader + "2013-05-27T09:30:00,42.44,-76.48,250,650,80,850\n"); });
  EXPECT_EQ(r.parameter, "time");
  r = refusal_of([&] {
    parse_irradiance_csv(kHeader + "2013-05-27T09:30:00Z,42.44,-76.48,250,2500,80,850\n");
  });
  EXPECT_EQ(r.parameter, "ghi");
  r = refusal_of(
      [&] { parse_irradiance_csv(kHeader + "2013-05-27T09:30:00Z,42.44,-76.48,250,,,\n"); });
  EXPECT_EQ(r.parameter, "ghi");
  EXPECT_NE(r.message.find("at least one"), std::string::npos) << r.message;
  r = refusal_of([] { parse_irradiance_csv("time,latitude,longitude,elevation_m\n"); });
  EXPECT_EQ(r.parameter, "ghi");
  r = refusal_of([] { parse_irradiance_csv("time,latitude,longitude,elevation_m,ghi,wind\n"); });
  EXPECT_EQ(r.parameter, "wind");
  r = refusal_of([] { parse_irradiance_csv(kHeader); });
  EXPECT_EQ(r.parameter, "body");
}

TEST(IrradianceJson, ReadsTheFileSiteAndNullComponents) {
  const auto samples = parse_irradiance_json(R"({
    "site": {"latitude": 42.44, "longitude": -76.48, "elevation_m": 250},
    "samples": [{"time": "2013-05-27T09:30:00-04:00", "ghi": 654.8, "dhi": null},
                {"time": "2013-05-27T09:31:00-04:00", "dhi": 80, "averaging_s": 60}]})");
  ASSERT_EQ(samples.size(), 2u);
  EXPECT_EQ(samples[0].ghi_w_m2, 654.8);
  EXPECT_FALSE(samples[0].dhi_w_m2);
  EXPECT_EQ(samples[1].dhi_w_m2, 80);
  EXPECT_EQ(samples[1].time_utc_s, 1369661460);
  EXPECT_DOUBLE_EQ(samples[1].elevation_m, 250);

  const Refusal r = refusal_of([] {
    parse_irradiance_json(R"({"samples": [{"time": "2013-05-27T09:30:00Z", "latitude": 1,
      "longitude": 2, "elevation_m": 3, "ghi": "650"}]})");
  });
  EXPECT_EQ(r.status, 400);
  EXPECT_EQ(r.parameter, "samples[0].ghi");
  EXPECT_EQ(refusal_of([] {
              parse_irradiance_json(R"({"samples": [{"time": "2013-05-27T09:30:00Z", "latitude": 1,
      "longitude": 2, "elevation_m": 3, "gni": 650}]})");
            }).parameter,
            "samples[0].gni");
}

TEST(IrradianceFormat, IsChosenByFormatWithTheOpenFormatsMediaTypes) {
  EXPECT_EQ(import_format_of(std::string("irradiance-csv"), "text/csv"), "irradiance-csv");
  EXPECT_EQ(import_format_of(std::string("irradiance-json"), "application/json; charset=utf-8"),
            "irradiance-json");
  EXPECT_EQ(import_format_of(std::string("irradiance-csv"), std::nullopt), "irradiance-csv");
  const Refusal wrong_type =
      refusal_of([] { import_format_of(std::string("irradiance-csv"), "application/json"); });
  EXPECT_EQ(wrong_type.status, 415);
  EXPECT_EQ(wrong_type.parameter, "Content-Type");
  EXPECT_EQ(refusal_of([] { import_format_of(std::string("irradiance"), std::nullopt); }).parameter,
            "format");
}

TEST(IrradianceImport, StoresTheSeriesOnceAndShowsIt) {
  clearsky::testing::TempDir dir;
  storage::Database db = storage::open_database(dir.path / "sky.db");
  const auto samples =
      parse_irradiance_csv(kHeader + "2013-05-27T09:30:00-04:00,42.44,-76.48,250,650,80,\n" +
                           "2013-05-27T09:31:00-04:00,42.44,-76.48,250,652,,\n");
  const auto report = import_irradiance_samples(db, "roof", kIrradianceDatasetFormat, samples);
  EXPECT_EQ(report["samples_added"], 2);
  EXPECT_EQ(report["kind"], "broadband_irradiance");
  EXPECT_EQ(report["first_time"], "2013-05-27T09:30:00-04:00");
  // Importing the same file again adds nothing.
  const auto again = import_irradiance_samples(db, "roof", kIrradianceDatasetFormat, samples);
  EXPECT_EQ(again["samples_added"], 0);
  EXPECT_EQ(again["samples_unchanged"], 2);

  const auto shown = show_dataset(db, "roof");
  EXPECT_EQ(shown["kind"], "broadband_irradiance");
  ASSERT_EQ(shown["irradiance"].size(), 2u);
  EXPECT_EQ(shown["irradiance"][0]["time"], "2013-05-27T09:30:00-04:00");
  EXPECT_EQ(shown["irradiance"][0]["dhi"], 80);
  EXPECT_TRUE(shown["irradiance"][1]["dhi"].is_null());
  EXPECT_TRUE(shown["irradiance"][0]["dni"].is_null());
  const ListPage page = list_datasets(db);
  ASSERT_EQ(page.items.size(), 1u);
  EXPECT_EQ(page.items[0]["kind"], "broadband_irradiance");
  EXPECT_EQ(page.items[0]["irradiance_samples"], 2);

  // A sky-radiance import into it is a conflict naming the dataset.
  EXPECT_EQ(refusal_of([&] {
              import_irradiance_samples(db, "roof", kKiderPyranometerDatasetFormat, samples);
            }).status,
            409);
}

}  // namespace
}  // namespace clearsky::api
