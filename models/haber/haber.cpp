// Descriptor, factory and queries of the Haber model (see haber.h).
#include "models/haber/haber.h"

#include <cmath>
#include <optional>
#include <sstream>
#include <string>

#include "models/atmosphere/atmosphere_parameter_table.h"
#include "models/atmosphere/solar_spectrum.h"
#include "models/core/invalid_input.h"
#include "models/core/numeric.h"
#include "models/haber/haber_dome_blob.h"

namespace clearsky::haber {

namespace {

ModelDescriptor make_descriptor() {
  return ModelDescriptor{
      .id = "haber",
      .name = "Haber 2005",
      .version = "1",
      .citation =
          "J. Haber, M. Magnor, H.-P. Seidel. Physically-based simulation of twilight "
          "phenomena. ACM Transactions on Graphics 24(4), 2005. As implemented in E. "
          "Bruneton, A Qualitative and Quantitative Evaluation of 8 Clear Sky Models, "
          "IEEE TVCG 2016.",
      .summary =
          "Multiple scattering on a spherical grid centred on the viewer (72 azimuths, 5-degree "
          "rings, shells growing by 1.09125 from 10 m), 50 layers of equal Rayleigh mass up to "
          "35 km, 4 orders, gathered on every 4th shell and interpolated. Rayleigh isotropic at "
          "every order, Cornette-Shanks for single-scattered Mie only, no ground albedo, ozone "
          "or refraction. Precomputed per sun zenith into a dome of 5 x 5 degree spectra read "
          "bilinearly.",
      .min_wavelength_nm = kSolarSpectrumMinNm,
      .max_wavelength_nm = kSolarSpectrumMaxNm,
      .parameters =
          {
              atmosphere_parameter_spec("alpha"),
              atmosphere_parameter_spec("beta"),
              // |g| <= 0.9: a more peaked phase broke the energy bound (haber.h).
              atmosphere_parameter_spec("g", -kMaxPhaseAsymmetry, kMaxPhaseAsymmetry),
              {.name = "azimuth_sectors",
               .description = "azimuth sectors n_phi (even); also sets ring width and shell "
                              "growth",
               .default_value = 72,
               .min_value = 12,
               .max_value = 144,
               .integer = true},
              {.name = "layers",
               .description = "layers of equal Rayleigh mass up to 35 km",
               .default_value = 50,
               .min_value = 5,
               .max_value = 200,
               .integer = true},
              {.name = "shell_stride",
               .description = "multiple scattering gathered on every n-th shell, interpolated "
                              "between",
               .default_value = 4,
               .min_value = 1,
               .max_value = 16,
               .integer = true},
              {.name = "scattering_orders",
               .description = "scattering orders (1: single scattering only)",
               .default_value = 4,
               .min_value = 1,
               .max_value = 8,
               .integer = true},
              {.name = "sun_zenith_bucket_deg",
               .unit = "deg",
               .description = "per-sun states are shared by suns within this zenith width (0: "
                              "exact, the study: RMSE 14.796 instead of 14.770; each new state "
                              "costs seconds)",
               .default_value = 1.0,
               .min_value = 0.0,
               .max_value = 5.0},
              {.name = "sun_state_cache_size",
               .description = "per-sun states kept in memory (96: every 1-degree bucket of the "
                              "day sky)",
               .default_value = 96,
               .min_value = 1,
               .max_value = 1024,
               .integer = true},
          },
      .capabilities =
          {
              .min_altitude_m = 0.0,
              .max_altitude_m = 0.0,
              .view_from_space = false,
              .view_below_horizon = false,
              .aerial_perspective = false,
              .max_sun_zenith_deg = 180.0,
              // 90 + 2 acos(R / (R + 35 km)) = 101.99, plus half the widest
              // sun_zenith_bucket_deg (README "Dark suns").
              .dark_beyond_sun_zenith_deg = 104.5,
              .scattering_orders = 4,
              .per_sun_precomputation = true,
              .sun_irradiance = true,
              .sky_irradiance = true,
          },
  };
}

HaberSettings settings_from(const ValidatedConfig& config) {
  HaberSettings s;
  s.azimuth_sectors = config.integer_option("azimuth_sectors");
  s.layer_count = config.integer_option("layers");
  s.shell_stride = config.integer_option("shell_stride");
  s.scattering_orders = config.integer_option("scattering_orders");
  return s;
}

std::size_t grid_table_bytes(const HaberGrid& grid) {
  return grid.ring_cells().size() * sizeof(RingCell) + grid.active().size() * sizeof(int);
}

}  // namespace

const ModelDescriptor& model_descriptor() {
  static const ModelDescriptor descriptor = make_descriptor();
  return descriptor;
}

ModelFactory model_factory() {
  return make_model_factory<&model_descriptor, &HaberModel::build,
                            &HaberModel::estimated_table_bytes>();
}

std::size_t HaberModel::estimated_table_bytes(const ValidatedConfig& config) {
  const HaberSettings settings = settings_from(config);
  if (settings.azimuth_sectors % 2 != 0) throw InvalidInput("azimuth_sectors", "must be even");
  const AtmosphereParameters& atmosphere = config.config().atmosphere;
  const HaberGrid grid(settings, atmosphere.earth_radius_m, atmosphere.rayleigh_scale_height_m,
                       atmosphere.mie_scale_height_m);
  return grid_table_bytes(grid);
}

std::shared_ptr<const HaberModel> HaberModel::create(const ModelConfig& config,
                                                     const PrecomputeContext& context) {
  return build(validated_config(model_descriptor(), config), context);
}

std::shared_ptr<const HaberModel> HaberModel::build(const ValidatedConfig& config,
                                                    const PrecomputeContext& context) {
  const HaberSettings settings = settings_from(config);
  if (settings.azimuth_sectors % 2 != 0) throw InvalidInput("azimuth_sectors", "must be even");
  context.check_cancelled();
  return std::shared_ptr<const HaberModel>(
      new HaberModel(config, settings, context.sun_state_memory_bytes));
}

HaberModel::HaberModel(const ValidatedConfig& validated, const HaberSettings& settings,
                       std::size_t sun_state_memory_bytes)
    : SkyModel(validated.config()),
      grid_(settings, config().atmosphere.earth_radius_m,
            config().atmosphere.rayleigh_scale_height_m, config().atmosphere.mie_scale_height_m),
      bucket_width_rad_(degrees_to_radians(validated.option("sun_zenith_bucket_deg"))),
      cache_prefix_(model_descriptor().id + "/" + model_descriptor().version + "/" +
                    config().canonical_string()),
      cache_(std::make_unique<SunStateCache<HaberDome>>(
          static_cast<std::size_t>(validated.integer_option("sun_state_cache_size")),
          sun_state_memory_bytes)) {}

std::size_t HaberModel::table_bytes() const { return grid_table_bytes(grid_); }

std::shared_ptr<const SunState> HaberModel::compute_sun_state(
    const SunPosition& sun, const PrecomputeContext& context) const {
  const double zenith = sun_zenith_bucket_centre(sun.zenith_rad, bucket_width_rad_);
  std::ostringstream key;
  key.precision(17);
  key << cache_prefix_ << ";sun_zenith_rad=" << zenith;
  // Single flight in memory; on a miss the disk table cache first (the key names the blob
  // format, the model version, the configuration and the zenith), then the computation,
  // stored for the next process (haber_dome_blob.h).
  auto dome = cache_->get_or_build(
      key.str(),
      [&]() -> std::shared_ptr<const HaberDome> {
        const std::string disk_key =
            "haber-dome/" + std::to_string(kDomeBlobVersion) + "/" + key.str();
        const std::size_t wavelengths = atmosphere().grid.size();
        if (context.cache != nullptr) {
          if (const std::optional<std::string> bytes = context.cache->load(disk_key)) {
            if (auto loaded = dome_from_bytes(*bytes, grid_.ring_count(), grid_.stored_sectors(),
                                              wavelengths, grid_.angular_step_rad()))
              return loaded;
          }
        }
        auto built = build_dome(grid_, atmosphere(), zenith, context);
        ++domes_computed_;
        if (context.cache != nullptr) context.cache->store(disk_key, dome_to_bytes(*built));
        return built;
      },
      context.keep_sun_state);
  return std::make_shared<const HaberSunState>(sun, std::move(dome), zenith);
}

void HaberModel::compute_sky_radiance(const SunState& sun, const Viewpoint&,
                                      std::span<const ViewDirection> views,
                                      SpectralBatch& out) const {
  const auto& state = dynamic_cast<const HaberSunState&>(sun);
  for (std::size_t i = 0; i < views.size(); ++i) {
    // View-sun azimuth folded into [0, pi]: the dome is symmetric about the sun's vertical plane.
    double azimuth = std::remainder(views[i].azimuth_rad - sun.sun().azimuth_rad, 2.0 * kPi);
    azimuth = std::abs(azimuth);
    state.dome().radiance(views[i].zenith_rad, azimuth, out.spectrum(i));
  }
}

Spectrum HaberModel::compute_sun_irradiance(const SunState& sun, const Viewpoint&) const {
  // Transmittance through the layers from 1 m above the ground, as the study computes it.
  const auto& layers = grid_.layers();
  const double zenith = sun.sun().zenith_rad;
  const Vec3 p{0.0, 0.0, layers.earth_radius_m() + 1.0};
  const Vec3 direction{std::sin(zenith), 0.0, std::cos(zenith)};
  const OpticalLength l = optical_length(layers, p, exit_point(layers, p, direction));
  const auto& a = atmosphere();
  Spectrum result(a.grid.size(), 0.0);
  if (l.blocked) return result;
  for (std::size_t w = 0; w < result.size(); ++w) {
    result[w] =
        a.solar_irradiance_w_m2_nm[w] * std::exp(-(a.rayleigh_scattering_per_m[w] * l.rayleigh_m +
                                                   a.mie_extinction_per_m[w] * l.mie_m));
  }
  return result;
}

}  // namespace clearsky::haber
