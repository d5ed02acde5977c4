// The float transmittance kernel (models/core/fast_exp.h add_weighted_transmittances_float)
// against the double one (within 2 ulp of std::exp: the exact formula) for a ray-marching
// model's single scattering, over the domain of Nishita93 and O'Neal: observers from the ground
// to 100 km (above their 60 km atmosphere), suns from the zenith to 10 degrees below the
// horizon, views every 7.5 degrees from zenith to nadir at 4 azimuths, whole rays and 20 km of
// aerial perspective. Every wavelength within the tolerance (relative), zeros where the exact
// one is zero, the same ground hits and transmittance (not the kernel's); the domain covered
// (most rays lit, some in the Earth's shadow) and the kernels seen to differ.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "models/core/numeric.h"
#include "models/core/ray_scattering.h"
#include "models/core/weighted_transmittance_sums.h"

namespace clearsky::testing {

// integrate(ray, distance_m, kernel): the model's single scattering along ray.
using RayIntegration =
    std::function<ScatteringAlongRay(const RaySunGeometry&, double, TransmittanceKernel)>;

inline void expect_float_kernel_within(double tolerance, const RayIntegration& integrate) {
  constexpr double kGroundRadiusM = 6360e3;
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
          const RaySunGeometry ray{kGroundRadiusM + altitude_m, mu, mu_s, nu};
          for (double distance_m : {std::numeric_limits<double>::infinity(), 20e3}) {
            const ScatteringAlongRay fast =
                integrate(ray, distance_m, TransmittanceKernel::float_polynomial);
            const ScatteringAlongRay exact =
                integrate(ray, distance_m, TransmittanceKernel::double_polynomial);
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
              ASSERT_LT(error, tolerance) << altitude_m << ' ' << sun_deg << ' ' << view_deg << ' '
                                          << azimuth_deg << ' ' << distance_m << ' ' << w;
            }
            if (exact.radiance[0] > 0.0) ++lit;
          }
        }
      }
    }
  }
  EXPECT_GT(lit, rays / 2);
  EXPECT_LT(lit, rays);
  EXPECT_GT(worst, 0.0);  // the kernels differ: this compares two things
}

}  // namespace clearsky::testing
