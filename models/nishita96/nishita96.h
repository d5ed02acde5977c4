// The Nishita96 model (Nishita, Dobashi, Kaneda, Yamashita 1996, "Display Method of the Sky
// Color Taking into Account Multiple Scattering") as the 2016 study implemented it (paper
// section "Nishita96 Model"): Nishita93's single scattering (reused from models/nishita93)
// plus double scattering through 8 sampling directions in the sun's vertical plane, each with
// a per-sun table of single-scattered radiance (nishita96_tables.h), combined with the paper's
// corrected equation
//   I_v = I_s int_{P_v}^{P_a} e^{-t(s)} [ R(s, theta) e^{-t(s')}
//         + int_{4 pi} R(s, theta_w) int_P^{P_w} R(s_w, theta'_w) e^{-t(s_w) - t(s'_w)} ds_w dw ] ds
// where the inner integral over directions is the sum over the sampling directions of their
// table's radiance times the phase functions integrated over the directions nearest to each
// (nishita96_functions.h). Third and higher orders are ignored. Views from inside the
// atmosphere, upwards (the double-scattering samples are the view ray's crossings of the
// Nishita93 spheres above the observer).
//
// | parameter             | unit | default | range           | meaning                                                  |
// |-----------------------|------|---------|-----------------|----------------------------------------------------------|
// | spheres               | -    | 64      | [4, 1024]       | Nishita93 spheres (tables and view-ray samples)          |
// | cylinders             | -    | 64      | [4, 1024]       | Nishita93 sun-aligned cylinders                          |
// | study_viewer_sample   | -    | 1       | {0, 1}          | the study's zero integrand at the observer               |
// | table_nodes           | -    | 33      | [5, 65]         | odd; nodes per axis of each sampling table (32^3 voxels) |
// | phase_theta_cells     | -    | 32      | [4, 256]        | theta cells of the phase integration (x 2 in phi)        |
// | sun_zenith_bucket_deg | deg  | 0       | [0, 5]          | per-sun tables shared within this width (0: exact)       |
// | sun_state_cache_size  | -    | 8       | [1, 256]        | per-sun table sets kept (24 to 47 MB each at 33 nodes)   |
// | alpha                 | -    | 0.8     | [0, 4]          | Angstrom exponent of the aerosols (atmosphere)           |
// | beta                  | -    | 0.04    | [0, 2]          | aerosol optical depth at 1 um (atmosphere)               |
// | g                     | -    | 0.7     | [-0.8, 0.8]     | Cornette-Shanks asymmetry (atmosphere)                   |
//
// The asymmetry g is declared within [-0.8, 0.8], narrower than the atmosphere's: the phase
// integration's midpoint rule on 32 x 64 cells integrates the Cornette-Shanks phase to within
// 0.5% of 1 at g = 0.7 and 1.1% at 0.8, but 5.4% at 0.9 and between 0.03 and 848 at 0.999, which
// made the sky irradiance 1200 times the extraterrestrial irradiance (found by `clearsky
// stress`, docs/stability.md); at |g| = 0.9 sky + direct irradiance already exceed the
// extraterrestrial irradiance (by 2.5% at the default resolution, 30% with 9 table nodes), at
// 0.8 they stay below it (0.96 and 0.99 of it, sun at the zenith). A larger |g| is refused
// (InvalidInput naming g). With fewer phase_theta_cells the Mie double scattering is
// underestimated (at 4 cells by up to 23% at g = 0.7).
#pragma once

#include <atomic>
#include <memory>

#include "models/core/model_factory.h"
#include "models/core/sky_model.h"
#include "models/core/sun_state_cache.h"
#include "models/nishita93/nishita93_tables.h"
#include "models/nishita96/nishita96_tables.h"

namespace clearsky {

// The largest |g| the model declares (see above).
inline constexpr double kMaxPhaseAsymmetry = 0.8;

const ModelDescriptor& nishita96_descriptor();
ModelFactory nishita96_factory();

// The per-sun state: the 8 tables of the sun's zenith bucket (shared) and the exact sun.
class Nishita96SunState final : public SunState {
 public:
  Nishita96SunState(const SunPosition& sun, std::shared_ptr<const nishita96::SunTables> tables)
      : SunState(sun), tables_(std::move(tables)) {}
  const nishita96::SunTables& tables() const { return *tables_; }
  std::size_t memory_bytes() const override { return sizeof(*this) + tables_->memory_bytes(); }

 private:
  std::shared_ptr<const nishita96::SunTables> tables_;
};

// Which scattering orders a query returns (the components are compared with references in
// the tests).
enum class Nishita96Orders { single_and_double, single_only, double_only };

class Nishita96Model final : public SkyModel {
 public:
  // Validates config (InvalidInput naming the parameter), then builds.
  static std::shared_ptr<const Nishita96Model> create(const ModelConfig& config,
                                                      const PrecomputeContext& context = {});
  static std::shared_ptr<const Nishita96Model> build(const ValidatedConfig& config,
                                                     const PrecomputeContext& context);
  // table_bytes() of the model build(config) makes: its optical-length tables, from the
  // sphere and cylinder counts (ModelFactory::estimate_table_bytes).
  static std::size_t estimated_table_bytes(const ValidatedConfig& config);

  const ModelDescriptor& descriptor() const override { return nishita96_descriptor(); }
  std::size_t table_bytes() const override { return optical_lengths_.memory_bytes(); }
  const Nishita93Tables& optical_lengths() const { return optical_lengths_; }
  SunStateCacheStats cache_stats() const { return cache_->stats(); }
  // Per-sun table sets computed (not loaded from the disk table cache).
  std::size_t sun_states_built() const override { return tables_computed_.load(); }

  // Radiance of the chosen orders for ground-or-above views inside the atmosphere (the
  // checked query sky_radiance() returns single_and_double).
  void radiance_orders(const Nishita96SunState& state, const Viewpoint& viewpoint,
                       const ViewDirection& view, Nishita96Orders orders,
                       std::span<double> out) const;

 protected:
  std::shared_ptr<const SunState> compute_sun_state(
      const SunPosition& sun, const PrecomputeContext& context) const override;
  void compute_sky_radiance(const SunState& sun, const Viewpoint& viewpoint,
                            std::span<const ViewDirection> views,
                            SpectralBatch& out) const override;
  Spectrum compute_sun_irradiance(const SunState& sun, const Viewpoint& viewpoint) const override;

 private:
  Nishita96Model(const ValidatedConfig& config, const PrecomputeContext& context);

  Nishita93Tables optical_lengths_;
  bool study_viewer_sample_;
  int table_nodes_;
  int phase_theta_cells_;
  double bucket_width_rad_;
  std::string cache_prefix_;
  // The one shared, internally synchronised piece of the model: per-sun tables by bucket.
  std::unique_ptr<SunStateCache<nishita96::SunTables>> cache_;
  mutable std::atomic<std::size_t> tables_computed_{0};
};

}  // namespace clearsky
