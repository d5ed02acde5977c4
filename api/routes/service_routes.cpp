// /healthz, /readyz, /metrics and /openapi.json (route_handlers.h).
#include <algorithm>

#include "api/openapi/openapi_document.h"
#include "api/routes/route_handlers.h"

namespace clearsky::api {

namespace {

// These routes take no parameter either: a query is refused like everywhere else.
void no_parameters(const ApiRequest& request) { query_parameters(request).reject_unused(); }

}  // namespace

ApiResponse healthz(const ApiContext&, const ApiRequest& request) {
  no_parameters(request);
  ApiResponse response;
  response.body = R"({"status":"ok"})";
  return response;
}

// 200 when the tables built at start are ready (each model's draft and standard but those built
// on first use, or serve --prebuild's list; docs/quality-levels.md), else 503 with Retry-After; both with each model's
// state (its default tables), the state of each quality level built or asked for, and the
// background pass over its day's per-sun states (buckets built / total) where it has one. A
// draining server (SIGTERM, docs/deploy.md "Graceful drain") is not
// ready whatever its tables: load balancers stop sending it requests.
ApiResponse readyz(const ApiContext& context, const ApiRequest& request) {
  no_parameters(request);
  if (context.draining && context.draining())
    return error_response(ApiError(503, "draining", "",
                                   "the server is stopping: it finishes the requests in flight and "
                                   "takes no new ones"));
  nlohmann::json models = nlohmann::json::object();
  const bool ready = context.models.start_builds_ready();
  const auto day_sun_states = context.day_sun_states
                                  ? context.day_sun_states()
                                  : std::map<std::string, std::pair<std::size_t, std::size_t>>{};
  for (const ModelFactory& f : context.models.factories()) {
    // not_built: a default neither built at start nor asked for (docs/quality-levels.md).
    const std::optional<ModelState> state = context.models.config_state(f, ModelConfig{});
    nlohmann::json levels = nlohmann::json::object();
    for (QualityLevel level : kQualityLevels) {
      ModelConfig config;
      apply_quality_level(*f.descriptor, quality_setting(f.descriptor->id, level), config.options);
      const auto level_state = context.models.config_state(f, config);
      levels[std::string(to_string(level))] =
          level_state ? nlohmann::json{{"status", to_string(level_state->status)},
                                       {"progress", finite(level_state->progress)}}
                      : nlohmann::json{{"status", "not_built"}, {"progress", 0.0}};
    }
    models[f.descriptor->id] = {{"status", state ? to_string(state->status) : "not_built"},
                                {"progress", finite(state ? state->progress : 0.0)},
                                {"levels", std::move(levels)}};
    // The day's per-sun states, built in the background; readiness does not wait for them.
    if (const auto it = day_sun_states.find(f.descriptor->id); it != day_sun_states.end()) {
      models[f.descriptor->id]["day_sun_states"] = {{"built", it->second.first},
                                                    {"total", it->second.second}};
    }
  }
  if (ready) return json_response(nlohmann::json{{"status", "ready"}, {"models", models}});
  ApiResponse response = error_response(ApiError(
      503, "not_ready", "", "the tables of some models are being built", context.retry_after_s));
  nlohmann::json body = nlohmann::json::parse(response.body);
  body["models"] = models;
  response.body = body.dump();
  return response;
}

ApiResponse metrics(const ApiContext& context, const ApiRequest& request) {
  no_parameters(request);
  if (!context.metrics_text) throw ApiError(503, "no_metrics", "", "this server keeps no metrics");
  ApiResponse response;
  response.content_type = "text/plain; version=0.0.4";
  response.body = context.metrics_text();
  return response;
}

ApiResponse openapi(const ApiContext&, const ApiRequest& request) {
  no_parameters(request);
  static const std::string document = openapi_document().dump(2);
  ApiResponse response;
  response.body = document;
  return response;
}

}  // namespace clearsky::api
