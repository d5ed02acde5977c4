// Sun azimuth from the mirror symmetry of a measured sky (sun_azimuth_estimate.h).
#include "models/evaluation/sun_azimuth_estimate.h"

#include <cmath>
#include <stdexcept>
#include <vector>

#include "models/core/numeric.h"
#include "models/evaluation/concentric_sky_interpolant.h"

namespace clearsky {

SunAzimuthEstimate estimate_sun_azimuth(const MeasuredCapture& capture, double computed_azimuth_deg,
                                        const SunAzimuthSearch& search) {
  if (!(std::isfinite(computed_azimuth_deg) && search.half_range_deg >= 0 && search.step_deg > 0))
    throw std::invalid_argument("sun azimuth search: invalid computed azimuth, range or step");
  const auto rings = arrange_concentric_rings(capture.samples);

  // The integral over wavelength is linear, so integrating each sample's spectrum first and
  // interpolating the integrals equals integrating the interpolated spectra.
  const WavelengthGrid& grid = search.wavelengths;
  std::array<std::vector<double>, kConcentricRingCount> integrals;
  for (int k = 0; k < kConcentricRingCount; ++k) {
    for (std::size_t s : rings[k]) {
      const Spectrum values = capture.samples[s].radiance.resample(grid, Resampling::point, OutOfRange::hold_end_values);
      double integral = 0;
      for (std::size_t i = 0; i < grid.size(); ++i) integral += values[i] * grid.integration_weight_nm(i);
      integrals[k].push_back(integral);
    }
  }
  const ConcentricSkyInterpolant<double> sky(std::move(integrals));

  constexpr int kZenithCount = 16;
  constexpr int kAzimuthCount = 64;
  std::vector<double> zenith_rad(kZenithCount);
  std::vector<double> direct(kZenithCount * kAzimuthCount);
  for (int i = 0; i < kZenithCount; ++i) {
    zenith_rad[i] = std::acos((i + 0.5) / kZenithCount);
    for (int j = 0; j < kAzimuthCount; ++j)
      direct[i * kAzimuthCount + j] = sky({zenith_rad[i], j * 2.0 * kPi / kAzimuthCount});
  }
  auto symmetry_error = [&](double axis_rad) {
    double error = 0;
    for (int i = 0; i < kZenithCount; ++i) {
      for (int j = 0; j < kAzimuthCount; ++j) {
        const double mirrored = 2.0 * axis_rad - j * 2.0 * kPi / kAzimuthCount;
        error += std::abs(direct[i * kAzimuthCount + j] - sky({zenith_rad[i], mirrored}));
      }
    }
    return error;
  };

  // Candidates computed - half_range + n step up to the first one >= computed + half_range (the
  // small slack absorbs the rounding of n * step).
  SunAzimuthEstimate best;
  const double first_deg = computed_azimuth_deg - search.half_range_deg;
  const double last_deg = computed_azimuth_deg + search.half_range_deg;
  for (int n = 0;; ++n) {
    const double candidate_deg = first_deg + n * search.step_deg;
    const double error = symmetry_error(candidate_deg * kDegree);
    if (n == 0 || error < best.symmetry_error) {
      best.azimuth_deg = candidate_deg;
      best.symmetry_error = error;
    }
    best.candidates = n + 1;
    if (candidate_deg >= last_deg - 1e-9 * search.step_deg) break;
  }
  best.azimuth_deg = std::fmod(best.azimuth_deg, 360.0);
  if (best.azimuth_deg < 0) best.azimuth_deg += 360.0;
  return best;
}

}  // namespace clearsky
