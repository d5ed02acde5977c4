// Phase functions integrate to 1 over the sphere (docs/conventions.md "Physical
// identities").
#include "models/atmosphere/phase_functions.h"

#include <gtest/gtest.h>

#include "models/core/quadrature.h"

namespace clearsky {
namespace {

template <typename Phase>
double integral_over_sphere(Phase phase) {
  double sum = 0.0;
  for (const auto& [mu, w] : gauss_legendre(200, -1.0, 1.0)) sum += 2.0 * kPi * w * phase(mu);
  return sum;
}

TEST(PhaseFunctions, RayleighIntegratesToOne) {
  EXPECT_NEAR(integral_over_sphere([](double mu) { return rayleigh_phase(mu); }), 1.0, 1e-12);
}

TEST(PhaseFunctions, CornetteShanksIntegratesToOneForEveryAsymmetry) {
  for (double g : {0.0, 0.3, 0.7, -0.5}) {
    EXPECT_NEAR(integral_over_sphere([g](double mu) { return cornette_shanks_phase(mu, g); }), 1.0,
                1e-6)
        << "g = " << g;
  }
  // g = 0.7 has a strong forward peak; integrate with more care near mu = 1.
  double sum = 0.0;
  for (const auto& [mu, w] : gauss_legendre(400, 0.9, 1.0))
    sum += 2.0 * kPi * w * cornette_shanks_phase(mu, 0.9);
  for (const auto& [mu, w] : gauss_legendre(400, -1.0, 0.9))
    sum += 2.0 * kPi * w * cornette_shanks_phase(mu, 0.9);
  EXPECT_NEAR(sum, 1.0, 1e-6);
}

TEST(PhaseFunctions, CornetteShanksWithZeroAsymmetryIsRayleigh) {
  for (double mu : {-1.0, -0.3, 0.0, 0.5, 1.0})
    EXPECT_NEAR(cornette_shanks_phase(mu, 0.0), rayleigh_phase(mu), 1e-15);
}

TEST(PhaseFunctions, IsotropicIntegratesToOne) {
  EXPECT_NEAR(integral_over_sphere([](double) { return isotropic_phase(); }), 1.0, 1e-12);
}

}  // namespace
}  // namespace clearsky
