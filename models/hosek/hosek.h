// The Hosek-Wilkie model (Hosek and Wilkie 2012; paper section "Hosek Model"): the fitted
// spectral sky distribution with the study's choices (models/hosek/README.md).
//
// | parameter          | unit | default | range   | meaning                                                                                       |
// |--------------------|------|---------|---------|-----------------------------------------------------------------------------------------------|
// | turbidity          | -    | 2.53    | [1, 10] | atmospheric turbidity (atmosphere)                                                            |
// | albedo             | -    | grass   | [0, 1]  | ground albedo; grass: Feister and Grewe, per lambda (atmosphere)                              |
// | native_bands       | -    | 0       | {0, 1}  | 1: evaluate the 11 fitted bands and interpolate                                               |
// | clamp_negative_fit | -    | 0       | {0, 1}  | 1: 0 where the fit turns negative; 0: refuse those samples (outside_fit_domain, fit_domain.h) |
//
// Sky radiance at grid wavelength lambda (320..720 nm; other wavelengths are reported as out
// of range): the authors' linear interpolation between the two fitted bands around lambda,
// both cooked with turbidity T, ground albedo albedo(lambda) and solar elevation
// pi/2 - sun zenith (the study builds one model state per grid wavelength), then rescaled to
// the study's extraterrestrial spectrum: x solar(lambda) / (original solar radiance(lambda) x
// 6.87e-5 sr), the original radiance interpolated linearly between bands. With native_bands
// = 1 each band is cooked once with the albedo at its own wavelength and the band radiances
// are interpolated: fewer evaluations, slightly different numbers (README: the trade-off).
//
// Sun irradiance: the solar disc radiance function (Hosek and Wilkie 2013, limb darkening
// included) integrated over the fit's disc (radius 0.255 degrees), each view of the disc at
// its own elevation; the disc radiance is rescaled so that the unattenuated disc carries the
// study's extraterrestrial irradiance. Ground views only; the sun below the horizon is refused.
// Immutable after creation; every query is const and thread-safe.
#pragma once

#include <memory>
#include <vector>

#include "models/core/model_factory.h"
#include "models/core/sky_model.h"
#include "models/hosek/hosek_functions.h"

namespace clearsky {

const ModelDescriptor& hosek_descriptor();
ModelFactory hosek_factory();

class HosekModel final : public SkyModel {
 public:
  // Validates config (InvalidInput naming the parameter), then builds.
  static std::shared_ptr<const HosekModel> create(const ModelConfig& config,
                                                  const PrecomputeContext& context = {});
  static std::shared_ptr<const HosekModel> build(const ValidatedConfig& config,
                                                 const PrecomputeContext& context);

  const ModelDescriptor& descriptor() const override { return hosek_descriptor(); }

  // Radiance of the solar disc alone (no sky) in a view direction, W/(m2.sr.nm) on
  // wavelengths(): zero outside the disc and for wavelengths outside 320..720 nm.
  Spectrum sun_disc_radiance(const SunState& sun, const ViewDirection& view) const;
  bool native_bands() const { return native_bands_; }
  double turbidity() const { return config().atmosphere.turbidity; }

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
  explicit HosekModel(const ValidatedConfig& validated);
  // The spectra of views above the horizon; a spectrum that turns negative is refused
  // (outside_fit_domain) or, with clamp_negative, clamped to 0.
  void fit_radiance(const SunState& sun, bool clamp_negative, std::span<const ViewDirection> views,
                    SpectralBatch& out) const;

  // Per grid wavelength: its bracketing bands and interpolation weight, and the factors that
  // move the fit's solar spectrum to the study's.
  struct WavelengthTerms {
    bool in_range = false;
    int band = 0;         // lower band
    double fraction = 0;  // weight of band + 1
    double albedo = 0;
    double sky_correction = 0;   // solar / (original x 6.87e-5 sr)
    double disc_correction = 0;  // solar / (original x limb-darkened disc solid angle)
  };
  std::vector<WavelengthTerms> terms_;
  std::array<double, hosek::kBandCount> band_albedo_{};
  bool native_bands_ = false;
  bool clamp_negative_fit_ = false;
};

}  // namespace clearsky
