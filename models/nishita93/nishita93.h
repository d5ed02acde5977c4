// The Nishita93 model (Nishita, Sirai, Tadamura, Nakamae 1993; paper section "Nishita93
// Model") as the 2016 study implemented it (models/nishita93/README.md): single
// scattering integrated along each view ray over its crossings with 64 spheres of equal
// Rayleigh optical depth, with the transmittance to the sun read from 2D tables built on those
// spheres and 64 sun-aligned cylinders (nishita93_tables.h, nishita93_functions.h).
//
// | parameter           | unit | default | range           | meaning                                         |
// |---------------------|------|---------|-----------------|-------------------------------------------------|
// | spheres             | -    | 64      | [4, 1024]       | n_s, spheres of the tables and view-ray samples |
// | cylinders           | -    | 64      | [4, 1024]       | n_c, cylinders of the tables                    |
// | study_viewer_sample | -    | 0       | {0, 1}          | 1: the study's zero integrand at the observer   |
// | alpha               | -    | 0.8     | [0, 4]          | Angstrom exponent of the aerosols (atmosphere)  |
// | beta                | -    | 0.04    | [0, 2]          | aerosol optical depth at 1 um (atmosphere)      |
// | g                   | -    | 0.7     | [-0.999, 0.999] | Cornette-Shanks asymmetry (atmosphere)          |
// | albedo              | -    | grass   | [0, 1]          | ground albedo (atmosphere)                      |
//
// Capabilities: any observer altitude from the ground to far above the atmosphere, views in
// every direction (a view that meets the ground sees the Lambertian ground of the shared albedo
// lit by the sun and the model's own sky, through the air before it: lambertian_ground.h),
// aerial perspective (SkyModel::aerial_perspective()), the sun anywhere (Earth's shadow
// included), single scattering only. Tables do not depend on the sun: no per-sun state. Immutable after creation; queries are const and thread-safe.
#pragma once

#include <memory>

#include "models/core/lambertian_ground.h"
#include "models/core/model_factory.h"
#include "models/core/ray_scattering.h"
#include "models/core/sky_model.h"
#include "models/nishita93/nishita93_tables.h"

namespace clearsky {

const ModelDescriptor& nishita93_descriptor();
ModelFactory nishita93_factory();

class Nishita93Model final : public SkyModel {
 public:
  // Validates config (InvalidInput naming the parameter), then builds.
  static std::shared_ptr<const Nishita93Model> create(const ModelConfig& config,
                                                      const PrecomputeContext& context = {});
  static std::shared_ptr<const Nishita93Model> build(const ValidatedConfig& config,
                                                     const PrecomputeContext& context);
  // table_bytes() of the model build(config) makes: its optical-length tables, from the
  // sphere and cylinder counts (ModelFactory::estimate_table_bytes).
  static std::size_t estimated_table_bytes(const ValidatedConfig& config);

  const ModelDescriptor& descriptor() const override { return nishita93_descriptor(); }
  std::size_t table_bytes() const override { return tables_.memory_bytes(); }
  const Nishita93Tables& tables() const { return tables_; }
  bool study_viewer_sample() const { return study_viewer_sample_; }

 protected:
  void compute_sky_radiance(const SunState& sun, const Viewpoint& viewpoint,
                            std::span<const ViewDirection> views,
                            SpectralBatch& out) const override;
  // The sky's radiance without the ground's light, for the irradiance quadratures.
  void radiance_to_integrate(const SunState& sun, const Viewpoint& viewpoint,
                             std::span<const ViewDirection> views,
                             SpectralBatch& out) const override;
  Spectrum compute_sun_irradiance(const SunState& sun, const Viewpoint& viewpoint) const override;
  // The same integration as the sky radiance, stopped at distance_m.
  ScatteringAlongRay compute_aerial_perspective(const SunState& sun, const Viewpoint& viewpoint,
                                                const ViewDirection& view,
                                                double distance_m) const override;

 private:
  Nishita93Model(const ValidatedConfig& config, const PrecomputeContext& context);
  // Single scattering along each view, plus the ground's light for views that meet it when
  // with_ground.
  void scattered_radiance(const SunState& sun, const Viewpoint& viewpoint,
                          std::span<const ViewDirection> views, SpectralBatch& out,
                          bool with_ground) const;

  Nishita93Tables tables_;
  bool study_viewer_sample_ = false;
  LambertianGround ground_;
};

}  // namespace clearsky
