// Nishita96: descriptor, factory and queries (see nishita96.h).
#include "models/nishita96/nishita96.h"

#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "models/atmosphere/atmosphere_parameter_table.h"
#include "models/atmosphere/solar_spectrum.h"
#include "models/core/fast_exp.h"
#include "models/core/invalid_input.h"
#include "models/nishita93/nishita93_functions.h"
#include "models/nishita96/nishita96_sun_tables_blob.h"

namespace clearsky {

namespace {

ModelDescriptor make_descriptor() {
  return ModelDescriptor{
      .id = "nishita96",
      .name = "Nishita96",
      .version = "2",
      .citation =
          "T. Nishita, Y. Dobashi, K. Kaneda, H. Yamashita. Display Method of the Sky "
          "Color Taking into Account Multiple Scattering. Pacific Graphics 1996, pages "
          "117-132. As implemented in E. Bruneton, A Qualitative and Quantitative "
          "Evaluation of 8 Clear Sky Models, IEEE TVCG 2016 (nearest-direction binning "
          "fixed).",
      .summary =
          "Nishita93 single scattering plus double scattering: 8 sampling directions in the "
          "sun's vertical plane (zenith, nadir, horizontals, sun, anti-sun, sun +-90 degrees), "
          "each with a per-sun 33^3 table of single-scattered radiance (ground reflection "
          "included) on a box of +-875.7 km x +-875.7 km x 60 km sheared along the direction, "
          "computed incrementally along it; phase functions integrated over 32 x 64 directions "
          "binned to the nearest sampling direction; the paper's corrected double-scattering "
          "equation; orders >= 3 ignored. Views from inside the atmosphere, upwards.",
      .min_wavelength_nm = kSolarSpectrumMinNm,
      .max_wavelength_nm = kSolarSpectrumMaxNm,
      .parameters =
          {
              {.name = "spheres",
               .description = "Nishita93 spheres n_s (tables and view-ray samples)",
               .default_value = 64,
               .min_value = 4,
               .max_value = 1024,
               .integer = true},
              {.name = "cylinders",
               .description = "Nishita93 sun-aligned cylinders n_c",
               .default_value = 64,
               .min_value = 4,
               .max_value = 1024,
               .integer = true},
              {.name = "study_viewer_sample",
               .description =
                   "1: start each view ray's single-scattering trapezoid with 0 at "
                   "the observer, as the study's code (the radiance then jumps where the observer "
                   "crosses a sphere: documented jump study_viewer_sample_sphere)",
               .default_value = 1,
               .min_value = 0,
               .max_value = 1,
               .integer = true},
              {.name = "table_nodes",
               .description = "nodes per axis of each sampling table (odd; 33 = the paper's "
                              "32^3 voxels)",
               .default_value = 33,
               .min_value = 5,
               .max_value = 65,
               .integer = true},
              {.name = "phase_theta_cells",
               .description = "theta cells of the phase-function integration (2x as many in "
                              "phi)",
               .default_value = 32,
               .min_value = 4,
               .max_value = 256,
               .integer = true},
              {.name = "sun_zenith_bucket_deg",
               .unit = "deg",
               .description =
                   "per-sun tables are shared by suns within this zenith width (0: exact)",
               .default_value = 0.0,
               .min_value = 0.0,
               .max_value = 5.0},
              {.name = "sun_state_cache_size",
               .description =
                   "per-sun table sets kept in memory (24 MB each at 33 nodes, up to 47 MB "
                   "near the horizon)",
               .default_value = 8,
               .min_value = 1,
               .max_value = 256,
               .integer = true},
              atmosphere_parameter_spec("alpha"),
              atmosphere_parameter_spec("beta"),
              // |g| <= 0.8: the midpoint rule of the phase integration
              // (nishita96_functions.h) diverges for a more peaked Cornette-Shanks phase (the
              // integral over the sphere reaches 848 instead of 1 at g = 0.999; see
              // nishita96.h and docs/stability.md "Findings").
              atmosphere_parameter_spec("g", -kMaxPhaseAsymmetry, kMaxPhaseAsymmetry),
          },
      .capabilities =
          {
              .min_altitude_m = 0.0,
              .max_altitude_m = 60e3,  // inside the default 60 km atmosphere
              .view_from_space = false,
              .view_below_horizon = false,
              .aerial_perspective = false,
              .max_sun_zenith_deg = 180.0,
              // Geometry, table interpolation and the widest sun_zenith_bucket_deg (README
              // "Dark suns").
              .dark_beyond_sun_zenith_deg = 111.0,
              .scattering_orders = 2,
              .per_sun_precomputation = true,
              .sun_irradiance = true,
              .sky_irradiance = true,
          },
  };
}

// Everything that selects a per-sun table set besides the sun: model, version, configuration.
std::string cache_prefix(const ModelConfig& config) {
  std::ostringstream out;
  out << "nishita96/" << nishita96_descriptor().version << '/' << config.canonical_string();
  return out.str();
}

}  // namespace

const ModelDescriptor& nishita96_descriptor() {
  static const ModelDescriptor descriptor = make_descriptor();
  return descriptor;
}

ModelFactory nishita96_factory() {
  return make_model_factory<&nishita96_descriptor, &Nishita96Model::build,
                            &Nishita96Model::estimated_table_bytes>();
}

std::size_t Nishita96Model::estimated_table_bytes(const ValidatedConfig& config) {
  return Nishita93Tables::memory_bytes_for(config.integer_option("spheres"),
                                           config.integer_option("cylinders"));
}

std::shared_ptr<const Nishita96Model> Nishita96Model::create(const ModelConfig& config,
                                                             const PrecomputeContext& context) {
  return build(validated_config(nishita96_descriptor(), config), context);
}

std::shared_ptr<const Nishita96Model> Nishita96Model::build(const ValidatedConfig& config,
                                                            const PrecomputeContext& context) {
  if (config.integer_option("table_nodes") % 2 == 0)
    throw InvalidInput("table_nodes", "must be odd");
  return std::shared_ptr<const Nishita96Model>(new Nishita96Model(config, context));
}

Nishita96Model::Nishita96Model(const ValidatedConfig& config, const PrecomputeContext& context)
    : SkyModel(config.config()),
      optical_lengths_(Nishita93Tables::build(this->config().atmosphere,
                                              config.integer_option("spheres"),
                                              config.integer_option("cylinders"), context)),
      study_viewer_sample_(config.integer_option("study_viewer_sample") != 0),
      table_nodes_(config.integer_option("table_nodes")),
      phase_theta_cells_(config.integer_option("phase_theta_cells")),
      bucket_width_rad_(degrees_to_radians(config.option("sun_zenith_bucket_deg"))),
      cache_prefix_(cache_prefix(this->config())),
      cache_(std::make_unique<SunStateCache<nishita96::SunTables>>(
          static_cast<std::size_t>(config.integer_option("sun_state_cache_size")),
          context.sun_state_memory_bytes)) {}

std::shared_ptr<const SunState> Nishita96Model::compute_sun_state(
    const SunPosition& sun, const PrecomputeContext& context) const {
  const double zenith = sun_zenith_bucket_centre(sun.zenith_rad, bucket_width_rad_);
  std::ostringstream key;
  key.precision(17);
  key << cache_prefix_ << ";sun_zenith_rad=" << zenith;
  // Single flight in memory; on a miss, for a bucketed configuration, the disk table cache first
  // (the key names the blob format, the model version, the configuration with its quality
  // options, and the bucket's zenith), then the computation, stored for the next process
  // (nishita96_sun_tables_blob.h). An exact sun (bucket width 0) is not stored: its keys are a
  // continuum, 24 to 47 MB each, which a client could use to fill the disk
  // (docs/tables-and-memory.md "Per-sun states").
  auto tables = cache_->get_or_build(
      key.str(),
      [&]() -> std::shared_ptr<const nishita96::SunTables> {
        const bool persist = context.cache != nullptr && bucket_width_rad_ > 0.0;
        const std::string disk_key = "nishita96-sun-tables/" +
                                     std::to_string(nishita96::kSunTablesBlobVersion) + "/" +
                                     key.str();
        if (persist) {
          if (const std::optional<std::string> bytes = context.cache->load(disk_key)) {
            if (auto loaded = nishita96::sun_tables_from_bytes(*bytes, atmosphere(), zenith,
                                                               table_nodes_, phase_theta_cells_))
              return loaded;
          }
        }
        auto built = nishita96::build_sun_tables(optical_lengths_, atmosphere(), zenith,
                                                 table_nodes_, phase_theta_cells_, context);
        ++tables_computed_;
        if (persist) context.cache->store(disk_key, nishita96::sun_tables_to_bytes(*built));
        return built;
      },
      context.keep_sun_state);
  return std::make_shared<const Nishita96SunState>(sun, std::move(tables));
}

void Nishita96Model::radiance_orders(const Nishita96SunState& state, const Viewpoint& viewpoint,
                                     const ViewDirection& view, Nishita96Orders orders,
                                     std::span<double> out) const {
  const auto& a = atmosphere();
  const std::size_t n = a.grid.size();
  std::fill(out.begin(), out.end(), 0.0);
  if (orders != Nishita96Orders::double_only) {
    std::vector<double> scratch(2 * n);
    const std::span<double> all(scratch);
    const nishita93::RayWorkspace workspace{all.subspan(0, n), all.subspan(n, n)};
    nishita93::single_scattering(
        optical_lengths_, a,
        RaySunGeometry::from(a.parameters.earth_radius_m, viewpoint, view, state.sun()),
        std::numeric_limits<double>::infinity(), out, {}, workspace, study_viewer_sample_);
  }
  if (orders == Nishita96Orders::single_only) return;

  // Double scattering in the tables' frame (x towards the sun's azimuth).
  const auto& tables = state.tables();
  const double azimuth = view.azimuth_rad - state.sun().azimuth_rad;
  const double sin_zenith = std::sin(view.zenith_rad);
  const Vec3 view_dir{std::cos(azimuth) * sin_zenith, std::sin(azimuth) * sin_zenith,
                      std::cos(view.zenith_rad)};
  const nishita96::PhaseIntegrals phase =
      tables.phase_bins().integrate(view_dir, a.parameters.mie_phase_g);
  const double r = a.parameters.earth_radius_m + viewpoint.altitude_m;
  const double rmu = r * view_dir.z;
  const Vec3 viewer{0.0, 0.0, r};
  double previous_rayleigh = std::exp(-viewpoint.altitude_m / a.parameters.rayleigh_scale_height_m);
  double previous_mie = std::exp(-viewpoint.altitude_m / a.parameters.mie_scale_height_m);
  double rayleigh_length = 0.0;
  double mie_length = 0.0;
  double previous_distance = 0.0;
  std::vector<double> sample(n), transmittance(n), accumulated(n, 0.0);
  std::vector<float> table_value(n);
  for (int i = 0; i < optical_lengths_.sphere_count(); ++i) {
    const double ri = optical_lengths_.sphere_radius_m(i);
    if (ri <= r) continue;
    const double rayleigh = optical_lengths_.sphere_rayleigh_density(i);
    const double mie = optical_lengths_.sphere_mie_density(i);
    const double distance = -rmu + safe_sqrt(ri * ri - r * r + rmu * rmu);
    const double half = 0.5 * (distance - previous_distance);
    rayleigh_length += (rayleigh + previous_rayleigh) * half;
    mie_length += (mie + previous_mie) * half;
    transmittance_from_lengths(n, a.rayleigh_scattering_per_m.data(), a.mie_extinction_per_m.data(),
                               rayleigh_length, mie_length, transmittance.data());
    const Vec3 p = viewer + distance * view_dir;
    std::fill(sample.begin(), sample.end(), 0.0);
    for (int k = 0; k < nishita96::kSamplingDirections; ++k) {
      tables.table(k).lookup(p, table_value);
      const double rayleigh_weight = rayleigh * phase.rayleigh[k];
      const double mie_weight = mie * phase.mie[k];
      for (std::size_t w = 0; w < n; ++w) {
        sample[w] += table_value[w] * (a.rayleigh_scattering_per_m[w] * rayleigh_weight +
                                       a.mie_scattering_per_m[w] * mie_weight);
      }
    }
    // The study's rule: each sample weighs the whole segment before it.
    for (std::size_t w = 0; w < n; ++w)
      accumulated[w] += transmittance[w] * sample[w] * (2.0 * half);
    previous_rayleigh = rayleigh;
    previous_mie = mie;
    previous_distance = distance;
  }
  for (std::size_t w = 0; w < n; ++w) out[w] += accumulated[w] * a.solar_irradiance_w_m2_nm[w];
}

void Nishita96Model::compute_sky_radiance(const SunState& sun, const Viewpoint& viewpoint,
                                          std::span<const ViewDirection> views,
                                          SpectralBatch& out) const {
  const auto& state = dynamic_cast<const Nishita96SunState&>(sun);
  for (std::size_t i = 0; i < views.size(); ++i) {
    radiance_orders(state, viewpoint, views[i], Nishita96Orders::single_and_double,
                    out.spectrum(i));
  }
}

Spectrum Nishita96Model::compute_sun_irradiance(const SunState& sun,
                                                const Viewpoint& viewpoint) const {
  Spectrum t(wavelengths().size());
  nishita93::sun_transmittance(optical_lengths_, atmosphere(),
                               config().atmosphere.earth_radius_m + viewpoint.altitude_m,
                               clamp_cosine(std::cos(sun.sun().zenith_rad)), {t.data(), t.size()});
  return t * atmosphere().solar_irradiance_w_m2_nm;
}

}  // namespace clearsky
