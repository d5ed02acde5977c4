// /v1/jobs in the route table (route_handlers.h): scheduled evaluations.
#include "api/evaluation/evaluations_api.h"
#include "api/jobs/jobs_api.h"
#include "api/paging/list_page.h"
#include "api/routes/data_access.h"
#include "api/routes/route_handlers.h"

namespace clearsky::api {

namespace {

// The job of the path, after the query was checked (it takes no parameter).
std::int64_t job_id(const ApiRequest& request) {
  query_parameters(request).reject_unused();
  return parse_id(request.path_parameter("id"), "id");
}

}  // namespace

ApiResponse list_jobs_route(const ApiContext& context, const ApiRequest& request) {
  Parameters query = query_parameters(request);
  storage::Database db = open_database(context);
  return list_page_response(request, list_jobs(db, std::move(query)));
}

// 201 with the job; Location is the job.
ApiResponse create_job_route(const ApiContext& context, const ApiRequest& request) {
  query_parameters(request).reject_unused();
  storage::Database db = open_database(context);
  const CreatedResource job =
      create_job(db, request.body, data_services(context).models, now_unix_s());
  ApiResponse response = ordered_json_response(job.body, 201);
  response.headers.emplace_back("Location", job.location);
  return response;
}

ApiResponse get_job_route(const ApiContext& context, const ApiRequest& request) {
  const std::int64_t id = job_id(request);
  storage::Database db = open_database(context);
  return ordered_json_response(show_job(db, id));
}

ApiResponse delete_job_route(const ApiContext& context, const ApiRequest& request) {
  const std::int64_t id = job_id(request);
  storage::Database db = open_database(context);
  return ordered_json_response(delete_job(db, id));
}

ApiResponse pause_job_route(const ApiContext& context, const ApiRequest& request) {
  const std::int64_t id = job_id(request);
  storage::Database db = open_database(context);
  return ordered_json_response(pause_job(db, id));
}

ApiResponse resume_job_route(const ApiContext& context, const ApiRequest& request) {
  const std::int64_t id = job_id(request);
  storage::Database db = open_database(context);
  return ordered_json_response(resume_job(db, id, now_unix_s()));
}

}  // namespace clearsky::api
