// The steps that turn an imported capture into what the paper's evaluation compares with
// (models/evaluation/README.md), each recorded in the capture's processing_steps:
//  1. repair of the known-defective samples (sample_repair.h), before anything else;
//  2. the sun position from the capture's time and site with NREL's SPA
//     (models/solar/solar_position.h). The study used the PSA algorithm with parallax and no
//     refraction; SPA agrees to a few thousandths of a degree. Refraction is off by default,
//     as in the study;
//  3. the sun azimuth estimated from the sky's mirror symmetry (sun_azimuth_estimate.h), for
//     captures of the 81-direction layout it needs (Kider's); other captures (the open format
//     of docs/measurement-formats.md, any directions) keep the computed azimuth, and the step
//     says so.
#pragma once

#include "models/evaluation/measured_sky.h"
#include "models/evaluation/sun_azimuth_estimate.h"

namespace clearsky {

struct CapturePreparation {
  bool repair_defective_samples = true;
  bool refraction = false;
  double pressure_mbar = 1013.25;  // used only with refraction
  double temperature_c = 15.0;     // used only with refraction
  double delta_t_s = 67.3;         // TT - UT1 in 2013 (IERS), s
  bool estimate_sun_azimuth = true;
  SunAzimuthSearch search;
};

// Computed sun zenith and azimuth (degrees) of a capture, from its time and site.
void compute_sun_position(MeasuredCapture& capture, const CapturePreparation& preparation = {});

// Applies the steps above in order (steps already applied are not repeated).
void prepare_capture(MeasuredCapture& capture, const CapturePreparation& preparation = {});

}  // namespace clearsky
