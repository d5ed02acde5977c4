// The instants and suns of a time-series request, one parser for GET /v1/irradiance/series and
// GET /v1/skypatches with start (docs/building-energy.md "Irradiance time series", "Sky
// matrices"): one place (api/request/place_time.h, time refused) from start to end every step.
//
// clang-format off
// | parameter  | unit     | default  | range          | meaning                                                     |
// |------------|----------|----------|----------------|-------------------------------------------------------------|
// | start, end | ISO 8601 | required | end >= start   | first and last instant (inclusive); an offset or Z, or local in tz |
// | tz         | IANA     | none     | a zone name    | local times of start/end and of the time_local output       |
// | step       | ISO 8601 | PT1H     | > 0            | duration between steps (PT10M, PT1H, P1D)                   |
// clang-format on
//
// A local time the zone skips is refused naming it, one it repeats is the earlier instant.
// sun_zenith, sun_azimuth and time are refused (each step's sun comes from lat and lon by NREL
// SPA, with Delta T of each step's month unless delta_t is given). Night: an apparent sun
// zenith of 90 degrees or more (no twilight). Refusals are ApiErrors naming the parameter.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "api/request/parameters.h"
#include "models/core/model_descriptor.h"
#include "models/core/sky_model.h"
#include "models/solar/solar_position.h"

namespace clearsky::api {

// A leap year at 10-minute steps.
inline constexpr std::size_t kMaxSeriesSteps = 8784 * 6;
// Daytime steps of a model that prepares each sun (per_sun_precomputation: Haber, Nishita96).
inline constexpr std::size_t kMaxPerSunDaySteps = 96;

struct TimeSteps {
  SolarPositionInput position;  // the place; unix_time_utc_s set per step
  bool delta_t_from_time = false;
  double start_unix_s = 0;
  long long step_s = 3600;
  std::string step_text = "PT1H";
  std::size_t steps = 0;
  std::optional<std::string> tz;
  // The apparent sun of each step, degrees.
  std::vector<double> zenith_deg, azimuth_deg;
  std::size_t day_steps = 0;

  double unix_time_s(std::size_t i) const {
    return start_unix_s + static_cast<double>(i) * static_cast<double>(step_s);
  }
  bool night(std::size_t i) const { return zenith_deg[i] >= 90.0; }
  SunPosition sun(std::size_t i) const;
};

// Reads start, end, step, tz and the place, refuses time and the sun angles, and computes the
// sun of every step. At most max_steps steps (413 naming step).
TimeSteps parse_time_steps(Parameters& p, std::size_t max_steps = kMaxSeriesSteps);

// Before the model is built: a model that prepares each sun takes at most kMaxPerSunDaySteps
// daytime steps (413 naming end).
void require_per_sun_day_steps(const TimeSteps& steps, const ModelDescriptor& d);

// Once it is built: every daytime sun within the model's domain (its refusal names start).
void require_answerable_suns(const TimeSteps& steps, const SkyModel& model);

}  // namespace clearsky::api
