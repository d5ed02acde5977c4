// GET /v1/sun: the sun query of api/handlers/sun_handler.h (shared with `clearsky sun`) behind
// the HTTP API's request and error types; without time, the current instant.
#include <chrono>

#include "api/handlers/handlers.h"
#include "api/handlers/sun_handler.h"
#include "api/parse/invalid_parameter.h"

namespace clearsky::api {

ApiResponse get_sun(const ApiContext&, const ApiRequest& request) {
  QueryParameters parameters;
  for (const auto& [name, value] : request.query) parameters.emplace(name, value);
  const double now_s =
      std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
  try {
    ApiResponse response;
    response.body = handle_sun(parameters, now_s).dump();
    return response;
  } catch (const InvalidParameter& e) {
    throw invalid_parameter(e.parameter(), e.message());
  }
}

}  // namespace clearsky::api
