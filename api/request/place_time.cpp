// The place-and-time table and its parser (place_time.h).
#include "api/request/place_time.h"

#include <chrono>
#include <sstream>
#include <stdexcept>

#include "api/error/api_error.h"
#include "api/parse/coordinates.h"
#include "api/parse/iso8601_time.h"
#include "models/core/invalid_input.h"
#include "models/solar/delta_t.h"

namespace clearsky::api {

namespace {

using Kind = PlaceTimeKind;
using In = SolarPositionInput;

// The default of delta_t: computed from the request's time (place_time.h).
constexpr std::string_view kFromTime = "from time";

// The table of place_time.h (a test compares the two).
// clang-format off
constexpr PlaceTimeParameter kParameters[] = {
    {"lat", Kind::latitude, "degree", "required", {-90.0, 90.0},
     "latitude, North positive: decimal or DMS (42d26'36\"N)", &In::latitude_deg},
    {"lon", Kind::longitude, "degree", "required", {-180.0, 180.0},
     "longitude, East positive: decimal or DMS (76d28'55\"W)", &In::longitude_deg},
    {"time", Kind::time, "ISO 8601", "now", {0.0, 6000.0},
     "instant with offset or Z (2013-05-27T11:45:00-04:00)", &In::unix_time_utc_s},
    {"altitude", Kind::number, "m", "0", {-500.0, 1e7},
     "observer above sea level (also the sky's viewpoint)", &In::elevation_m},
    {"pressure", Kind::number, "mbar", "1013.25", {0.0, 5000.0},
     "annual mean local pressure, for refraction", &In::pressure_mbar},
    {"temperature", Kind::number, "Celsius", "15", {-273.0, 6000.0, true, false},
     "annual mean local temperature, for refraction", &In::temperature_c},
    {"delta_t", Kind::number, "s", "from time", {-8000.0, 8000.0},
     "TT - UT1; absent: Espenak-Meeus for the year", &In::delta_t_s},
    {"delta_ut1", Kind::number, "s", "0", {-1.0, 1.0, true, true}, "UT1 - UTC", &In::delta_ut1_s},
    {"refraction", Kind::boolean, "bool", "true", {}, "apply atmospheric refraction to the zenith",
     nullptr},
};
// clang-format on

std::string format_number(double x) {
  std::ostringstream out;
  out.precision(10);
  out << x;
  return out.str();
}

const PlaceTimeParameter& row(std::string_view name) {
  for (const PlaceTimeParameter& r : kParameters) {
    if (r.name == name) return r;
  }
  throw std::logic_error("no place/time parameter " + std::string(name));
}

// The text of a parameter: the request's, or the table's default.
std::string text_or_default(Parameters& p, const PlaceTimeParameter& r) {
  const auto text = p.text(std::string(r.name));
  if (text) return *text;
  if (r.fallback == "required") throw missing_parameter(std::string(r.name));
  return std::string(r.fallback);
}

double number_of(Parameters& p, const PlaceTimeParameter& r) {
  const std::string name(r.name);
  const std::string text = text_or_default(p, r);
  const double x = number_value(name, text);
  if (!r.range.contains(x)) {
    throw invalid_parameter(
        name, "must be in " + r.range.text() + " " + std::string(r.unit) + ", got " + text);
  }
  return x;
}

double angle_of(Parameters& p, const PlaceTimeParameter& r) {
  const std::string name(r.name);
  const std::string text = text_or_default(p, r);
  const double degrees =
      r.kind == Kind::latitude ? parse_latitude(text, name) : parse_longitude(text, name);
  if (!r.range.contains(degrees)) {
    throw invalid_parameter(name, "must be in " + r.range.text() + " degrees, got " + text);
  }
  return degrees;
}

// Unix seconds of 0h UTC on January 1 of a (proleptic Gregorian) year.
double start_of_year_unix_s(int year) {
  using namespace std::chrono;
  const sys_days day{std::chrono::year{year} / January / 1};
  return duration<double>(day.time_since_epoch()).count();
}

void read_time(Parameters& p, const PlaceTimeParameter& r, std::optional<double> now_unix_s,
               PlaceTime& out) {
  const std::string name(r.name);
  const auto text = p.text(name);
  if (text) {
    const Iso8601Time parsed = parse_iso8601_time(*text, name);
    out.position.*r.field = parsed.unix_time_utc_s;
    out.utc_offset_min = parsed.utc_offset_min;
    out.utc_designator = parsed.utc_designator;
  } else {
    if (!now_unix_s) throw missing_parameter(name, "this endpoint has no default instant");
    out.position.*r.field = *now_unix_s;
    out.utc_offset_min = 0;
    out.utc_designator = true;
  }
  const double t = out.position.*r.field;
  if (!(t >= start_of_year_unix_s(static_cast<int>(r.range.min)) &&
        t < start_of_year_unix_s(static_cast<int>(r.range.max) + 1))) {
    throw invalid_parameter(name, "must lie in the years " + r.range.text() + " (UTC)" +
                                      (text ? ", got " + *text : std::string()));
  }
}

}  // namespace

std::string Interval::text() const {
  return std::string(min_open ? "(" : "[") + format_number(min) + ", " + format_number(max) +
         (max_open ? ")" : "]");
}

std::span<const PlaceTimeParameter> place_time_parameters() { return kParameters; }

double current_unix_time_s() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

PlaceTime parse_place_and_time(Parameters& p, std::optional<double> now_unix_s) {
  PlaceTime out;
  SolarPositionInput& in = out.position;
  for (const PlaceTimeParameter& r : kParameters) {
    switch (r.kind) {
      case Kind::latitude:
      case Kind::longitude:
        in.*r.field = angle_of(p, r);
        break;
      case Kind::time:
        read_time(p, r, now_unix_s, out);
        break;
      case Kind::boolean:
        in.refraction = p.boolean_or(std::string(r.name), r.fallback == "true");
        break;
      case Kind::number:
        if (r.fallback == kFromTime && !p.text(std::string(r.name))) {
          // delta_t, by the table's row order read after time (models/solar/delta_t.h).
          try {
            in.*r.field = espenak_meeus_delta_t_at_s(in.unix_time_utc_s);
          } catch (const InvalidInput& e) {
            throw from_invalid_input(e);
          }
          out.delta_t_from_time = true;
          break;
        }
        in.*r.field = number_of(p, r);
        break;
    }
  }
  return out;
}

double parse_altitude_m(Parameters& p) { return number_of(p, row("altitude")); }

SolarPosition solar_position_checked(const SolarPositionInput& input) {
  try {
    return solar_position(input);
  } catch (const InvalidInput& e) {
    throw from_invalid_input(e);
  }
}

}  // namespace clearsky::api
