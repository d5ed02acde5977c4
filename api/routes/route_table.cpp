// The rows of the route table (route_table.h).
#include "api/routes/route_table.h"

#include <array>

#include "api/handlers/handlers.h"
#include "api/routes/route_handlers.h"

namespace clearsky::api {

namespace {

using enum BodyPolicy;
using enum Caching;
constexpr bool kToken = true;
constexpr bool kOpen = false;

// clang-format off
constexpr std::array kRoutes = {
  //    method    pattern                              operationId            handler               body    token   caching
  Route{"GET",    "/healthz",                          "healthz",             healthz,              none,   kOpen,  no_store},
  Route{"GET",    "/readyz",                           "readyz",              readyz,               none,   kOpen,  no_store},
  Route{"GET",    "/metrics",                          "metrics",             metrics,              none,   kOpen,  no_store},
  Route{"GET",    "/openapi.json",                     "openapi",             openapi,              none,   kOpen,  revalidate},
  Route{"GET",    "/v1/models",                        "listModels",          get_models,           none,   kOpen,  revalidate},
  Route{"GET",    "/v1/sun",                           "getSun",              get_sun_route,        none,   kOpen,  deterministic},
  Route{"GET",    "/v1/radiance",                      "getRadiance",         radiance,             none,   kOpen,  deterministic},
  Route{"POST",   "/v1/radiance",                      "postRadiance",        radiance,             json,   kOpen,  no_store},
  Route{"GET",    "/v1/irradiance",                    "getIrradiance",       irradiance,           none,   kOpen,  deterministic},
  Route{"GET",    "/v1/irradiance/series",             "getIrradianceSeries", irradiance_series,    none,   kOpen,  deterministic},
  Route{"GET",    "/v1/rgb",                           "getRgb",              rgb,                  none,   kOpen,  deterministic},
  Route{"POST",   "/v1/rgb",                           "postRgb",             rgb,                  json,   kOpen,  no_store},
  Route{"GET",    "/v1/skydome",                       "getSkydome",          get_skydome,          none,   kOpen,  deterministic},
  Route{"GET",    "/v1/skypatches",                    "getSkyPatches",       skypatches,           none,   kOpen,  deterministic},
  Route{"GET",    "/v1/datasets",                      "listDatasets",        list_datasets_route,  none,   kOpen,  no_store},
  Route{"POST",   "/v1/datasets",                      "importDataset",       import_dataset_route, upload, kToken, no_store},
  Route{"GET",    "/v1/datasets/{name}",               "getDataset",          get_dataset_route,    none,   kOpen,  no_store},
  Route{"DELETE", "/v1/datasets/{name}",               "deleteDataset",       delete_dataset_route, none,   kToken, no_store},
  Route{"GET",    "/v1/imports",                       "listImports",         list_imports_route,   none,   kOpen,  no_store},
  Route{"GET",    "/v1/imports/{id}",                  "getImport",           get_import_route,     none,   kOpen,  no_store},
  Route{"GET",    "/v1/evaluations",                   "listEvaluations",     list_evaluations_route, none, kOpen,  no_store},
  Route{"POST",   "/v1/evaluations",                   "createEvaluation",    create_evaluation_route, json, kToken, no_store},
  Route{"GET",    "/v1/evaluations/{id}",              "getEvaluation",       get_evaluation_route, none,   kOpen,  no_store},
  Route{"GET",    "/v1/evaluations/tickets/{ticket}",  "getEvaluationTicket", get_ticket_route,     none,   kOpen,  no_store},
  Route{"GET",    "/v1/fits",                          "listFits",            list_fits_route,      none,   kOpen,  no_store},
  Route{"POST",   "/v1/fits",                          "createFit",           create_fit_route,     json,   kToken, no_store},
  Route{"GET",    "/v1/fits/{id}",                     "getFit",              get_fit_route,        none,   kOpen,  no_store},
  Route{"GET",    "/v1/aerosols",                      "listAerosols",        list_aerosols_route,  none,   kOpen,  no_store},
  Route{"POST",   "/v1/aerosols",                      "uploadAerosols",      upload_aerosols_route, json,  kToken, no_store},
  Route{"GET",    "/v1/aerosols/{id}",                 "getAerosols",         get_aerosols_route,   none,   kOpen,  no_store},
  Route{"GET",    "/v1/jobs",                          "listJobs",            list_jobs_route,      none,   kOpen,  no_store},
  Route{"POST",   "/v1/jobs",                          "createJob",           create_job_route,     json,   kToken, no_store},
  Route{"GET",    "/v1/jobs/{id}",                     "getJob",              get_job_route,        none,   kOpen,  no_store},
  Route{"DELETE", "/v1/jobs/{id}",                     "deleteJob",           delete_job_route,     none,   kToken, no_store},
  Route{"POST",   "/v1/jobs/{id}/pause",               "pauseJob",            pause_job_route,      none,   kToken, no_store},
  Route{"POST",   "/v1/jobs/{id}/resume",              "resumeJob",           resume_job_route,     none,   kToken, no_store},
};
// clang-format on

}  // namespace

std::span<const Route> routes() { return kRoutes; }

}  // namespace clearsky::api
