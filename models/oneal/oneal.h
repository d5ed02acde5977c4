// The O'Neal model (O'Neil 2005, GPU Gems 2 chapter 16; paper section "O'Neal Model") as the
// 2016 study implemented it (models/oneal/README.md): single scattering by a few
// midpoint samples along each view ray, with Schuler's Chapman-function approximation for
// every transmittance instead of a table (oneal_functions.h). No precomputation.
//
// | parameter | unit | default | range           | meaning                                          |
// |-----------|------|---------|-----------------|--------------------------------------------------|
// | samples   | -    | 4       | [1, 1024]       | midpoint samples per view ray (O'Neil's code: 2) |
// | alpha     | -    | 0.8     | [0, 4]          | Angstrom exponent of the aerosols (atmosphere)   |
// | beta      | -    | 0.04    | [0, 2]          | aerosol optical depth at 1 um (atmosphere)       |
// | g         | -    | 0.7     | [-0.999, 0.999] | Cornette-Shanks asymmetry (atmosphere)           |
// | albedo    | -    | grass   | [0, 1]          | ground albedo (atmosphere)                       |
//
// Capabilities: observers from the ground to far above the atmosphere, views in every
// direction (a view that meets the ground sees the Lambertian ground of the shared albedo lit
// by the sun and the model's own sky, through the air before it: lambertian_ground.h), aerial
// perspective (SkyModel::aerial_perspective()), the sun anywhere (Earth's shadow included),
// single scattering only. Immutable; queries are const and thread-safe.
#pragma once

#include <memory>

#include "models/core/lambertian_ground.h"
#include "models/core/model_factory.h"
#include "models/core/ray_scattering.h"
#include "models/core/sky_model.h"

namespace clearsky {

const ModelDescriptor& oneal_descriptor();
ModelFactory oneal_factory();

class ONealModel final : public SkyModel {
 public:
  // Validates config (InvalidInput naming the parameter), then builds.
  static std::shared_ptr<const ONealModel> create(const ModelConfig& config,
                                                  const PrecomputeContext& context = {});
  static std::shared_ptr<const ONealModel> build(const ValidatedConfig& config,
                                                 const PrecomputeContext& context);

  const ModelDescriptor& descriptor() const override { return oneal_descriptor(); }
  int samples() const { return samples_; }

 protected:
  void compute_sky_radiance(const SunState& sun, const Viewpoint& viewpoint,
                            std::span<const ViewDirection> views,
                            SpectralBatch& out) const override;
  // The sky's radiance without the ground's light, for the irradiance quadratures.
  void radiance_to_integrate(const SunState& sun, const Viewpoint& viewpoint,
                             std::span<const ViewDirection> views,
                             SpectralBatch& out) const override;
  Spectrum compute_sun_irradiance(const SunState& sun, const Viewpoint& viewpoint) const override;
  ScatteringAlongRay compute_aerial_perspective(const SunState& sun, const Viewpoint& viewpoint,
                                                const ViewDirection& view,
                                                double distance_m) const override;

 private:
  explicit ONealModel(const ValidatedConfig& config);
  // Single scattering along each view, plus the ground's light for views that meet it when
  // with_ground.
  void scattered_radiance(const SunState& sun, const Viewpoint& viewpoint,
                          std::span<const ViewDirection> views, SpectralBatch& out,
                          bool with_ground) const;

  int samples_ = 4;
  LambertianGround ground_;
};

}  // namespace clearsky
