// The paper's accuracy measure of a sky model against measured skies (Bruneton 2016, section
// "Quantitative evaluations"; models/evaluation/README.md). Per capture: the root mean square, over
// the 81 measured directions and the model-grid wavelengths inside 360..720 nm (31 wavelengths, 360
// to 712.5 nm, on the paper's 40-bin grid), of model minus measurement, the measured 1-nm spectra
// read by linear interpolation at those wavelengths; the model is queried at viewer altitude 0 with
// the capture's computed sun zenith and estimated sun azimuth. Total: the root of the mean of the
// per-capture squared RMSE. RMSE in mW/(m2.sr.nm).
// Per sample (direction) the result keeps the RMSE over the compared wavelengths, the mean
// signed error (bias) and the signed error at each compared wavelength, all model minus
// measurement: every sample compares the same wavelengths, so the capture's RMSE is the root of
// the mean of its samples' squared RMSE (what lets a user see where on the sky a model errs).
// Captures must be prepared first (capture_preparation.h): repaired and with sun positions.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "models/core/precompute_context.h"
#include "models/core/sky_model.h"
#include "models/evaluation/measured_sky.h"

namespace clearsky {

struct EvaluationOptions {
  double min_wavelength_nm = 360.0;
  double max_wavelength_nm = 720.0;
  bool use_estimated_sun_azimuth = true;  // false: the computed azimuth
  double viewer_altitude_m = 0.0;
  PrecomputeContext context;     // for the model's precomputation
  unsigned capture_threads = 0;  // captures evaluated in parallel; 0: all cores
};

// One measured direction of a capture (the Kider sample), errors in mW/(m2.sr.nm).
struct SampleEvaluation {
  int index = 0;  // the instrument's scan index (Kider: 0..80)
  double view_zenith_deg = 0;
  double view_azimuth_deg = 0;  // clockwise from North
  double rmse = 0;              // over the compared wavelengths
  double bias = 0;              // mean of model - measured over the compared wavelengths
};

struct CaptureEvaluation {
  std::string label;
  std::string time_iso;  // local time with offset
  double unix_time_utc_s = 0;
  double sun_zenith_deg = 0;   // as given to the model
  double sun_azimuth_deg = 0;  // as given to the model (clockwise from North)
  double rmse = 0;             // mW/(m2.sr.nm)
  std::size_t values_compared = 0;
  std::vector<SampleEvaluation> samples;  // in the capture's order
  // Model - measured, mW/(m2.sr.nm): samples.size() rows of EvaluationResult::wavelengths_nm.
  std::vector<double> sample_errors;
  std::span<const double> errors_of(std::size_t sample) const {
    const std::size_t n = samples.empty() ? 0 : sample_errors.size() / samples.size();
    return std::span<const double>(sample_errors).subspan(sample * n, n);
  }
};

struct EvaluationResult {
  std::string model_id;
  std::string model_version;
  double rmse = 0;                          // mW/(m2.sr.nm), over all captures
  std::vector<CaptureEvaluation> captures;  // in the order given
  std::vector<double> wavelengths_nm;       // the wavelengths compared
  double precompute_seconds = 0;
  double evaluate_seconds = 0;  // sun preparation and queries of all captures
};

// Precomputes the model (timed) and evaluates it. Throws std::invalid_argument for an
// unprepared capture or no wavelength to compare, std::runtime_error when the model cannot
// answer a sample (the status names why), and whatever the factory throws.
EvaluationResult evaluate_model(const ModelFactory& factory, const ModelConfig& config,
                                std::span<const MeasuredCapture> captures,
                                const EvaluationOptions& options = {});

// Evaluates an already built model (precompute_seconds = 0).
EvaluationResult evaluate_sky_model(const SkyModel& model,
                                    std::span<const MeasuredCapture> captures,
                                    const EvaluationOptions& options = {});

}  // namespace clearsky
