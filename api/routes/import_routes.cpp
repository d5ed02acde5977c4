// /v1/imports in the route table (route_handlers.h): the state of dataset imports.
#include "api/evaluation/evaluations_api.h"
#include "api/imports/imports_api.h"
#include "api/paging/list_page.h"
#include "api/routes/data_access.h"
#include "api/routes/route_handlers.h"

namespace clearsky::api {

ApiResponse list_imports_route(const ApiContext& context, const ApiRequest& request) {
  Parameters query = query_parameters(request);
  storage::Database db = open_database(context);
  return list_page_response(request,
                            list_imports(db, data_services(context).imports, std::move(query)));
}

ApiResponse get_import_route(const ApiContext& context, const ApiRequest& request) {
  query_parameters(request).reject_unused();
  const std::int64_t id = parse_id(request.path_parameter("id"), "id");
  storage::Database db = open_database(context);
  return ordered_json_response(show_import(db, data_services(context).imports, id));
}

}  // namespace clearsky::api
