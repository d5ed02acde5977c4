// GET /v1/sun: the sun query of api/handlers/sun_handler.h (shared with `clearsky sun`) on the
// request's parameters; without time, the current instant.
#include "api/handlers/handlers.h"
#include "api/handlers/sun_handler.h"

namespace clearsky::api {

ApiResponse get_sun(const ApiContext&, const ApiRequest& request) {
  Parameters parameters = request_parameters(request);
  ApiResponse response;
  response.body = handle_sun(parameters, current_unix_time_s()).dump();
  return response;
}

}  // namespace clearsky::api
