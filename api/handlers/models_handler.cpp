// GET /v1/models: each registered model's descriptor (verbatim, api/encode/model_json.h) with
// the state of its default tables: status (queued, precomputing, ready, failed, not_built), progress and
// stage, measured precompute (or cache load) time and table memory.
#include "api/encode/model_json.h"
#include "api/handlers/handlers.h"

namespace clearsky::api {

ApiResponse get_models(const ApiContext& context, const ApiRequest& request) {
  Parameters p = request_parameters(request);
  p.reject_unused();
  nlohmann::json models = nlohmann::json::array();
  for (const ModelFactory& factory : context.models.factories()) {
    // not_built: a default neither built at start nor asked for (docs/quality-levels.md).
    const std::optional<ModelState> known = context.models.config_state(factory, ModelConfig{});
    const ModelState s = known.value_or(ModelState{});
    nlohmann::json state = {{"status", known ? to_string(s.status) : "not_built"},
                            {"progress", finite(s.progress)},
                            {"stage", s.stage}};
    if (s.status == ModelState::Status::ready) {
      state["precompute_seconds"] = finite(s.precompute_seconds);
      state["table_bytes"] = s.table_bytes;
      state["loaded_from_cache"] = s.loaded_from_cache;
    }
    if (s.status == ModelState::Status::failed) state["error"] = s.error;
    nlohmann::json entry = descriptor_to_json(*factory.descriptor);
    entry["state"] = std::move(state);
    models.push_back(std::move(entry));
  }
  return json_response({{"models", std::move(models)}});
}

}  // namespace clearsky::api
