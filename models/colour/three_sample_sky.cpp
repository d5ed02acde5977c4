// 3-sample spectral reconstruction around any model.
#include "models/colour/three_sample_sky.h"

#include <algorithm>
#include <stdexcept>

#include "models/core/invalid_input.h"

namespace clearsky {

ThreeSampleSky::ThreeSampleSky(std::shared_ptr<const SkyModel> three_point_model,
                               ModelConfig target_config)
    : SkyModel(std::move(target_config)), inner_(std::move(three_point_model)) {
  if (!inner_) throw std::invalid_argument("three-sample sky: no model");
  if (!(inner_->wavelengths() == method_.grid())) {
    throw InvalidInput("wavelengths", "the three-sample sky's model must be built on " +
                                          method_.grid().canonical_string());
  }
  if (!(inner_->config().atmosphere == config().atmosphere)) {
    throw InvalidInput("atmosphere",
                       "the three-sample sky's model and target use different atmospheres");
  }
}

std::shared_ptr<const SunState> ThreeSampleSky::compute_sun_state(
    const SunPosition& sun, const PrecomputeContext& context) const {
  return inner_->prepare_sun(sun, context);
}

Spectrum ThreeSampleSky::reconstruct(std::span<const double> three) const {
  return method_.reconstruct_spectrum(Spectrum(std::vector<double>(three.begin(), three.end())),
                                      wavelengths());
}

void ThreeSampleSky::compute_sky_radiance(const SunState& sun, const Viewpoint& viewpoint,
                                          std::span<const ViewDirection> views,
                                          SpectralBatch& out) const {
  SpectralBatch three;
  inner_->sky_radiance(sun, viewpoint, views, three);
  for (std::size_t i = 0; i < views.size(); ++i) {
    out.status[i] = three.status[i];
    if (three.status[i] != SampleStatus::ok) continue;
    const Spectrum s = reconstruct(three.spectrum(i));
    std::copy(s.begin(), s.end(), out.spectrum(i).begin());
  }
}

Spectrum ThreeSampleSky::compute_sun_irradiance(const SunState& sun,
                                                const Viewpoint& viewpoint) const {
  const SpectralSample three = inner_->sun_irradiance(sun, viewpoint);
  if (three.status != SampleStatus::ok) {
    throw std::runtime_error("three-sample sky: the wrapped model refused the sun irradiance");
  }
  return reconstruct({three.value.data(), three.value.size()});
}

}  // namespace clearsky
