// The open broadband irradiance format (docs/measurement-formats.md "Broadband irradiance"),
// after its syntax (CSV: irradiance_csv.h, JSON: irradiance_json.h): one row per measured
// instant with its site and any of global horizontal (ghi), diffuse horizontal (dhi) and direct
// normal (dni) irradiance, W/m2, at least one, and optionally the period the values average.
// Every value is checked here; every refusal is a 400 invalid_body naming the member (the CSV
// column, or samples[i].member of the JSON) with the row, so that a whole upload is checked
// before it is accepted.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "api/datasets/sky_radiance_rows.h"
#include "storage/repositories/irradiance_sample_repository.h"

namespace clearsky::api {

// One row as read, before it is checked. Members are as written in the file.
struct IrradianceRow {
  std::string time;  // ISO 8601 with a UTC offset or Z (api/parse/iso8601_time.h)
  double latitude_deg = 0;
  double longitude_deg = 0;
  double elevation_m = 0;
  std::optional<double> ghi_w_m2;
  std::optional<double> dhi_w_m2;
  std::optional<double> dni_w_m2;
  std::optional<double> averaging_s;
};

// Irradiance values a pyranometer or pyrheliometer can report: a thermopile's zero offset
// makes night values slightly negative (ISO 9060:2018 "zero offset a", up to -15 W/m2 for the
// lowest class), and no horizontal irradiance at the ground reaches twice the solar constant.
inline constexpr double kMinIrradianceW_m2 = -20.0;
inline constexpr double kMaxIrradianceW_m2 = 2000.0;

// The samples of the rows in their order. Refuses (400 invalid_body): a time without offset,
// values out of range (latitude [-90, 90], longitude [-180, 180], elevation_m [-500, 9000],
// ghi, dhi and dni [-20, 2000], averaging_s (0, 86400]), a row without any of ghi, dhi and dni,
// and no rows at all. The row names (SkyRadianceRowNames) say where a refusal is.
std::vector<storage::IrradianceSample> irradiance_samples(const std::vector<IrradianceRow>& rows,
                                                          const SkyRadianceRowNames& names);

}  // namespace clearsky::api
