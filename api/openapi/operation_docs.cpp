// The operations and components of every area, merged once (operation_docs.h).
#include "api/openapi/operation_docs.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "api/openapi/openapi_area.h"

namespace clearsky::api {
namespace {

using openapi::Json;

struct Content {
  Json operations = Json::object();
  Json components = openapi::common_components();
};

// Adds each member of from to into; a name defined twice is a programming error.
void merge_members(Json& into, const Json& from, const std::string& where) {
  for (const auto& [name, value] : from.items()) {
    if (into.contains(name)) throw std::logic_error("OpenAPI: " + where + " " + name + " twice");
    into[name] = value;
  }
}

const Content& content() {
  static const Content all = [] {
    Content c;
    for (const openapi::Area& area :
         {openapi::service_area(), openapi::sky_area(), openapi::datasets_area(),
          openapi::evaluations_area(), openapi::fits_area(), openapi::aerosols_area()}) {
      merge_members(c.operations, area.operations, "operation");
      for (const auto& [kind, members] : area.components.items()) {
        if (!c.components.contains(kind)) c.components[kind] = Json::object();
        merge_members(c.components[kind], members, "component " + kind);
      }
    }
    // Responses in the order of their status codes.
    for (auto& [id, operation] : c.operations.items()) {
      Json sorted = Json::object();
      for (const char* first : {"1", "2", "3", "4", "5"}) {
        std::vector<std::string> statuses;
        for (const auto& [status, response] : operation["responses"].items())
          if (status.rfind(first, 0) == 0) statuses.push_back(status);
        std::sort(statuses.begin(), statuses.end());
        for (const std::string& status : statuses) sorted[status] = operation["responses"][status];
      }
      operation["responses"] = std::move(sorted);
    }
    return c;
  }();
  return all;
}

}  // namespace

const nlohmann::ordered_json* operation_doc(std::string_view operation_id) {
  const Json& operations = content().operations;
  const auto it = operations.find(std::string(operation_id));
  return it == operations.end() ? nullptr : &*it;
}

nlohmann::ordered_json openapi_components() { return content().components; }

nlohmann::ordered_json openapi_tags() {
  return openapi::parse(R"json([
  {"name": "sky", "description": "Radiance, irradiance, colour and images of the sky"},
  {"name": "sun", "description": "The sun's position and day"},
  {"name": "models", "description": "The served models"},
  {"name": "datasets", "description": "Stored measured skies"},
  {"name": "imports", "description": "Background dataset imports"},
  {"name": "evaluations", "description": "Runs of models against a dataset (RMSE)"},
  {"name": "fits", "description": "Atmosphere parameters fitted to a dataset"},
  {"name": "aerosols", "description": "Users' AERONET inversions for measured_aerosols"},
  {"name": "jobs", "description": "Scheduled evaluations (cron, UTC)"},
  {"name": "operations", "description": "Liveness, readiness, metrics and this document"}
])json");
}

}  // namespace clearsky::api
