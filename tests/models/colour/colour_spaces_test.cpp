// Colour conversions: white maps to white, round trips, luminance units.
#include "models/colour/colour_spaces.h"

#include <gtest/gtest.h>

#include "models/colour/daylight_spectrum.h"
#include "models/spectral/reference_spectra.h"

namespace clearsky {
namespace {

TEST(ColourSpaces, D65WhiteMapsToEqualLinearSrgb) {
  const WavelengthGrid grid = WavelengthGrid::bins(360.0, 5.0, 95);
  // D65 = S0 + M1 S1 + M2 S2 with the CIE's rounded D65 weights.
  const Spectrum d65 = daylight_relative_spectrum({-0.2955, -0.6851}, grid);
  const LinearSrgb rgb = spectrum_to_linear_srgb(d65, grid);
  EXPECT_NEAR(rgb.r / rgb.g, 1.0, 0.01);
  EXPECT_NEAR(rgb.b / rgb.g, 1.0, 0.01);
  const Xyy xyy = xyz_to_xyy(spectrum_to_xyz(d65, grid));
  EXPECT_NEAR(xyy.chroma_x, 0.3127, 1e-3);
  EXPECT_NEAR(xyy.chroma_y, 0.3290, 1e-3);
}

TEST(ColourSpaces, RoundTripsAreExact) {
  const Xyz xyz{0.3, 0.4, 0.5};
  const Xyz back = linear_srgb_to_xyz(xyz_to_linear_srgb(xyz));
  EXPECT_NEAR(back.x, xyz.x, 1e-6);
  EXPECT_NEAR(back.y, xyz.y, 1e-6);
  EXPECT_NEAR(back.z, xyz.z, 1e-6);
  const Xyz via_xyy = xyy_to_xyz(xyz_to_xyy(xyz));
  EXPECT_NEAR(via_xyy.x, xyz.x, 1e-12);
  EXPECT_NEAR(via_xyy.z, xyz.z, 1e-12);
  EXPECT_EQ(xyz_to_xyy({0, 0, 0}).luminance_y, 0.0);
}

TEST(ColourSpaces, LuminanceOfAFlatSpectrumIs683TimesTheAreaUnderYBar) {
  // A flat 1 W/(m2.sr.nm) over 360..830: integral of y_bar is 106.86 nm (CIE 1931, 1 nm data).
  const WavelengthGrid grid = WavelengthGrid::bins(360.0, 1.0, 470);
  EXPECT_NEAR(spectrum_to_luminance(Spectrum(grid.size(), 1.0), grid), 683.0 * 106.86, 683.0 * 0.3);
}

TEST(DaylightSpectrum, D65ChromaticityGivesTheCieWeightsAndTheRequestedY) {
  const WavelengthGrid grid = WavelengthGrid::paper_bins();
  // The daylight locus reproduces its own chromaticity (to the 10 nm basis data).
  for (double x : {0.25, 0.31271, 0.38}) {
    const double y = -3.000 * x * x + 2.870 * x - 0.275;  // CIE daylight locus
    const Spectrum s = daylight_spectrum({x, y, 2.5}, grid);
    const Xyy back = xyz_to_xyy(spectrum_to_xyz(s, grid));
    EXPECT_NEAR(back.chroma_x, x, 2e-3) << x;
    EXPECT_NEAR(back.chroma_y, y, 2e-3) << x;
    EXPECT_NEAR(back.luminance_y, 2.5, 1e-12);
  }
  EXPECT_EQ(daylight_spectrum({0.3, 0.3, 0.0}, grid)[10], 0.0);
}

}  // namespace
}  // namespace clearsky
