// /v1/evaluations in the route table (route_handlers.h): stored runs, and evaluations started
// on the background pool (202 with a ticket to follow).
#include "api/evaluation/evaluation_pool.h"
#include "api/evaluation/evaluations_api.h"
#include "api/paging/list_page.h"
#include "api/routes/data_access.h"
#include "api/routes/route_handlers.h"

namespace clearsky::api {

namespace {

EvaluationPool& evaluation_pool(const ApiContext& context) {
  EvaluationPool* pool = data_services(context).evaluations;
  if (pool == nullptr)
    throw ApiError(503, "evaluations_unavailable", "", "this server runs no evaluation workers");
  return *pool;
}

}  // namespace

ApiResponse list_evaluations_route(const ApiContext& context, const ApiRequest& request) {
  const EvaluationFilter filter = parse_evaluation_filter(query_parameters(request));
  storage::Database db = open_database(context);
  return list_page_response(request, list_evaluations(db, filter));
}

ApiResponse get_evaluation_route(const ApiContext& context, const ApiRequest& request) {
  const ShowEvaluationOptions options = parse_show_evaluation_options(query_parameters(request));
  const std::int64_t id = parse_id(request.path_parameter("id"), "id");
  storage::Database db = open_database(context);
  return ordered_json_response(show_evaluation(db, id, options));
}

ApiResponse get_ticket_route(const ApiContext& context, const ApiRequest& request) {
  query_parameters(request).reject_unused();
  const std::string& text = request.path_parameter("ticket");
  const auto ticket = evaluation_pool(context).ticket(parse_id(text, "ticket"));
  if (!ticket)
    throw ApiError(404, "unknown_ticket", "ticket", "ticket: no evaluation ticket " + text);
  return ordered_json_response(ticket_to_json(*ticket));
}

// 202 with the ticket's state; Location (and "location") is the ticket to follow.
ApiResponse create_evaluation_route(const ApiContext& context, const ApiRequest& request) {
  query_parameters(request).reject_unused();
  const DataServices& data = data_services(context);
  EvaluationPool& pool = evaluation_pool(context);
  storage::Database db = open_database(context);
  const std::int64_t ticket =
      pool.submit(parse_evaluation_request(db, request.body, data.models, data.software_version));
  nlohmann::ordered_json body = ticket_to_json(*pool.ticket(ticket));
  body["location"] = ticket_location(ticket);
  ApiResponse response = ordered_json_response(body, 202);
  response.headers.emplace_back("Location", ticket_location(ticket));
  return response;
}

}  // namespace clearsky::api
