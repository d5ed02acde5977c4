// The OpenAPI document, generated once from the route table.
#include "api/openapi/openapi_document.h"

#include <stdexcept>
#include <string>

#include "api/openapi/operation_docs.h"
#include "api/routes/route_table.h"

namespace clearsky::api {

namespace {

using nlohmann::ordered_json;

ordered_json build() {
  ordered_json paths = ordered_json::object();
  for (const Route& route : routes()) {
    const ordered_json* doc = operation_doc(route.operation_id);
    if (doc == nullptr)
      throw std::logic_error("no operation doc for " + std::string(route.operation_id));
    std::string method(route.method);
    for (char& c : method) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    ordered_json operation = *doc;
    operation["operationId"] = route.operation_id;
    paths[std::string(route.pattern)][method] = std::move(operation);
  }
  ordered_json document = {
      {"openapi", "3.0.3"},
      {"info",
       {{"title", "clearsky"},
        {"version", "1"},
        {"description",
         "Spectral radiance, irradiance and colour of the clear sky from the 8 models of "
         "Bruneton 2016. Angles in degrees, azimuth clockwise from North; radiance "
         "W/(m2.sr.nm). Unknown, unused or conflicting parameters are errors naming the "
         "parameter; NaN is never sent."}}},
      // The document is served by the server it describes: "/" is that server, wherever it
      // listens; the second entry is `clearsky serve`'s default address, for tools that read
      // the document from a file.
      {"servers",
       ordered_json::array(
           {{{"url", "/"}, {"description", "The server that serves this document"}},
            {{"url", "http://{host}:{port}"},
             {"description", "A clearsky serve instance"},
             {"variables",
              {{"host", {{"default", "127.0.0.1"}}}, {"port", {{"default", "8080"}}}}}}})},
      {"tags", openapi_tags()},
      {"paths", std::move(paths)},
      {"components", openapi_components()}};
  return document;
}

}  // namespace

const ordered_json& openapi_document() {
  static const ordered_json document = build();
  return document;
}

}  // namespace clearsky::api
