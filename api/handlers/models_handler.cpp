// GET /v1/models: each registered model's descriptor (verbatim, api/encode/model_json.h) with
// the state of its default tables: status (queued, precomputing, ready, failed), progress and
// stage, measured precompute (or cache load) time and table memory.
#include "api/encode/model_json.h"
#include "api/handlers/handlers.h"

namespace clearsky::api {

ApiResponse get_models(const ApiContext& context, const ApiRequest& request) {
  Parameters p = request_parameters(request);
  p.reject_unused();
  nlohmann::json models = nlohmann::json::array();
  for (const ModelFactory& factory : context.models.factories()) {
    const ModelState s = context.models.default_state(factory);
    nlohmann::json state = {
        {"status", to_string(s.status)}, {"progress", finite(s.progress)}, {"stage", s.stage}};
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
