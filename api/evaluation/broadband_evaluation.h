// A model against a broadband irradiance dataset (docs/data-api.md "Evaluations of broadband
// irradiance"): at each measured instant, the model's broadband (300..4000 nm) global
// horizontal, diffuse horizontal and direct normal irradiance, by the one computation of
// GET /v1/irradiance/series (api/irradiance/broadband_plane_irradiance.h), compared with what
// was measured:
//  - the sun is computed from the instant and the site (NREL SPA, no refraction, as for
//    captures: models/evaluation/capture_preparation.h), the Earth-Sun distance from the date;
//  - the model answers at the site's elevation where its descriptor answers that altitude, at
//    its ground otherwise (broadband_model_altitude.h), with the absorbers of its configuration
//    (precipitable water, ozone);
//  - a sample that averages a period (averaging_s) is compared with the model's mean over that
//    period, labelled at its end (averaging_period_quadrature.h);
//  - a sample is compared, per component it measured, when the sun is above the horizon
//    (zenith below 90 degrees) at its instant, or at the middle of the period it averages; its
//    error is model minus measured, W/m2;
//  - per component, the RMSE and the mean bias over the samples compared (absent with none).
// Models without a broadband answer (broadband_unavailable_reason: Preetham, Hosek-Wilkie) are
// refused by the caller with an error naming `model`. Thread-safe (const inputs only).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "models/core/sky_model.h"
#include "storage/repositories/irradiance_sample_repository.h"

namespace clearsky::api {

inline constexpr std::array<const char*, 3> kIrradianceComponents = {"ghi", "dhi", "dni"};

// The model's broadband figures at one sample; absent at night or where it did not answer.
struct ModelledIrradiance {
  double sun_zenith_deg = 0;  // at the sample's instant, or the middle of its period
  std::optional<double> ghi_w_m2, dhi_w_m2, dni_w_m2;
};

// One model's answers at every sample, in their order.
std::vector<ModelledIrradiance> modelled_broadband_irradiance(
    const SkyModel& model, const std::vector<storage::IrradianceSample>& samples);

struct BroadbandComponentResult {
  std::string component;  // ghi, dhi or dni
  std::optional<double> rmse_w_m2;
  std::optional<double> mean_bias_w_m2;  // mean of model minus measured
  std::int64_t samples_compared = 0;
  std::vector<double> errors_w_m2;  // per sample, NaN where not compared
};

// The components the samples measure (in kIrradianceComponents' order), compared.
std::vector<BroadbandComponentResult> compare_broadband_irradiance(
    const std::vector<storage::IrradianceSample>& samples,
    const std::vector<ModelledIrradiance>& modelled);

// The RMSE over the components compared, all their samples pooled: the fits' objective.
std::optional<double> pooled_rmse_w_m2(const std::vector<BroadbandComponentResult>& results);

}  // namespace clearsky::api
