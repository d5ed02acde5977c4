// The OpenAPI document, built once from the routes' operationIds (openapi_document.h).
#include "api/openapi/openapi_document.h"

#include <stdexcept>
#include <string>

#include "api/openapi/operation_docs.h"

namespace clearsky::api {

namespace {

using Json = nlohmann::ordered_json;

struct Route {
  const char* method;  // lower case, as in a Path Item
  const char* path;
  const char* operation_id;
};

// The served routes (server/http/http_server.cpp, server/http/data_routes.cpp).
constexpr Route kRoutes[] = {
    {"get", "/healthz", "healthz"},
    {"get", "/readyz", "readyz"},
    {"get", "/metrics", "metrics"},
    {"get", "/openapi.json", "openapi"},
    {"get", "/v1/models", "listModels"},
    {"get", "/v1/sun", "getSun"},
    {"get", "/v1/radiance", "getRadiance"},
    {"post", "/v1/radiance", "postRadiance"},
    {"get", "/v1/irradiance", "getIrradiance"},
    {"get", "/v1/rgb", "getRgb"},
    {"post", "/v1/rgb", "postRgb"},
    {"get", "/v1/skydome", "getSkydome"},
    {"get", "/v1/datasets", "listDatasets"},
    {"post", "/v1/datasets", "importDataset"},
    {"get", "/v1/datasets/{name}", "getDataset"},
    {"delete", "/v1/datasets/{name}", "deleteDataset"},
    {"get", "/v1/imports", "listImports"},
    {"get", "/v1/imports/{id}", "getImport"},
    {"get", "/v1/evaluations", "listEvaluations"},
    {"post", "/v1/evaluations", "createEvaluation"},
    {"get", "/v1/evaluations/{id}", "getEvaluation"},
    {"get", "/v1/evaluations/tickets/{ticket}", "getEvaluationTicket"},
    {"get", "/v1/jobs", "listJobs"},
    {"post", "/v1/jobs", "createJob"},
    {"get", "/v1/jobs/{id}", "getJob"},
    {"delete", "/v1/jobs/{id}", "deleteJob"},
    {"post", "/v1/jobs/{id}/pause", "pauseJob"},
    {"post", "/v1/jobs/{id}/resume", "resumeJob"},
};

Json build() {
  Json paths = Json::object();
  for (const Route& route : kRoutes) {
    const Json* operation = operation_doc(route.operation_id);
    if (operation == nullptr)
      throw std::logic_error(std::string("OpenAPI: no description of ") + route.operation_id);
    paths[route.path][route.method] = *operation;
  }
  return {{"openapi", "3.0.3"},
          {"info",
           {{"title", "clearsky"},
            {"version", "1"},
            {"description",
             "Spectral radiance, irradiance and colour of the clear sky from the 8 models of "
             "Bruneton's 2016 study, and their evaluation against measured skies. Angles are "
             "degrees, azimuth clockwise from North; radiance W/(m2.sr.nm). Unknown, unused or "
             "conflicting parameters are errors naming the parameter; no NaN or infinity is "
             "ever sent. Errors are {\"error\": {\"code\", \"message\", \"parameter\"}}; a "
             "method a path does not serve is a 404 or 405 with that body."}}},
          {"servers",
           Json::array({{{"url", "/"}, {"description", "The server that serves this document"}}})},
          {"tags", openapi_tags()},
          {"paths", std::move(paths)},
          {"components", openapi_components()}};
}

}  // namespace

const nlohmann::ordered_json& openapi_document() {
  static const Json document = build();
  return document;
}

}  // namespace clearsky::api
