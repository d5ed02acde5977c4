// The broadband parameters and the answer's broadband member (broadband_request.h).
#include "api/irradiance/broadband_request.h"

#include "api/irradiance/broadband_irradiance.h"
#include "models/atmosphere/atmosphere_parameter_table.h"

namespace clearsky::api {

AtmosphereParameters parse_broadband_absorbers(Parameters& p, AtmosphereParameters atmosphere) {
  for (const char* name : {"precipitable_water_cm", "ozone_atm_cm"}) {
    const AtmosphereParameterInfo& info = *find_atmosphere_parameter(name);
    info.set(atmosphere, p.number_or(name, info.default_value, info.min_value, info.max_value));
  }
  return atmosphere;
}

nlohmann::json broadband_json(const std::optional<std::string>& unavailable,
                              const AtmosphereParameters& absorbers) {
  if (unavailable) return nullptr;
  return {{"range_nm", {kBroadbandMinNm, kBroadbandMaxNm}},
          {"precipitable_water_cm", absorbers.precipitable_water_cm},
          {"ozone_atm_cm", absorbers.ozone_atm_cm},
          {"method",
           "the model's spectra inside integrated_range_nm, absorbed by water vapour, "
           "ozone and mixed gases (Bird and Riordan 1986); outside it the model's "
           "extinction and SPCTRAL2's diffuse scaled to the model at the range ends"}};
}

}  // namespace clearsky::api
