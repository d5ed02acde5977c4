// Synthetic captures whose "measurements" a model made (docs/fits.md "Tests"): on the Kider
// 81-direction layout (tests/models/evaluation/synthetic_sky.h), every sample's spectrum is the
// model's radiance for that view, linearly interpolated between the model's grid wavelengths.
// With a grid of whole nanometres (integer_nm_grid) the evaluation, which reads the 1-nm
// measurements at the grid wavelengths, finds exactly the model's values, and a fit of that
// model must recover the parameters that made them.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "models/core/numeric.h"
#include "models/core/sky_model.h"
#include "models/spectral/wavelength_grid.h"
#include "tests/models/evaluation/synthetic_sky.h"

namespace clearsky::testing {

// Whole nanometres from 360 to 720 every step_nm: the wavelengths of the evaluation's range.
inline WavelengthGrid integer_nm_grid(int step_nm) {
  std::vector<double> nm;
  for (int w = 360; w <= 720; w += step_nm) nm.push_back(w);
  return WavelengthGrid::points(std::move(nm));
}

inline MeasuredCapture model_made_capture(const SkyModel& model, double sun_zenith_deg,
                                          double sun_azimuth_deg) {
  const std::shared_ptr<const SunState> sun =
      model.prepare_sun({sun_zenith_deg * kDegree, sun_azimuth_deg * kDegree});
  const std::vector<double>& grid = model.wavelengths().nanometres();
  ViewDirection last_view{-1, -1};
  SpectralBatch batch;
  const SkyFunction radiance = [&](const ViewDirection& view, double wavelength_nm) {
    if (view.zenith_rad != last_view.zenith_rad || view.azimuth_rad != last_view.azimuth_rad) {
      const ViewDirection views[] = {view};
      model.sky_radiance(*sun, Viewpoint{}, views, batch);
      last_view = view;
    }
    const std::span<const double> s = batch.spectrum(0);
    if (wavelength_nm <= grid.front()) return s.front();
    for (std::size_t i = 1; i < grid.size(); ++i)
      if (wavelength_nm <= grid[i]) {
        const double t = (wavelength_nm - grid[i - 1]) / (grid[i] - grid[i - 1]);
        return s[i - 1] + t * (s[i] - s[i - 1]);
      }
    return s.back();
  };
  MeasuredCapture capture = synthetic_capture(radiance, sun_zenith_deg, sun_azimuth_deg);
  capture.label = "model-made " + std::to_string(sun_zenith_deg);
  return capture;
}

}  // namespace clearsky::testing
