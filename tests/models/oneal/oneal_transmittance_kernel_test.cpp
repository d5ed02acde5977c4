// O'Neal's radiances with the float transmittance kernel (the model's default,
// models/core/fast_exp.h add_weighted_transmittances_float) against the same integration with
// the double kernel (the exact formula) across the model's domain
// (tests/support/transmittance_kernel_agreement.h), the study's 4 samples and 64. Every
// wavelength within 1e-7 relative (models/oneal/README.md "Cost").
#include <gtest/gtest.h>

#include <string>

#include "models/atmosphere/atmosphere_spectra.h"
#include "models/oneal/oneal_functions.h"
#include "tests/support/transmittance_kernel_agreement.h"

namespace clearsky {
namespace {

TEST(ONealTransmittanceKernel, FloatKernelWithinOneInTenMillionOfTheExactFormula) {
  const AtmosphereSpectra atmosphere = AtmosphereSpectra::build({}, WavelengthGrid::paper_bins());
  for (int samples : {4, 64}) {
    SCOPED_TRACE(std::to_string(samples) + " samples");
    testing::expect_float_kernel_within(
        1e-7, [&](const RaySunGeometry& ray, double distance_m, TransmittanceKernel kernel) {
          return oneal::single_scattering(atmosphere, ray, samples, distance_m, kernel);
        });
  }
}

}  // namespace
}  // namespace clearsky
