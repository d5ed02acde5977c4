// Bruneton and Neyret 2008, "Precomputed Atmospheric Scattering" (Computer Graphics Forum
// 27(4), EGSR 2008), run spectrally as in Bruneton 2016 (section "Bruneton Model"): all orders
// of scattering precomputed into 4D tables over (r, mu, mu_s, nu), then O(1) queries from the
// ground to space, with aerial perspective and the sun below the horizon.
//
// | parameter          | unit | default | range           | meaning                                                          |
// |--------------------|------|---------|-----------------|------------------------------------------------------------------|
// | scattering_orders  | -    | 4       | [1, 10]         | orders of scattering precomputed                                 |
// | table_r_size       | -    | 32      | [3, 128]        | 4D tables: altitudes (RES_R)                                     |
// | table_mu_size      | -    | 128     | [4, 512]        | 4D tables: view zenith cosines (RES_MU, even)                    |
// | table_mu_s_size    | -    | 32      | [2, 128]        | 4D tables: sun zenith cosines (RES_MU_S)                         |
// | table_nu_size      | -    | 8       | [2, 64]         | 4D tables: view-sun cosines (RES_NU)                             |
// | max_sun_zenith_deg | deg  | 101.39  | [95, 120]       | sun range of the 4D and irradiance tables                        |
// | alpha              | -    | 0.8     | [0, 4]          | Angstrom exponent of the aerosols (atmosphere)                   |
// | beta               | -    | 0.04    | [0, 2]          | aerosol optical depth at 1 um (atmosphere)                       |
// | g                  | -    | 0.7     | [-0.999, 0.999] | Cornette-Shanks asymmetry (atmosphere)                           |
// | albedo             | -    | grass   | [0, 1]          | ground albedo; grass: Feister and Grewe, per lambda (atmosphere) |
// (atmosphere): the shared parameters of models/atmosphere/atmosphere_parameter_table.h. This
// table is checked against the descriptor by tests/models/contract/model_contract_test.cpp.
//
// table_r_size starts at 3: with 2 altitudes (the ground and the top) the ground-irradiance table
// put sky + direct irradiance 15 to 29% above the extraterrestrial irradiance (docs/stability.md).
//
// Limits: by default the tables hold mu_s >= -0.1975 (the 2008 code), so the sun is answered up
// to 101.39 degrees zenith; max_sun_zenith_deg (up to 120) spreads the same sun texels over a
// wider range (README "Twilight"). Beyond the range the lookup would silently repeat the edge
// value, so the model refuses it (its descriptor's capabilities.max_sun_zenith_deg follows the
// option). Observer altitudes 0 .. 1e8 m; above the top of the atmosphere the view ray is moved
// to where it enters the atmosphere.
//
// Thread-safety: immutable after construction; all queries are const and thread-safe.
#pragma once

#include <memory>
#include <string>

#include "models/atmosphere/spectral_phase_function.h"
#include "models/bruneton/bruneton_tables.h"
#include "models/core/model_factory.h"
#include "models/core/sky_model.h"

namespace clearsky {

// Aerosols given by their optical properties instead of the atmosphere's Angstrom law and
// Cornette-Shanks phase function (models/measured_aerosols): everything else of the model (the
// air, the ground, the tables and their resolution) stays Bruneton's.
struct AerosolOptics {
  Spectrum mie_extinction_per_m;  // at sea level, on the configuration's grid
  Spectrum mie_scattering_per_m;  // at sea level, on the configuration's grid
  // Per wavelength: the single scattering of every query.
  std::shared_ptr<const SpectralPhaseFunction> phase;
  // One function for all wavelengths: the precomputation of the orders >= 2.
  std::shared_ptr<const TabulatedPhaseFunction> precomputation_phase;
  // What the tables depend on beyond the configuration (the source of the optics), and the
  // prefix of their cache key.
  std::string description;
  std::string cache_prefix;
};

class BrunetonModel : public SkyModel {
 public:
  // Validates config against descriptor, then build(). Throws InvalidInput naming the
  // parameter for an invalid config.
  static std::shared_ptr<const BrunetonModel> create(const ModelDescriptor& descriptor,
                                                     const ModelConfig& config,
                                                     const PrecomputeContext& context);
  // Loads the tables from context.cache when a valid blob exists, else precomputes them (and
  // stores them in the cache). Throws PrecomputeCancelled when cancelled.
  static std::shared_ptr<const BrunetonModel> build(const ValidatedConfig& config,
                                                    const PrecomputeContext& context);
  // The same engine with the aerosols given by their optics (the atmosphere's alpha, beta,
  // mie_single_scattering_albedo and g are not used). The tables' description and cache key are
  // aerosols.description / aerosols.cache_prefix followed by those of the configuration.
  static std::shared_ptr<const BrunetonModel> build_with_aerosols(const ValidatedConfig& config,
                                                                  const PrecomputeContext& context,
                                                                  const AerosolOptics& aerosols);
  // table_bytes() of the model build(config) makes, from the resolution and the wavelength
  // count alone (ModelFactory::estimate_table_bytes).
  static std::size_t estimated_table_bytes(const ValidatedConfig& config);

  // The descriptor it was created with, its capabilities.max_sun_zenith_deg set to what the
  // tables cover (option max_sun_zenith_deg).
  const ModelDescriptor& descriptor() const override { return descriptor_; }
  std::size_t table_bytes() const override { return tables_->bytes(); }
  const bruneton::Tables& tables() const { return *tables_; }
  // Whether the tables came from the cache, and the wall time to obtain them (s).
  bool loaded_from_cache() const { return loaded_from_cache_; }
  // Whether the tables are those another live model already held (Elek and Bruneton of one
  // configuration: one copy in memory, bruneton/shared_tables.h).
  bool shares_tables() const { return shares_tables_; }
  double precompute_seconds() const { return precompute_seconds_; }

  // The table resolution a configuration selects (options of the descriptor).
  static bruneton::Resolution resolution(const ModelDescriptor& descriptor,
                                         const ModelConfig& config);
  // What the tables depend on: implementation, table version, configuration. Elek shares the
  // tables of Bruneton for the same configuration.
  static std::string table_description(const ModelConfig& config);
  // The TableCache key: "bruneton-" and the FNV-1a hash of the description.
  static std::string cache_key(const ModelConfig& config);

 protected:
  // Aerial perspective (SkyModel::aerial_perspective checks the inputs): for a point at
  // distance_m along the view (infinity: to the end of the atmosphere or the ground), the
  // in-scattered radiance between observer and point (all orders) and the transmittance to the
  // point. The ground's own radiance is not included.
  ScatteringAlongRay compute_aerial_perspective(const SunState& sun, const Viewpoint& viewpoint,
                                                const ViewDirection& view,
                                                double distance_m) const override;
  void compute_sky_radiance(const SunState& sun, const Viewpoint& viewpoint,
                            std::span<const ViewDirection> views,
                            SpectralBatch& out) const override;
  Spectrum compute_sun_irradiance(const SunState& sun, const Viewpoint& viewpoint) const override;
  // Horizontal planes in the atmosphere: the irradiance table; other planes and observers
  // above the atmosphere: the quadrature of the sky radiance.
  Spectrum compute_sky_irradiance(const SunState& sun, const Viewpoint& viewpoint,
                                  const PlaneOrientation& plane) const override;

 private:
  BrunetonModel(const ModelDescriptor& descriptor, ModelConfig config,
                const PrecomputeContext& context, const AerosolOptics* aerosols);

  // All orders of scattering at c (and nu), with the aerosol phase function of the model.
  void scattering(const bruneton::Coord4& c, double nu, float* out) const;
  void scattering(double r, double mu, double mu_s, double nu, float* out) const;

  // Radiance seen along (r, mu) for the sun at (mu_s, nu), per unit solar irradiance:
  // scattering of all orders plus, when the ray hits the ground, the attenuated light the
  // ground reflects. out holds tables().stride floats.
  void radiance(double r, double mu, double mu_s, double nu, float* out) const;
  // The ground's reflected light seen along (r, mu) (r within the atmosphere, the ray hitting
  // the ground), attenuated, added to out.
  void add_ground(double r, double mu, double mu_s, double nu, float* out) const;

  ModelDescriptor descriptor_;
  // Shared with every live model whose tables have the same description (shared_tables.h).
  std::shared_ptr<const bruneton::Tables> tables_;
  std::vector<float> solar_;  // padded
  std::vector<float> albedo_over_pi_;
  // Set for aerosols given by their optics: the phase function per wavelength.
  std::shared_ptr<const SpectralPhaseFunction> mie_phase_;
  bool loaded_from_cache_ = false;
  bool shares_tables_ = false;
  double precompute_seconds_ = 0;
};

const ModelDescriptor& bruneton_descriptor();
ModelFactory bruneton_factory();

}  // namespace clearsky
