// A test-only sky model whose radiance is a given function of view direction and wavelength
// (the measured sky itself when it is the function a synthetic capture was made of), for tests
// of the evaluation whose error is known by hand.
#pragma once

#include <utility>

#include "models/core/sky_model.h"
#include "tests/models/evaluation/synthetic_sky.h"

namespace clearsky::testing {

inline const ModelDescriptor& test_descriptor() {
  static const ModelDescriptor descriptor = [] {
    ModelDescriptor d;
    d.id = "test-model";
    d.name = "Test model";
    d.version = "1";
    d.min_wavelength_nm = 300;
    d.max_wavelength_nm = 1000;
    d.capabilities.max_sun_zenith_deg = 90.0;
    return d;
  }();
  return descriptor;
}

// Radiance = f(view, wavelength) on its grid: the measured sky itself when f is the function
// the synthetic capture was made of.
class FunctionModel : public SkyModel {
 public:
  explicit FunctionModel(SkyFunction f, ModelConfig config = {},
                         const ModelDescriptor& descriptor = test_descriptor())
      : SkyModel(std::move(config)), f_(std::move(f)), descriptor_(descriptor) {}
  const ModelDescriptor& descriptor() const override { return descriptor_; }

 protected:
  void compute_sky_radiance(const SunState&, const Viewpoint&, std::span<const ViewDirection> views,
                            SpectralBatch& out) const override {
    for (std::size_t v = 0; v < views.size(); ++v) {
      auto spectrum = out.spectrum(v);
      for (std::size_t i = 0; i < wavelengths().size(); ++i)
        spectrum[i] = f_(views[v], wavelengths()[i]);
    }
  }
  Spectrum compute_sun_irradiance(const SunState&, const Viewpoint&) const override {
    return Spectrum(wavelengths().size(), 0.0);
  }

 private:
  SkyFunction f_;
  const ModelDescriptor& descriptor_;
};

}  // namespace clearsky::testing
