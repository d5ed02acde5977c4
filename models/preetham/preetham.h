// The Preetham model (Preetham, Shirley and Smits 1999; paper section "Preetham Model") with
// the 2016 study's choices (models/preetham/README.md): Perez distributions of the
// luminance Y and chromaticities x, y from the zenith values, and the absolute spectral
// radiance S0 + M1 S1 + M2 S2 (CIE daylight basis, point-sampled on the grid) scaled so that
// 683 lm/W x integral of y_bar L over the study's 40 bins (360 + 11.75 i nm, i = 0..39) equals
// Y. The zenith luminance formula gives kcd/m2: Y in cd/m2 is 1000 times it, and the
// radiometric Y the spectrum must carry is that divided by 683 lm/W.
//
// | parameter          | unit | default | range   | meaning                                                                                                 |
// |--------------------|------|---------|---------|---------------------------------------------------------------------------------------------------------|
// | turbidity          | -    | 2.53    | [2, 10] | atmospheric turbidity, narrowed (atmosphere): below 2 the zenith luminance of a high sun turns negative |
// | clamp_negative_fit | -    | 0       | {0, 1}  | 1: 0 where the fitted spectrum turns negative; 0: refuse those samples (outside_fit_domain)             |
//
// The model ignores the extraterrestrial spectrum, the ground albedo and the aerosol
// parameters (all built into the fit), as the study did. Sun irradiance: the study's
// extraterrestrial spectrum times Preetham's appendix-1 transmittance. Ground views only; the
// sun below the horizon is refused. Immutable after creation; queries are const, thread-safe.
#pragma once

#include <memory>

#include "models/core/model_factory.h"
#include "models/core/sky_model.h"
#include "models/preetham/preetham_functions.h"

namespace clearsky {

const ModelDescriptor& preetham_descriptor();
ModelFactory preetham_factory();

class PreethamModel final : public SkyModel {
 public:
  // Validates config (InvalidInput naming the parameter), then builds.
  static std::shared_ptr<const PreethamModel> create(const ModelConfig& config,
                                                     const PrecomputeContext& context = {});
  static std::shared_ptr<const PreethamModel> build(const ValidatedConfig& config,
                                                    const PrecomputeContext& context);

  const ModelDescriptor& descriptor() const override { return preetham_descriptor(); }
  double turbidity() const { return config().atmosphere.turbidity; }

  // Luminance (cd/m2) and chromaticity of the sky in a view: the model's native output.
  struct LuminanceChromaticity {
    double luminance_cd_m2 = 0, chroma_x = 0, chroma_y = 0;
  };
  LuminanceChromaticity luminance_chromaticity(const SunState& sun,
                                               const ViewDirection& view) const;

 protected:
  std::shared_ptr<const SunState> compute_sun_state(
      const SunPosition& sun, const PrecomputeContext& context) const override;
  void compute_sky_radiance(const SunState& sun, const Viewpoint& viewpoint,
                            std::span<const ViewDirection> views,
                            SpectralBatch& out) const override;
  Spectrum compute_sun_irradiance(const SunState& sun, const Viewpoint& viewpoint) const override;
  // The sky irradiance integrates the fit clamped at zero (fit_domain.h), whatever
  // clamp_negative_fit.
  void radiance_to_integrate(const SunState& sun, const Viewpoint& viewpoint,
                             std::span<const ViewDirection> views,
                             SpectralBatch& out) const override;

 private:
  explicit PreethamModel(const ValidatedConfig& config);
  // The spectra of views above the horizon; a spectrum that turns negative is refused
  // (outside_fit_domain) or, with clamp_negative, clamped to 0.
  void fit_radiance(const SunState& sun, bool clamp_negative, std::span<const ViewDirection> views,
                    SpectralBatch& out) const;

  bool clamp_negative_fit_ = false;

  // The daylight basis on wavelengths() and its radiometric Y over the study's 40 bins.
  Spectrum s0_, s1_, s2_;
  double y_s0_ = 0, y_s1_ = 0, y_s2_ = 0;
};

}  // namespace clearsky
