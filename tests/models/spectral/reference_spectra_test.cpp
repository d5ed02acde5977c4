// The embedded physical tables: present, parsed, and consistent with their known values.
#include "models/spectral/reference_spectra.h"

#include <gtest/gtest.h>

#include "models/atmosphere/solar_spectrum.h"

namespace clearsky {
namespace {

TEST(ReferenceSpectra, AstmG173ExtraterrestrialIntegral) {
  // ASTM G-173-03 scales its extraterrestrial spectrum to a 1366.1 W/m2 solar constant; the
  // table's 280..4000 nm range holds 1347.9 W/m2 of it (trapezoid rule over the 2002 rows).
  const auto& astm = ReferenceSpectra::get().astm_g173_extraterrestrial;
  ASSERT_EQ(astm.values().size(), 2002u);
  EXPECT_NEAR(astm.integral(280.0, 4000.0, OutOfRange::error), 1347.9, 0.1);
  EXPECT_NEAR(astm.integral(280.0, 4000.0, OutOfRange::error) / 1366.1, 0.987, 0.001);
  // The visible part the models use, 360..830 nm, from the 40-bin table: 11.75 nm x sum.
  double visible = 0.0;
  for (double v : ReferenceSpectra::get().solar_irradiance_40_bins.values()) visible += 11.75 * v;
  EXPECT_NEAR(visible, astm.integral(360.0, 830.0, OutOfRange::error), 0.005 * visible);
}

TEST(ReferenceSpectra, FortyBinSolarSpectrumIsTheBinAverageOfAstm) {
  const auto& bins = ReferenceSpectra::get().solar_irradiance_40_bins;
  const Spectrum ours = solar_irradiance_on(WavelengthGrid::paper_bins());
  ASSERT_EQ(bins.values().size(), 40u);
  for (std::size_t i = 0; i < 40; ++i) {
    EXPECT_NEAR(ours[i], bins.values()[i], 1e-5 * bins.values()[i]) << "bin " << i;
  }
}

TEST(ReferenceSpectra, CieTablesHaveTheirKnownPeaks) {
  const auto& r = ReferenceSpectra::get();
  EXPECT_NEAR(r.cie_y_bar.at(555.0, OutOfRange::error), 1.0, 2e-3);
  EXPECT_NEAR(r.daylight_s0.at(560.0, OutOfRange::error), 100.0, 1e-9);
  EXPECT_GT(r.grass_albedo.at(750.0, OutOfRange::error),
            r.grass_albedo.at(550.0, OutOfRange::error));
}

}  // namespace
}  // namespace clearsky
