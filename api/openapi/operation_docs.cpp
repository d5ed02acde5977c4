// Operation Objects per operationId, adapted from the path documents the server had before
// its route table (the sky paths below, the data paths of data_paths.cpp): each route's entry
// is looked up by its pattern and method (operation_docs.h).
#include "api/openapi/operation_docs.h"

#include <map>
#include <string>
#include <vector>

#include "api/openapi/data_paths.h"
#include "api/routes/route_table.h"

namespace clearsky::api {

namespace {

using nlohmann::json;

json param(const std::string& name, const std::string& type, const std::string& description,
           bool required = false, json extra = json::object()) {
  json schema = {{"type", type}};
  for (const auto& [k, v] : extra.items()) schema[k] = v;
  return {{"name", name},
          {"in", "query"},
          {"required", required},
          {"description", description},
          {"schema", schema}};
}

std::vector<json> sun_params() {
  return {
      param("sun_zenith", "number",
            "Sun zenith angle, degrees [0, 180]; give with sun_azimuth, or give lat, lon and time",
            false, {{"minimum", 0}, {"maximum", 180}}),
      param("sun_azimuth", "number", "Sun azimuth, degrees clockwise from North [-360, 360]", false,
            {{"minimum", -360}, {"maximum", 360}}),
      param("lat", "string",
            "Latitude: decimal degrees or DMS (42d26'36\"N), North positive; the sun then comes "
            "from NREL SPA"),
      param("lon", "string", "Longitude: decimal degrees or DMS, East positive"),
      param("time", "string",
            "ISO 8601 time with UTC offset, e.g. 2013-05-27T11:45:00-04:00 or ...Z", false,
            {{"format", "date-time"}}),
      param("pressure", "number", "Annual mean pressure for refraction, mbar (default 1013.25)"),
      param("temperature", "number",
            "Annual mean temperature for refraction, Celsius (default 15)"),
      param("delta_t", "number", "TT - UT1, seconds (default 69)"),
      param("refraction", "boolean", "Apply atmospheric refraction to the sun (default true)"),
  };
}

std::vector<json> sky_params() {
  std::vector<json> p = {param("model", "string", "Model id (GET /v1/models)", true)};
  for (auto& s : sun_params()) p.push_back(s);
  p.push_back(param("altitude", "number", "Observer altitude above sea level, m (default 0)", false,
                    {{"minimum", -500}, {"maximum", 1e7}}));
  for (const char* name : {"alpha", "beta", "g", "turbidity"}) {
    p.push_back(param(name, "number",
                      std::string("Atmosphere parameter ") + name +
                          ", accepted when the model's descriptor lists it (range and default "
                          "there); selects or builds matching tables"));
  }
  p.push_back(param("albedo", "string",
                    "Ground albedo: a number in [0, 1] or 'grass', when the model lists it"));
  return p;
}

json error_response(const std::string& description) {
  return {
      {"description", description},
      {"content", {{"application/json", {{"schema", {{"$ref", "#/components/schemas/Error"}}}}}}}};
}

json responses(json ok) {
  json r = {
      {"200", std::move(ok)},
      {"400", error_response(
                  "Invalid, unknown, unused or conflicting parameter (named in error.parameter)")},
      {"404", error_response("Unknown model")},
      {"413", error_response("Above a configured limit (views, wavelengths, size; a request "
                             "body above payload-max-bytes)")},
      {"422",
       error_response("The model's capabilities exclude the request (the message says why)")},
      {"503", error_response("Tables still being built; see the Retry-After header")}};
  return r;
}

json json_ok(const std::string& description) {
  return {{"description", description},
          {"content", {{"application/json", {{"schema", {{"type", "object"}}}}}}}};
}

json views_body() {
  return {{"required", true},
          {"content",
           {{"application/json",
             {{"schema",
               {{"type", "object"},
                {"description",
                 "The query parameters as members (numbers or strings), plus views: an array of "
                 "{view_zenith, view_azimuth} objects or [zenith, azimuth] pairs, degrees"},
                {"required", json::array({"model", "views"})},
                {"properties",
                 {{"views",
                   {{"type", "array"},
                    {"items",
                     {{"oneOf", json::array({{{"type", "object"},
                                              {"properties",
                                               {{"view_zenith", {{"type", "number"}}},
                                                {"view_azimuth", {{"type", "number"}}}}}},
                                             {{"type", "array"},
                                              {"items", {{"type", "number"}}},
                                              {"minItems", 2},
                                              {"maxItems", 2}}})}}}}}}}}}}}}}};
}

json build() {
  json paths = json::object();
  const auto view_params = [] {
    return std::vector<json>{
        param("view_zenith", "number", "View zenith angle, degrees [0, 180]", true),
        param("view_azimuth", "number", "View azimuth, degrees clockwise from North", true)};
  };
  const auto wavelengths = param(
      "wavelengths", "string",
      "Wavelengths, nm: a list '400,500,600' or 'start:stop:step'. Values on the paper's "
      "40-bin grid are read from its tables; other values build tables on exactly those points");

  paths["/healthz"]["get"] = {{"summary", "Liveness: 200 as soon as the process serves"},
                              {"responses", {{"200", json_ok("Alive")}}}};
  paths["/readyz"]["get"] = {
      {"summary", "Readiness: 200 when the default tables of every registered model are ready"},
      {"responses",
       {{"200", json_ok("Ready")},
        {"503", error_response("Tables still being built (Retry-After)")}}}};
  paths["/metrics"]["get"] = {
      {"summary",
       "Prometheus metrics: requests and latency per endpoint and model, table memory, cache "
       "lookups"},
      {"responses",
       {{"200",
         {{"description", "Prometheus text format"},
          {"content", {{"text/plain", {{"schema", {{"type", "string"}}}}}}}}}}}};
  paths["/openapi.json"]["get"] = {{"summary", "This document"},
                                   {"responses", {{"200", json_ok("OpenAPI 3.0")}}}};
  paths["/v1/models"]["get"] = {{"summary",
                                 "Registered models: descriptor (citation, parameters, "
                                 "capabilities, wavelengths) and state of the default tables"},
                                {"responses", responses(json_ok("{models: [...]}"))}};
  {
    std::vector<json> p;
    for (auto& s : sun_params()) {
      if (s["name"] != "sun_zenith" && s["name"] != "sun_azimuth") p.push_back(s);
    }
    p.push_back(param("altitude", "number", "Observer elevation, m"));
    p.push_back(param("delta_ut1", "number", "UT1 - UTC, seconds in (-1, 1) (default 0)"));
    paths["/v1/sun"]["get"] = {
        {"summary", "Sun zenith/azimuth (NREL SPA) and sunrise, transit, sunset of the local day"},
        {"parameters", p},
        {"responses", responses(json_ok("Sun position"))}};
  }
  {
    std::vector<json> p = sky_params();
    for (auto& v : view_params()) p.push_back(v);
    p.push_back(wavelengths);
    p.push_back(
        param("format", "string", "json (default) or csv", false, {{"enum", {"json", "csv"}}}));
    json ok = {{"description", "Spectral radiance, W/(m2.sr.nm)"},
               {"content",
                {{"application/json", {{"schema", {{"type", "object"}}}}},
                 {"text/csv", {{"schema", {{"type", "string"}}}}}}}};
    paths["/v1/radiance"]["get"] = {{"summary", "Spectral sky radiance for one view"},
                                    {"parameters", p},
                                    {"responses", responses(ok)}};
    paths["/v1/radiance"]["post"] = {
        {"summary", "Spectral sky radiance for a batch of views (body: the parameters and views)"},
        {"requestBody", views_body()},
        {"responses", responses(ok)}};
  }
  {
    std::vector<json> p = sky_params();
    p.push_back(
        param("tilt", "number", "Plane tilt from horizontal, degrees [0, 180] (default 0)"));
    p.push_back(param("surface_azimuth", "number",
                      "Azimuth of the plane's normal, degrees clockwise from North (default 180)"));
    p.push_back(param("component", "string", "all (default), direct, diffuse or global", false,
                      {{"enum", {"all", "direct", "diffuse", "global"}}}));
    p.push_back(param("spectral", "boolean", "Add spectra, W/(m2.nm) (default false)"));
    paths["/v1/irradiance"]["get"] = {{"summary",
                                       "Direct, diffuse (sky, ground reflection excluded) and "
                                       "global irradiance on a plane: W/m2, lx, spectra"},
                                      {"parameters", p},
                                      {"responses", responses(json_ok("Irradiance"))}};
  }
  {
    std::vector<json> p = sky_params();
    for (auto& v : view_params()) p.push_back(v);
    p.push_back(
        param("method", "string",
              "spectral (40 wavelengths, CIE 1931) or three (the paper's 3-wavelength method)",
              false, {{"enum", {"spectral", "three"}}}));
    paths["/v1/rgb"]["get"] = {{"summary", "Linear sRGB and luminance (cd/m2) for one view"},
                               {"parameters", p},
                               {"responses", responses(json_ok("Colours"))}};
    paths["/v1/rgb"]["post"] = {{"summary", "Linear sRGB and luminance for a batch of views"},
                                {"requestBody", views_body()},
                                {"responses", responses(json_ok("Colours"))}};
  }
  {
    std::vector<json> p = sky_params();
    p.push_back(param("projection", "string",
                      "fisheye (size x size, North up, East left), latlong (size x size/2) or "
                      "cubemap (size x 6 size), OpenEXR envmap conventions",
                      false, {{"enum", {"fisheye", "latlong", "cubemap"}}}));
    p.push_back(param("size", "integer", "Image width in pixels, 8 .. configured limit (4096)",
                      false, {{"minimum", 8}, {"maximum", 4096}}));
    p.push_back(param("channels", "string",
                      "rgb (R,G,B linear sRGB), luminance (Y, cd/m2) or spectral (Fichet et al. "
                      "2021 S0.<nm>nm channels); every image also has A, 1 where the model "
                      "answered and 0 where it did not (colour 0 there)",
                      false, {{"enum", {"rgb", "luminance", "spectral"}}}));
    p.push_back(param("pixel_type", "string", "half (default for rgb) or float", false,
                      {{"enum", {"half", "float"}}}));
    p.push_back(param("method", "string", "rgb only: spectral or three", false,
                      {{"enum", {"spectral", "three"}}}));
    p.push_back(param("wavelengths", "string", "spectral only: as for /v1/radiance"));
    json ok = {
        {"description",
         "An uncompressed scan-line OpenEXR file, streamed (chunked) as it is computed"},
        {"content", {{"image/x-exr", {{"schema", {{"type", "string"}, {"format", "binary"}}}}}}}};
    paths["/v1/skydome"]["get"] = {
        {"summary", "An EXR image of the sky"}, {"parameters", p}, {"responses", responses(ok)}};
  }

  add_data_paths(paths);
  return paths;
}

const std::map<std::string, nlohmann::ordered_json, std::less<>>& operations() {
  static const auto index = [] {
    const json paths = build();
    std::map<std::string, nlohmann::ordered_json, std::less<>> by_id;
    for (const Route& route : routes()) {
      std::string method(route.method);
      for (char& c : method) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      const std::string pattern(route.pattern);
      if (!paths.contains(pattern) || !paths[pattern].contains(method)) continue;
      by_id.emplace(route.operation_id,
                    nlohmann::ordered_json::parse(paths[pattern][method].dump()));
    }
    return by_id;
  }();
  return index;
}

}  // namespace

const nlohmann::ordered_json* operation_doc(std::string_view operation_id) {
  const auto it = operations().find(operation_id);
  return it == operations().end() ? nullptr : &it->second;
}

nlohmann::ordered_json openapi_components() {
  const json components =
      json::object({{"securitySchemes", {{"bearer", {{"type", "http"}, {"scheme", "bearer"}}}}},
                    {"schemas",
                     {{"Error",
                       {{"type", "object"},
                        {"required", json::array({"error"})},
                        {"properties",
                         {{"error",
                           {{"type", "object"},
                            {"required", json::array({"code", "message", "parameter"})},
                            {"properties",
                             {{"code", {{"type", "string"}}},
                              {"message", {{"type", "string"}}},
                              {"parameter", {{"type", "string"}, {"nullable", true}}}}}}}}}}}}}});
  return nlohmann::ordered_json::parse(components.dump());
}

}  // namespace clearsky::api
