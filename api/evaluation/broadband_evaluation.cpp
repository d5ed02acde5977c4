// A model against a broadband irradiance dataset (broadband_evaluation.h).
#include "api/evaluation/broadband_evaluation.h"

#include <cmath>
#include <limits>
#include <numeric>

#include "api/evaluation/averaging_period_quadrature.h"
#include "api/evaluation/broadband_model_altitude.h"
#include "api/irradiance/broadband_plane_irradiance.h"
#include "models/atmosphere/spctral2.h"
#include "models/core/numeric.h"
#include "models/solar/solar_position.h"

namespace clearsky::api {
namespace {

std::optional<double> measured(const storage::IrradianceSample& s, std::size_t component) {
  return component == 0 ? s.ghi_w_m2 : component == 1 ? s.dhi_w_m2 : s.dni_w_m2;
}

// The sun at the sample's site at an instant (NREL SPA, no refraction, as for captures).
SolarPosition sun_at(const storage::IrradianceSample& s, double time_utc_s) {
  SolarPositionInput input;
  input.unix_time_utc_s = time_utc_s;
  input.latitude_deg = s.latitude_deg;
  input.longitude_deg = s.longitude_deg;
  input.elevation_m = s.elevation_m;
  input.refraction = false;
  return solar_position(input);
}

std::optional<double> modelled_of(const ModelledIrradiance& m, std::size_t component) {
  return component == 0 ? m.ghi_w_m2 : component == 1 ? m.dhi_w_m2 : m.dni_w_m2;
}

}  // namespace

std::vector<ModelledIrradiance> modelled_broadband_irradiance(
    const SkyModel& model, const std::vector<storage::IrradianceSample>& samples) {
  std::vector<std::size_t> indices(model.wavelengths().size());
  std::iota(indices.begin(), indices.end(), std::size_t{0});
  std::vector<ModelledIrradiance> modelled;
  modelled.reserve(samples.size());
  for (const storage::IrradianceSample& s : samples) {
    const Viewpoint site{model_altitude_for_site(model.descriptor(), s.elevation_m).altitude_m};
    ModelledIrradiance m;
    m.sun_zenith_deg = sun_at(s, representative_time_utc_s(s.time_utc_s, s.averaging_s)).zenith_deg;
    if (!(m.sun_zenith_deg < 90.0)) {
      modelled.push_back(m);
      continue;
    }
    // The mean over the period the sample averages (averaging_period_quadrature.h); a node with
    // the sun below the horizon adds nothing.
    std::optional<double> ghi = 0.0, dhi = 0.0, dni = 0.0;
    // A component the model did not answer at one node is not answered for the sample.
    const auto add = [](std::optional<double>& sum, double weight, std::optional<double> value) {
      if (sum && value && std::isfinite(*value))
        *sum += weight * *value;
      else
        sum.reset();
    };
    for (const AveragingNode& node : averaging_nodes(s.time_utc_s, s.averaging_s)) {
      const SolarPosition position = sun_at(s, node.time_utc_s);
      if (!(position.zenith_deg < 90.0)) continue;
      const SunPosition sun{position.zenith_deg * kDegree, position.azimuth_deg * kDegree};
      const auto state = model.prepare_sun(sun);
      const HorizontalIrradiance h = horizontal_irradiance(model, *state, site, true, true, "time");
      const BroadbandConditions conditions{
          .sun_zenith_rad = sun.zenith_rad,
          .altitude_m = site.altitude_m,
          .atmosphere = model.config().atmosphere,
          .earth_sun_distance_factor =
              spctral2::earth_sun_distance_factor(day_of_year_utc(node.time_utc_s))};
      const BroadbandExtension extension(model.wavelengths(), indices, conditions);
      const BroadbandHorizontalIrradiance b = broadband_horizontal_irradiance(extension, h);
      add(ghi, node.weight, b.global_w_m2);
      add(dhi, node.weight, b.diffuse_w_m2);
      add(dni, node.weight, b.direct_normal_w_m2);
    }
    m.ghi_w_m2 = ghi;
    m.dhi_w_m2 = dhi;
    m.dni_w_m2 = dni;
    modelled.push_back(m);
  }
  return modelled;
}

std::vector<BroadbandComponentResult> compare_broadband_irradiance(
    const std::vector<storage::IrradianceSample>& samples,
    const std::vector<ModelledIrradiance>& modelled) {
  std::vector<BroadbandComponentResult> results;
  for (std::size_t c = 0; c < kIrradianceComponents.size(); ++c) {
    bool measured_any = false;
    for (const auto& s : samples) measured_any = measured_any || measured(s, c).has_value();
    if (!measured_any) continue;
    BroadbandComponentResult r;
    r.component = kIrradianceComponents[c];
    r.errors_w_m2.assign(samples.size(), std::numeric_limits<double>::quiet_NaN());
    double sum = 0, sum_squares = 0;
    for (std::size_t i = 0; i < samples.size(); ++i) {
      const auto value = measured(samples[i], c);
      const auto model_value = modelled_of(modelled[i], c);
      if (!value || !model_value || !std::isfinite(*model_value)) continue;
      const double error = *model_value - *value;
      r.errors_w_m2[i] = error;
      sum += error;
      sum_squares += error * error;
      ++r.samples_compared;
    }
    if (r.samples_compared > 0) {
      const double n = static_cast<double>(r.samples_compared);
      r.rmse_w_m2 = std::sqrt(sum_squares / n);
      r.mean_bias_w_m2 = sum / n;
    }
    results.push_back(std::move(r));
  }
  return results;
}

std::optional<double> pooled_rmse_w_m2(const std::vector<BroadbandComponentResult>& results) {
  double sum_squares = 0;
  std::int64_t n = 0;
  for (const auto& r : results)
    if (r.rmse_w_m2) {
      sum_squares += *r.rmse_w_m2 * *r.rmse_w_m2 * static_cast<double>(r.samples_compared);
      n += r.samples_compared;
    }
  if (n == 0) return std::nullopt;
  return std::sqrt(sum_squares / static_cast<double>(n));
}

}  // namespace clearsky::api
