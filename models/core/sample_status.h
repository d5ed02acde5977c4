// Why a sample has (or has no) value. Every query answers a status per sample; only `ok`
// samples carry numbers, and the service reports the others with their reason.
#pragma once

#include <cstdint>
#include <string_view>

namespace clearsky {

enum class SampleStatus : std::uint8_t {
  ok,
  sun_below_horizon_unsupported,   // sun zenith beyond the model's max_sun_zenith_deg
  view_below_horizon_unsupported,  // view zenith > 90 degrees for a model that cannot
  viewpoint_unsupported,           // observer altitude outside the model's range
  wavelength_out_of_range,         // a requested wavelength outside the model's range
  invalid_input,                   // NaN or out-of-domain angles
  numerical_failure,               // the model produced NaN, infinity or negative radiance
  outside_fit_domain,              // a fitted model's formula turns negative here (no number)
};

std::string_view to_string(SampleStatus status);
std::string_view describe(SampleStatus status);

}  // namespace clearsky
