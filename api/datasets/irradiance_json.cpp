// JSON of the open broadband irradiance format (irradiance_json.h).
#include "api/datasets/irradiance_json.h"

#include "api/datasets/irradiance_rows.h"
#include "api/datasets/site_and_samples_json.h"

namespace clearsky::api {

std::vector<storage::IrradianceSample> parse_irradiance_json(std::string_view text) {
  const SiteAndSamplesJson body(text, {"ghi", "dhi", "dni", "averaging_s"});
  std::vector<IrradianceRow> rows;
  rows.reserve(body.size());
  for (std::size_t i = 0; i < body.size(); ++i) {
    const JsonSample sample = body.sample(i);
    IrradianceRow r;
    r.time = sample.time;
    r.latitude_deg = sample.latitude_deg;
    r.longitude_deg = sample.longitude_deg;
    r.elevation_m = sample.elevation_m;
    // Each component is optional: absent or null is a value not measured.
    r.ghi_w_m2 = sample.optional_number("ghi");
    r.dhi_w_m2 = sample.optional_number("dhi");
    r.dni_w_m2 = sample.optional_number("dni");
    r.averaging_s = sample.optional_number("averaging_s");
    rows.push_back(std::move(r));
  }
  return irradiance_samples(rows, body.names());
}

}  // namespace clearsky::api
