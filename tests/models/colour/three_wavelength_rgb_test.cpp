// The paper's 3-wavelength RGB and 3-sample spectrum reconstruction against the full
// 40-wavelength CIE path, on skies of the form S(lambda) lambda^-a (a = 4: molecules only;
// smaller: aerosols), the approximation the method rests on (section "Spectrum sampling").
#include "models/colour/three_wavelength_rgb.h"

#include <gtest/gtest.h>

#include <cmath>

#include "models/atmosphere/solar_spectrum.h"

namespace clearsky {
namespace {

// A sky-like spectrum: solar irradiance times lambda^-exponent, normalised at 550 nm.
Spectrum sky_like(const WavelengthGrid& grid, double exponent) {
  Spectrum s = solar_irradiance_on(grid);
  for (std::size_t i = 0; i < grid.size(); ++i) s[i] *= std::pow(grid[i] / 550.0, -exponent) * 0.05;
  return s;
}

double relative_rgb_error(const LinearSrgb& a, const LinearSrgb& reference) {
  const double norm =
      std::sqrt(reference.r * reference.r + reference.g * reference.g + reference.b * reference.b);
  return std::sqrt((a.r - reference.r) * (a.r - reference.r) +
                   (a.g - reference.g) * (a.g - reference.g) +
                   (a.b - reference.b) * (a.b - reference.b)) /
         norm;
}

class ThreeWavelengthRgbTest : public ::testing::TestWithParam<double> {};

TEST_P(ThreeWavelengthRgbTest, MatchesTheFortyWavelengthPath) {
  const double exponent = GetParam();
  const ThreeWavelengthRgb method;
  const WavelengthGrid full = WavelengthGrid::paper_bins();
  const LinearSrgb reference = spectrum_to_linear_srgb(sky_like(full, exponent), full);
  const LinearSrgb three = method.rgb(sky_like(method.grid(), exponent));
  const double error = relative_rgb_error(three, reference);
  RecordProperty("relative_rgb_error", std::to_string(error));
  std::printf(
      "lambda^-%.1f sky: 3-wavelength RGB relative error %.4f (rgb %.5f %.5f %.5f vs %.5f %.5f "
      "%.5f)\n",
      exponent, error, three.r, three.g, three.b, reference.r, reference.g, reference.b);
  // The paper reports a PSNR of about 40 dB on rendered skies; on these spectra the method is
  // exact for a = 3 up to solar-spectrum detail and the 40-bin quadrature.
  EXPECT_LT(error, exponent == 3.0 ? 0.02 : 0.06);
}

TEST_P(ThreeWavelengthRgbTest, ReconstructedSpectrumIsCloseToTheFullSpectrum) {
  const double exponent = GetParam();
  const ThreeWavelengthRgb method;
  const WavelengthGrid full = WavelengthGrid::paper_bins();
  const Spectrum truth = sky_like(full, exponent);
  const Spectrum rebuilt = method.reconstruct_spectrum(sky_like(method.grid(), exponent), full);
  double squared = 0.0, mean = 0.0;
  int n = 0;
  for (std::size_t i = 0; i < full.size() && full[i] <= 712.5; ++i, ++n) {
    squared += (rebuilt[i] - truth[i]) * (rebuilt[i] - truth[i]);
    mean += truth[i];
  }
  const double relative_rmse = std::sqrt(squared / n) / (mean / n);
  std::printf("lambda^-%.1f sky: 3-sample reconstruction relative RMSE %.4f over 360..712.5 nm\n",
              exponent, relative_rmse);
  // Measured: 0.199 (a = 4), 0.141 (3), 0.109 (2), 0.110 (1.3); the CIE daylight basis cannot
  // follow a pure lambda^-4 sky exactly. Real sky spectra are compared in the models' tests.
  EXPECT_LT(relative_rmse, exponent >= 4.0 ? 0.21 : exponent >= 3.0 ? 0.15 : 0.12);
}

INSTANTIATE_TEST_SUITE_P(SkyExponents, ThreeWavelengthRgbTest,
                         ::testing::Values(4.0, 3.0, 2.0, 1.3));

TEST(ThreeWavelengthRgb, ConstantsArePositiveAndGridIsIncreasing) {
  const ThreeWavelengthRgb method;
  for (double k : method.k()) EXPECT_GT(k, 0.0);
  EXPECT_EQ(method.grid().canonical_string(), "points:440,550,680");
}

}  // namespace
}  // namespace clearsky
