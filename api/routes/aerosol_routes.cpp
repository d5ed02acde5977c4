// /v1/aerosols in the route table (route_handlers.h): users' AERONET inversions for the
// measured_aerosols model, uploaded, listed and described (api/aerosols/aerosols_api.h).
#include "api/aerosols/aerosols_api.h"
#include "api/evaluation/evaluations_api.h"
#include "api/paging/list_page.h"
#include "api/routes/data_access.h"
#include "api/routes/route_handlers.h"

namespace clearsky::api {

ApiResponse list_aerosols_route(const ApiContext& context, const ApiRequest& request) {
  Parameters query = query_parameters(request);
  data_services(context);
  storage::Database db = open_database(context);
  return list_page_response(request, list_aerosol_inversions(db, std::move(query)));
}

ApiResponse get_aerosols_route(const ApiContext& context, const ApiRequest& request) {
  query_parameters(request).reject_unused();
  const std::int64_t id = parse_id(request.path_parameter("id"), "id");
  data_services(context);
  storage::Database db = open_database(context);
  return ordered_json_response(show_aerosol_inversion(db, id));
}

// The body is the .pfn file, read whole under the payload limit; it is checked whole by the
// reader before the row is written: 201 with the stored inversion and its Location.
ApiResponse upload_aerosols_route(const ApiContext& context, const ApiRequest& request) {
  Parameters p = query_parameters(request);
  const std::string name = p.text("name").value_or("");
  p.reject_unused();
  data_services(context);
  check_aerosol_media_type(request.header("Content-Type"));
  storage::Database db = open_database(context);
  const std::int64_t id = store_aerosol_inversion(db, name, request.body);
  ApiResponse response = ordered_json_response(show_aerosol_inversion(db, id), 201);
  response.headers.emplace_back("Location", aerosols_location(id));
  return response;
}

}  // namespace clearsky::api
