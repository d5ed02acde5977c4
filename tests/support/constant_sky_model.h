// A sky of constant radiance under any descriptor, for the tests of the server's machinery
// around a model (table builds, their priority, per-sun preparations and waits) where the
// values do not matter: 0.01 W/(m2.sr.nm) in every view, a direct normal irradiance of
// 1 W/(m2.nm). A test that observes or delays the per-sun preparation derives from it and
// overrides compute_sun_state. For a sky whose answers a test checks, see test_sky_model.h.
#pragma once

#include <span>

#include "models/core/sky_model.h"

namespace clearsky::testing {

class ConstantSky : public SkyModel {
 public:
  // descriptor must outlive the model (the tests' descriptors are function-local statics).
  ConstantSky(const ModelDescriptor& descriptor, const ModelConfig& config)
      : SkyModel(config), descriptor_(descriptor) {}
  const ModelDescriptor& descriptor() const override { return descriptor_; }

 protected:
  void compute_sky_radiance(const SunState&, const Viewpoint&, std::span<const ViewDirection> views,
                            SpectralBatch& out) const override {
    for (std::size_t i = 0; i < views.size(); ++i)
      for (double& v : out.spectrum(i)) v = 0.01;
  }
  Spectrum compute_sun_irradiance(const SunState&, const Viewpoint&) const override {
    return Spectrum(wavelengths().size(), 1.0);
  }

 private:
  const ModelDescriptor& descriptor_;
};

}  // namespace clearsky::testing
