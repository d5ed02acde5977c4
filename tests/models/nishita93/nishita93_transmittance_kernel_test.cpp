// Nishita93's radiances with the float transmittance kernel (the model's default,
// models/core/fast_exp.h add_weighted_transmittances_float) against the same integration with
// the double kernel (the exact formula) across the model's domain
// (tests/support/transmittance_kernel_agreement.h), both trapezoid starts. Every wavelength
// within 1e-7 relative (models/nishita93/README.md "Cost").
#include <gtest/gtest.h>

#include "models/atmosphere/atmosphere_spectra.h"
#include "models/nishita93/nishita93_functions.h"
#include "models/nishita93/nishita93_tables.h"
#include "tests/support/transmittance_kernel_agreement.h"

namespace clearsky {
namespace {

TEST(Nishita93TransmittanceKernel, FloatKernelWithinOneInTenMillionOfTheExactFormula) {
  const Nishita93Tables tables = Nishita93Tables::build({}, 64, 64);
  const AtmosphereSpectra atmosphere = AtmosphereSpectra::build({}, WavelengthGrid::paper_bins());
  for (bool study_viewer_sample : {false, true}) {
    SCOPED_TRACE(study_viewer_sample ? "study_viewer_sample" : "trapezoid from the observer");
    testing::expect_float_kernel_within(
        1e-7, [&](const RaySunGeometry& ray, double distance_m, TransmittanceKernel kernel) {
          return nishita93::single_scattering(tables, atmosphere, ray, distance_m,
                                              study_viewer_sample, kernel);
        });
  }
}

}  // namespace
}  // namespace clearsky
