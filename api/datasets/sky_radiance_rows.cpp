// Rows of the open sky-radiance format into captures (sky_radiance_rows.h).
#include "api/datasets/sky_radiance_rows.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "api/error/api_error.h"
#include "api/parse/iso8601_time.h"
#include "models/core/numeric.h"

namespace clearsky::api {
namespace {

// Site elevations as the import's `elevation` parameter (import_site_clock.cpp).
constexpr double kMinElevationM = -500.0;
constexpr double kMaxElevationM = 9000.0;
constexpr double kMaxWavelengthNm = 1e6;

ApiError invalid_row(const SkyRadianceRowNames& names, std::size_t row, const std::string& member,
                     const std::string& why) {
  return ApiError(400, "invalid_body", names.member(row, member),
                  names.where(row) + ", " + member + ": " + why);
}

void check_range(const SkyRadianceRowNames& names, std::size_t row, const std::string& member,
                 double value, double min, double max, bool max_inclusive = true) {
  if (!(value >= min && (max_inclusive ? value <= max : value < max)))
    throw invalid_row(names, row, member,
                      std::to_string(value) + " is outside [" + std::to_string(min) + ", " +
                          std::to_string(max) + (max_inclusive ? "]" : ")"));
}

struct Direction {
  std::size_t first_row = 0;
  std::map<double, double> radiance_by_nm;
};

struct CaptureRows {
  std::size_t first_row = 0;
  int utc_offset_minutes = 0;
  SiteLocation site;
  std::vector<std::pair<double, double>> direction_order;  // zenith, azimuth (degrees)
  std::map<std::pair<double, double>, Direction> directions;
};

}  // namespace

std::vector<MeasuredCapture> sky_radiance_captures(const std::vector<SkyRadianceRow>& rows,
                                                   const SkyRadianceRowNames& names) {
  if (rows.empty())
    throw ApiError(400, "invalid_body", "body", "body: no measured values (no rows)");
  std::map<double, CaptureRows> by_instant;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const SkyRadianceRow& r = rows[i];
    Iso8601Time time;
    try {
      time = parse_iso8601_time(r.time, names.member(i, "time"));
    } catch (const ApiError& e) {
      throw invalid_row(names, i, "time", e.reason());
    }
    check_range(names, i, "latitude", r.latitude_deg, -90, 90);
    check_range(names, i, "longitude", r.longitude_deg, -180, 180);
    check_range(names, i, "elevation_m", r.elevation_m, kMinElevationM, kMaxElevationM);
    check_range(names, i, "view_zenith", r.view_zenith_deg, 0, 180);
    check_range(names, i, "view_azimuth", r.view_azimuth_deg, 0, 360, false);
    if (!(r.wavelength_nm > 0 && r.wavelength_nm <= kMaxWavelengthNm))
      throw invalid_row(names, i, "wavelength_nm", "must be in (0, 1e6] nm");
    if (!(r.radiance_w_m2_sr_nm >= 0 && std::isfinite(r.radiance_w_m2_sr_nm)))
      throw invalid_row(names, i, "radiance", "must be a finite radiance >= 0 W/(m2.sr.nm)");

    const SiteLocation site{r.latitude_deg, r.longitude_deg, r.elevation_m};
    auto [found, added] = by_instant.try_emplace(time.unix_time_utc_s);
    CaptureRows& capture = found->second;
    if (added) {
      capture.first_row = i;
      capture.utc_offset_minutes = time.utc_offset_min;
      capture.site = site;
    } else {
      const std::string first = names.where(capture.first_row);
      if (time.utc_offset_min != capture.utc_offset_minutes)
        throw invalid_row(names, i, "time",
                          "the same instant as " + first + " with another UTC offset");
      if (site.latitude_deg != capture.site.latitude_deg)
        throw invalid_row(names, i, "latitude", "the same instant as " + first + ", another site");
      if (site.longitude_deg != capture.site.longitude_deg)
        throw invalid_row(names, i, "longitude", "the same instant as " + first + ", another site");
      if (site.elevation_m != capture.site.elevation_m)
        throw invalid_row(names, i, "elevation_m",
                          "the same instant as " + first + ", another site");
    }
    const std::pair<double, double> view{r.view_zenith_deg, r.view_azimuth_deg};
    auto [direction, new_direction] = capture.directions.try_emplace(view);
    if (new_direction) {
      direction->second.first_row = i;
      capture.direction_order.push_back(view);
    }
    if (!direction->second.radiance_by_nm.emplace(r.wavelength_nm, r.radiance_w_m2_sr_nm).second)
      throw invalid_row(names, i, "wavelength_nm",
                        "given twice for this time and view direction (first at " +
                            names.where(direction->second.first_row) + " onwards)");
  }

  std::vector<MeasuredCapture> captures;
  captures.reserve(by_instant.size());
  for (auto& [instant, rows_of_capture] : by_instant) {
    MeasuredCapture capture;
    capture.unix_time_utc_s = instant;
    capture.utc_offset_minutes = rows_of_capture.utc_offset_minutes;
    capture.site = rows_of_capture.site;
    capture.label = local_time_iso8601(instant, capture.utc_offset_minutes);
    if (!captures.empty() && captures.back().label == capture.label)
      throw invalid_row(names, rows_of_capture.first_row, "time",
                        "within the same second as another capture (captures are labelled by "
                        "their time to the second)");
    int index = 0;
    for (const auto& view : rows_of_capture.direction_order) {
      Direction& direction = rows_of_capture.directions.at(view);
      std::vector<double> nm, values;
      nm.reserve(direction.radiance_by_nm.size());
      values.reserve(direction.radiance_by_nm.size());
      for (const auto& [wavelength, radiance] : direction.radiance_by_nm) {
        nm.push_back(wavelength);
        values.push_back(radiance);
      }
      MeasuredSample sample;
      sample.index = index++;
      sample.view = {view.first * kDegree, view.second * kDegree};
      sample.radiance = TabulatedSpectrum(std::move(nm), std::move(values));
      capture.samples.push_back(std::move(sample));
    }
    captures.push_back(std::move(capture));
  }
  return captures;
}

}  // namespace clearsky::api
