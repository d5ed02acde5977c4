// The draft colour grid (api/colour/colour_wavelengths.h): its XYZ weights against the colour
// matching functions. Its measured colour error over the skydome is an accuracy test
// (tests/accuracy/colour/draft_colour_accuracy_test.cpp).
#include "api/colour/colour_wavelengths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "api/colour/xyz_weights.h"
#include "models/colour/delta_e_2000.h"
#include "models/core/numeric.h"
#include "models/registry.h"
#include "models/spectral/reference_spectra.h"

namespace clearsky::api {
namespace {

// A constant spectrum is of the interpolated shape: its XYZ is the integral of the colour
// matching functions, which the 5 nm table gives by the trapezoid rule to its own precision.
TEST(DraftColour, InterpolatingWeightsIntegrateAConstantSpectrumExactly) {
  const WavelengthGrid grid = WavelengthGrid::points(kDraftColourWavelengthsNm);
  const XyzWeights w = XyzWeights::interpolating(grid);
  const Xyz c = w.xyz(std::vector<double>(grid.size(), 1.0));
  const auto& ref = ReferenceSpectra::get();
  const auto integral = [](const TabulatedSpectrum& s) {
    double sum = 0.0;
    for (double nm = s.min_nm(); nm < s.max_nm(); nm += 5.0)
      sum += 2.5 * (s.at(nm, OutOfRange::zero) + s.at(nm + 5.0, OutOfRange::zero));
    return sum;
  };
  EXPECT_NEAR(c.x, integral(ref.cie_x_bar), 1e-9 * integral(ref.cie_x_bar));
  EXPECT_NEAR(c.y, integral(ref.cie_y_bar), 1e-9 * integral(ref.cie_y_bar));
  EXPECT_NEAR(c.z, integral(ref.cie_z_bar), 1e-9 * integral(ref.cie_z_bar));
}

// A spectrum linear in wavelength between the nodes (here a ramp) is also integrated exactly,
// where point-sampling the functions at the nodes (the grid's trapezoid weights) is not.
TEST(DraftColour, InterpolatingWeightsIntegrateARampExactly) {
  const WavelengthGrid grid = WavelengthGrid::points(kDraftColourWavelengthsNm);
  std::vector<double> ramp;
  for (double nm : kDraftColourWavelengthsNm) ramp.push_back(nm / 560.0);
  const Xyz c = XyzWeights::interpolating(grid).xyz(ramp);
  const auto& ref = ReferenceSpectra::get();
  const double first = kDraftColourWavelengthsNm.front(), last = kDraftColourWavelengthsNm.back();
  double y = 0.0;
  for (double nm = 360.0; nm < 830.0; nm += 0.01) {
    const double mid = nm + 0.005;
    y += 0.01 * ref.cie_y_bar.at(mid, OutOfRange::zero) * std::clamp(mid, first, last) / 560.0;
  }
  EXPECT_NEAR(c.y, y, 1e-4 * y);
  const Xyz sampled = XyzWeights(grid).xyz(ramp);
  EXPECT_GT(std::abs(sampled.y - y), 1e-3 * y);
}

}  // namespace
}  // namespace clearsky::api
