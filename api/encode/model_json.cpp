// Descriptor encoding. Infinite limits are written as null (JSON has no infinity).
#include "api/encode/model_json.h"

#include <cmath>

namespace clearsky::api {

namespace {

nlohmann::json finite_or_null(double x) {
  return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr);
}

}  // namespace

nlohmann::json descriptor_to_json(const ModelDescriptor& d) {
  nlohmann::json parameters = nlohmann::json::array();
  for (const ParameterSpec& p : d.parameters) {
    parameters.push_back({{"name", p.name},
                          {"unit", p.unit},
                          {"description", p.description},
                          {"default", finite_or_null(p.default_value)},
                          {"min", finite_or_null(p.min_value)},
                          {"max", finite_or_null(p.max_value)},
                          {"integer", p.integer},
                          {"kind", p.atmosphere ? "atmosphere" : "model"}});
  }
  const ModelCapabilities& c = d.capabilities;
  return {{"id", d.id},
          {"name", d.name},
          {"version", d.version},
          {"citation", d.citation},
          {"summary", d.summary},
          {"native_wavelengths_nm", d.native_wavelengths_nm},
          {"wavelength_range_nm",
           {finite_or_null(d.min_wavelength_nm), finite_or_null(d.max_wavelength_nm)}},
          {"parameters", parameters},
          {"capabilities",
           {{"altitude_range_m", {c.min_altitude_m, finite_or_null(c.max_altitude_m)}},
            {"view_from_space", c.view_from_space},
            {"view_below_horizon", c.view_below_horizon},
            {"aerial_perspective", c.aerial_perspective},
            {"max_sun_zenith_deg", c.max_sun_zenith_deg},
            {"sun_below_horizon", c.max_sun_zenith_deg > 90.0},
            {"dark_beyond_sun_zenith_deg", c.dark_beyond_sun_zenith_deg.has_value()
                                               ? nlohmann::json(*c.dark_beyond_sun_zenith_deg)
                                               : nlohmann::json(nullptr)},
            {"scattering_orders",
             c.scattering_orders < 0 ? nlohmann::json("all") : nlohmann::json(c.scattering_orders)},
            {"per_sun_precomputation", c.per_sun_precomputation},
            {"sun_irradiance", c.sun_irradiance},
            {"sky_irradiance", c.sky_irradiance}}}};
}

}  // namespace clearsky::api
