// Preparation of measured captures for the evaluation (capture_preparation.h).
#include "models/evaluation/capture_preparation.h"

#include <cmath>
#include <cstdio>

#include "models/evaluation/concentric_sky_interpolant.h"
#include "models/evaluation/sample_repair.h"
#include "models/solar/solar_position.h"

namespace clearsky {

void compute_sun_position(MeasuredCapture& capture, const CapturePreparation& preparation) {
  SolarPositionInput input;
  input.unix_time_utc_s = capture.unix_time_utc_s;
  input.latitude_deg = capture.site.latitude_deg;
  input.longitude_deg = capture.site.longitude_deg;
  input.elevation_m = capture.site.elevation_m;
  input.pressure_mbar = preparation.pressure_mbar;
  input.temperature_c = preparation.temperature_c;
  input.delta_t_s = preparation.delta_t_s;
  input.refraction = preparation.refraction;
  const SolarPosition sun = solar_position(input);
  capture.sun_zenith_computed_deg = sun.zenith_deg;
  capture.sun_azimuth_computed_deg = sun.azimuth_deg;
  char step[200];
  std::snprintf(
      step, sizeof step,
      "sun position from SPA (%s refraction, delta T %.1f s): zenith %.3f deg, azimuth %.3f deg",
      preparation.refraction ? "with" : "no", preparation.delta_t_s, sun.zenith_deg,
      sun.azimuth_deg);
  capture.processing_steps.emplace_back(step);
}

void prepare_capture(MeasuredCapture& capture, const CapturePreparation& preparation) {
  if (preparation.repair_defective_samples) repair_defective_samples(capture);
  if (std::isnan(capture.sun_zenith_computed_deg) || std::isnan(capture.sun_azimuth_computed_deg))
    compute_sun_position(capture, preparation);
  if (preparation.estimate_sun_azimuth && std::isnan(capture.sun_azimuth_estimated_deg) &&
      !is_concentric_layout(capture.samples)) {
    capture.processing_steps.emplace_back(
        "sun azimuth not estimated: the samples are not the 81-direction layout the mirror "
        "symmetry needs; the computed azimuth is used");
  } else if (preparation.estimate_sun_azimuth && std::isnan(capture.sun_azimuth_estimated_deg)) {
    const SunAzimuthEstimate estimate =
        estimate_sun_azimuth(capture, capture.sun_azimuth_computed_deg, preparation.search);
    capture.sun_azimuth_estimated_deg = estimate.azimuth_deg;
    char step[200];
    std::snprintf(step, sizeof step,
                  "sun azimuth estimated from mirror symmetry: %.3f deg (computed %.3f deg, %d "
                  "candidates, +-%.1f deg "
                  "in %.2f deg steps)",
                  estimate.azimuth_deg, capture.sun_azimuth_computed_deg, estimate.candidates,
                  preparation.search.half_range_deg, preparation.search.step_deg);
    capture.processing_steps.emplace_back(step);
  }
}

}  // namespace clearsky
