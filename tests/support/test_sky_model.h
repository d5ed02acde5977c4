// A small analytic sky for the API and server tests, with answers known in closed form:
//   L(lambda, view) = g t 0.01 (lambda / 500 nm) (1 + cos(theta) + 0.5 sin(theta) cos(phi -
//   phi_sun)) W/(m2.sr.nm), g = option "gain", t = turbidity / 2.53; direct normal irradiance g 1.5
//   (lambda / 500 nm) W/(m2.nm).
// So the sky irradiance on a horizontal plane is g t 0.01 (lambda/500) (pi + 2 pi / 3) (the
// azimuthal term integrates to zero). Ground-only up to 1000 m, views above the horizon, sun
// above the horizon (like Preetham and Hosek). Option "build_ms" delays the build (with
// progress and cancellation) to exercise 503s and single-flight; builds are counted.
#pragma once

#include <atomic>
#include <chrono>
#include <memory>
#include <span>
#include <thread>
#include <vector>

#include "models/core/sky_model.h"

namespace clearsky::testing {

inline std::atomic<int>& test_sky_builds() {
  static std::atomic<int> builds{0};
  return builds;
}

inline const ModelDescriptor& test_sky_descriptor() {
  static const ModelDescriptor d{
      .id = "testsky",
      .name = "Analytic test sky",
      .version = "1",
      .citation = "tests/support/test_sky_model.h",
      .summary = "A closed-form sky for tests.",
      .native_wavelengths_nm = {},
      .min_wavelength_nm = 360.0,
      .max_wavelength_nm = 830.0,
      .parameters = {{"turbidity", "", "scales the radiance", 2.53, 1.0, 10.0, false, true},
                     {"gain", "", "scales everything", 1.0, 0.1, 10.0, false, false},
                     {"build_ms", "ms", "build delay", 0.0, 0.0, 60000.0, true, false}},
      .capabilities = {.min_altitude_m = 0.0, .max_altitude_m = 1000.0, .max_sun_zenith_deg = 90.0},
  };
  return d;
}

class TestSky final : public SkyModel {
 public:
  explicit TestSky(const ModelConfig& config) : SkyModel(config) {
    gain_ = option_or_default(test_sky_descriptor(), config, "gain") * config.atmosphere.turbidity /
            2.53;
    direct_gain_ = option_or_default(test_sky_descriptor(), config, "gain");
  }
  const ModelDescriptor& descriptor() const override { return test_sky_descriptor(); }
  std::size_t table_bytes() const override { return 1234; }

  static double radiance(double gain, double wavelength_nm, const SkyDirection& view,
                         const SkyDirection& sun) {
    return gain * 0.01 * (wavelength_nm / 500.0) *
           (1.0 + std::cos(view.zenith_rad) +
            0.5 * std::sin(view.zenith_rad) * std::cos(view.azimuth_rad - sun.azimuth_rad));
  }

 protected:
  void compute_sky_radiance(const SunState& sun, const Viewpoint&,
                            std::span<const ViewDirection> views,
                            SpectralBatch& out) const override {
    for (std::size_t i = 0; i < views.size(); ++i) {
      auto s = out.spectrum(i);
      for (std::size_t w = 0; w < s.size(); ++w)
        s[w] = radiance(gain_, wavelengths()[w], views[i], sun.sun());
    }
  }
  Spectrum compute_sun_irradiance(const SunState&, const Viewpoint&) const override {
    Spectrum e(wavelengths().size());
    for (std::size_t w = 0; w < e.size(); ++w) e[w] = direct_gain_ * 1.5 * wavelengths()[w] / 500.0;
    return e;
  }

 private:
  double gain_ = 1.0;
  double direct_gain_ = 1.0;
};

inline std::shared_ptr<const SkyModel> create_test_sky(const ModelConfig& config,
                                                       const PrecomputeContext& context) {
  validate_config(test_sky_descriptor(), config);
  const double delay_ms = option_or_default(test_sky_descriptor(), config, "build_ms");
  for (int step = 0; step < 10; ++step) {
    context.check_cancelled();
    context.report(step / 10.0, "waiting");
    std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(delay_ms / 10.0));
  }
  ++test_sky_builds();
  return std::make_shared<const TestSky>(config);
}

// TestSky::table_bytes(), without building.
inline std::size_t estimate_test_sky_bytes(const ModelConfig& config) {
  validate_config(test_sky_descriptor(), config);
  return 1234;
}

inline std::vector<ModelFactory> test_factories() {
  return {ModelFactory{&test_sky_descriptor(), &create_test_sky, &estimate_test_sky_bytes}};
}

}  // namespace clearsky::testing
