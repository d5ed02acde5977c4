// Checked batch radiance.
#include "api/handlers/sky_radiance_query.h"

#include <nlohmann/json.hpp>

#include "api/http/api_types.h"

namespace clearsky::api {

SpectralBatch checked_sky_radiance(const ModelProvider& provider,
                                   const std::shared_ptr<const SkyModel>& model_ptr,
                                   const SunSpec& sun, const Viewpoint& viewpoint,
                                   const ViewList& views) {
  const SkyModel& model = *model_ptr;
  const auto state = prepare_sun(provider, model_ptr, sun);
  SpectralBatch batch;
  model.sky_radiance(*state, viewpoint, views.views, batch);
  for (std::size_t i = 0; i < batch.size(); ++i) {
    if (batch.status[i] != SampleStatus::ok) {
      require_answer(batch.status[i], status_parameter(batch.status[i], sun, views, i),
                     model.descriptor().id);
    }
  }
  return batch;
}

nlohmann::json sun_json(const SunSpec& sun) {
  return {{"zenith_deg", finite(sun.zenith_deg)},
          {"azimuth_deg", finite(sun.azimuth_deg)},
          {"source", sun.from_place_and_time ? "spa" : "given"}};
}

}  // namespace clearsky::api
