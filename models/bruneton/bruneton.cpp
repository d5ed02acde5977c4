// Bruneton 2008: descriptor, table life cycle (cache or precomputation) and the O(1) queries.
#include "models/bruneton/bruneton.h"

#include <array>
#include <chrono>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "models/atmosphere/atmosphere_parameter_table.h"
#include "models/atmosphere/phase_functions.h"
#include "models/atmosphere/solar_spectrum.h"
#include "models/bruneton/shared_tables.h"
#include "models/core/content_hash.h"
#include "models/core/invalid_input.h"
#include "models/core/ray_sphere.h"

namespace clearsky {

namespace {

using bruneton::ScratchRow;

// Bumped whenever the numbers of the tables change (part of every cache key).
constexpr const char* kTablesVersion = "1";

// The 2008 code's range: mu_s clamped to -0.1975 before lookup (101.39 degrees). A function,
// not a constant, so that descriptors built during static initialisation see its value.
double default_max_sun_zenith_deg() {
  return radians_to_degrees(bruneton::SunRange::legacy().max_sun_zenith_rad());
}

// float rows of a spectrum, padded to the tables' stride.
std::vector<float> padded(const Spectrum& s, int stride) {
  std::vector<float> v(static_cast<std::size_t>(stride), 0.0f);
  for (std::size_t i = 0; i < s.size(); ++i) v[i] = static_cast<float>(s[i]);
  return v;
}

// Moves an observer above the atmosphere to where its ray enters it. False when the ray
// misses the atmosphere. The sun's cosine is transported along the ray.
bool enter_atmosphere(const bruneton::ShellGeometry& g, double& r, double& mu, double& mu_s,
                      double nu, double* travelled_m = nullptr) {
  if (travelled_m != nullptr) *travelled_m = 0.0;
  if (r <= g.top_m) return true;
  if (!ray_hits_sphere_from_outside(r, mu, g.top_m)) return false;
  const double d = distance_to_sphere_from_outside(r, mu, g.top_m);
  const double new_mu = clamp_cosine((r * mu + d) / g.top_m);
  const double new_mu_s = clamp_cosine((r * mu_s + d * nu) / g.top_m);
  r = g.top_m;
  mu = new_mu;
  mu_s = new_mu_s;
  if (travelled_m != nullptr) *travelled_m = d;
  return true;
}

}  // namespace

const ModelDescriptor& bruneton_descriptor() {
  static const ModelDescriptor d{
      .id = "bruneton",
      .name = "Bruneton 2008",
      .version = kTablesVersion,
      .citation =
          "E. Bruneton and F. Neyret, Precomputed Atmospheric Scattering, Computer "
          "Graphics Forum 27(4) (EGSR 2008), 1079-1086",
      .summary =
          "All orders of scattering precomputed by the method of Bruneton and Neyret 2008 into "
          "4D tables over altitude, view zenith, sun zenith and view-sun angle (32 x 128 x 32 x "
          "8), with 2D transmittance (256 x 64) and ground irradiance (64 x 16) tables; 4 "
          "scattering orders, single scattering stored as separate Rayleigh and Mie tables "
          "without phase function, orders 2..4 summed, grass albedo in the multiple scattering "
          "and the irradiance, as the 2016 study ran it on 40 wavelengths (the original used 3). "
          "O(1) queries from the ground to space, aerial perspective, sun up to 101.39 degrees "
          "zenith (up to 120 with the option max_sun_zenith_deg, which widens the tables' sun "
          "axis).",
      .min_wavelength_nm = kSolarSpectrumMinNm,
      .max_wavelength_nm = kSolarSpectrumMaxNm,
      .parameters =
          {
              {.name = "scattering_orders",
               .description = "orders of scattering precomputed (1: single scattering)",
               .default_value = 4,
               .min_value = 1,
               .max_value = 10,
               .integer = true},
              // At least 3 altitudes: with 2 (the ground and the top) the ground-irradiance
              // table makes sky + direct irradiance 15 to 29% above the extraterrestrial
              // irradiance (found by `clearsky stress`, docs/stability.md "Findings").
              {.name = "table_r_size",
               .description = "4D tables: number of altitudes (RES_R)",
               .default_value = 32,
               .min_value = 3,
               .max_value = 128,
               .integer = true},
              {.name = "table_mu_size",
               .description = "4D tables: number of view zenith cosines (RES_MU, even)",
               .default_value = 128,
               .min_value = 4,
               .max_value = 512,
               .integer = true},
              {.name = "table_mu_s_size",
               .description = "4D tables: number of sun zenith cosines (RES_MU_S)",
               .default_value = 32,
               .min_value = 2,
               .max_value = 128,
               .integer = true},
              {.name = "table_nu_size",
               .description = "4D tables: number of view-sun angle cosines (RES_NU)",
               .default_value = 8,
               .min_value = 2,
               .max_value = 64,
               .integer = true},
              {.name = "max_sun_zenith_deg",
               .unit = "deg",
               .description =
                   "largest sun zenith angle the tables cover; the default (acos(-0.1975)) is "
                   "the 2008 code's sun mapping, any other value spreads the same number of sun "
                   "texels (table_mu_s_size) from the zenith to that angle",
               .default_value = default_max_sun_zenith_deg(),
               .min_value = 95.0,
               .max_value = 120.0},
              atmosphere_parameter_spec("alpha"),
              atmosphere_parameter_spec("beta"),
              atmosphere_parameter_spec("g"),
              atmosphere_parameter_spec("albedo"),
          },
      .capabilities =
          {
              .min_altitude_m = 0.0,
              .max_altitude_m = 1e8,
              .view_from_space = true,
              .view_below_horizon = true,
              .aerial_perspective = true,
              .max_sun_zenith_deg = default_max_sun_zenith_deg(),
              .scattering_orders = 4,
              .per_sun_precomputation = false,
              .sun_irradiance = true,
              .sky_irradiance = true,
          },
  };
  return d;
}

ModelFactory bruneton_factory() {
  return make_model_factory<&bruneton_descriptor, &BrunetonModel::build,
                            &BrunetonModel::estimated_table_bytes>();
}

bruneton::Resolution BrunetonModel::resolution(const ModelDescriptor& descriptor,
                                               const ModelConfig& config) {
  bruneton::Resolution res;
  res.orders = static_cast<int>(option_or_default(descriptor, config, "scattering_orders"));
  res.r = static_cast<int>(option_or_default(descriptor, config, "table_r_size"));
  res.mu = static_cast<int>(option_or_default(descriptor, config, "table_mu_size"));
  res.mu_s = static_cast<int>(option_or_default(descriptor, config, "table_mu_s_size"));
  res.nu = static_cast<int>(option_or_default(descriptor, config, "table_nu_size"));
  if (res.mu % 2 != 0) throw InvalidInput("table_mu_size", "must be even");
  const double max_sun_zenith_deg = option_or_default(descriptor, config, "max_sun_zenith_deg");
  // Within rounding of the default: the 2008 mapping, so that an explicit default shares its
  // tables.
  if (std::abs(max_sun_zenith_deg - default_max_sun_zenith_deg()) > 1e-9)
    res.sun = bruneton::SunRange::up_to(degrees_to_radians(max_sun_zenith_deg));
  return res;
}

std::string BrunetonModel::table_description(const ModelConfig& config) {
  // The resolution is in the options; defaults are written out so that an explicit default
  // and an absent option share their tables.
  const bruneton::Resolution res = resolution(bruneton_descriptor(), config);
  std::ostringstream out;
  out << "bruneton-tables;version=" << kTablesVersion << ";format=" << bruneton::kTableFormatVersion
      << ";atmosphere=" << config.atmosphere.canonical_string()
      << ";grid=" << config.wavelengths.canonical_string() << ";orders=" << res.orders
      << ";r=" << res.r << ";mu=" << res.mu << ";mu_s=" << res.mu_s << ";nu=" << res.nu;
  // Only an extended sun range is written, so that the default keys of the 2008 mapping stay.
  if (res.sun.extended) {
    out.precision(17);
    out << ";mu_s_min=" << res.sun.lookup_min_mu_s;
  }
  return out.str();
}

std::string BrunetonModel::cache_key(const ModelConfig& config) {
  return "bruneton-" + hex64(fnv1a_64(table_description(config)));
}

std::shared_ptr<const BrunetonModel> BrunetonModel::create(const ModelDescriptor& descriptor,
                                                           const ModelConfig& config,
                                                           const PrecomputeContext& context) {
  return build(validated_config(descriptor, config), context);
}

std::shared_ptr<const BrunetonModel> BrunetonModel::build(const ValidatedConfig& config,
                                                          const PrecomputeContext& context) {
  return std::shared_ptr<const BrunetonModel>(
      new BrunetonModel(config.descriptor(), config.config(), context, nullptr));
}

std::shared_ptr<const BrunetonModel> BrunetonModel::build_with_aerosols(
    const ValidatedConfig& config, const PrecomputeContext& context,
    const AerosolOptics& aerosols) {
  return std::shared_ptr<const BrunetonModel>(
      new BrunetonModel(config.descriptor(), config.config(), context, &aerosols));
}

std::size_t BrunetonModel::estimated_table_bytes(const ValidatedConfig& config) {
  return bruneton::Tables::bytes_for(resolution(config.descriptor(), config.config()),
                                     static_cast<int>(config.config().wavelengths.size()));
}

BrunetonModel::BrunetonModel(const ModelDescriptor& descriptor, ModelConfig config,
                             const PrecomputeContext& context, const AerosolOptics* aerosols)
    : SkyModel(std::move(config)), descriptor_(descriptor) {
  const auto start = std::chrono::steady_clock::now();
  const bruneton::Resolution res = resolution(descriptor, this->config());
  std::string description = table_description(this->config());
  std::string key = cache_key(this->config());
  AtmosphereSpectra spectra = atmosphere();
  std::shared_ptr<const TabulatedPhaseFunction> precomputation_phase;
  if (aerosols != nullptr) {
    description = aerosols->description + ";" + description;
    key = aerosols->cache_prefix + "-" + hex64(fnv1a_64(description));
    spectra.mie_extinction_per_m = aerosols->mie_extinction_per_m;
    spectra.mie_scattering_per_m = aerosols->mie_scattering_per_m;
    precomputation_phase = aerosols->precomputation_phase;
    mie_phase_ = aerosols->phase;
  }
  const auto load_or_precompute = [&]() -> bruneton::Tables {
    if (context.cache != nullptr) {
      if (std::optional<std::string> blob = context.cache->load(key)) {
        if (std::optional<bruneton::Tables> cached =
                bruneton::deserialise_tables(*blob, description, res.sun)) {
          loaded_from_cache_ = true;
          return std::move(*cached);
        }
      }
    }
    bruneton::Tables built =
        bruneton::precompute_tables(spectra, res, context, precomputation_phase);
    if (context.cache != nullptr)
      context.cache->store(key, bruneton::serialise_tables(built, description));
    return built;
  };
  bruneton::SharedTablesResult shared =
      bruneton::shared_tables(description, load_or_precompute, context);
  tables_ = std::move(shared.tables);
  shares_tables_ = !shared.made;
  descriptor_.capabilities.max_sun_zenith_deg =
      radians_to_degrees(tables_->resolution.sun.max_sun_zenith_rad());
  solar_ = padded(atmosphere().solar_irradiance_w_m2_nm, tables_->stride);
  albedo_over_pi_ = padded(atmosphere().ground_albedo * (1.0 / kPi), tables_->stride);
  precompute_seconds_ =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void BrunetonModel::radiance(double r, double mu, double mu_s, double nu, float* out) const {
  const bruneton::ShellGeometry& g = tables_->geometry;
  const int stride = tables_->stride;
  if (!enter_atmosphere(g, r, mu, mu_s, nu)) {
    std::fill(out, out + stride, 0.0f);
    return;
  }
  r = std::clamp(r, g.bottom_m, g.top_m);
  scattering(r, mu, mu_s, nu, out);
  if (mu < bruneton::horizon_mu(r, g)) add_ground(r, mu, mu_s, nu, out);
}

void BrunetonModel::scattering(const bruneton::Coord4& c, double nu, float* out) const {
  if (!mie_phase_) {
    tables_->scattering(c, nu, atmosphere().parameters.mie_phase_g, out);
    return;
  }
  ScratchRow phase(tables_->stride);
  std::fill(phase.data(), phase.data() + tables_->stride, 0.0f);
  mie_phase_->evaluate(nu, phase.data());
  tables_->scattering(c, nu, phase.data(), out);
}

void BrunetonModel::scattering(double r, double mu, double mu_s, double nu, float* out) const {
  scattering(bruneton::coordinates_4d(r, mu, mu_s, nu, tables_->resolution, tables_->geometry), nu,
             out);
}

void BrunetonModel::add_ground(double r, double mu, double mu_s, double nu, float* out) const {
  // The ray ends on the ground: add the Lambertian reflection of the direct sun and the sky
  // there, attenuated on the way (the 2008 code's ground colour, without the sun's glint).
  const bruneton::ShellGeometry& g = tables_->geometry;
  const int stride = tables_->stride;
  const double d = distance_to_sphere_from_outside(r, mu, g.bottom_m);
  if (!std::isfinite(d)) return;
  const double mu_ground = clamp_cosine((r * mu_s + d * nu) / g.bottom_m);
  ScratchRow sun(stride), sky(stride), path(stride);
  if (mu_ground > 0.0) {
    tables_->transmittance_to_top(g.bottom_m, mu_ground, sun.data());
  } else {
    std::fill(sun.data(), sun.data() + stride, 0.0f);
  }
  tables_->irradiance(g.bottom_m, mu_ground, sky.data());
  tables_->transmittance_between(r, mu, d, path.data());
  const float cosine = static_cast<float>(std::max(mu_ground, 0.0));
  for (int w = 0; w < stride; ++w) {
    out[w] += albedo_over_pi_[w] * (sun.data()[w] * cosine + sky.data()[w]) * path.data()[w];
  }
}

void BrunetonModel::compute_sky_radiance(const SunState& sun, const Viewpoint& viewpoint,
                                         std::span<const ViewDirection> views,
                                         SpectralBatch& out) const {
  const bruneton::ShellGeometry& g = tables_->geometry;
  const double r = g.bottom_m + viewpoint.altitude_m;
  const double mu_s = std::cos(sun.sun().zenith_rad);
  const double sin_s = std::sin(sun.sun().zenith_rad);
  const std::size_t n = wavelengths().size();
  ScratchRow value(tables_->stride);
  // Inside the atmosphere the altitude and sun axes of the lookup are the same for every view.
  const bool inside = r <= g.top_m;
  const double r_lookup = std::max(r, g.bottom_m);
  const bruneton::Axis r_axis = bruneton::r_axis_4d(r_lookup, tables_->resolution, g);
  const bruneton::Axis mu_s_axis = bruneton::texture_axis(
      bruneton::u_mu_s(mu_s, tables_->resolution.mu_s, tables_->resolution.sun),
      tables_->resolution.mu_s);
  const double mu_horizon = bruneton::horizon_mu(r_lookup, g);
  for (std::size_t i = 0; i < views.size(); ++i) {
    const double mu = std::cos(views[i].zenith_rad);
    const double sin_v = std::sin(views[i].zenith_rad);
    const double nu = clamp_cosine(
        mu * mu_s + sin_v * sin_s * std::cos(views[i].azimuth_rad - sun.sun().azimuth_rad));
    if (inside) {
      const bruneton::Coord4 c{r_axis, bruneton::mu_axis_4d(r_lookup, mu, tables_->resolution, g),
                               mu_s_axis, bruneton::nu_axis_4d(nu, tables_->resolution)};
      scattering(c, nu, value.data());
      if (mu < mu_horizon) add_ground(r_lookup, mu, mu_s, nu, value.data());
    } else {
      radiance(r, mu, mu_s, nu, value.data());
    }
    auto spectrum = out.spectrum(i);
    for (std::size_t w = 0; w < n; ++w)
      spectrum[w] = static_cast<double>(value.data()[w]) * solar_[w];
  }
}

Spectrum BrunetonModel::compute_sun_irradiance(const SunState& sun,
                                               const Viewpoint& viewpoint) const {
  const bruneton::ShellGeometry& g = tables_->geometry;
  const std::size_t n = wavelengths().size();
  double r = g.bottom_m + viewpoint.altitude_m;
  double mu_s = std::cos(sun.sun().zenith_rad);
  Spectrum result(n, 0.0);
  // Above the atmosphere the sunlight crosses the atmosphere only if the line of sight to the
  // sun does; it is blocked if that line meets the ground.
  if (r > g.top_m) {
    if (ray_hits_sphere_from_outside(r, mu_s, g.bottom_m)) return result;
    if (!ray_hits_sphere_from_outside(r, mu_s, g.top_m)) {
      for (std::size_t w = 0; w < n; ++w) result[w] = solar_[w];
      return result;
    }
    double transported = mu_s;  // the line of sight to the sun is the ray moved here
    enter_atmosphere(g, r, mu_s, transported, 1.0);
  }
  if (mu_s < bruneton::horizon_mu(r, g)) return result;
  ScratchRow t(tables_->stride);
  tables_->transmittance_to_top(r, mu_s, t.data());
  for (std::size_t w = 0; w < n; ++w) result[w] = static_cast<double>(t.data()[w]) * solar_[w];
  return result;
}

Spectrum BrunetonModel::compute_sky_irradiance(const SunState& sun, const Viewpoint& viewpoint,
                                               const PlaneOrientation& plane) const {
  const bruneton::ShellGeometry& g = tables_->geometry;
  const double r = g.bottom_m + viewpoint.altitude_m;
  if (plane.tilt_rad != 0.0 || r > g.top_m)
    return sky_irradiance_by_quadrature(sun, viewpoint, plane);
  ScratchRow e(tables_->stride);
  tables_->irradiance(r, std::cos(sun.sun().zenith_rad), e.data());
  Spectrum result(wavelengths().size(), 0.0);
  for (std::size_t w = 0; w < result.size(); ++w)
    result[w] = static_cast<double>(e.data()[w]) * solar_[w];
  return result;
}

ScatteringAlongRay BrunetonModel::compute_aerial_perspective(const SunState& sun,
                                                             const Viewpoint& viewpoint,
                                                             const ViewDirection& view,
                                                             double distance_m) const {
  const std::size_t n = wavelengths().size();
  ScatteringAlongRay sample{Spectrum(n, 0.0), Spectrum(n, 1.0), 0.0, false};
  const bruneton::ShellGeometry& g = tables_->geometry;
  const int stride = tables_->stride;
  double r = g.bottom_m + viewpoint.altitude_m;
  double mu = std::cos(view.zenith_rad);
  double mu_s = std::cos(sun.sun().zenith_rad);
  const double nu = cos_angle_between(view, sun.sun());
  double travelled = 0.0;
  if (!enter_atmosphere(g, r, mu, mu_s, nu, &travelled) || distance_m <= travelled) return sample;
  r = std::clamp(r, g.bottom_m, g.top_m);
  const AtmosphereSegment segment = atmosphere_segment(r, mu, g.bottom_m, g.top_m);
  const double d = std::min(distance_m - travelled, segment.end);
  sample.length_m = d;
  sample.hits_ground = segment.hits_ground && d >= segment.end;
  ScratchRow radiance_value(stride), transmittance_value(stride), far(stride), near_b(stride),
      far_b(stride);
  float* l = radiance_value.data();
  float* t = transmittance_value.data();
  tables_->transmittance_between(r, mu, d, t);
  if (d >= segment.end) {
    // To the end of the ray: the full in-scattered radiance.
    scattering(r, mu, mu_s, nu, l);
  } else {
    // S(x) - T(x, x0) S(x0) (paper Eq. 11), with the 2008 code's fix near the horizon, where the
    // difference of two lookups is imprecise: interpolate between mu_h - eps and mu_h + eps.
    const double mu_s0 = clamp_cosine((r * mu_s + d * nu) / radius_at_distance(r, mu, d));
    auto difference = [&](double mu_used, float* out, float* scratch) {
      const double r0 = std::clamp(radius_at_distance(r, mu_used, d), g.bottom_m, g.top_m);
      const double mu0 = clamp_cosine((r * mu_used + d) / std::max(r0, 1.0));
      scattering(r, mu_used, mu_s, nu, out);
      scattering(r0, mu0, mu_s0, nu, scratch);
      for (int w = 0; w < stride; ++w) out[w] = std::max(out[w] - t[w] * scratch[w], 0.0f);
    };
    constexpr double kHorizonEpsilon = 0.004;
    const double mu_horizon = bruneton::horizon_mu(r, g);
    if (std::abs(mu - mu_horizon) < kHorizonEpsilon) {
      const double a = (mu - mu_horizon + kHorizonEpsilon) / (2.0 * kHorizonEpsilon);
      difference(mu_horizon - kHorizonEpsilon, l, far.data());
      difference(mu_horizon + kHorizonEpsilon, near_b.data(), far_b.data());
      for (int w = 0; w < stride; ++w)
        l[w] = static_cast<float>((1.0 - a) * l[w] + a * near_b.data()[w]);
    } else {
      difference(mu, l, far.data());
    }
  }
  for (std::size_t w = 0; w < n; ++w) {
    sample.radiance[w] = std::max(static_cast<double>(l[w]), 0.0) * solar_[w];
    sample.transmittance[w] = std::clamp(static_cast<double>(t[w]), 0.0, 1.0);
  }
  return sample;
}

}  // namespace clearsky
