// The instants and suns of a time-series request (time_steps.h).
#include "api/request/time_steps.h"

#include <cmath>
#include <stdexcept>

#include "api/encode/iso8601_time.h"
#include "api/error/api_error.h"
#include "api/parse/iso8601_duration.h"
#include "api/parse/iso8601_time.h"
#include "api/request/place_time.h"
#include "api/request/sky_request.h"
#include "models/core/invalid_input.h"
#include "models/core/numeric.h"
#include "models/solar/delta_t.h"

namespace clearsky::api {

namespace {

// An instant with its offset, or a local time in tz (the zone's offset, DST included).
double parse_instant(const std::string& text, const std::string& parameter,
                     const std::optional<std::string>& tz) {
  const std::size_t t = text.find('T');
  const bool has_offset =
      t != std::string::npos && text.find_first_of("Zz+-", t) != std::string::npos;
  if (has_offset || !tz) return parse_iso8601_time(text, parameter).unix_time_utc_s;
  return parse_iso8601_local_time(text, *tz, parameter, "tz").unix_time_utc_s;
}

void check_zone(const std::string& zone) {
  try {
    (void)utc_offset_min_in_zone(0.0, zone);
  } catch (const std::exception&) {
    throw invalid_parameter("tz",
                            "must be an IANA time zone name (e.g. Europe/Paris), got " + zone);
  }
}

SolarPosition sun_at(SolarPositionInput position, bool delta_t_from_time, double unix_s) {
  position.unix_time_utc_s = unix_s;
  try {
    if (delta_t_from_time) position.delta_t_s = espenak_meeus_delta_t_at_s(unix_s);
    return solar_position(position);
  } catch (const InvalidInput& e) {
    throw invalid_parameter(
        "end", std::string("a step the sun position cannot be computed for: ") + e.what());
  }
}

}  // namespace

SunPosition TimeSteps::sun(std::size_t i) const {
  return {degrees_to_radians(zenith_deg[i]), degrees_to_radians(azimuth_deg[i])};
}

TimeSteps parse_time_steps(Parameters& p, std::size_t max_steps) {
  if (p.has("time"))
    throw invalid_parameter("time", "a series takes start, end and step instead of time");
  for (const char* name : {"sun_zenith", "sun_azimuth"}) {
    if (p.has(name))
      throw invalid_parameter(name, "a series computes the sun of each step from lat and lon");
  }
  TimeSteps s;
  s.tz = p.text("tz");
  if (s.tz) check_zone(*s.tz);
  const std::string start_text = p.required_text("start");
  const std::string end_text = p.required_text("end");
  s.start_unix_s = parse_instant(start_text, "start", s.tz);
  const double end_unix_s = parse_instant(end_text, "end", s.tz);
  if (end_unix_s < s.start_unix_s)
    throw invalid_parameter("end",
                            "must not be before start (" + start_text + "), got " + end_text);
  if (auto step = p.text("step")) {
    s.step_text = *step;
    s.step_s = parse_iso8601_duration_s(*step, "step");
  }
  const double span_steps =
      std::floor((end_unix_s - s.start_unix_s) / static_cast<double>(s.step_s));
  if (span_steps + 1.0 > static_cast<double>(max_steps)) {
    throw too_large("step", "start to end every " + s.step_text + " is " +
                                std::to_string(static_cast<long long>(span_steps) + 1) +
                                " steps, above the limit of " + std::to_string(max_steps) +
                                "; ask for a longer step or a shorter period");
  }
  s.steps = static_cast<std::size_t>(span_steps) + 1;
  const PlaceTime place = parse_place_and_time(p, s.start_unix_s);
  s.position = place.position;
  s.delta_t_from_time = place.delta_t_from_time;
  s.zenith_deg.resize(s.steps);
  s.azimuth_deg.resize(s.steps);
  for (std::size_t i = 0; i < s.steps; ++i) {
    const SolarPosition sun = sun_at(s.position, s.delta_t_from_time, s.unix_time_s(i));
    s.zenith_deg[i] = sun.zenith_deg;
    s.azimuth_deg[i] = sun.azimuth_deg;
    if (!s.night(i)) ++s.day_steps;
  }
  return s;
}

void require_per_sun_day_steps(const TimeSteps& s, const ModelDescriptor& d) {
  if (d.capabilities.per_sun_precomputation && s.day_steps > kMaxPerSunDaySteps) {
    throw too_large("end", "model " + d.id + " precomputes its tables for each sun position; a " +
                               "series by it takes at most " + std::to_string(kMaxPerSunDaySteps) +
                               " steps with the sun up, this one has " +
                               std::to_string(s.day_steps) +
                               "; ask for a shorter period or use a model with shared tables " +
                               "(bruneton, elek, hosek, preetham)");
  }
}

void require_answerable_suns(const TimeSteps& s, const SkyModel& model) {
  for (std::size_t i = 0; i < s.steps; ++i) {
    if (s.night(i)) continue;
    const SampleStatus status = model.check_sun(s.sun(i));
    if (status != SampleStatus::ok) require_answer(status, "start", model.descriptor().id);
  }
}

}  // namespace clearsky::api
