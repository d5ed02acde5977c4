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
// Samples a model cannot answer (docs/model-contract.md "What the public query functions check":
// the sun beyond its max_sun_zenith_deg, a view below its horizon, an observer altitude outside
// its range, a fitted formula outside its domain, an InvalidInput from its sun preparation, no
// answered wavelength in the compared range) never fail the evaluation. With
// OutOfDomain::exclude (the default) they are left out and listed per capture and reason; the
// capture's RMSE covers the samples compared, and a capture with none is unanswered (no RMSE,
// left out of the total). With OutOfDomain::clamp the model is evaluated at the nearest point of
// its domain instead, listed the same way: the sun at max_sun_zenith_deg, the view at the
// horizon, the altitude at the end of its range, and a fitted formula's negative radiance at 0
// (the model's own clamp_negative_fit, fit_domain.h); what has no nearest point (a NaN angle, a
// wavelength outside the model's range) is still excluded. A model producing NaN, infinity or a
// negative value (numerical_failure) is a bug, not a refusal: the evaluation fails.
// Measured spectra of any range (the open format, docs/measurement-formats.md): the compared
// wavelengths are at most those some measured spectrum of the captures reaches, and a sample
// whose spectrum does not reach every compared wavelength is excluded (wavelength_out_of_range)
// like a sample the model cannot answer. The sun azimuth is the estimated one where the capture
// has one, else the computed one (capture_preparation.h).
// Captures must be prepared first (capture_preparation.h): repaired and with sun positions.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "models/core/precompute_context.h"
#include "models/core/sky_model.h"
#include "models/evaluation/measured_sky.h"

namespace clearsky {

// What the evaluation does with a sample the model cannot answer (see above).
enum class OutOfDomain { exclude, clamp };
std::string_view to_string(OutOfDomain handling);
// "exclude" or "clamp"; nothing for other text.
std::optional<OutOfDomain> out_of_domain_from_string(std::string_view text);

struct EvaluationOptions {
  double min_wavelength_nm = 360.0;
  double max_wavelength_nm = 720.0;
  bool use_estimated_sun_azimuth = true;  // false: the computed azimuth
  double viewer_altitude_m = 0.0;
  PrecomputeContext context;     // for the model's precomputation
  unsigned capture_threads = 0;  // captures evaluated in parallel; 0: all cores
  OutOfDomain out_of_domain = OutOfDomain::exclude;
};

// The samples of a capture left out (or clamped) for one reason: scan indices, ascending.
struct OutOfDomainSamples {
  SampleStatus reason = SampleStatus::ok;
  std::vector<int> indices;
  bool operator==(const OutOfDomainSamples&) const = default;
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
  double rmse = 0;             // mW/(m2.sr.nm), over `samples`; 0 when unanswered
  std::size_t values_compared = 0;
  std::size_t samples_measured = 0;          // the capture's samples, compared or not
  std::vector<SampleEvaluation> samples;     // the compared samples, in the capture's order
  std::vector<OutOfDomainSamples> excluded;  // by reason, in SampleStatus order
  std::vector<OutOfDomainSamples> clamped;   // compared at the nearest point of the domain
  // A capture of which the model answered no sample: no RMSE, not in the total.
  bool answered() const { return !samples.empty(); }
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
  // mW/(m2.sr.nm): sqrt of the mean over the answered captures of their squared RMSE; NaN
  // when no capture is answered.
  double rmse = 0;
  std::vector<CaptureEvaluation> captures;  // in the order given
  std::size_t samples_compared = 0;         // what the RMSE covers, over all captures
  std::size_t samples_excluded = 0;
  std::size_t samples_clamped = 0;
  std::size_t captures_unanswered = 0;
  std::vector<double> wavelengths_nm;  // the wavelengths compared
  double precompute_seconds = 0;
  double evaluate_seconds = 0;  // sun preparation and queries of all captures
};

// Precomputes the model (timed) and evaluates it. Throws std::invalid_argument for an
// unprepared capture, std::runtime_error when the model fails numerically on a sample (the
// status names why), and whatever the factory throws. With OutOfDomain::clamp, a model whose
// descriptor lists clamp_negative_fit (off in `config`) is built a second time with it on, for
// the samples outside its fit domain.
EvaluationResult evaluate_model(const ModelFactory& factory, const ModelConfig& config,
                                std::span<const MeasuredCapture> captures,
                                const EvaluationOptions& options = {});

// Evaluates an already built model (precompute_seconds = 0). fit_clamped: the same model with
// clamp_negative_fit on, which answers the samples outside the fit domain under
// OutOfDomain::clamp (without it they are excluded).
EvaluationResult evaluate_sky_model(const SkyModel& model,
                                    std::span<const MeasuredCapture> captures,
                                    const EvaluationOptions& options = {},
                                    const SkyModel* fit_clamped = nullptr);

}  // namespace clearsky
