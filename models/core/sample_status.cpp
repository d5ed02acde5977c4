// Names and explanations of the sample statuses.
#include "models/core/sample_status.h"

namespace clearsky {

std::string_view to_string(SampleStatus s) {
  switch (s) {
    case SampleStatus::ok:
      return "ok";
    case SampleStatus::sun_below_horizon_unsupported:
      return "sun_below_horizon_unsupported";
    case SampleStatus::view_below_horizon_unsupported:
      return "view_below_horizon_unsupported";
    case SampleStatus::viewpoint_unsupported:
      return "viewpoint_unsupported";
    case SampleStatus::wavelength_out_of_range:
      return "wavelength_out_of_range";
    case SampleStatus::invalid_input:
      return "invalid_input";
    case SampleStatus::numerical_failure:
      return "numerical_failure";
    case SampleStatus::outside_fit_domain:
      return "outside_fit_domain";
  }
  return "unknown";
}

std::string_view describe(SampleStatus s) {
  switch (s) {
    case SampleStatus::ok:
      return "computed";
    case SampleStatus::sun_below_horizon_unsupported:
      return "the model does not answer for a sun this far below the zenith (see its "
             "max_sun_zenith_deg)";
    case SampleStatus::view_below_horizon_unsupported:
      return "the model answers only views above the horizon (view zenith <= 90 degrees)";
    case SampleStatus::viewpoint_unsupported:
      return "the model does not answer for an observer at this altitude";
    case SampleStatus::wavelength_out_of_range:
      return "a requested wavelength is outside the model's spectral range";
    case SampleStatus::invalid_input:
      return "an angle or altitude is not a finite number in its range";
    case SampleStatus::numerical_failure:
      return "the model produced a non-finite or negative value; no number is returned";
    case SampleStatus::outside_fit_domain:
      return "the model's fitted formula gives negative radiance in this direction (a low sun, "
             "outside "
             "the skies it was fitted to); the option clamp_negative_fit=1 returns 0 there instead";
  }
  return "unknown";
}

}  // namespace clearsky
