// The 15 public Kider et al. 2014 captures of 2013-05-27 (README.md "Data"), loaded
// once per process and prepared as the paper's evaluation does (capture_preparation.h: North
// sample repaired, SPA sun zenith without refraction, sun azimuth estimated from the sky's
// symmetry), so that an accuracy test is a few lines:
//
//   CLEARSKY_REQUIRE_SHARED_DATA("kider2014");
//   const auto r = evaluate_model(*find_model("preetham"), ModelConfig{}, public_captures(), {});
//   EXPECT_NEAR(r.rmse, 88.72, 0.05 * 88.72);
//
// Thread-safe (initialised once); throws std::runtime_error when the data is missing.
#pragma once

#include <vector>

#include "models/evaluation/measured_sky.h"

namespace clearsky::testing {

// Prepared captures, in time order.
const std::vector<MeasuredCapture>& public_captures();
// The same captures as imported (spectra as measured, no sun position).
const std::vector<MeasuredCapture>& public_captures_as_imported();
// Wall time of the first call's import and of its preparation, seconds.
struct PublicCapturesTiming {
  double import_seconds = 0;
  double prepare_seconds = 0;
};
PublicCapturesTiming public_captures_timing();

}  // namespace clearsky::testing
