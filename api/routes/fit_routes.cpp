// /v1/fits in the route table (route_handlers.h): atmosphere fits started on the background fit
// workers (202 with the fit to follow) and the stored fits (docs/fits.md "Over HTTP").
#include "api/evaluation/evaluations_api.h"
#include "api/fits/fit_pool.h"
#include "api/fits/fits_api.h"
#include "api/paging/list_page.h"
#include "api/routes/data_access.h"
#include "api/routes/route_handlers.h"

namespace clearsky::api {

namespace {

FitPool& fit_pool(const ApiContext& context) {
  FitPool* pool = data_services(context).fits;
  if (pool == nullptr)
    throw ApiError(503, "fits_unavailable", "", "this server runs no fit workers");
  return *pool;
}

}  // namespace

ApiResponse list_fits_route(const ApiContext& context, const ApiRequest& request) {
  Parameters query = query_parameters(request);
  storage::Database db = open_database(context);
  return list_page_response(request, list_fits(db, std::move(query)));
}

ApiResponse get_fit_route(const ApiContext& context, const ApiRequest& request) {
  const bool history = parse_show_fit_history(query_parameters(request));
  const std::int64_t id = parse_id(request.path_parameter("id"), "id");
  storage::Database db = open_database(context);
  return json_response(show_fit(db, id, history));
}

// 202 with the queued fit; Location (and "location") is the fit to follow.
ApiResponse create_fit_route(const ApiContext& context, const ApiRequest& request) {
  query_parameters(request).reject_unused();
  const DataServices& data = data_services(context);
  FitPool& pool = fit_pool(context);
  storage::Database db = open_database(context);
  const std::int64_t id = pool.submit(parse_fit_request(db, request.body, data.software_version));
  nlohmann::json body = show_fit(db, id, false);
  body["location"] = fit_location(id);
  ApiResponse response = json_response(body, 202);
  response.headers.emplace_back("Location", fit_location(id));
  return response;
}

}  // namespace clearsky::api
