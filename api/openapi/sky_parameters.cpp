// The shared query parameters of the sky endpoints (openapi_area.h), from the code's own tables:
// the sun and place parameters of api/request/sky_request.h and place_time.h, and the
// parameters each registered model's descriptor lists (models/core/model_descriptor.h), whose
// ranges differ between models: the schema carries the union, the description each model's.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "api/openapi/openapi_area.h"
#include "models/registry.h"

namespace clearsky::api::openapi {
namespace {

std::string number_text(double x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

Json query(const std::string& name, const std::string& description, Json schema,
           const Json& example = nullptr) {
  Json parameter = {{"name", name},
                    {"in", "query"},
                    {"required", false},
                    {"description", description},
                    {"schema", std::move(schema)}};
  if (!example.is_null()) parameter["example"] = example;
  return parameter;
}

// A parameter listed by one or more models' descriptors.
struct ListedParameter {
  std::string name;
  std::string description;
  std::string unit;
  bool atmosphere = false;
  bool integer = true;
  double min = INFINITY, max = -INFINITY;
  std::string per_model;  // "preetham [2, 10], default 2.53; ..."
  std::vector<double> defaults;
};

std::vector<ListedParameter> listed_parameters() {
  std::vector<ListedParameter> out;
  for (const ModelFactory& factory : registered_models()) {
    const ModelDescriptor& d = *factory.descriptor;
    for (const ParameterSpec& spec : d.parameters) {
      auto it = std::find_if(out.begin(), out.end(),
                             [&](const ListedParameter& p) { return p.name == spec.name; });
      if (it == out.end()) {
        ListedParameter added;
        added.name = spec.name;
        added.description = spec.description;
        added.unit = spec.unit;
        added.atmosphere = spec.atmosphere;
        out.push_back(std::move(added));
        it = out.end() - 1;
      }
      it->integer = it->integer && spec.integer;
      it->min = std::min(it->min, spec.min_value);
      it->max = std::max(it->max, spec.max_value);
      it->defaults.push_back(spec.default_value);
      if (!it->per_model.empty()) it->per_model += "; ";
      it->per_model +=
          d.id + " [" + number_text(spec.min_value) + ", " + number_text(spec.max_value) +
          "], default " +
          (spec.name == "albedo" ? std::string("grass") : number_text(spec.default_value));
    }
  }
  return out;
}

Json listed_schema(const ListedParameter& p) {
  Json number = {{"type", p.integer ? "integer" : "number"}};
  if (std::isfinite(p.min)) number["minimum"] = p.min;
  if (std::isfinite(p.max)) number["maximum"] = p.max;
  // A default in the schema only when every model that lists the parameter has the same one.
  const bool one_default = std::all_of(p.defaults.begin(), p.defaults.end(),
                                       [&](double x) { return x == p.defaults.front(); });
  if (p.name != "albedo" && one_default && std::isfinite(p.defaults.front())) {
    if (p.integer)
      number["default"] = static_cast<long long>(p.defaults.front());
    else
      number["default"] = p.defaults.front();
  }
  if (p.name != "albedo") return number;
  // "grass" selects the spectral albedo of grass, the study's default (sky_request.cpp).
  return {{"oneOf", Json::array({number, {{"type", "string"}, {"enum", {"grass"}}}})}};
}

std::string listed_key(const ListedParameter& p) { return "model_parameter." + p.name; }

// The sun, place and altitude parameters: name -> parameter (sky_request.h, place_time.h).
Json place_parameters() {
  return parse(R"json({
  "sun_zenith": {
    "name": "sun_zenith", "in": "query", "required": false,
    "description": "Sun zenith angle, degrees. Give it with sun_azimuth, or give lat, lon and time instead (both ways at once: 400 conflicting_parameters).",
    "schema": {"type": "number", "minimum": 0, "maximum": 180},
    "example": 30
  },
  "sun_azimuth": {
    "name": "sun_azimuth", "in": "query", "required": false,
    "description": "Sun azimuth, degrees clockwise from North.",
    "schema": {"type": "number", "minimum": -360, "maximum": 360},
    "example": 135
  },
  "lat": {
    "name": "lat", "in": "query", "required": false,
    "description": "Latitude of the observer, degrees North in [-90, 90]: decimal (42.444) or DMS (42d26'36\"N). With lon and time the sun comes from NREL SPA.",
    "schema": {"type": "string"},
    "example": "42.444"
  },
  "lon": {
    "name": "lon", "in": "query", "required": false,
    "description": "Longitude, degrees East in [-180, 180]: decimal or DMS.",
    "schema": {"type": "string"},
    "example": "-76.5"
  },
  "time": {
    "name": "time", "in": "query", "required": false,
    "description": "ISO 8601 time with a UTC offset or Z (years -2000 to 6000).",
    "schema": {"type": "string", "format": "date-time"},
    "example": "2013-05-27T11:45:00-04:00"
  },
  "pressure": {
    "name": "pressure", "in": "query", "required": false,
    "description": "Annual mean pressure for SPA's refraction, mbar (with lat, lon and time).",
    "schema": {"type": "number", "minimum": 0, "maximum": 5000, "default": 1013.25}
  },
  "temperature": {
    "name": "temperature", "in": "query", "required": false,
    "description": "Annual mean temperature for SPA's refraction, degrees Celsius (with lat, lon and time).",
    "schema": {"type": "number", "minimum": -273, "maximum": 6000, "default": 15}
  },
  "delta_t": {
    "name": "delta_t", "in": "query", "required": false,
    "description": "TT - UT1, seconds (with lat, lon and time); absent: Delta T of the year and month of time by the Espenak-Meeus expressions (years -1999 to 3000; later years need delta_t).",
    "schema": {"type": "number", "minimum": -8000, "maximum": 8000}
  },
  "refraction": {
    "name": "refraction", "in": "query", "required": false,
    "description": "Apply atmospheric refraction to the computed sun (true/false or 1/0; with lat, lon and time).",
    "schema": {"type": "boolean", "default": true}
  },
  "altitude": {
    "name": "altitude", "in": "query", "required": false,
    "description": "Observer altitude above sea level, m; each model answers its own range (capabilities.altitude_range_m; outside it: 422).",
    "schema": {"type": "number", "minimum": -500, "maximum": 10000000, "default": 0}
  }
})json");
}

}  // namespace

Json sky_parameter_components() {
  Json model_ids = Json::array();
  for (const ModelFactory& factory : registered_models())
    model_ids.push_back(factory.descriptor->id);
  Json components = Json::object();
  components["model"] = {
      {"name", "model"},
      {"in", "query"},
      {"required", true},
      {"description",
       "The model that answers (GET /v1/models). A server started with --models serves a subset: "
       "any other id is a 404 unknown_model."},
      {"schema", {{"type", "string"}, {"enum", model_ids}}},
      {"example", "preetham"}};
  components["quality"] = {
      {"name", "quality"},
      {"in", "query"},
      {"required", false},
      {"description",
       "The model's cost options: draft (cheaper), standard (the model's defaults, the 2016 "
       "study's setting) or reference (finer); absent: the server's --quality (standard by "
       "default). An option given explicitly wins over the level's. The answer states the "
       "level asked and served, the setting and its measured error (JSON members, the "
       "Clearsky-Quality, Clearsky-Served-Quality and Clearsky-Quality-Detail headers, the "
       "skydome's clearskyQuality attributes); another value: 400 naming quality "
       "(docs/quality-levels.md)."},
      {"schema", {{"type", "string"}, {"enum", {"draft", "standard", "reference"}}}}};
  components["fit"] = {
      {"name", "fit"},
      {"in", "query"},
      {"required", false},
      {"description",
       "A stored atmosphere fit of the request's model (GET /v1/fits; docs/fits.md \"Using a "
       "fit\"): its id, latest (the model's newest succeeded fit) or latest:DATASET (the newest "
       "on that dataset). Its fitted values (the free parameters it fitted) are used as if the "
       "request gave them, range-checked like them; its fixed parameters are not applied. A "
       "parameter given too that the fit sets: 400 conflicting_parameters naming it. An unknown "
       "id or no such fit: 404 unknown_fit; a fit not succeeded or of another model: 409 "
       "fit_not_succeeded or fit_model_mismatch; a server without a database (serve --role "
       "query): 404 no_database; each naming fit. The answer has a fit member (id, model, "
       "model_version, dataset, parameters) and the header Clearsky-Fit (the skydome: also its "
       "clearskyFit attribute); with latest it is Cache-Control: no-store."},
      {"schema", {{"type", "string"}, {"pattern", "^([1-9][0-9]*|latest(:.+)?)$"}}},
      {"example", "latest"}};
  const Json place = place_parameters();
  for (const auto& [name, parameter] : place.items()) components[name] = parameter;
  for (const ListedParameter& p : listed_parameters()) {
    std::string description = p.description;
    if (!p.unit.empty()) description += " (" + p.unit + ")";
    description += std::string(p.atmosphere ? ". Atmosphere parameter" : ". Model option") +
                   " taken by: " + p.per_model +
                   ". A model that does not list it answers 400 unknown_parameter; each distinct "
                   "value selects or builds matching tables.";
    components[listed_key(p)] = query(p.name, description, listed_schema(p));
  }
  return components;
}

Json sky_parameter_refs() {
  Json refs = Json::array();
  const Json components = sky_parameter_components();
  for (const auto& [key, parameter] : components.items()) refs.push_back(ref("parameters", key));
  return refs;
}

Json sky_body_properties() {
  Json properties = Json::object();
  const Json components = sky_parameter_components();
  for (const auto& [key, parameter] : components.items()) {
    Json schema = parameter["schema"];
    // In a body, coordinates may be JSON numbers as well as (DMS) text.
    if (key == "lat" || key == "lon") {
      const double bound = key == "lat" ? 90 : 180;
      schema = {
          {"oneOf", Json::array({{{"type", "number"}, {"minimum", -bound}, {"maximum", bound}},
                                 {{"type", "string"}}})}};
    }
    schema["description"] = parameter["description"];
    properties[parameter["name"].get<std::string>()] = std::move(schema);
  }
  return properties;
}

}  // namespace clearsky::api::openapi
