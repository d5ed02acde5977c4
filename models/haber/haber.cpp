// Descriptor, factory and queries of the Haber model (see haber.h).
#include "models/haber/haber.h"

#include <cmath>
#include <sstream>

#include "models/core/numeric.h"

namespace clearsky::haber {

const ModelDescriptor kDescriptor = [] {
  ModelDescriptor d;
  d.id = "haber";
  d.name = "Haber 2005";
  d.version = "1";
  d.citation =
      "J. Haber, M. Magnor, H.-P. Seidel. Physically-based simulation of twilight phenomena. "
      "ACM Transactions on Graphics 24(4), 2005. As implemented in E. Bruneton, A Qualitative and "
      "Quantitative Evaluation of 8 Clear Sky Models, IEEE TVCG 2016.";
  d.summary =
      "Multiple scattering on a spherical grid centred on the viewer (72 azimuths, 5-degree rings, "
      "shells "
      "growing by 1.09125 from 10 m), 50 layers of equal Rayleigh mass up to 35 km, 4 orders, "
      "gathered on "
      "every 4th shell and interpolated. Rayleigh isotropic at every order, Cornette-Shanks for "
      "single-"
      "scattered Mie only, no ground albedo, ozone or refraction. Precomputed per sun zenith into "
      "a dome of "
      "5 x 5 degree spectra read bilinearly.";
  d.min_wavelength_nm = 0.0;
  d.parameters = {
      {"alpha", "", "Angstrom exponent of the aerosol optical depth", 0.8, 0.0, 4.0, false, true},
      {"beta", "", "aerosol optical depth at 1 um", 0.04, 0.0, 2.0, false, true},
      {"g", "", "Cornette-Shanks asymmetry of aerosol scattering", 0.7, -0.999, 0.999, false, true},
      {"azimuth_sectors", "", "azimuth sectors n_phi (even); also sets ring width and shell growth",
       72, 12, 144, true, false},
      {"layers", "", "layers of equal Rayleigh mass up to 35 km", 50, 5, 200, true, false},
      {"shell_stride", "", "multiple scattering gathered on every n-th shell, interpolated between",
       4, 1, 16, true, false},
      {"scattering_orders", "", "scattering orders (1: single scattering only)", 4, 1, 8, true,
       false},
      {"sun_zenith_bucket_deg", "deg",
       "per-sun states are shared by suns within this zenith width (0: exact, the study: RMSE "
       "14.796 instead of "
       "14.770; each new state costs seconds)",
       1.0, 0.0, 5.0, false, false},
      {"sun_state_cache_size", "",
       "per-sun states kept in memory (96: every 1-degree bucket of the day sky)", 96, 1, 1024,
       true, false},
  };
  d.capabilities.min_altitude_m = 0.0;
  d.capabilities.max_altitude_m = 0.0;
  d.capabilities.view_from_space = false;
  d.capabilities.view_below_horizon = false;
  d.capabilities.aerial_perspective = false;
  d.capabilities.max_sun_zenith_deg = 180.0;
  d.capabilities.scattering_orders = 4;
  d.capabilities.per_sun_precomputation = true;
  d.capabilities.sun_irradiance = true;
  d.capabilities.sky_irradiance = true;
  return d;
}();

namespace {

HaberSettings settings_from(const ModelConfig& config) {
  HaberSettings s;
  s.azimuth_sectors = static_cast<int>(option_or_default(kDescriptor, config, "azimuth_sectors"));
  s.layer_count = static_cast<int>(option_or_default(kDescriptor, config, "layers"));
  s.shell_stride = static_cast<int>(option_or_default(kDescriptor, config, "shell_stride"));
  s.scattering_orders =
      static_cast<int>(option_or_default(kDescriptor, config, "scattering_orders"));
  return s;
}

std::shared_ptr<const SkyModel> create_model(const ModelConfig& config,
                                             const PrecomputeContext& context) {
  return HaberModel::create(config, context);
}

}  // namespace

const ModelFactory kFactory{&kDescriptor, &create_model};

std::shared_ptr<const HaberModel> HaberModel::create(const ModelConfig& config,
                                                     const PrecomputeContext& context) {
  validate_config(kDescriptor, config);
  const HaberSettings settings = settings_from(config);
  if (settings.azimuth_sectors % 2 != 0)
    throw std::invalid_argument("azimuth_sectors: must be even");
  context.check_cancelled();
  return std::shared_ptr<const HaberModel>(new HaberModel(config, settings));
}

HaberModel::HaberModel(ModelConfig config, const HaberSettings& settings)
    : SkyModel(std::move(config)),
      grid_(settings, this->config().atmosphere.earth_radius_m,
            this->config().atmosphere.rayleigh_scale_height_m,
            this->config().atmosphere.mie_scale_height_m),
      bucket_width_rad_(degrees_to_radians(
          option_or_default(kDescriptor, this->config(), "sun_zenith_bucket_deg"))),
      cache_prefix_(kDescriptor.id + "/" + kDescriptor.version + "/" +
                    this->config().canonical_string()),
      cache_(std::make_unique<SunStateCache<HaberDome>>(static_cast<std::size_t>(
          option_or_default(kDescriptor, this->config(), "sun_state_cache_size")))) {}

std::size_t HaberModel::table_bytes() const {
  return grid_.ring_cells().size() * sizeof(RingCell) + grid_.active().size() * sizeof(int);
}

std::shared_ptr<const SunState> HaberModel::compute_sun_state(
    const SunPosition& sun, const PrecomputeContext& context) const {
  const double zenith = sun_zenith_bucket_centre(sun.zenith_rad, bucket_width_rad_);
  std::ostringstream key;
  key.precision(17);
  key << cache_prefix_ << ";sun_zenith_rad=" << zenith;
  auto dome = cache_->get_or_build(
      key.str(), [&] { return build_dome(grid_, atmosphere(), zenith, context); });
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
