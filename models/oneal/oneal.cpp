// O'Neal: descriptor, factory and queries (see oneal.h).
#include "models/oneal/oneal.h"

#include <cmath>
#include <limits>
#include <vector>

#include "models/oneal/oneal_functions.h"

namespace clearsky {

namespace {

ModelDescriptor make_descriptor() {
  ModelDescriptor d;
  d.id = "oneal";
  d.name = "O'Neal";
  d.version = "1";
  d.citation =
      "S. O'Neil. Accurate Atmospheric Scattering. In GPU Gems 2, chapter 16, pages 253-268. "
      "Addison-Wesley, "
      "2005.";
  d.summary =
      "Single scattering by numerical integration along each view ray with a few midpoint samples, "
      "every "
      "transmittance from an analytic approximation of the Chapman function instead of a table. As "
      "in the "
      "2016 study: 4 samples (2 in O'Neil's code), separate Rayleigh and Mie scale heights, the "
      "Rayleigh phase "
      "function, Cornette-Shanks for aerosols, and Schuler's (2012) approximation H c / (c mu + "
      "1), "
      "c = sqrt(R / H), instead of O'Neil's fit to his own atmosphere. No multiple scattering, no "
      "ground "
      "reflection.";
  d.parameters = {
      ParameterSpec{"samples", "", "midpoint samples per view ray", 4, 1, 1024, true, false},
      ParameterSpec{"alpha", "", "Angstrom exponent of the aerosol optical depth", 0.8, 0.0, 4.0,
                    false, true},
      ParameterSpec{"beta", "", "Angstrom turbidity (aerosol optical depth at 1 um)", 0.04, 0.0,
                    2.0, false, true},
      ParameterSpec{"g", "", "Cornette-Shanks asymmetry of the aerosol phase function", 0.7, -0.999,
                    0.999, false, true},
  };
  ModelCapabilities& c = d.capabilities;
  c.min_altitude_m = 0.0;
  c.max_altitude_m = 1.0e8;
  c.view_from_space = true;
  c.view_below_horizon = true;
  c.aerial_perspective = true;
  c.max_sun_zenith_deg = 180.0;
  c.scattering_orders = 1;
  c.per_sun_precomputation = false;
  c.sun_irradiance = true;
  c.sky_irradiance = true;
  return d;
}

}  // namespace

const ModelDescriptor& oneal_descriptor() {
  static const ModelDescriptor descriptor = make_descriptor();
  return descriptor;
}

ModelFactory oneal_factory() { return {&oneal_descriptor(), &ONealModel::create}; }

std::shared_ptr<const SkyModel> ONealModel::create(const ModelConfig& config,
                                                   const PrecomputeContext&) {
  validate_config(oneal_descriptor(), config);
  return std::shared_ptr<const SkyModel>(new ONealModel(config));
}

ONealModel::ONealModel(const ModelConfig& config)
    : SkyModel(config),
      samples_(static_cast<int>(option_or_default(oneal_descriptor(), config, "samples"))) {}

void ONealModel::compute_sky_radiance(const SunState& sun, const Viewpoint& viewpoint,
                                      std::span<const ViewDirection> views,
                                      SpectralBatch& out) const {
  const std::size_t n = wavelengths().size();
  std::vector<double> scratch(3 * n);
  const std::span<double> all(scratch);
  const oneal::RayWorkspace workspace{all.subspan(0, n), all.subspan(n, n), all.subspan(2 * n, n)};
  const double bottom = config().atmosphere.earth_radius_m;
  for (std::size_t i = 0; i < views.size(); ++i) {
    oneal::single_scattering(
        atmosphere(), RaySunGeometry::from(bottom, viewpoint, views[i], sun.sun()), samples_,
        std::numeric_limits<double>::infinity(), out.spectrum(i), {}, workspace);
  }
}

Spectrum ONealModel::compute_sun_irradiance(const SunState& sun, const Viewpoint& viewpoint) const {
  const auto lengths = oneal::optical_lengths_to_infinity(
      config().atmosphere, config().atmosphere.earth_radius_m + viewpoint.altitude_m,
      clamp_cosine(std::cos(sun.sun().zenith_rad)));
  if (!lengths) return Spectrum(wavelengths().size(), 0.0);
  return transmittance(atmosphere(), *lengths) * atmosphere().solar_irradiance_w_m2_nm;
}

ScatteringAlongRay ONealModel::compute_aerial_perspective(const SunState& sun,
                                                          const Viewpoint& viewpoint,
                                                          const ViewDirection& view,
                                                          double distance_m) const {
  return oneal::single_scattering(
      atmosphere(),
      RaySunGeometry::from(config().atmosphere.earth_radius_m, viewpoint, view, sun.sun()),
      samples_, distance_m);
}

}  // namespace clearsky
