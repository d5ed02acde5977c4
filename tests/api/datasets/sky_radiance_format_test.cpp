// The open sky-radiance format (api/datasets/sky_radiance_csv.h, sky_radiance_json.h,
// sky_radiance_rows.h), the import's format from format= and the media type
// (import_format.h) and the site and clock of archives (import_site_clock.h).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "api/datasets/import_format.h"
#include "api/datasets/import_site_clock.h"
#include "api/datasets/sky_radiance_csv.h"
#include "api/datasets/sky_radiance_import.h"
#include "api/datasets/sky_radiance_json.h"
#include "api/error/api_error.h"
#include "api/parse/iso8601_time.h"
#include "models/core/numeric.h"
#include "tests/support/api_refusal.h"
#include "tests/support/temp_dir.h"

namespace clearsky::api {
namespace {

const std::string kHeader =
    "time,latitude,longitude,elevation_m,view_zenith,view_azimuth,wavelength_nm,radiance\n";

using Refusal = clearsky::testing::ApiRefusal;
using clearsky::testing::refusal_of;

TEST(SkyRadianceCsv, RowsAreGroupedIntoCapturesByTimeAndDirectionsByView) {
  // Two instants written in two offsets; rows in any order, columns in another order.
  const std::string csv =
      "\xEF\xBB\xBFradiance,wavelength_nm,view_azimuth,view_zenith,time,latitude,longitude,"
      "elevation_m\r\n"
      "0.2,500,90,30,2024-06-21T10:00:00+02:00,48.85,2.35,35\r\n"
      "0.3,400,90,30,2024-06-21T10:00:00+02:00,48.85,2.35,35\r\n"
      "0.1,500,0,0,2024-06-21T09:00:00Z,48.85,2.35,35\r\n"
      "0.4,450,270,60,2024-06-21T10:00:00+02:00,48.85,2.35,35\r\n"
      "\r\n";
  const std::vector<MeasuredCapture> captures = parse_sky_radiance_csv(csv);
  ASSERT_EQ(captures.size(), 2u);
  EXPECT_EQ(captures[0].label, "2024-06-21T10:00:00+02:00");
  EXPECT_EQ(captures[0].utc_offset_minutes, 120);
  EXPECT_DOUBLE_EQ(captures[0].unix_time_utc_s,
                   parse_iso8601_time("2024-06-21T08:00:00Z").unix_time_utc_s);
  EXPECT_EQ(captures[1].label, "2024-06-21T09:00:00+00:00");
  ASSERT_EQ(captures[0].samples.size(), 2u);
  const MeasuredSample& first = captures[0].samples[0];
  EXPECT_EQ(first.index, 0);
  EXPECT_DOUBLE_EQ(first.view.zenith_rad, 30 * kDegree);
  EXPECT_DOUBLE_EQ(first.view.azimuth_rad, 90 * kDegree);
  // Sorted by wavelength.
  EXPECT_EQ(first.radiance.wavelengths_nm(), (std::vector<double>{400, 500}));
  EXPECT_EQ(first.radiance.values(), (std::vector<double>{0.3, 0.2}));
  EXPECT_EQ(captures[0].samples[1].index, 1);
  EXPECT_DOUBLE_EQ(captures[0].site.latitude_deg, 48.85);
  EXPECT_DOUBLE_EQ(captures[0].site.elevation_m, 35);
}

TEST(SkyRadianceCsv, RefusalsNameTheColumnAndTheRow) {
  const std::string row = "2024-06-21T10:00:00+02:00,48.85,2.35,35,30,90,550,0.05\n";
  const Refusal bad = refusal_of([&] {
    parse_sky_radiance_csv(kHeader + row + "2024-06-21T10:00:00+02:00,48.85,2.35,35,30,90,560,x\n");
  });
  EXPECT_EQ(bad.status, 400);
  EXPECT_EQ(bad.parameter, "radiance");
  EXPECT_NE(bad.message.find("row 2 (line 3)"), std::string::npos) << bad.message;
  EXPECT_EQ(
      refusal_of([&] {
        parse_sky_radiance_csv(kHeader + "2024-06-21T10:00:00+02:00,91,2.35,35,30,90,550,0.05\n");
      }).parameter,
      "latitude");
  EXPECT_EQ(refusal_of([&] {
              parse_sky_radiance_csv(kHeader + "2024-06-21T10:00:00,48,2,35,30,90,550,0.05\n");
            }).parameter,
            "time");
  EXPECT_EQ(refusal_of([&] {
              parse_sky_radiance_csv(kHeader + "2024-06-21T10:00:00Z,48,2,35,30,90,550,-0.05\n");
            }).parameter,
            "radiance");
  EXPECT_EQ(refusal_of([&] {
              parse_sky_radiance_csv(kHeader + "2024-06-21T10:00:00Z,48,2,35,30,90,0,0.05\n");
            }).parameter,
            "wavelength_nm");
  // The same instant at another site, and a quoted field.
  EXPECT_EQ(refusal_of([&] {
              parse_sky_radiance_csv(kHeader + "2024-06-21T10:00:00Z,48,2,35,30,90,550,0.05\n" +
                                     "2024-06-21T10:00:00Z,48,3,35,30,90,560,0.05\n");
            }).parameter,
            "longitude");
  EXPECT_EQ(refusal_of([&] {
              parse_sky_radiance_csv(kHeader + "\"2024-06-21T10:00:00Z\",48,2,35,30,90,550,0.05\n");
            }).parameter,
            "time");
  // Blank lines only at the end; a header only holds no values.
  EXPECT_EQ(refusal_of([&] { parse_sky_radiance_csv(kHeader + "\n" + row); }).parameter, "body");
  EXPECT_EQ(refusal_of([&] { parse_sky_radiance_csv(kHeader); }).parameter, "body");
  EXPECT_EQ(refusal_of([&] { parse_sky_radiance_csv(""); }).parameter, "body");
}

TEST(SkyRadianceJson, TheFileSiteOrEachSamplesOwn) {
  const std::string file_site = R"({"site": {"latitude": 10, "longitude": 20, "elevation_m": 30},
    "samples": [{"time": "2024-01-01T12:00:00-05:00", "view_zenith": 10, "view_azimuth": 20,
                 "wavelength_nm": 500, "radiance": 0.5}]})";
  const std::vector<MeasuredCapture> captures = parse_sky_radiance_json(file_site);
  ASSERT_EQ(captures.size(), 1u);
  EXPECT_EQ(captures[0].utc_offset_minutes, -300);
  EXPECT_DOUBLE_EQ(captures[0].site.longitude_deg, 20);
  EXPECT_EQ(captures[0].samples[0].radiance.values(), std::vector<double>{0.5});

  const std::string own_site = R"({"samples": [{"time": "2024-01-01T12:00:00Z",
    "latitude": 1, "longitude": 2, "elevation_m": 3, "view_zenith": 10, "view_azimuth": 20,
    "wavelength_nm": 500, "radiance": 0.5}]})";
  EXPECT_DOUBLE_EQ(parse_sky_radiance_json(own_site)[0].site.latitude_deg, 1);

  const std::string both = R"({"site": {"latitude": 10, "longitude": 20, "elevation_m": 30},
    "samples": [{"time": "2024-01-01T12:00:00Z", "latitude": 1, "longitude": 2,
    "elevation_m": 3, "view_zenith": 10, "view_azimuth": 20, "wavelength_nm": 500,
    "radiance": 0.5}]})";
  EXPECT_EQ(refusal_of([&] { parse_sky_radiance_json(both); }).parameter, "samples[0].latitude");
  const std::string unknown = R"({"samples": [], "colour": 1})";
  EXPECT_EQ(refusal_of([&] { parse_sky_radiance_json(unknown); }).parameter, "colour");
  const Refusal empty = refusal_of([&] { parse_sky_radiance_json(R"({"samples": []})"); });
  EXPECT_EQ(empty.status, 400);
  EXPECT_EQ(empty.parameter, "body");
  EXPECT_EQ(refusal_of([&] { parse_sky_radiance_json("[1,"); }).status, 400);
}

TEST(SkyRadianceFile, IsHeldToTheEntryLimit) {
  clearsky::testing::TempDir dir;
  const std::filesystem::path file = dir.path / "sky.csv";
  std::ofstream(file) << kHeader << "2024-06-21T10:00:00Z,48,2,35,30,90,550,0.05\n";
  storage::ImportByteLimits limits;
  EXPECT_EQ(read_sky_radiance_file(file, kSkyRadianceCsvFormat, limits, "body").size(), 1u);
  limits.max_entry_bytes = 64;
  const Refusal r =
      refusal_of([&] { read_sky_radiance_file(file, kSkyRadianceCsvFormat, limits, "body"); });
  EXPECT_EQ(r.status, 413);
  EXPECT_EQ(r.parameter, "max_entry_bytes");
  EXPECT_EQ(r.message.find(dir.path.string()), std::string::npos) << r.message;
}

TEST(ImportFormat, FromTheParameterOrTheMediaType) {
  EXPECT_EQ(import_format_of(std::nullopt, std::nullopt), "kider");
  EXPECT_EQ(import_format_of(std::nullopt, "text/csv; charset=utf-8"), "sky-radiance-csv");
  EXPECT_EQ(import_format_of(std::nullopt, "Application/JSON"), "sky-radiance-json");
  EXPECT_EQ(import_format_of(std::nullopt, "application/x-7z-compressed"), "kider");
  EXPECT_EQ(import_format_of(std::string("sky-radiance-csv"), "application/x-www-form-urlencoded"),
            "sky-radiance-csv");
  const Refusal other = refusal_of([] { import_format_of(std::nullopt, "image/png"); });
  EXPECT_EQ(other.status, 415);
  EXPECT_EQ(other.parameter, "Content-Type");
  EXPECT_EQ(refusal_of([] { import_format_of(std::string("kider"), "text/csv"); }).status, 415);
  EXPECT_EQ(refusal_of([] { import_format_of(std::string("csv"), std::nullopt); }).parameter,
            "format");
}

TEST(ImportSiteClock, DefaultsToThePublishedCapturesAndReadsEachParameter) {
  Parameters none("test");
  const storage::KiderImportOptions defaults = parse_import_site_clock(none);
  EXPECT_DOUBLE_EQ(defaults.site.latitude_deg, kider_cornell_site().latitude_deg);
  EXPECT_DOUBLE_EQ(defaults.site.elevation_m, 250);
  EXPECT_EQ(defaults.utc_offset_minutes, -240);

  Parameters given("test");
  given.add("lat", "48d51'N");
  given.add("lon", "-2.5");
  given.add("elevation", "1200");
  given.add("utc_offset", "+05:30");
  const storage::KiderImportOptions options = parse_import_site_clock(given);
  EXPECT_DOUBLE_EQ(options.site.latitude_deg, 48.85);
  EXPECT_DOUBLE_EQ(options.site.longitude_deg, -2.5);
  EXPECT_DOUBLE_EQ(options.site.elevation_m, 1200);
  EXPECT_EQ(options.utc_offset_minutes, 330);
  given.reject_unused();

  for (const auto& [name, value] :
       std::vector<std::pair<std::string, std::string>>{{"lat", "91"},
                                                        {"lon", "east"},
                                                        {"elevation", "1e5"},
                                                        {"utc_offset", "+15:00"},
                                                        {"utc_offset", "04:00"},
                                                        {"utc_offset", "-04:60"}}) {
    Parameters bad("test");
    bad.add(name, value);
    const Refusal r = refusal_of([&] { parse_import_site_clock(bad); });
    EXPECT_EQ(r.status, 400) << name << "=" << value;
    EXPECT_EQ(r.parameter, name) << name << "=" << value;
  }
}

}  // namespace
}  // namespace clearsky::api
