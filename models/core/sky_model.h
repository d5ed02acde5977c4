// The interface every model implements (docs/model-contract.md).
//
// Life cycle: a ModelFactory turns a ModelConfig (atmosphere, wavelength grid, model options)
// into an immutable SkyModel; that is the model's precomputation (tables), explicit and
// cancellable. Models whose precomputation depends on the sun (Nishita96, Haber) build an
// immutable SunState per sun position in prepare_sun(); for the others a SunState just holds
// the sun. Queries are const, thread-safe and batch-first, with a status per sample.
//
// The public query functions are non-virtual: they check each request against the
// descriptor's capabilities before any computation and check every value the model produced
// (no NaN, infinity or negative radiance leaves them), then call the protected compute_*
// functions only for the samples the model can answer.
#pragma once

#include <cstddef>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "models/atmosphere/atmosphere_parameters.h"
#include "models/atmosphere/atmosphere_spectra.h"
#include "models/core/geometry.h"
#include "models/core/model_descriptor.h"
#include "models/core/precompute_context.h"
#include "models/core/ray_scattering.h"
#include "models/core/sample_status.h"
#include "models/spectral/spectrum.h"
#include "models/spectral/wavelength_grid.h"

namespace clearsky {

// Everything that selects a model's tables: the cache key is built from it.
struct ModelConfig {
  AtmosphereParameters atmosphere;
  WavelengthGrid wavelengths = WavelengthGrid::paper_bins();
  std::map<std::string, double> options;  // model-specific, named in the descriptor

  std::string canonical_string() const;
};

// N spectra on one grid, row-major (sample i at values[i * wavelength_count]), with a status
// per sample. Samples whose status is not ok hold zeros.
struct SpectralBatch {
  std::size_t wavelength_count = 0;
  std::vector<double> values;
  std::vector<SampleStatus> status;

  void resize(std::size_t samples, std::size_t wavelengths);
  std::size_t size() const { return status.size(); }
  std::span<double> spectrum(std::size_t i) {
    return {values.data() + i * wavelength_count, wavelength_count};
  }
  std::span<const double> spectrum(std::size_t i) const {
    return {values.data() + i * wavelength_count, wavelength_count};
  }
};

struct SpectralSample {
  Spectrum value;
  SampleStatus status = SampleStatus::ok;
};

// Aerial perspective between the observer and a point along the view: an object of radiance
// L_object there is seen as L_object * transmittance + radiance.
struct AerialPerspectiveSample {
  Spectrum radiance;       // in-scattered, W/(m2.sr.nm)
  Spectrum transmittance;  // dimensionless, in [0, 1]
  SampleStatus status = SampleStatus::ok;
};

// Orientation of a receiving plane: tilt from horizontal and azimuth of its normal (clockwise
// from North), radians.
struct PlaneOrientation {
  double tilt_rad = 0;
  double azimuth_rad = 0;
};

class SunState {
 public:
  // dark: the sun lies beyond the model's dark_beyond_sun_zenith_deg and the state was made
  // without precomputation; the queries answer zeros for it without computing.
  explicit SunState(const SunPosition& sun, bool dark = false) : sun_(sun), dark_(dark) {}
  virtual ~SunState() = default;
  const SunPosition& sun() const { return sun_; }
  bool dark() const { return dark_; }
  virtual std::size_t memory_bytes() const { return sizeof(*this); }

 private:
  SunPosition sun_;
  bool dark_;
};

class SkyModel {
 public:
  virtual ~SkyModel() = default;
  SkyModel(const SkyModel&) = delete;
  SkyModel& operator=(const SkyModel&) = delete;

  virtual const ModelDescriptor& descriptor() const = 0;
  const ModelConfig& config() const { return config_; }
  const WavelengthGrid& wavelengths() const { return config_.wavelengths; }
  const AtmosphereSpectra& atmosphere() const { return atmosphere_; }
  // Whether wavelength i of wavelengths() lies in the descriptor's spectral range. Values at
  // other wavelengths are 0 and must be reported as wavelength_out_of_range by callers.
  bool answers_wavelength(std::size_t i) const;
  // The wavelengths answered, as indices [first, end) of wavelengths(): contiguous, since the
  // grid increases (empty when none is in range).
  struct WavelengthRange {
    std::size_t first = 0;
    std::size_t end = 0;
  };
  WavelengthRange answered_wavelengths() const;
  // Bytes held by the precomputed tables.
  virtual std::size_t table_bytes() const { return 0; }

  // Status of a sun position for this model (ok, sun_below_horizon_unsupported, invalid_input).
  SampleStatus check_sun(const SunPosition& sun) const;
  // Whether the sun lies beyond descriptor().capabilities.dark_beyond_sun_zenith_deg (false
  // when the model declares none).
  bool sun_is_dark(const SunPosition& sun) const;
  // Per-sun preparation; throws std::invalid_argument when check_sun() is not ok. A dark sun
  // (sun_is_dark) gets a dark SunState at once, without precomputation, unless
  // context.dark_sun_at_once is false.
  std::shared_ptr<const SunState> prepare_sun(const SunPosition& sun,
                                              const PrecomputeContext& context = {}) const;
  // Per-sun states this model has built (its per-sun cache's builds); 0 for a model without
  // per-sun precomputation.
  virtual std::size_t sun_states_built() const { return 0; }

  // The queries below answer zeros (status ok where the inputs are answered) for a dark
  // SunState without calling the compute_* functions.
  // Spectral sky radiance, W/(m2.sr.nm), for each view, on wavelengths().
  void sky_radiance(const SunState& sun, const Viewpoint& viewpoint,
                    std::span<const ViewDirection> views, SpectralBatch& out) const;
  // Direct solar irradiance on a plane normal to the sun, W/(m2.nm), at the viewpoint.
  SpectralSample sun_irradiance(const SunState& sun, const Viewpoint& viewpoint) const;
  // Diffuse irradiance from the sky on a plane, W/(m2.nm): the sky radiance integrated over
  // the part of the sky the plane sees (ground-reflected light excluded).
  SpectralSample sky_irradiance(const SunState& sun, const Viewpoint& viewpoint,
                                const PlaneOrientation& plane = {}) const;
  // Radiance scattered towards the observer and transmittance between it and the point at
  // distance_m (m, >= 0; +infinity: the whole view) along the view; the segment stops earlier
  // at the ground or where the view leaves the atmosphere. invalid_input when the model does
  // not declare capabilities.aerial_perspective or distance_m is NaN or negative. For a dark
  // SunState the radiance is zero and the transmittance, which does not depend on the sun, is
  // still computed: a model declaring both aerial_perspective and dark_beyond_sun_zenith_deg
  // computes it from a plain SunState.
  AerialPerspectiveSample aerial_perspective(const SunState& sun, const Viewpoint& viewpoint,
                                             const ViewDirection& view, double distance_m) const;

 protected:
  // Builds atmosphere() from config.atmosphere and config.wavelengths (validating both).
  explicit SkyModel(ModelConfig config);

  virtual std::shared_ptr<const SunState> compute_sun_state(const SunPosition& sun,
                                                            const PrecomputeContext& context) const;
  // Called with views whose status is ok; write out.spectrum(i) and may set out.status[i].
  virtual void compute_sky_radiance(const SunState& sun, const Viewpoint& viewpoint,
                                    std::span<const ViewDirection> views,
                                    SpectralBatch& out) const = 0;
  virtual Spectrum compute_sun_irradiance(const SunState& sun,
                                          const Viewpoint& viewpoint) const = 0;
  // Default: sky_irradiance_by_quadrature(), or for ground-view models the lune rule of
  // sky_plane_quadrature.h over radiance_to_integrate(). Models with an irradiance table
  // override it.
  virtual Spectrum compute_sky_irradiance(const SunState& sun, const Viewpoint& viewpoint,
                                          const PlaneOrientation& plane) const;
  // The radiance the irradiance quadratures integrate (out already sized): the sky's, without
  // light reflected by the ground. Default: the checked answers of sky_radiance(). A model that
  // refuses samples it can still integrate (fit_domain.h), or whose views meeting the ground
  // carry the ground's light (lambertian_ground.h), overrides it.
  virtual void radiance_to_integrate(const SunState& sun, const Viewpoint& viewpoint,
                                     std::span<const ViewDirection> views,
                                     SpectralBatch& out) const;
  // Called only for models that declare capabilities.aerial_perspective, with checked inputs.
  // Default: throws std::logic_error (a descriptor that declares what the model lacks).
  virtual ScatteringAlongRay compute_aerial_perspective(const SunState& sun,
                                                        const Viewpoint& viewpoint,
                                                        const ViewDirection& view,
                                                        double distance_m) const;

  // Gauss-Legendre quadrature of L cos(theta) over the plane's hemisphere (restricted to the
  // directions the model answers), zenith_nodes x azimuth_nodes directions.
  Spectrum sky_irradiance_by_quadrature(const SunState& sun, const Viewpoint& viewpoint,
                                        const PlaneOrientation& plane, int zenith_nodes = 24,
                                        int azimuth_nodes = 48) const;

 private:
  SampleStatus check_viewpoint(const Viewpoint& viewpoint) const;
  SampleStatus check_view(const ViewDirection& view) const;

  ModelConfig config_;
  AtmosphereSpectra atmosphere_;
};

// How a model is made: its descriptor and its precomputation. Made by make_model_factory()
// (model_factory.h), which validates the configuration once per build.
struct ModelFactory {
  const ModelDescriptor* descriptor = nullptr;
  // Validates config against the descriptor (InvalidInput naming the parameter), then
  // precomputes. May throw PrecomputeCancelled.
  std::shared_ptr<const SkyModel> (*create)(const ModelConfig& config,
                                            const PrecomputeContext& context) = nullptr;
  // Validates config likewise, then returns the bytes SkyModel::table_bytes() of the model
  // create(config) builds will report, computed from the configuration (wavelength count,
  // table resolutions) without precomputing anything: the server admits a build against its
  // table memory budget on it (docs/model-contract.md "Table size"). Null: unknown.
  std::size_t (*estimate_table_bytes)(const ModelConfig& config) = nullptr;
  // Whether a server builds this model's default (standard) tables when something first asks
  // for them instead of at start (docs/quality-levels.md "Serving at once"): an optional model
  // whose tables most servers would hold unused (measured_aerosols, 254.5 MB). Its draft is
  // still built at start, and its first standard requests are answered from it meanwhile.
  bool standard_on_first_use = false;
};

// Checks the atmosphere (AtmosphereParameters::validate, then the ranges of the atmosphere
// parameters the descriptor lists) and config.options names and ranges against the
// descriptor; throws InvalidInput (a std::invalid_argument) naming the first offending
// parameter. Defined in model_factory.cpp; models call it through validated_config().
void validate_config(const ModelDescriptor& descriptor, const ModelConfig& config);
// The option value, or the descriptor's default.
double option_or_default(const ModelDescriptor& descriptor, const ModelConfig& config,
                         const std::string& name);

}  // namespace clearsky
