// The Haber model (Haber, Magnor and Seidel 2005, "Physically-based simulation of twilight
// phenomena") as the 2016 study implemented it: descriptor, parameters and the model object.
// Ground views only; the sun may be below the horizon (the model was made for twilight).
//
// | parameter             | unit | default | range           | meaning                                            |
// |-----------------------|------|---------|-----------------|----------------------------------------------------|
// | alpha                 | -    | 0.8     | [0, 4]          | Angstrom exponent of the aerosols (atmosphere)     |
// | beta                  | -    | 0.04    | [0, 2]          | aerosol optical depth at 1 um (atmosphere)         |
// | g                     | -    | 0.7     | [-0.9, 0.9]     | Cornette-Shanks asymmetry (atmosphere)             |
// | azimuth_sectors       | -    | 72      | [12, 144]       | n_phi (even); also sets ring width and shells      |
// | layers                | -    | 50      | [5, 200]        | layers of equal Rayleigh mass up to 35 km          |
// | shell_stride          | -    | 4       | [1, 16]         | multiple scattering gathered on every n-th shell   |
// | scattering_orders     | -    | 4       | [1, 8]          | 1: single scattering only                          |
// | sun_zenith_bucket_deg | deg  | 1       | [0, 5]          | per-sun states shared within this width (0: exact) |
// | sun_state_cache_size  | -    | 96      | [1, 1024]       | per-sun states kept                                |
//
// The asymmetry g is declared within [-0.9, 0.9], narrower than the atmosphere's: at |g| = 0.999
// sky + direct irradiance reached 1.64 (g = -0.999) and 1.40 (0.999) times the extraterrestrial
// irradiance at 285.875 nm (sun zenith 30; found by `clearsky stress`, docs/stability.md), at
// 0.9 they stay below it (0.70 and 0.66). A larger |g| is refused (InvalidInput naming g).
#pragma once

#include <atomic>
#include <memory>

#include "models/core/model_factory.h"
#include "models/core/sky_model.h"
#include "models/core/sun_state_cache.h"
#include "models/haber/haber_tables.h"

namespace clearsky::haber {

// The largest |g| the model declares (see above).
inline constexpr double kMaxPhaseAsymmetry = 0.9;

const ModelDescriptor& model_descriptor();
ModelFactory model_factory();

// The per-sun state: the sky dome of the sun's zenith bucket (shared with other suns of the
// bucket) and the exact sun.
class HaberSunState final : public SunState {
 public:
  HaberSunState(const SunPosition& sun, std::shared_ptr<const HaberDome> dome,
                double dome_sun_zenith_rad)
      : SunState(sun), dome_(std::move(dome)), dome_sun_zenith_rad_(dome_sun_zenith_rad) {}
  const HaberDome& dome() const { return *dome_; }
  double dome_sun_zenith_rad() const { return dome_sun_zenith_rad_; }
  std::size_t memory_bytes() const override { return sizeof(*this) + dome_->memory_bytes(); }

 private:
  std::shared_ptr<const HaberDome> dome_;
  double dome_sun_zenith_rad_;
};

class HaberModel final : public SkyModel {
 public:
  // Validates config (InvalidInput naming the parameter), then builds.
  static std::shared_ptr<const HaberModel> create(const ModelConfig& config,
                                                  const PrecomputeContext& context = {});
  static std::shared_ptr<const HaberModel> build(const ValidatedConfig& config,
                                                 const PrecomputeContext& context);
  // table_bytes() of the model build(config) makes. Its tables are the grid's geometry, which
  // is laid out without any radiative transfer (the costly part is per sun), so the estimate
  // lays it out (ModelFactory::estimate_table_bytes).
  static std::size_t estimated_table_bytes(const ValidatedConfig& config);

  const ModelDescriptor& descriptor() const override { return model_descriptor(); }
  std::size_t table_bytes() const override;
  const HaberGrid& grid() const { return grid_; }
  SunStateCacheStats cache_stats() const { return cache_->stats(); }
  // Domes computed (not loaded from the disk table cache).
  std::size_t sun_states_built() const override { return domes_computed_.load(); }

 protected:
  std::shared_ptr<const SunState> compute_sun_state(
      const SunPosition& sun, const PrecomputeContext& context) const override;
  void compute_sky_radiance(const SunState& sun, const Viewpoint& viewpoint,
                            std::span<const ViewDirection> views,
                            SpectralBatch& out) const override;
  Spectrum compute_sun_irradiance(const SunState& sun, const Viewpoint& viewpoint) const override;

 private:
  // sun_state_memory_bytes: the byte bound of the per-sun cache (PrecomputeContext).
  HaberModel(const ValidatedConfig& validated, const HaberSettings& settings,
             std::size_t sun_state_memory_bytes);

  HaberGrid grid_;
  double bucket_width_rad_;
  std::string cache_prefix_;
  // The one shared, internally synchronised piece of the model: per-sun domes by bucket.
  std::unique_ptr<SunStateCache<HaberDome>> cache_;
  mutable std::atomic<std::size_t> domes_computed_{0};
};

}  // namespace clearsky::haber
