// Rows of the open broadband irradiance format into samples (irradiance_rows.h).
#include "api/datasets/irradiance_rows.h"

#include "api/error/api_error.h"
#include "api/parse/iso8601_time.h"

namespace clearsky::api {
namespace {

// Site elevations as the import's `elevation` parameter (import_site_clock.cpp).
constexpr double kMinElevationM = -500.0;
constexpr double kMaxElevationM = 9000.0;
constexpr double kMaxAveragingS = 86400.0;  // a daily mean at most

ApiError invalid_row(const SkyRadianceRowNames& names, std::size_t row, const std::string& member,
                     const std::string& why) {
  return ApiError(400, "invalid_body", names.member(row, member),
                  names.where(row) + ", " + member + ": " + why);
}

void check_range(const SkyRadianceRowNames& names, std::size_t row, const std::string& member,
                 double value, double min, double max) {
  if (!(value >= min && value <= max))
    throw invalid_row(names, row, member,
                      std::to_string(value) + " is outside [" + std::to_string(min) + ", " +
                          std::to_string(max) + "]");
}

}  // namespace

std::vector<storage::IrradianceSample> irradiance_samples(const std::vector<IrradianceRow>& rows,
                                                          const SkyRadianceRowNames& names) {
  if (rows.empty())
    throw ApiError(400, "invalid_body", "body", "body: no measured values (no rows)");
  std::vector<storage::IrradianceSample> samples;
  samples.reserve(rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const IrradianceRow& r = rows[i];
    Iso8601Time time;
    try {
      time = parse_iso8601_time(r.time, names.member(i, "time"));
    } catch (const ApiError& e) {
      throw invalid_row(names, i, "time", e.reason());
    }
    check_range(names, i, "latitude", r.latitude_deg, -90, 90);
    check_range(names, i, "longitude", r.longitude_deg, -180, 180);
    check_range(names, i, "elevation_m", r.elevation_m, kMinElevationM, kMaxElevationM);
    if (!r.ghi_w_m2 && !r.dhi_w_m2 && !r.dni_w_m2)
      throw invalid_row(names, i, "ghi", "no value: give at least one of ghi, dhi and dni");
    for (const auto& [member, value] :
         {std::pair<const char*, std::optional<double>>{"ghi", r.ghi_w_m2},
          {"dhi", r.dhi_w_m2},
          {"dni", r.dni_w_m2}})
      if (value) check_range(names, i, member, *value, kMinIrradianceW_m2, kMaxIrradianceW_m2);
    if (r.averaging_s && !(*r.averaging_s > 0 && *r.averaging_s <= kMaxAveragingS))
      throw invalid_row(names, i, "averaging_s",
                        std::to_string(*r.averaging_s) + " is outside (0, 86400]");
    storage::IrradianceSample sample;
    sample.time_utc_s = time.unix_time_utc_s;
    sample.utc_offset_minutes = time.utc_offset_min;
    sample.latitude_deg = r.latitude_deg;
    sample.longitude_deg = r.longitude_deg;
    sample.elevation_m = r.elevation_m;
    sample.ghi_w_m2 = r.ghi_w_m2;
    sample.dhi_w_m2 = r.dhi_w_m2;
    sample.dni_w_m2 = r.dni_w_m2;
    sample.averaging_s = r.averaging_s;
    samples.push_back(sample);
  }
  return samples;
}

}  // namespace clearsky::api
