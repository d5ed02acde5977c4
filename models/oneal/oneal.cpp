// O'Neal: descriptor, factory and queries (see oneal.h).
#include "models/oneal/oneal.h"

#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "models/atmosphere/atmosphere_parameter_table.h"
#include "models/atmosphere/solar_spectrum.h"
#include "models/core/ray_sphere.h"
#include "models/core/ray_sun_frame.h"
#include "models/oneal/oneal_functions.h"

namespace clearsky {

namespace {

ModelDescriptor make_descriptor() {
  return ModelDescriptor{
      .id = "oneal",
      .name = "O'Neal",
      .version = "3",
      .citation =
          "S. O'Neil. Accurate Atmospheric Scattering. In GPU Gems 2, chapter 16, pages "
          "253-268. Addison-Wesley, 2005.",
      .summary =
          "Single scattering by numerical integration along each view ray with a few midpoint "
          "samples, every transmittance from an analytic approximation of the Chapman function "
          "instead of a table. As in the 2016 study: 4 samples (2 in O'Neil's code), separate "
          "Rayleigh and Mie scale heights, the Rayleigh phase function, Cornette-Shanks for "
          "aerosols, and Schuler's (2012) approximation H c / (c mu + 1), c = sqrt(R / H), "
          "instead of O'Neil's fit to his own atmosphere. No multiple scattering; views that meet "
          "the ground see a Lambertian ground lit by the sun and the model's sky.",
      .min_wavelength_nm = kSolarSpectrumMinNm,
      .max_wavelength_nm = kSolarSpectrumMaxNm,
      .parameters =
          {
              {.name = "samples",
               .description = "midpoint samples per view ray",
               .default_value = 4,
               .min_value = 1,
               .max_value = 1024,
               .integer = true},
              atmosphere_parameter_spec("alpha"),
              atmosphere_parameter_spec("beta"),
              atmosphere_parameter_spec("g"),
              atmosphere_parameter_spec("albedo"),
          },
      .capabilities =
          {
              .min_altitude_m = 0.0,
              .max_altitude_m = 1.0e8,
              .view_from_space = true,
              .view_below_horizon = true,
              .aerial_perspective = true,
              .max_sun_zenith_deg = 180.0,
              .scattering_orders = 1,
              .per_sun_precomputation = false,
              .sun_irradiance = true,
              .sky_irradiance = true,
          },
  };
}

}  // namespace

const ModelDescriptor& oneal_descriptor() {
  static const ModelDescriptor descriptor = make_descriptor();
  return descriptor;
}

ModelFactory oneal_factory() {
  return make_model_factory<&oneal_descriptor, &ONealModel::build, &no_precomputed_tables>();
}

std::shared_ptr<const ONealModel> ONealModel::create(const ModelConfig& config,
                                                     const PrecomputeContext& context) {
  return build(validated_config(oneal_descriptor(), config), context);
}

std::shared_ptr<const ONealModel> ONealModel::build(const ValidatedConfig& config,
                                                    const PrecomputeContext&) {
  return std::shared_ptr<const ONealModel>(new ONealModel(config));
}

ONealModel::ONealModel(const ValidatedConfig& config)
    : SkyModel(config.config()), samples_(config.integer_option("samples")) {
  // The ground's sky irradiance from the model's own sky (its quadrature integrates the sky
  // without the ground: radiance_to_integrate).
  ground_ = LambertianGround(atmosphere().ground_albedo, atmosphere().solar_irradiance_w_m2_nm,
                             [this](double mu_s) {
                               const SunState sun(SunPosition{std::acos(mu_s), 0.0});
                               return compute_sky_irradiance(sun, Viewpoint{0.0}, {});
                             });
}

void ONealModel::scattered_radiance(const SunState& sun, const Viewpoint& viewpoint,
                                    std::span<const ViewDirection> views, SpectralBatch& out,
                                    bool with_ground) const {
  const std::size_t n = wavelengths().size();
  // Scratch on the stack for the usual grids (the study's 40 bins), on the heap beyond: a
  // one-view query then allocates nothing.
  constexpr std::size_t kStackWavelengths = 64;
  std::array<double, 3 * kStackWavelengths> stack_scratch;
  std::vector<double> heap_scratch(n > kStackWavelengths ? 3 * n : 0);
  const std::span<double> all = n > kStackWavelengths
                                    ? std::span<double>(heap_scratch)
                                    : std::span<double>(stack_scratch).first(3 * n);
  const oneal::RayWorkspace workspace{all.subspan(0, n), all.subspan(n, n)};
  const std::span<double> view_transmittance = all.subspan(2 * n, n);
  const auto& p = config().atmosphere;
  const RaySunFrame frame(p.earth_radius_m, viewpoint, sun.sun());
  for (std::size_t i = 0; i < views.size(); ++i) {
    const RaySunGeometry ray = frame.ray(views[i]);
    const AtmosphereSegment segment =
        atmosphere_segment(ray.r_m, ray.mu, p.earth_radius_m, p.top_radius_m);
    if (!with_ground || !segment.hits_ground) {
      oneal::single_scattering(atmosphere(), ray, samples_, std::numeric_limits<double>::infinity(),
                               out.spectrum(i), {}, workspace);
      continue;
    }
    oneal::single_scattering(atmosphere(), ray, samples_, std::numeric_limits<double>::infinity(),
                             out.spectrum(i), view_transmittance, workspace);
    const double mu_s = ray.mu_s_at(segment.end, p.earth_radius_m);
    const auto lengths = oneal::optical_lengths_to_infinity(p, p.earth_radius_m, mu_s);
    const Spectrum sun_transmittance =
        lengths ? transmittance(atmosphere(), *lengths) : Spectrum(n, 0.0);
    ground_.add_reflected(mu_s, {sun_transmittance.data(), n}, view_transmittance, out.spectrum(i));
  }
}

void ONealModel::compute_sky_radiance(const SunState& sun, const Viewpoint& viewpoint,
                                      std::span<const ViewDirection> views,
                                      SpectralBatch& out) const {
  scattered_radiance(sun, viewpoint, views, out, true);
}

void ONealModel::radiance_to_integrate(const SunState& sun, const Viewpoint& viewpoint,
                                       std::span<const ViewDirection> views,
                                       SpectralBatch& out) const {
  out.resize(views.size(), wavelengths().size());
  scattered_radiance(sun, viewpoint, views, out, false);
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
