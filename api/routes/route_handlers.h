// The handlers of the route table (route_table.h) beyond the sky queries of
// api/handlers/handlers.h, one file per resource. Each checks its whole request (path and
// query parameters: an unknown one is a 400 naming it) before acting; errors are ApiError.
// The data handlers answer 503 on a server without a database (ApiContext::data null).
#pragma once

#include "api/http/api_types.h"

namespace clearsky::api {

// service_routes.cpp: liveness, readiness, metrics, the OpenAPI document.
ApiResponse healthz(const ApiContext& context, const ApiRequest& request);
ApiResponse readyz(const ApiContext& context, const ApiRequest& request);
ApiResponse metrics(const ApiContext& context, const ApiRequest& request);
ApiResponse openapi(const ApiContext& context, const ApiRequest& request);

// sky_routes.cpp: the sun (not stored without an explicit time) and the streamed skydome.
ApiResponse get_sun_route(const ApiContext& context, const ApiRequest& request);
ApiResponse get_skydome(const ApiContext& context, const ApiRequest& request);

// dataset_routes.cpp
ApiResponse list_datasets_route(const ApiContext& context, const ApiRequest& request);
ApiResponse import_dataset_route(const ApiContext& context, const ApiRequest& request);
ApiResponse get_dataset_route(const ApiContext& context, const ApiRequest& request);
ApiResponse delete_dataset_route(const ApiContext& context, const ApiRequest& request);

// import_routes.cpp
ApiResponse list_imports_route(const ApiContext& context, const ApiRequest& request);
ApiResponse get_import_route(const ApiContext& context, const ApiRequest& request);

// evaluation_routes.cpp
ApiResponse list_evaluations_route(const ApiContext& context, const ApiRequest& request);
ApiResponse create_evaluation_route(const ApiContext& context, const ApiRequest& request);
ApiResponse get_evaluation_route(const ApiContext& context, const ApiRequest& request);
ApiResponse get_ticket_route(const ApiContext& context, const ApiRequest& request);

// fit_routes.cpp
ApiResponse list_fits_route(const ApiContext& context, const ApiRequest& request);
ApiResponse create_fit_route(const ApiContext& context, const ApiRequest& request);
ApiResponse get_fit_route(const ApiContext& context, const ApiRequest& request);

// aerosol_routes.cpp
ApiResponse list_aerosols_route(const ApiContext& context, const ApiRequest& request);
ApiResponse upload_aerosols_route(const ApiContext& context, const ApiRequest& request);
ApiResponse get_aerosols_route(const ApiContext& context, const ApiRequest& request);

// job_routes.cpp
ApiResponse list_jobs_route(const ApiContext& context, const ApiRequest& request);
ApiResponse create_job_route(const ApiContext& context, const ApiRequest& request);
ApiResponse get_job_route(const ApiContext& context, const ApiRequest& request);
ApiResponse delete_job_route(const ApiContext& context, const ApiRequest& request);
ApiResponse pause_job_route(const ApiContext& context, const ApiRequest& request);
ApiResponse resume_job_route(const ApiContext& context, const ApiRequest& request);

}  // namespace clearsky::api
