// O'Neal's radiances with the float transmittance kernel (the model's default,
// models/core/fast_exp.h add_weighted_transmittances_float) against the same integration with
// the double kernel (within 2 ulp of std::exp: the exact formula) across the model's domain:
// suns from the zenith to 10 degrees below the horizon, views in every direction, observers
// from the ground to 100 km (above the 60 km atmosphere), whole rays and aerial perspective,
// the study's 4 samples and 64. Every wavelength within 1e-7 relative (models/oneal/README.md
// "Cost").
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "models/atmosphere/atmosphere_spectra.h"
#include "models/core/numeric.h"
#include "models/oneal/oneal_functions.h"

namespace clearsky {
namespace {

constexpr double kR = 6360e3;

TEST(ONealTransmittanceKernel, FloatKernelWithinOneInTenMillionOfTheExactFormula) {
  const AtmosphereSpectra atmosphere = AtmosphereSpectra::build({}, WavelengthGrid::paper_bins());
  double worst = 0.0;
  int rays = 0, lit = 0;
  for (double altitude_m : {0.0, 500.0, 3000.0, 10e3, 30e3, 59e3, 100e3}) {
    for (double sun_deg : {0.0, 20.0, 45.0, 70.0, 85.0, 89.5, 90.5, 93.0, 96.0, 100.0}) {
      for (double view_deg = 0.0; view_deg <= 180.0; view_deg += 7.5) {
        for (double azimuth_deg : {0.0, 60.0, 120.0, 180.0}) {
          const double mu = clamp_cosine(std::cos(degrees_to_radians(view_deg)));
          const double mu_s = clamp_cosine(std::cos(degrees_to_radians(sun_deg)));
          const double nu =
              clamp_cosine(mu * mu_s + safe_sqrt(1.0 - mu * mu) * safe_sqrt(1.0 - mu_s * mu_s) *
                                           std::cos(degrees_to_radians(azimuth_deg)));
          const RaySunGeometry ray{kR + altitude_m, mu, mu_s, nu};
          for (double distance_m : {std::numeric_limits<double>::infinity(), 20e3}) {
            for (int samples : {4, 64}) {
              const ScatteringAlongRay fast = oneal::single_scattering(
                  atmosphere, ray, samples, distance_m, TransmittanceKernel::float_polynomial);
              const ScatteringAlongRay exact = oneal::single_scattering(
                  atmosphere, ray, samples, distance_m, TransmittanceKernel::double_polynomial);
              ++rays;
              ASSERT_EQ(fast.hits_ground, exact.hits_ground);
              ASSERT_EQ(fast.transmittance, exact.transmittance);  // not the kernel's
              for (std::size_t w = 0; w < exact.radiance.size(); ++w) {
                if (exact.radiance[w] == 0.0) {
                  ASSERT_EQ(fast.radiance[w], 0.0);
                  continue;
                }
                const double error = std::abs(fast.radiance[w] / exact.radiance[w] - 1.0);
                worst = std::max(worst, error);
                ASSERT_LT(error, 1e-7) << altitude_m << ' ' << sun_deg << ' ' << view_deg << ' '
                                       << azimuth_deg << ' ' << distance_m << ' ' << w;
              }
              if (exact.radiance[0] > 0.0) ++lit;
            }
          }
        }
      }
    }
  }
  // The domain was covered: most rays see light, some (the Earth's shadow) none.
  EXPECT_GT(lit, rays / 2);
  EXPECT_LT(lit, rays);
  EXPECT_GT(worst, 0.0);  // the kernels differ: this compares two things
}

}  // namespace
}  // namespace clearsky
