// The aerosols option checked against the installed inversion source.
#include "api/request/aerosols_option.h"

#include <cstdint>

#include "api/error/api_error.h"
#include "models/measured_aerosols/aerosol_inversion_source.h"

namespace clearsky::api {

void check_aerosols_option(const std::string& name, double value) {
  if (name != kAerosolsOption || value == 0) return;
  const auto id = static_cast<std::int64_t>(value);
  if (!aerosol_inversion_bytes(id)) {
    throw ApiError::about(404, "unknown_aerosols", kAerosolsOption,
                          "no aerosol inversion " + std::to_string(id) +
                              " (GET /v1/aerosols lists the uploaded ones)");
  }
}

}  // namespace clearsky::api
