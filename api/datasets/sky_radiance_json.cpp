// JSON of the open sky-radiance format (sky_radiance_json.h).
#include "api/datasets/sky_radiance_json.h"

#include "api/datasets/site_and_samples_json.h"
#include "api/datasets/sky_radiance_rows.h"

namespace clearsky::api {

std::vector<MeasuredCapture> parse_sky_radiance_json(std::string_view text) {
  const SiteAndSamplesJson body(text, {"view_zenith", "view_azimuth", "wavelength_nm", "radiance"});
  std::vector<SkyRadianceRow> rows;
  rows.reserve(body.size());
  for (std::size_t i = 0; i < body.size(); ++i) {
    const JsonSample sample = body.sample(i);
    SkyRadianceRow r;
    r.time = sample.time;
    r.latitude_deg = sample.latitude_deg;
    r.longitude_deg = sample.longitude_deg;
    r.elevation_m = sample.elevation_m;
    r.view_zenith_deg = sample.number("view_zenith");
    r.view_azimuth_deg = sample.number("view_azimuth");
    r.wavelength_nm = sample.number("wavelength_nm");
    r.radiance_w_m2_sr_nm = sample.number("radiance");
    rows.push_back(std::move(r));
  }
  return sky_radiance_captures(rows, body.names());
}

}  // namespace clearsky::api
